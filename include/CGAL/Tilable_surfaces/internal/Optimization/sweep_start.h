// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H

// An exact starting point for the clusterings of a quad grid whose clusters
// each lie in one column (sweep_clusterings() in segment_candidates.h).
//
// On a grid, rows of quads between the rings of vertices 0..R, let every
// ring be the image of the one before under a rigid motion M_i that is the
// same for all the rows of a run: ring_{i+1} = M_i ring_i. Then the quad of
// column c in row i + 1 is M_i applied to the one in row i, so every column
// of a run is congruent quad by quad, in grid order: a swept surface of one
// section (a piece of a screw sweep per run). Such a surface is exact for
// any clustering whose clusters lie in one column of one run, whatever the
// input. The Gauss-Newton solver, started at the input, does not find it on
// large grids (10k seashell, K = 100: stalls near 3e-3, user manual, section
// Optimization): the section must stop growing, a large and coherent move.
// Built directly it costs O(F):
// - M_i of a run: the rigid motion that best maps its rings onto the next
//   ones (Umeyama, no scale), stacked;
// - the section: the mean of the input rings pulled back to the middle ring
//   by the composed motions;
// - the rings: the section pushed forward again, the whole then rigidly
//   aligned with the input.

#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The rings of vertex indices of `grid` (rows + 1 of them, each of columns
// vertices, one more when the rows are open), in grid order: the quad of
// row r and column c has its corners on rings r and r + 1 at positions c
// and c + 1. Empty when the rows do not share rings as a grid does, or the
// grid is closed across its rows (the first ring is the last).
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap>
std::vector<std::vector<std::size_t> > grid_rings(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim,
                                                  const Quad_grid& grid)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t rows = grid.rows, columns = grid.columns;
  if(closed_across_rows(grid))
    return {};
  std::vector<face_descriptor> face_of(num_faces(pm));
  for(face_descriptor f : faces(pm))
    face_of[get(fim, f)] = f;
  auto corner = [&](std::size_t r, std::size_t c, int i) {
    const std::size_t f = grid.face_at[r * columns + c];
    halfedge_descriptor h = halfedge(face_of[f], pm);
    for(int k = 0; k < grid.corner_offset[f] + i; ++k)
      h = next(h, pm);
    return std::size_t(get(vim, target(h, pm)));
  };
  // Corners 0 and 1 of every face of a row lie on one ring, 3 and 2 on the
  // other; corner 0 of column c is corner 1 of column c + 1.
  const bool closed = corner(0, columns - 1, 0) == corner(0, 0, 1);
  auto ring = [&](std::size_t r, int first, int last) {
    std::vector<std::size_t> v;
    for(std::size_t c = 0; c < columns; ++c)
      v.push_back(corner(r, c, first));
    if(!closed)
      v.push_back(corner(r, columns - 1, last));
    return v;
  };
  std::vector<std::vector<std::size_t> > side_a(rows), side_b(rows);
  for(std::size_t r = 0; r < rows; ++r)
  {
    side_a[r] = ring(r, 1, 0);
    side_b[r] = ring(r, 2, 3);
  }
  std::vector<std::vector<std::size_t> > rings;
  for(int flip = 0; flip < 2 && rings.empty(); ++flip)
  {
    const std::vector<std::vector<std::size_t> >& first = flip ? side_b : side_a;
    const std::vector<std::vector<std::size_t> >& second = flip ? side_a : side_b;
    bool shared = true;
    for(std::size_t r = 0; r + 1 < rows && shared; ++r)
      shared = second[r] == first[r + 1];
    if(!shared)
      continue;
    rings.push_back(first[0]);
    rings.insert(rings.end(), second.begin(), second.end());
  }
  return rings;
}

// Positions, by vertex index, at which the clustering `label` (by face
// index) is exact, as described above; an empty matrix when the quads do
// not form a grid whose every cluster lies in one column and one run of
// rows. `points` are the input positions by vertex index.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Point_matrix sweep_start(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                         const Point_matrix& points, const std::vector<std::size_t>& label)
{
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  for(int row_direction = 0; row_direction < 2; ++row_direction)
  {
    const Quad_grid grid = quad_grid(pm, fim, vpm, strips, row_direction);
    if(grid.rows == 0)
      continue;
    const std::size_t rows = grid.rows, columns = grid.columns;
    auto label_at = [&](std::size_t r, std::size_t c) { return label[grid.face_at[r * columns + c]]; };
    // Rows r and r + 1 share a motion when a cluster holds a quad of both.
    std::vector<std::size_t> run_of(rows, 0);
    for(std::size_t r = 1; r < rows; ++r)
    {
      bool tied = false;
      for(std::size_t c = 0; c < columns && !tied; ++c)
        tied = label_at(r, c) == label_at(r - 1, c);
      run_of[r] = run_of[r - 1] + (tied ? 0 : 1);
    }
    // Every cluster in one column and one run.
    const std::size_t k = *std::max_element(label.begin(), label.end()) + 1;
    std::vector<std::size_t> column_of(k, no_index()), run_of_cluster(k, no_index());
    bool fits = true;
    for(std::size_t r = 0; r < rows && fits; ++r)
      for(std::size_t c = 0; c < columns && fits; ++c)
      {
        const std::size_t l = label_at(r, c);
        if(column_of[l] == no_index())
        {
          column_of[l] = c;
          run_of_cluster[l] = run_of[r];
        }
        fits = column_of[l] == c && run_of_cluster[l] == run_of[r];
      }
    if(!fits)
      continue;
    const std::vector<std::vector<std::size_t> > rings = grid_rings(pm, fim, vim, grid);
    if(rings.empty())
      continue;
    const Eigen::Index width = Eigen::Index(rings[0].size());
    std::vector<Eigen::Matrix3Xd> ring(rows + 1, Eigen::Matrix3Xd(3, width));
    for(std::size_t i = 0; i <= rows; ++i)
      for(Eigen::Index j = 0; j < width; ++j)
        ring[i].col(j) = points.row(Eigen::Index(rings[i][std::size_t(j)])).transpose();
    // The motion of each run.
    const std::size_t runs = run_of.back() + 1;
    std::vector<Eigen::Matrix4d> motion(runs);
    for(std::size_t s = 0, a = 0; s < runs; ++s)
    {
      std::size_t b = a;
      while(b < rows && run_of[b] == s)
        ++b;
      Eigen::Matrix3Xd from(3, width * Eigen::Index(b - a)), to(3, width * Eigen::Index(b - a));
      for(std::size_t i = a; i < b; ++i)
      {
        from.middleCols(width * Eigen::Index(i - a), width) = ring[i];
        to.middleCols(width * Eigen::Index(i - a), width) = ring[i + 1];
      }
      motion[s] = Eigen::umeyama(from, to, false);
      a = b;
    }
    // frame[i] maps the middle ring's frame to ring i's.
    const std::size_t middle = rows / 2;
    std::vector<Eigen::Matrix4d> frame(rows + 1, Eigen::Matrix4d::Identity());
    for(std::size_t i = middle; i < rows; ++i)
      frame[i + 1] = motion[run_of[i]] * frame[i];
    for(std::size_t i = middle; i > 0; --i)
      frame[i - 1] = motion[run_of[i - 1]].inverse() * frame[i];
    auto apply = [](const Eigen::Matrix4d& m, const Eigen::Matrix3Xd& x) -> Eigen::Matrix3Xd {
      return (m.topLeftCorner<3, 3>() * x).colwise() + m.topRightCorner<3, 1>();
    };
    Eigen::Matrix3Xd section = Eigen::Matrix3Xd::Zero(3, width);
    for(std::size_t i = 0; i <= rows; ++i)
      section += apply(frame[i].inverse(), ring[i]);
    section /= double(rows + 1);
    Eigen::Matrix3Xd swept(3, width * Eigen::Index(rows + 1)), input(3, width * Eigen::Index(rows + 1));
    for(std::size_t i = 0; i <= rows; ++i)
    {
      swept.middleCols(width * Eigen::Index(i), width) = apply(frame[i], section);
      input.middleCols(width * Eigen::Index(i), width) = ring[i];
    }
    const Eigen::Matrix3Xd aligned = apply(Eigen::umeyama(swept, input, false), swept);
    Point_matrix start = points;
    for(std::size_t i = 0; i <= rows; ++i)
      for(Eigen::Index j = 0; j < width; ++j)
        start.row(Eigen::Index(rings[i][std::size_t(j)])) = aligned.col(width * Eigen::Index(i) + j).transpose();
    return start;
  }
  return Point_matrix();
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
