// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_IMPL_H

// The bodies of the non-template functions declared in sweep_start.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> grid_row_runs(const Quad_grid& grid, const std::vector<std::size_t>& label,
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

CGAL_TILABLE_SURFACES_INLINE
Sweep_layout sweep_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
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

CGAL_TILABLE_SURFACES_INLINE
void place_sweep(Point_matrix& points, const Eigen::Matrix3Xd& surface,
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::pair<std::size_t, std::size_t> > section_groups(const std::vector<std::size_t>& run_of)
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

CGAL_TILABLE_SURFACES_INLINE
Point_matrix grouped_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
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

CGAL_TILABLE_SURFACES_INLINE
bool coaxial_transition_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
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

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix4d coaxial_motion(const Regular_polygon& previous, const Regular_polygon& next, double gap)
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

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix4d bent_motion(const Eigen::Matrix4d& m, const Eigen::Vector3d& center, double f)
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

CGAL_TILABLE_SURFACES_INLINE
void bend_sweep(Swept_section& swept, std::size_t rows, double f)
{
  swept.motion[0] = bent_motion(swept.motion[0], swept.section.rowwise().mean(), f);
  const std::size_t middle = rows / 2;
  for(std::size_t i = middle; i < rows; ++i)
    swept.frame[i + 1] = swept.motion[0] * swept.frame[i];
  for(std::size_t i = middle; i > 0; --i)
    swept.frame[i - 1] = swept.motion[0].inverse() * swept.frame[i];
}

CGAL_TILABLE_SURFACES_INLINE
Point_matrix coaxial_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_IMPL_H
