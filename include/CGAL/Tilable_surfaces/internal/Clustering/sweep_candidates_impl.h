// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_IMPL_H

// The bodies of the non-template functions declared in sweep_candidates.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
bool closed_across_rows(const Quad_grid& grid, const Trimmed_grid_points& points)
{
  if(!points.cell.empty())
    return false;
  const Panel& first = grid.corners[grid.face_at[0]];
  const Panel& last = grid.corners[grid.face_at[(grid.rows - 1) * grid.columns]];
  int shared = 0;
  for(const Eigen::Vector3d& p : first)
    shared += int(std::count(last.begin(), last.end(), p) > 0);
  return shared > (grid.rows == 2 ? 2 : 0);
}

CGAL_TILABLE_SURFACES_INLINE
bool close_up(Eigen::Matrix4d& m, std::size_t rows)
{
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(m.topLeftCorner<3, 3>()));
  const double turns = std::round(turn.angle() * double(rows) / (2 * CGAL_PI));
  if(turns < 1)
    return false;
  // A point of the axis: the least-squares solution of (I - R) o = t - (t.a) a.
  const Eigen::Vector3d axis = turn.axis(), t = m.topRightCorner<3, 1>();
  const Eigen::Matrix3d i_minus_r = Eigen::Matrix3d::Identity() - m.topLeftCorner<3, 3>();
  const Eigen::Vector3d o =
    i_minus_r.jacobiSvd(Eigen::ComputeFullU | Eigen::ComputeFullV).solve(t - t.dot(axis) * axis);
  const Eigen::Matrix3d r = Eigen::AngleAxisd(2 * CGAL_PI * turns / double(rows), axis).toRotationMatrix();
  m.setIdentity();
  m.topLeftCorner<3, 3>() = r;
  m.topRightCorner<3, 1>() = o - r * o;
  return true;
}

CGAL_TILABLE_SURFACES_INLINE
Swept_section swept_section(const std::vector<Eigen::Matrix3Xd>& ring, const std::vector<std::size_t>& run_of,
                            bool column_runs, const std::vector<Eigen::ArrayXd>& present, bool closed)
{
  Swept_section s;
  const std::size_t rows = run_of.size(), runs = run_of.back() + 1;
  const Eigen::Index width = ring[0].cols();
  auto is_present = [&](std::size_t i, Eigen::Index j) { return present[i](j) > 0; };
  s.motion.resize(runs);
  for(std::size_t r = 0, a = 0; r < runs; ++r)
  {
    std::size_t b = a;
    while(b < rows && run_of[b] == r)
      ++b;
    Eigen::Matrix3Xd from(3, width * Eigen::Index(b - a)), to(3, width * Eigen::Index(b - a));
    Eigen::Index pairs = 0;
    for(std::size_t i = a; i < b; ++i)
      for(Eigen::Index j = 0; j < width; ++j)
        if(is_present(i, j) && is_present(i + 1, j))
        {
          from.col(pairs) = ring[i].col(j);
          to.col(pairs++) = ring[i + 1].col(j);
        }
    if(pairs < 3)
    {
      s.valid = false;
      return s;
    }
    s.motion[r] = Eigen::umeyama(from.leftCols(pairs), to.leftCols(pairs), false);
    a = b;
  }
  if(closed && (runs > 1 || !close_up(s.motion[0], rows)))
  {
    s.valid = false;
    return s;
  }
  if(column_runs && Eigen::AngleAxisd(Eigen::Matrix3d(s.motion[0].topLeftCorner<3, 3>())).angle() < tuning::screw_angle_min)
    s.motion[0].topLeftCorner<3, 3>().setIdentity();
  const std::size_t middle = rows / 2;
  s.frame.assign(rows + 1, Eigen::Matrix4d::Identity());
  for(std::size_t i = middle; i < rows; ++i)
    s.frame[i + 1] = s.motion[run_of[i]] * s.frame[i];
  for(std::size_t i = middle; i > 0; --i)
    s.frame[i - 1] = s.motion[run_of[i - 1]].inverse() * s.frame[i];
  s.section = Eigen::Matrix3Xd::Zero(3, width);
  Eigen::ArrayXd count = Eigen::ArrayXd::Zero(width);
  // A closed grid's last ring is its first.
  const std::size_t distinct_rings = closed ? rows : rows + 1;
  for(std::size_t i = 0; i < distinct_rings; ++i)
  {
    const Eigen::Matrix3Xd pulled = apply_motion(s.frame[i].inverse(), ring[i]);
    for(Eigen::Index j = 0; j < width; ++j)
      if(is_present(i, j))
      {
        s.section.col(j) += pulled.col(j);
        count(j) += 1;
      }
  }
  s.valid = (count > 0).all();
  for(Eigen::Index j = 0; j < width && s.valid; ++j)
    s.section.col(j) /= count(j);
  return s;
}

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3Xd screw_run(const Eigen::Matrix3Xd& section, const Screw_coordinates& coordinates,
                           std::size_t first, std::size_t length)
{
  const Eigen::Index n = Eigen::Index(length) + 1, width = section.cols();
  Eigen::Matrix3Xd q(3, n);
  for(Eigen::Index j = 0; j < n; ++j)
  {
    q.col(j) = coordinates.to(section.col((Eigen::Index(first) + j) % width));
    // Unwrapped angles.
    if(j > 0 && !coordinates.is_translation())
      q(1, j) -= 2 * CGAL_PI * std::round((q(1, j) - q(1, j - 1)) / (2 * CGAL_PI));
  }
  const Eigen::ArrayXd t = Eigen::ArrayXd::LinSpaced(n, 0, double(n - 1)) - double(n - 1) / 2;
  for(int d = 0; d < 3; ++d)
  {
    const double mean = q.row(d).mean();
    if(d == 0 && !coordinates.is_translation())
      q.row(d).setConstant(mean);
    else
      q.row(d) = (mean + t * ((q.row(d).array() - mean) * t.transpose()).sum() / (t * t).sum()).matrix().transpose();
  }
  Eigen::Matrix3Xd p(3, n);
  for(Eigen::Index j = 0; j < n; ++j)
    p.col(j) = coordinates.from(q.col(j));
  return p;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_runs_from(const std::vector<double>& cost, std::size_t longest,
                                                std::size_t columns, std::size_t groups, bool closed,
                                                std::size_t cut, double& total)
{
  const double infinity = (std::numeric_limits<double>::max)();
  // best[(p * (groups + 1) + g) * 2 + m]: the first p columns from the cut in
  // g runs, the last of several columns when m.
  auto state = [groups](std::size_t p, std::size_t g, int m) { return (p * (groups + 1) + g) * 2 + std::size_t(m); };
  std::vector<double> best((columns + 1) * (groups + 1) * 2, infinity);
  std::vector<std::size_t> from(best.size(), 0);
  best[closed ? state(1, 1, 0) : state(0, 0, 0)] = 0;
  for(std::size_t p = closed ? 1 : 0; p < columns; ++p)
    for(std::size_t g = 0; g < groups; ++g)
      for(int m = 0; m < 2; ++m)
      {
        const double here = best[state(p, g, m)];
        if(here == infinity)
          continue;
        for(std::size_t l = 1; l <= longest && p + l <= columns; ++l)
        {
          if(l > 1 && m == 1)
            break;
          const double run = l == 1 ? 0. : cost[((cut + p) % columns) * (longest + 1) + l];
          const std::size_t next = state(p + l, g + 1, l > 1 ? 1 : 0);
          if(here + run < best[next])
          {
            best[next] = here + run;
            from[next] = state(p, g, m);
          }
        }
      }
  std::size_t s = best[state(columns, groups, 1)] < best[state(columns, groups, 0)] ? state(columns, groups, 1)
                                                                                      : state(columns, groups, 0);
  total = best[s];
  if(total == infinity)
    return {};
  std::vector<std::size_t> run_of_column(columns, 0);
  for(std::size_t g = groups; s != state(0, 0, 0) && s != state(1, 1, 0); --g)
  {
    const std::size_t end = s / 2 / (groups + 1), start = from[s] / 2 / (groups + 1);
    for(std::size_t p = start; p < end; ++p)
      run_of_column[(cut + p) % columns] = g - 1;
    s = from[s];
  }
  return run_of_column;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_runs(const Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
                                           std::size_t columns, std::size_t groups)
{
  const bool closed = std::size_t(section.cols()) == columns;
  if(groups == 0 || groups > columns || columns < 3)
    return {};
  const Screw_coordinates coordinates(motion);
  // Runs of at most half the ring, and O(columns^3 / 8) work at most ~1e8.
  const std::size_t longest =
    (std::max)(std::size_t(2), (std::min)(columns / 2, std::size_t(std::sqrt(tuning::screw_column_runs_work / double(columns)))));
  const double infinity = (std::numeric_limits<double>::max)();
  // cost[c * (longest + 1) + l]: the run of l columns from column c; none
  // when its steps shrink to less than half their mean length (a section
  // running straight away from the axis would collapse onto one point).
  std::vector<double> cost(columns * (longest + 1), infinity);
  for(std::size_t c = 0; c < columns; ++c)
    for(std::size_t l = 2; l <= longest && (closed || c + l <= columns); ++l)
    {
      const Eigen::Matrix3Xd fit = screw_run(section, coordinates, c, l);
      double sum = 0, length = 0;
      for(Eigen::Index j = 0; j < fit.cols(); ++j)
      {
        const Eigen::Index v = (Eigen::Index(c) + j) % section.cols();
        sum += (fit.col(j) - section.col(v)).squaredNorm();
        if(j > 0)
          length += (section.col(v) - section.col((v + section.cols() - 1) % section.cols())).norm();
      }
      if((fit.col(1) - fit.col(0)).norm() >= tuning::screw_run_min_step * length / double(l))
        cost[c * (longest + 1) + l] = sum;
    }
  std::vector<std::size_t> cuts(1, 0);
  if(closed)
  {
    // The bend at vertex c: a run of the two columns around it.
    auto bend = [&](std::size_t c) { return cost[((c + columns - 1) % columns) * (longest + 1) + 2]; };
    cuts.resize(columns);
    std::iota(cuts.begin(), cuts.end(), std::size_t(0));
    std::stable_sort(cuts.begin(), cuts.end(), [&](std::size_t a, std::size_t b) {
      return bend(a) + bend((a + 1) % columns) > bend(b) + bend((b + 1) % columns);
    });
    cuts.resize((std::min)(cuts.size(), std::size_t(3)));
  }
  double least = infinity;
  std::vector<std::size_t> result;
  for(std::size_t cut : cuts)
  {
    double total = infinity;
    std::vector<std::size_t> runs = screw_column_runs_from(cost, longest, columns, groups, closed, cut, total);
    if(total < least)
    {
      least = total;
      result.swap(runs);
    }
  }
  return result;
}

CGAL_TILABLE_SURFACES_INLINE
bool fit_screw_column_runs(Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
                           const std::vector<std::size_t>& run_of_column)
{
  const std::size_t columns = run_of_column.size();
  const bool closed = std::size_t(section.cols()) == columns;
  // Start at a column that begins a run.
  std::size_t start = 0;
  if(closed)
  {
    while(start < columns && run_of_column[start] == run_of_column[(start + columns - 1) % columns])
      ++start;
    if(start == columns)
      return false;
  }
  std::vector<std::pair<std::size_t, std::size_t> > runs;  // first column, length
  std::vector<bool> seen(*std::max_element(run_of_column.begin(), run_of_column.end()) + 1, false);
  for(std::size_t p = 0; p < columns;)
  {
    const std::size_t c = (start + p) % columns, r = run_of_column[c];
    if(seen[r])
      return false;
    seen[r] = true;
    std::size_t l = 1;
    while(p + l < columns && run_of_column[(c + l) % columns] == r)
      ++l;
    runs.emplace_back(c, l);
    p += l;
  }
  const Screw_coordinates coordinates(motion);
  Eigen::Matrix3Xd fitted = section;
  for(const std::pair<std::size_t, std::size_t>& run : runs)
    if(run.second > 1)
    {
      const Eigen::Matrix3Xd p = screw_run(section, coordinates, run.first, run.second);
      for(Eigen::Index j = 0; j < p.cols(); ++j)
        fitted.col((Eigen::Index(run.first) + j) % section.cols()) = p.col(j);
    }
  section = fitted;
  return true;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<Eigen::Matrix3Xd> grid_ring_points(const Quad_grid& grid, const Trimmed_grid_points& points,
                                               std::vector<Eigen::ArrayXd>& present)
{
  auto corner = [&](std::size_t r, std::size_t c, int i) {
    return Eigen::Vector3d(grid.corners[grid.face_at[r * grid.columns + c]][i]);
  };
  const std::vector<std::vector<Eigen::Vector3d> > rings = present_grid_rings(grid, points, corner, present);
  std::vector<Eigen::Matrix3Xd> ring;
  for(const std::vector<Eigen::Vector3d>& points_of_ring : rings)
  {
    ring.emplace_back(3, Eigen::Index(points_of_ring.size()));
    for(std::size_t j = 0; j < points_of_ring.size(); ++j)
      ring.back().col(Eigen::Index(j)) = points_of_ring[j];
  }
  return ring;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_sweep(const Quad_grid& grid, const Trimmed_grid_points& points,
                                            std::size_t k)
{
  const std::size_t rows = grid.rows, columns = grid.columns;
  std::vector<Eigen::ArrayXd> present;
  const std::vector<Eigen::Matrix3Xd> ring = grid_ring_points(grid, points, present);
  if(ring.empty())
    return {};
  const Swept_section swept =
    swept_section(ring, std::vector<std::size_t>(rows, 0), true, present, closed_across_rows(grid, points));
  if(!swept.valid)
    return {};
  const std::vector<std::size_t> run_of_column = screw_column_runs(swept.section, swept.motion[0], columns, k);
  if(run_of_column.empty())
    return {};
  std::vector<std::size_t> label(grid.corners.size());
  for(std::size_t r = 0; r < rows; ++r)
    for(std::size_t c = 0; c < columns; ++c)
      if(grid.face_at[r * columns + c] != no_index())
        label[grid.face_at[r * columns + c]] = run_of_column[c];
  relabel_by_first_face(label);
  return label;
}

CGAL_TILABLE_SURFACES_INLINE
bool split_columns_to(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t k)
{
  const std::size_t columns = grid.columns;
  std::vector<std::vector<std::size_t> > quads(columns);  // per column, in row order
  for(std::size_t r = 0; r < grid.rows; ++r)
    for(std::size_t c = 0; c < columns; ++c)
      if(grid.face_at[r * columns + c] != no_index())
        quads[c].push_back(grid.face_at[r * columns + c]);
  std::vector<std::size_t> pieces(columns, 1);
  for(std::size_t total = columns; total < k; ++total)
  {
    std::size_t best = no_index();
    for(std::size_t c = 0; c < columns; ++c)
      if(pieces[c] < quads[c].size() &&
         (best == no_index() || quads[c].size() * pieces[best] > quads[best].size() * pieces[c]))
        best = c;
    if(best == no_index())
      return false;
    ++pieces[best];
  }
  std::size_t first = 0;
  for(std::size_t c = 0; c < columns; first += pieces[c++])
    for(std::size_t i = 0; i < quads[c].size(); ++i)
      label[quads[c][i]] = first + i * pieces[c] / quads[c].size();
  relabel_by_first_face(label);
  return true;
}

CGAL_TILABLE_SURFACES_INLINE
Swept_section group_swept_section(const std::vector<Eigen::Matrix3Xd>& ring,
                                  const std::vector<Eigen::ArrayXd>& present,
                                  const std::vector<std::size_t>& run_of, std::size_t a, std::size_t b)
{
  const std::vector<Eigen::Matrix3Xd> group_ring(ring.begin() + a, ring.begin() + b + 1);
  const std::vector<Eigen::ArrayXd> group_present(present.begin() + a, present.begin() + b + 1);
  return swept_section(group_ring, run_of.empty() ? std::vector<std::size_t>(b - a, 0) : run_of, false, group_present);
}

CGAL_TILABLE_SURFACES_INLINE
double sweep_group_deviation(const std::vector<Eigen::Matrix3Xd>& ring,
                             const std::vector<Eigen::ArrayXd>& present, std::size_t a, std::size_t b)
{
  const Swept_section swept = group_swept_section(ring, present, {}, a, b);
  if(!swept.valid)
    return std::numeric_limits<double>::infinity();
  double deviation = 0;
  for(std::size_t i = a; i <= b; ++i)
    deviation = (std::max)(deviation, (apply_motion(swept.frame[i - a], swept.section) - ring[i]).colwise().norm().maxCoeff());
  return deviation;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<Sweep_group>
transition_groups(const std::vector<Eigen::Matrix3Xd>& ring, const std::vector<Eigen::ArrayXd>& present,
           std::size_t groups)
{
  const std::size_t rows = ring.size() - 1;
  const std::size_t step = (std::max)(std::size_t(1), rows / tuning::transition_row_choices);
  // Node 0 is the first row, node m + 1 past the last; node i in 1..m the transition row i * step.
  const std::size_t m = (rows - 1) / step;
  auto first_row = [&](std::size_t i) { return i == 0 ? std::size_t(0) : i * step + 1; };
  auto end_row = [&](std::size_t j) { return j == m + 1 ? rows : j * step; };
  const double infinity = std::numeric_limits<double>::infinity();
  std::vector<std::vector<double> > cost(m + 2, std::vector<double>(m + 2, infinity));
  for(std::size_t i = 0; i <= m; ++i)
    for(std::size_t j = i + 1; j <= m + 1; ++j)
      if(end_row(j) >= first_row(i) + 2)
        cost[i][j] = sweep_group_deviation(ring, present, first_row(i), end_row(j));
  // best[g][j]: the least largest deviation of g groups ending at node j; from[g][j] its last group's start.
  std::vector<std::vector<double> > best(groups + 1, std::vector<double>(m + 2, infinity));
  std::vector<std::vector<std::size_t> > from(groups + 1, std::vector<std::size_t>(m + 2, 0));
  best[0][0] = 0;
  for(std::size_t g = 1; g <= groups; ++g)
    for(std::size_t j = 1; j <= m + 1; ++j)
      for(std::size_t i = 0; i < j; ++i)
        if((std::max)(best[g - 1][i], cost[i][j]) < best[g][j])
        {
          best[g][j] = (std::max)(best[g - 1][i], cost[i][j]);
          from[g][j] = i;
        }
  std::vector<Sweep_group> result;
  if(best[groups][m + 1] == infinity)
    return result;
  for(std::size_t g = groups, j = m + 1; g > 0; j = from[g--][j])
    result.push_back(Sweep_group{first_row(from[g][j]), end_row(j), cost[from[g][j]][j]});
  std::reverse(result.begin(), result.end());
  return result;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> sweep_run_first_rows(const Quad_grid& grid, const std::vector<std::size_t>& label)
{
  std::vector<std::size_t> first_row(1, 0);
  for(std::size_t r = 1; r < grid.rows; ++r)
    if(label[grid.face_at[r * grid.columns]] != label[grid.face_at[(r - 1) * grid.columns]])
      first_row.push_back(r);
  first_row.push_back(grid.rows);
  return first_row;
}

CGAL_TILABLE_SURFACES_INLINE
bool add_leftover_molds(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t used,
                        std::size_t left)
{
  const std::vector<std::size_t> first_row = sweep_run_first_rows(grid, label);
  std::size_t longest = 0;
  for(std::size_t s = 1; s + 1 < first_row.size(); ++s)
    if(first_row[s + 1] - first_row[s] > first_row[longest + 1] - first_row[longest])
      longest = s;
  const std::size_t length = first_row[longest + 1] - first_row[longest];
  if(left > 0 && length < 2)
    return false;
  for(std::size_t t = 0; t < left; ++t)
  {
    const std::size_t c = t * grid.columns / left;
    for(std::size_t r = first_row[longest] + length / 2; r < first_row[longest + 1]; ++r)
      label[grid.face_at[r * grid.columns + c]] = used + t;
  }
  relabel_by_first_face(label);
  return true;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> transition_sweep(const Quad_grid& grid, std::size_t slots)
{
  std::vector<Eigen::ArrayXd> present;
  const std::vector<Eigen::Matrix3Xd> ring = grid_ring_points(grid, Trimmed_grid_points(), present);
  const std::size_t groups = (slots + 1) / 2;
  if(ring.empty() || groups < 2)
    return {};
  const std::vector<Sweep_group> group = transition_groups(ring, present, groups);
  if(group.empty())
    return {};
  // The run of every row; a transition row is a run of its own.
  std::vector<std::size_t> run_of(grid.rows, no_index());
  std::size_t farthest = 0;
  double deviation = -1;
  for(std::size_t g = 0; g < group.size(); ++g)
    if(group[g].deviation > deviation && group[g].end - group[g].first >= 4)
    {
      deviation = group[g].deviation;
      farthest = g;
    }
  const bool split_one = 2 * groups == slots;
  if(split_one && deviation < 0)
    return {};
  std::size_t runs = 0;
  for(std::size_t r = 0, g = 0; r < grid.rows; ++r)
  {
    const bool in_group = g < group.size() && r >= group[g].first;
    const bool split = split_one && g == farthest && r == (group[g].first + group[g].end) / 2;
    if(r > 0 && (!in_group || r == group[g].first || split))
      ++runs;
    run_of[r] = runs;
    if(in_group && r + 1 == group[g].end)
      ++g;
  }
  std::vector<std::size_t> label(grid.corners.size());
  for(std::size_t r = 0; r < grid.rows; ++r)
    for(std::size_t c = 0; c < grid.columns; ++c)
      label[grid.face_at[r * grid.columns + c]] = run_of[r] * grid.columns + c;
  relabel_by_first_face(label);
  return label;
}

CGAL_TILABLE_SURFACES_INLINE
Regular_polygon fit_regular_polygon(const Eigen::Matrix3Xd& ring)
{
  const Eigen::Index width = ring.cols();
  Regular_polygon polygon;
  polygon.center = ring.rowwise().mean();
  const Eigen::Matrix3Xd v = ring.colwise() - polygon.center;
  Eigen::Vector3d area = Eigen::Vector3d::Zero();
  for(Eigen::Index j = 0; j < width; ++j)
    area += v.col(j).cross(v.col((j + 1) % width));
  polygon.normal = area.normalized();
  const Eigen::Vector3d e1 = polygon.normal.unitOrthogonal(), e2 = polygon.normal.cross(e1);
  double radius = 0, c = 0, s = 0;
  for(Eigen::Index j = 0; j < width; ++j)
  {
    const double x = v.col(j).dot(e1), y = v.col(j).dot(e2);
    const double phase = std::atan2(y, x) - 2 * CGAL_PI * double(j) / double(width);
    radius += std::hypot(x, y) / double(width);
    c += std::cos(phase);
    s += std::sin(phase);
  }
  const double phase = std::atan2(s, c);
  polygon.radius = radius;
  polygon.first = std::cos(phase) * e1 + std::sin(phase) * e2;
  return polygon;
}

CGAL_TILABLE_SURFACES_INLINE
bool rings_are_round(const std::vector<Eigen::Matrix3Xd>& ring)
{
  for(const Eigen::Matrix3Xd& r : ring)
  {
    const Eigen::Index width = r.cols();
    double length = 0;
    for(Eigen::Index j = 0; j < width; ++j)
      length += (r.col((j + 1) % width) - r.col(j)).norm() / double(width);
    const Eigen::Matrix3Xd polygon = fit_regular_polygon(r).points(width);
    if((polygon - r).colwise().norm().maxCoeff() > tuning::round_ring_deviation * length)
      return false;
  }
  return true;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> coaxial_transition_sweep(const Quad_grid& grid, std::size_t k)
{
  const std::size_t rows = grid.rows, columns = grid.columns;
  std::vector<Eigen::ArrayXd> present;
  const std::vector<Eigen::Matrix3Xd> ring = grid_ring_points(grid, Trimmed_grid_points(), present);
  if(ring.empty() || std::size_t(ring[0].cols()) != columns || columns < 3 || !rings_are_round(ring))
    return {};
  const std::size_t groups = (k + 1) / (columns + 1);
  const std::vector<Sweep_group> group = groups < 2 ? std::vector<Sweep_group>() : transition_groups(ring, present, groups);
  if(group.empty())
    return {};
  std::vector<std::size_t> label(grid.corners.size());
  for(std::size_t r = 0, g = 0, run = 0; r < rows; ++r)
  {
    const bool in_group = g < group.size() && r >= group[g].first;
    if(r > 0 && (!in_group || r == group[g].first))
      ++run;
    for(std::size_t c = 0; c < columns; ++c)
      label[grid.face_at[r * columns + c]] = run * columns + (in_group ? c : 0);
    if(in_group && r + 1 == group[g].end)
      ++g;
  }
  relabel_by_first_face(label);
  const std::size_t used = groups * columns + groups - 1;
  if(!add_leftover_molds(label, grid, used, k - used))
    return {};
  return label;
}

CGAL_TILABLE_SURFACES_INLINE
Screw_coordinates::Screw_coordinates(const Eigen::Matrix4d& m)
{
  const Eigen::AngleAxisd turn(Eigen::Matrix3d(m.topLeftCorner<3, 3>()));
  m_translation = turn.angle() < tuning::screw_angle_min;
  if(m_translation)
    return;
  m_axis = turn.axis();
  m_e1 = m_axis.unitOrthogonal();
  m_e2 = m_axis.cross(m_e1);
  // The axis point in the plane through the origin: (I - R) o = t - (t.a) a.
  Eigen::Matrix<double, 3, 2> e;
  e << m_e1, m_e2;
  const Eigen::Matrix3d i_minus_r = Eigen::Matrix3d::Identity() - m.topLeftCorner<3, 3>();
  const Eigen::Vector3d t = m.topRightCorner<3, 1>();
  const Eigen::Vector2d o = (e.transpose() * i_minus_r * e).lu().solve(e.transpose() * (t - t.dot(m_axis) * m_axis));
  m_origin = e * o;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_IMPL_H
