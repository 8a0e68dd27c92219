// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H

// An exact starting point for the sweep clusterings of a quad grid
// (sweep_clusterings() in sweep_candidates.h, which says why they are
// exact). The Gauss-Newton solver, started at the input, does not find
// such surfaces on large grids (10k seashell, K = 100: stalls near 3e-3,
// user manual, section Optimization): the section must stop growing, a
// large and coherent move. Built directly it costs O(F):
// - M_i of a run: the rigid motion that best maps its rings onto the next
//   ones (Umeyama, no scale), stacked;
// - the section: the mean of the input rings pulled back to the middle ring
//   by the composed motions, its column runs put on their helices;
// - the rings: the section pushed forward again, the whole then rigidly
//   aligned with the input.
// A row that is a run of its own has a mold per quad: the groups of runs it
// separates are each built so, from a section of their own
// (grouped_sweep_start()). A row that is one mold on a tube of round section
// joins groups swept from regular polygons on one axis
// (coaxial_sweep_start()).

#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The label of the cell of row r and column c of `grid`, no_index() at a
// missing cell of a trimmed grid.
inline std::size_t grid_cell_label(const Quad_grid& grid, const std::vector<std::size_t>& label, std::size_t r,
                                   std::size_t c)
{
  const std::size_t f = grid.face_at[r * grid.columns + c];
  return f == no_index() ? no_index() : label[f];
}

// The run of rows of every row: rows r and r + 1 share a motion when a
// cluster holds a quad of both. With `one_run` (a trimmed grid, or one
// closed across its rows, swept as one run by sweep_clusterings(), whose
// columns may be cut into pieces), every row is in run 0.
inline std::vector<std::size_t> grid_row_runs(const Quad_grid& grid, const std::vector<std::size_t>& label,
                                              bool one_run)
{
  std::vector<std::size_t> run_of(grid.rows, 0);
  for(std::size_t r = 1; r < grid.rows && !one_run; ++r)
  {
    bool tied = false;
    for(std::size_t c = 0; c < grid.columns && !tied; ++c)
      tied = grid_cell_label(grid, label, r, c) != no_index() &&
             grid_cell_label(grid, label, r, c) == grid_cell_label(grid, label, r - 1, c);
    run_of[r] = run_of[r - 1] + (tied ? 0 : 1);
  }
  return run_of;
}

// How the clusters of `label` lie in the runs `run_of` of the grid.
enum class Sweep_layout { NONE, COLUMNS_OF_RUNS, COLUMN_RUNS };

// COLUMNS_OF_RUNS when every cluster lies in one column and one run,
// COLUMN_RUNS when the grid is one run whose clusters are runs of columns
// (screw_column_runs()), NONE otherwise. `run_of_column` receives the label
// of the first quad of every column.
inline Sweep_layout sweep_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
                                 const std::vector<std::size_t>& run_of, std::vector<std::size_t>& run_of_column)
{
  const std::size_t rows = grid.rows, columns = grid.columns;
  const std::size_t k = *std::max_element(label.begin(), label.end()) + 1;
  std::vector<std::size_t> column_of(k, no_index()), run_of_cluster(k, no_index());
  bool fits = true;
  for(std::size_t r = 0; r < rows && fits; ++r)
    for(std::size_t c = 0; c < columns && fits; ++c)
    {
      const std::size_t l = grid_cell_label(grid, label, r, c);
      if(l == no_index())
        continue;
      if(column_of[l] == no_index())
      {
        column_of[l] = c;
        run_of_cluster[l] = run_of[r];
      }
      fits = column_of[l] == c && run_of_cluster[l] == run_of[r];
    }
  run_of_column.assign(columns, no_index());
  for(std::size_t r = 0; r < rows; ++r)
    for(std::size_t c = 0; c < columns; ++c)
      if(run_of_column[c] == no_index())
        run_of_column[c] = grid_cell_label(grid, label, r, c);
  if(fits)
    return Sweep_layout::COLUMNS_OF_RUNS;
  bool column_runs = run_of.back() == 0;
  for(std::size_t r = 1; r < rows && column_runs; ++r)
    for(std::size_t c = 0; c < columns && column_runs; ++c)
      column_runs = grid_cell_label(grid, label, r, c) == no_index() ||
                    grid_cell_label(grid, label, r, c) == run_of_column[c];
  return column_runs ? Sweep_layout::COLUMN_RUNS : Sweep_layout::NONE;
}

// Moves the points present of the rings in `points` (by vertex index) to the
// swept `surface` (rings side by side), rigidly aligned with the input
// (Umeyama, no scale). `ring`: the input rings, `rings`: their vertex
// indices, `present`: per ring, 1 or 0 per point. A closed grid's last ring
// is its first, and is not placed twice.
inline void place_sweep(Point_matrix& points, const Eigen::Matrix3Xd& surface,
                        const std::vector<Eigen::Matrix3Xd>& ring,
                        const std::vector<std::vector<std::size_t> >& rings,
                        const std::vector<Eigen::ArrayXd>& present, bool closed)
{
  const std::size_t rows = ring.size() - 1;
  const Eigen::Index width = Eigen::Index(rings[0].size());
  Eigen::Matrix3Xd input(3, width * Eigen::Index(rows + 1)), swept_points(3, input.cols());
  std::vector<std::size_t> vertex_of;
  const std::size_t distinct_rings = closed ? rows : rows + 1;
  for(std::size_t i = 0; i < distinct_rings; ++i)
    for(Eigen::Index j = 0; j < width; ++j)
      if(present[i](j) > 0)
      {
        input.col(Eigen::Index(vertex_of.size())) = ring[i].col(j);
        swept_points.col(Eigen::Index(vertex_of.size())) = surface.col(width * Eigen::Index(i) + j);
        vertex_of.push_back(rings[i][std::size_t(j)]);
      }
  const Eigen::Index count = Eigen::Index(vertex_of.size());
  const Eigen::Matrix3Xd aligned =
    apply_motion(Eigen::umeyama(swept_points.leftCols(count), input.leftCols(count), false), swept_points.leftCols(count));
  for(Eigen::Index p = 0; p < count; ++p)
    points.row(Eigen::Index(vertex_of[std::size_t(p)])) = aligned.col(p).transpose();
}

// The rows [first, end) of the groups of runs of `run_of` that share one
// section: maximal sequences of runs of two rows or more. A run of a single
// row has a mold per quad, so the section may change across it: the rings
// on its two sides belong to different groups (a transition row).
inline std::vector<std::pair<std::size_t, std::size_t> > section_groups(const std::vector<std::size_t>& run_of)
{
  const std::size_t rows = run_of.size();
  std::vector<bool> single(rows);
  for(std::size_t r = 0; r < rows; ++r)
    single[r] = (r == 0 || run_of[r - 1] != run_of[r]) && (r + 1 == rows || run_of[r + 1] != run_of[r]);
  std::vector<std::pair<std::size_t, std::size_t> > groups;
  for(std::size_t r = 0; r < rows; ++r)
    if(!single[r])
    {
      if(groups.empty() || groups.back().second != r)
        groups.emplace_back(r, r);
      groups.back().second = r + 1;
    }
  return groups;
}

// The sweep start of an open full grid whose runs `run_of` may include
// transition rows (section_groups()): every group swept from its own
// section and rigidly aligned with its input rings; the rings of a group
// start where the rows between two groups are all transitions stay as
// input. Arguments as place_sweep() takes them.
inline Point_matrix grouped_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
                                        const std::vector<std::vector<std::size_t> >& rings,
                                        const std::vector<Eigen::ArrayXd>& present,
                                        const std::vector<std::size_t>& run_of)
{
  Point_matrix start = points;
  for(const std::pair<std::size_t, std::size_t>& group : section_groups(run_of))
  {
    const std::size_t a = group.first, b = group.second;
    std::vector<std::size_t> group_run_of(run_of.begin() + a, run_of.begin() + b);
    for(std::size_t& run : group_run_of)
      run -= run_of[a];
    const Swept_section swept = group_swept_section(ring, present, group_run_of, a, b);
    if(!swept.valid)
      return Point_matrix();
    place_sweep(start, swept.swept(), std::vector<Eigen::Matrix3Xd>(ring.begin() + a, ring.begin() + b + 1),
                std::vector<std::vector<std::size_t> >(rings.begin() + a, rings.begin() + b + 1),
                std::vector<Eigen::ArrayXd>(present.begin() + a, present.begin() + b + 1), false);
  }
  return start;
}

// Whether the clusters of `label` on a full grid with the runs `run_of` lie
// as coaxial_transition_sweep() makes them: every cluster in one run, and in
// one column or a whole row, at least one a whole row.
inline bool coaxial_transition_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
                                      const std::vector<std::size_t>& run_of)
{
  const std::size_t columns = grid.columns;
  const std::size_t k = *std::max_element(label.begin(), label.end()) + 1;
  std::vector<std::size_t> row_of(k, no_index()), column_of(k, no_index()), count(k, 0);
  std::vector<bool> one_row(k, true), one_column(k, true);
  for(std::size_t r = 0; r < grid.rows; ++r)
    for(std::size_t c = 0; c < columns; ++c)
    {
      const std::size_t l = grid_cell_label(grid, label, r, c);
      if(l == no_index())
        return false;
      if(row_of[l] == no_index())
      {
        row_of[l] = r;
        column_of[l] = c;
      }
      if(run_of[row_of[l]] != run_of[r])
        return false;
      one_row[l] = one_row[l] && row_of[l] == r;
      one_column[l] = one_column[l] && column_of[l] == c;
      ++count[l];
    }
  bool has_row = false;
  for(std::size_t l = 0; l < k; ++l)
  {
    const bool whole_row = one_row[l] && count[l] == columns;
    if(!one_column[l] && !whole_row)
      return false;
    has_row = has_row || whole_row;
  }
  return has_row;
}

// The rigid motion that puts the regular polygon `next` on the axis of
// `previous`, `gap` farther along its normal, in a parallel plane and with
// the same phase (the coaxial transition row, sweep_candidates.h).
inline Eigen::Matrix4d coaxial_motion(const Regular_polygon& previous, const Regular_polygon& next, double gap)
{
  auto basis = [](const Regular_polygon& p) {
    Eigen::Matrix3d b;
    b << p.first, p.normal.cross(p.first), p.normal;
    return b;
  };
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = basis(previous) * basis(next).transpose();
  m.topRightCorner<3, 1>() = previous.center + gap * previous.normal - m.topLeftCorner<3, 3>() * next.center;
  return m;
}

// The screw motion with the axis direction and the step along it of `m`
// that turns `f` times as far per row, about an axis moved so that `center`
// keeps its distance per row and its path's tangent: that path bent `f`
// times as much. `m` when it hardly turns.
inline Eigen::Matrix4d bent_motion(const Eigen::Matrix4d& m, const Eigen::Vector3d& center, double f)
{
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(m.topLeftCorner<3, 3>()));
  if(turn.angle() < tuning::screw_angle_min)
    return m;
  const Eigen::Vector3d a = turn.axis(), t = m.topRightCorner<3, 1>();
  // A point of the axis: the least-squares solution of (I - R) o = t - (t.a) a.
  const Eigen::Matrix3d i_minus_r = Eigen::Matrix3d::Identity() - m.topLeftCorner<3, 3>();
  const Eigen::Vector3d o = i_minus_r.jacobiSvd(Eigen::ComputeFullU | Eigen::ComputeFullV).solve(t - t.dot(a) * a);
  const Eigen::Vector3d v = (center - o) - (center - o).dot(a) * a;
  const Eigen::Vector3d moved = o + (1 - 1 / f) * v;
  Eigen::Matrix4d bent = Eigen::Matrix4d::Identity();
  bent.topLeftCorner<3, 3>() = Eigen::AngleAxisd(turn.angle() * f, a).toRotationMatrix();
  bent.topRightCorner<3, 1>() = moved - bent.topLeftCorner<3, 3>() * moved + t.dot(a) * a;
  return bent;
}

// The one-run sweep `swept` of `rows` rows with its motion bent `f` times
// as much about its middle ring's centre (bent_motion()), its frames
// composed again from the middle ring.
inline void bend_sweep(Swept_section& swept, std::size_t rows, double f)
{
  swept.motion[0] = bent_motion(swept.motion[0], swept.section.rowwise().mean(), f);
  const std::size_t middle = rows / 2;
  for(std::size_t i = middle; i < rows; ++i)
    swept.frame[i + 1] = swept.motion[0] * swept.frame[i];
  for(std::size_t i = middle; i > 0; --i)
    swept.frame[i - 1] = swept.motion[0].inverse() * swept.frame[i];
}

// The sweep start of a full grid closed around its round rings whose runs
// `run_of` are groups separated by coaxial transition rows
// (coaxial_transition_layout()): every group swept from its own section made
// a regular polygon (fit_regular_polygon()), the first group rigidly aligned
// with its input rings, every next one put coaxially after the one before,
// as far along the axis as their input rings' centres are apart; the whole
// then rigidly aligned with the input. Empty when a ring lies in no group or
// two transition rows meet. Arguments as place_sweep() takes them.
inline Point_matrix coaxial_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
                                        const std::vector<std::vector<std::size_t> >& rings,
                                        const std::vector<Eigen::ArrayXd>& present,
                                        const std::vector<std::size_t>& run_of)
{
  const std::size_t rows = run_of.size();
  const Eigen::Index width = ring[0].cols();
  Eigen::Matrix3Xd surface(3, width * Eigen::Index(rows + 1));
  std::size_t next_ring = 0;
  for(const std::pair<std::size_t, std::size_t>& group : section_groups(run_of))
  {
    const std::size_t a = group.first, b = group.second;
    if(a != next_ring)
      return Point_matrix();
    std::vector<std::size_t> group_run_of(run_of.begin() + a, run_of.begin() + b);
    for(std::size_t& run : group_run_of)
      run -= run_of[a];
    Swept_section swept = group_swept_section(ring, present, group_run_of, a, b);
    if(!swept.valid)
      return Point_matrix();
    swept.section = fit_regular_polygon(swept.section).points(width);
    // The straight transition rows turn by nothing: the groups on both sides
    // bend by half of a row's turn more each.
    const double transitions = double(int(a > 0) + int(b < rows));
    if(group_run_of.back() == 0)
      bend_sweep(swept, b - a, (double(b - a) + transitions / 2) / double(b - a));
    Eigen::Matrix3Xd group_surface = swept.swept();
    Eigen::Matrix4d motion;
    if(a == 0)
    {
      Eigen::Matrix3Xd input(3, group_surface.cols());
      for(std::size_t i = a; i <= b; ++i)
        input.middleCols(width * Eigen::Index(i - a), width) = ring[i];
      motion = Eigen::umeyama(group_surface, input, false);
    }
    else
    {
      const double gap = (ring[a].rowwise().mean() - ring[a - 1].rowwise().mean()).norm();
      motion = coaxial_motion(fit_regular_polygon(surface.middleCols(width * Eigen::Index(a - 1), width)),
                              fit_regular_polygon(group_surface.leftCols(width)), gap);
    }
    surface.middleCols(width * Eigen::Index(a), group_surface.cols()) = apply_motion(motion, group_surface);
    next_ring = b + 1;
  }
  if(next_ring != rows + 1)
    return Point_matrix();
  Point_matrix start = points;
  place_sweep(start, surface, ring, rings, present, false);
  return start;
}

// The start of quad_grid_sweep_start() on the grid `grid` of `pm` (its
// lattice points `points_of_grid` when trimmed); empty when the clusters do
// not lie as a sweep of it.
template <typename PolygonMesh, typename VertexIndexMap>
Point_matrix grid_sweep_start(const PolygonMesh& pm, VertexIndexMap vim,
                              const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                              const Quad_grid& grid, const Trimmed_grid_points& points_of_grid,
                              const Point_matrix& points, const std::vector<std::size_t>& label, bool closed)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t rows = grid.rows, columns = grid.columns;
  const bool one_run = closed || !points_of_grid.cell.empty();
  const std::vector<std::size_t> run_of = grid_row_runs(grid, label, one_run);
  std::vector<std::size_t> run_of_column;
  const Sweep_layout layout = sweep_layout(grid, label, run_of, run_of_column);
  if(layout == Sweep_layout::NONE && one_run)
    return Point_matrix();
  const bool column_runs = layout == Sweep_layout::COLUMN_RUNS;
  auto vertex = [&](std::size_t r, std::size_t c, int i) {
    const std::size_t f = grid.face_at[r * columns + c];
    halfedge_descriptor h = halfedge(face_of[f], pm);
    for(int j = 0; j < grid.corner_offset[f] + i; ++j)
      h = next(h, pm);
    return std::size_t(get(vim, target(h, pm)));
  };
  std::vector<Eigen::ArrayXd> present;
  const std::vector<std::vector<std::size_t> > rings = present_grid_rings(grid, points_of_grid, vertex, present);
  if(rings.empty())
    return Point_matrix();
  const Eigen::Index width = Eigen::Index(rings[0].size());
  const bool coaxial = layout == Sweep_layout::NONE && !one_run && std::size_t(width) == columns &&
                       coaxial_transition_layout(grid, label, run_of);
  if(layout == Sweep_layout::NONE && !coaxial)
    return Point_matrix();
  std::vector<Eigen::Matrix3Xd> ring(rows + 1, Eigen::Matrix3Xd::Zero(3, width));
  for(std::size_t i = 0; i <= rows; ++i)
    for(Eigen::Index j = 0; j < width; ++j)
      if(present[i](j) > 0)
        ring[i].col(j) = points.row(Eigen::Index(rings[i][std::size_t(j)])).transpose();
  if(coaxial)
    return coaxial_sweep_start(points, ring, rings, present, run_of);
  if(!one_run && !column_runs)
    return grouped_sweep_start(points, ring, rings, present, run_of);
  Swept_section swept = swept_section(ring, run_of, column_runs, present, closed);
  if(!swept.valid || (column_runs && !fit_screw_column_runs(swept.section, swept.motion[0], run_of_column)))
    return Point_matrix();
  Point_matrix start = points;
  place_sweep(start, swept.swept(), ring, rings, present, closed);
  return start;
}

// Positions, by vertex index, at which the clustering `label` (by face
// index) is exact, as described above; an empty matrix when the quads do
// not form a grid, full or trimmed (trimmed_grid.h: only the points
// present are fitted and placed), whose every cluster lies in one column
// and one run of rows, or in one run of columns of a single run of rows
// (the only run of a trimmed grid or one closed across its rows: its
// clusters may then be pieces of columns). `points` are the
// input positions by vertex index. `orientation`, if given, receives the
// orientation of every face (by face index) at which the clusters' quads
// correspond corner by corner there, in grid order: exact, where a best
// match on the swept shapes would pick among the symmetries of a
// symmetric quad by round-off. With `closed_only`, only a grid closed
// across its rows.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Point_matrix quad_grid_sweep_start(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                                   const Point_matrix& points, const std::vector<std::size_t>& label,
                                   std::vector<Panel_orientation>* orientation, bool closed_only)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> face_of(num_faces(pm));
  for(face_descriptor f : faces(pm))
    face_of[get(fim, f)] = f;
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  for(int row_direction = 0; row_direction < 2; ++row_direction)
  {
    Trimmed_grid_points points_of_grid;
    const Quad_grid grid = full_or_trimmed_grid(pm, fim, vpm, strips, row_direction, points_of_grid);
    if(grid.rows == 0)
      continue;
    const bool closed = closed_across_rows(grid, points_of_grid);
    if(closed_only && !closed)
      continue;
    Point_matrix start = grid_sweep_start(pm, vim, face_of, grid, points_of_grid, points, label, closed);
    if(start.rows() == 0)
      continue;
    // Corner i in grid order is the face's vertex corner_offset + i.
    if(orientation != nullptr)
      for(std::size_t f = 0; f < grid.corner_offset.size(); ++f)
        (*orientation)[f] = Panel_orientation(grid.corner_offset[f] % 4);
    return start;
  }
  return Point_matrix();
}

// The positions at which the sweep clustering `label` (by face index) of a
// quad grid, or of one capped by pole fans, is exact: quad_grid_sweep_start()
// of the grid, or of the capped grid's quads, which must then be closed
// across its rows, with the poles put on the axes (pole_fans.h). Empty
// when there is none; `orientation` as quad_grid_sweep_start() says, each
// triangle's from its pole.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Point_matrix sweep_start(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                         const Point_matrix& points, const std::vector<std::size_t>& label,
                         std::vector<Panel_orientation>* orientation = nullptr)
{
  Pole_fans fans;
  const Triangle_layout layout = pole_fans(pm, fim, vim, vpm, fans);
  if(layout == Triangle_layout::NONE)
    return quad_grid_sweep_start(pm, fim, vim, vpm, points, label, orientation, false);
  const std::vector<std::size_t> quad_label =
    layout == Triangle_layout::POLE_FANS ? quad_part_label(fans, label) : std::vector<std::size_t>();
  if(quad_label.empty())
    return Point_matrix();
  const Pole_fans::Quad_part& quads = fans.quads;
  Point_matrix quad_points(Eigen::Index(fans.vertex_of.size()), 3);
  for(std::size_t v = 0; v < fans.vertex_of.size(); ++v)
    quad_points.row(Eigen::Index(v)) = points.row(Eigen::Index(fans.vertex_of[v]));
  std::vector<Panel_orientation> quad_orientation(quad_label.size());
  const Point_matrix quad_start =
    quad_grid_sweep_start(quads, get(CGAL::face_index, quads), get(CGAL::vertex_index, quads),
                          get(CGAL::vertex_point, quads), quad_points, quad_label, &quad_orientation, true);
  if(quad_start.rows() == 0)
    return quad_start;
  Point_matrix start = points;
  for(std::size_t v = 0; v < fans.vertex_of.size(); ++v)
    start.row(Eigen::Index(fans.vertex_of[v])) = quad_start.row(Eigen::Index(v));
  if(!put_poles_on_axes(fans, start, points, Tilable_surfaces::mean_edge_length(quads)))
    return Point_matrix();
  if(orientation != nullptr)
  {
    // A quad's corner 0 in grid order, found in its face in the mesh.
    for(std::size_t f = 0; f < quad_label.size(); ++f)
    {
      auto h = halfedge(Pole_fans::Quad_part::Face_index(std::uint32_t(f)), quads);
      for(int i = 0; i < quad_orientation[f].index(); ++i)
        h = next(h, quads);
      const std::array<std::size_t, 4>& corners = fans.quad_corners[f];
      const std::size_t first = fans.vertex_of[std::size_t(target(h, quads))];
      (*orientation)[fans.face_of[f]] =
        Panel_orientation(int(std::find(corners.begin(), corners.end(), first) - corners.begin()));
    }
    for(std::size_t fan = 0; fan < fans.triangles.size(); ++fan)
      for(std::size_t t = 0; t < fans.triangles[fan].size(); ++t)
        (*orientation)[fans.triangles[fan][t]] = Panel_orientation(fans.pole_corner[fan][t]);
  }
  return start;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
