// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_H

// Sweep clusterings of quad grids, and the swept surfaces at which they are
// exact (built by sweep_start.h).
//
// On a grid, rows of quads between the rings of vertices 0..R, let every
// ring be the image of the one before under a rigid motion M_s that is the
// same for all the rows of a run s: then the quad of column c in row i + 1
// is M_s applied to the one in row i, and every column of a run is one mold.
//
// With more columns than molds (the 100k seashell: 316 quads per ring,
// K = 100), one run of rows takes the whole grid, and its columns are cut
// into K runs of consecutive columns, each one mold: the section's vertices
// of a column run are put on a helix about M's axis, with equal steps,
// p_{c+1} = C p_c for a screw C about that axis (a translation when M is
// one). C commutes with M, so C maps quad c of every ring onto quad c + 1.
// A piece of the section keeps its place where it runs at a constant
// distance from the axis; single columns take the rest. The runs are chosen
// by dynamic programming with the least squared move of the section.
//
// A sweep freezes the section: every ring is congruent to the first. With
// 3 molds per column or more, a transition sweep lets it change: groups of
// rows, each a sweep of its own section, separated by single rows whose
// every quad is a mold of its own (transition_sweep()): the 10k-quad
// seashell parametrization at K = 400 ends 4.2% of the diagonal away
// instead of 8.7%, and at K = 1,000 1.5% instead of 7.8%. On a tube of
// round section a transition row is one mold (coaxial_transition_sweep()),
// so more groups fit: 2.9% at K = 400, 1.2% at K = 1,000.
//
// A grid trimmed by its outline (trimmed_grid.h) has rings with points
// missing: the motion is fitted on the pairs present, the section is the
// mean of the points present; it is one run of rows (runs of rows need
// whole rows), with more columns than molds cut into column runs, else
// every column cut into pieces of consecutive quads (split_columns_to()).
//
// A grid closed across its rows (ring R is ring 0) is one run whose M^R
// must be the identity: M is made a rotation by a whole number of turns
// over the R rows (close_up()), and the swept surface is one of revolution.

#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/pole_fans.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/trimmed_grid.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Whether the last row of `grid` meets the first (a torus, or a tube swept
// about its axis): a sweep then closes up only as a rotation whose rows-th
// power is the identity (swept_section()). The first quad of the last row
// shares its corners with the first quad of the first row, beyond the edge
// that two rows share anyway when there are only two. `points`: those of a
// trimmed grid, else empty; a trimmed grid never closes (its strips do not,
// trimmed_quad_grid()) and may miss those two quads.
inline bool closed_across_rows(const Quad_grid& grid, const Trimmed_grid_points& points)
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

// The rings of `grid` (rows + 1 of them, each of columns vertices, one more
// when the rings are open), in grid order, as given by `corner(r, c, i)`: a
// vertex index or a point of corner i of the quad of row r and column c.
// The quad of row r and column c has its corners on rings r and r + 1 at
// positions c and c + 1; when the grid is closed across its rows, the last
// ring is the first. Empty when the rows do not share rings as a grid does.
template <typename Corner>
auto grid_rings(const Quad_grid& grid, Corner corner)
  -> std::vector<std::vector<decltype(corner(std::size_t(0), std::size_t(0), 0))> >
{
  typedef std::vector<decltype(corner(std::size_t(0), std::size_t(0), 0))> Ring;
  const std::size_t rows = grid.rows, columns = grid.columns;
  if(rows == 0)
    return {};
  // Corners 0 and 1 of every face of a row lie on one ring, 3 and 2 on the
  // other; corner 0 of column c is corner 1 of column c + 1.
  const bool closed = corner(0, columns - 1, 0) == corner(0, 0, 1);
  auto ring = [&](std::size_t r, int first, int last) {
    Ring v;
    for(std::size_t c = 0; c < columns; ++c)
      v.push_back(corner(r, c, first));
    if(!closed)
      v.push_back(corner(r, columns - 1, last));
    return v;
  };
  std::vector<Ring> side_a(rows), side_b(rows);
  for(std::size_t r = 0; r < rows; ++r)
  {
    side_a[r] = ring(r, 1, 0);
    side_b[r] = ring(r, 2, 3);
  }
  std::vector<Ring> rings;
  for(int flip = 0; flip < 2 && rings.empty(); ++flip)
  {
    const std::vector<Ring>& first = flip ? side_b : side_a;
    const std::vector<Ring>& second = flip ? side_a : side_b;
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

// The rings of `grid` as grid_rings() gives them, and `present`: per ring,
// 1 or 0 per point. On a full grid (`points` empty) every point is present;
// on a trimmed one there are rows + 1 rings of columns + 1 lattice points,
// a default value where a point is missing.
template <typename Corner>
auto present_grid_rings(const Quad_grid& grid, const Trimmed_grid_points& points, Corner corner,
                        std::vector<Eigen::ArrayXd>& present)
  -> std::vector<std::vector<decltype(corner(std::size_t(0), std::size_t(0), 0))> >
{
  typedef decltype(corner(std::size_t(0), std::size_t(0), 0)) Value;
  if(points.cell.empty())
  {
    std::vector<std::vector<Value> > rings = grid_rings(grid, corner);
    present.assign(rings.size(), Eigen::ArrayXd::Ones(rings.empty() ? 0 : Eigen::Index(rings[0].size())));
    return rings;
  }
  const std::size_t width = grid.columns + 1;
  std::vector<std::vector<Value> > rings(grid.rows + 1, std::vector<Value>(width, Value()));
  present.assign(grid.rows + 1, Eigen::ArrayXd::Zero(Eigen::Index(width)));
  for(std::size_t r = 0; r <= grid.rows; ++r)
    for(std::size_t c = 0; c < width; ++c)
    {
      const std::size_t cell = points.cell[r * width + c];
      if(cell == no_index())
        continue;
      rings[r][c] = corner(cell / grid.columns, cell % grid.columns, points.corner[r * width + c]);
      present[r](Eigen::Index(c)) = 1;
    }
  return rings;
}

// The grid of `pm` whose rows are the strips of direction `row_direction`:
// a full grid (quad_grid()), else a trimmed one (trimmed_quad_grid(), which
// fills `points`; left empty for a full grid); rows == 0 when neither.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Quad_grid full_or_trimmed_grid(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                               const std::array<std::vector<std::size_t>, 2>& strips, int row_direction,
                               Trimmed_grid_points& points)
{
  points = Trimmed_grid_points();
  Quad_grid grid = quad_grid(pm, fim, vpm, strips, row_direction);
  return grid.rows > 0 ? grid : trimmed_quad_grid(pm, fim, vpm, row_direction, points);
}

// The strips the strip candidates group (strip_clusterings()): the
// directions carried across the mesh (quad_strips()) when they make it a
// grid, full or trimmed, else each face's own parities. On a grid whose
// faces start at any corner, only the carried strips are its rows and
// columns (the tunnel so started, K = 10: 1.56% Hausdorff with the carried
// strips, as the bundled file, 2.07% with each face's parities); on other
// meshes, carried strips make free_negshell_marc_anet's result cross itself.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::array<std::vector<std::size_t>, 2> candidate_strips(const PolygonMesh& pm, FaceIndexMap fim,
                                                         VertexPointMap vpm)
{
  std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  Trimmed_grid_points points;
  return full_or_trimmed_grid(pm, fim, vpm, strips, 0, points).rows > 0 ? strips : quad_strips(pm, fim, false);
}

inline Eigen::Matrix3Xd apply_motion(const Eigen::Matrix4d& m, const Eigen::Matrix3Xd& x)
{
  return (m.topLeftCorner<3, 3>() * x).colwise() + m.topRightCorner<3, 1>();
}

// A swept surface close to the rings of a grid: per run of rows the rigid
// motion that best maps its rings onto the next ones (Umeyama, no scale),
// and the section, the mean of the rings pulled back to the middle ring.
// On a trimmed grid only the points present count, in both.
struct Swept_section
{
  bool valid = true;  // false when a position of the section is on no ring, or a run has too few points
  std::vector<Eigen::Matrix4d> motion;  // per run
  std::vector<Eigen::Matrix4d> frame;   // per ring: the middle ring's to its own
  Eigen::Matrix3Xd section;             // in the middle ring's frame

  // The rings of the swept surface, side by side.
  Eigen::Matrix3Xd swept() const
  {
    const Eigen::Index width = section.cols();
    Eigen::Matrix3Xd x(3, width * Eigen::Index(frame.size()));
    for(std::size_t i = 0; i < frame.size(); ++i)
      x.middleCols(width * Eigen::Index(i), width) = apply_motion(frame[i], section);
    return x;
  }
};

// The rigid motion closest to `m` whose `rows`-th power is the identity: a
// rotation about m's axis by a whole number of turns over the rows, at
// least one. False when m turns by less than half a row's share of a turn.
inline bool close_up(Eigen::Matrix4d& m, std::size_t rows)
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

// `ring`: the input rings, `run_of`: the run of each row, `present`: per
// ring, 1 or 0 per point (present_grid_rings()). With `column_runs`, a single
// run whose motion hardly turns is made a translation (tuning::screw_angle_min).
// With `closed` (the last ring is the first), a single run whose motion is
// made to close up (close_up()).
inline Swept_section swept_section(const std::vector<Eigen::Matrix3Xd>& ring, const std::vector<std::size_t>& run_of,
                                   bool column_runs, const std::vector<Eigen::ArrayXd>& present, bool closed = false)
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

// Coordinates about the axis of a screw motion: (radius, angle, height), or
// the Cartesian ones when the motion is a translation.
class Screw_coordinates
{
public:
  explicit Screw_coordinates(const Eigen::Matrix4d& m)
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

  bool is_translation() const { return m_translation; }

  Eigen::Vector3d to(const Eigen::Vector3d& p) const
  {
    if(m_translation)
      return p;
    const Eigen::Vector3d v = p - m_origin;
    const double x = v.dot(m_e1), y = v.dot(m_e2);
    return Eigen::Vector3d(std::hypot(x, y), std::atan2(y, x), v.dot(m_axis));
  }

  Eigen::Vector3d from(const Eigen::Vector3d& q) const
  {
    if(m_translation)
      return q;
    return m_origin + q(0) * (std::cos(q(1)) * m_e1 + std::sin(q(1)) * m_e2) + q(2) * m_axis;
  }

private:
  bool m_translation = true;
  Eigen::Vector3d m_origin = Eigen::Vector3d::Zero(), m_axis, m_e1, m_e2;
};

// The section's vertices first..first + length (indices modulo its width)
// moved onto a helix of equal steps about the axis of `coordinates`: the
// least-squares line in (angle, height) at the mean radius, or a line of
// equal steps for a translation.
inline Eigen::Matrix3Xd screw_run(const Eigen::Matrix3Xd& section, const Screw_coordinates& coordinates,
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

// screw_column_runs() with the ring opened at column `cut` (left alone
// when the ring is closed), given `cost[c * (longest + 1) + l]`, the move of
// the run of l columns from column c; `total` is set to the least move.
inline std::vector<std::size_t> screw_column_runs_from(const std::vector<double>& cost, std::size_t longest,
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

// The columns of a one-run sweep cut into exactly `groups` runs of
// consecutive columns, with the least squared move of the section's vertices
// onto their runs' helices (screw_run()); two runs of several columns never
// meet, since they would share a vertex. The run of every column, numbered
// along the ring; empty when no such cut exists. A closed ring is opened at
// a column left alone: of the three whose vertices bend most (the cost of a
// run of two columns through each), the one with the least total move.
inline std::vector<std::size_t> screw_column_runs(const Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
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

// The section of a one-run sweep moved onto the helices of its column runs:
// `run_of_column` numbers them, each a set of consecutive columns. False,
// and the section unchanged, when a run is not one set of consecutive
// columns or takes the whole of a closed ring.
inline bool fit_screw_column_runs(Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
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

// The rings of `grid` (present_grid_rings()) as point matrices, from the
// corners of its quads; empty when its rows do not share rings.
inline std::vector<Eigen::Matrix3Xd> grid_ring_points(const Quad_grid& grid, const Trimmed_grid_points& points,
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

// The one-run sweep clustering of `grid` whose columns are cut into k screw
// column runs; empty when there is none.
// `points`: those of a trimmed grid, else empty.
inline std::vector<std::size_t> screw_column_sweep(const Quad_grid& grid, const Trimmed_grid_points& points,
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

// `label`, one cluster per column of `grid` (fewer than k), with its
// columns cut into pieces of consecutive quads until there are k clusters,
// each new piece going to the column with the most quads per piece. On a
// one-run sweep every quad of a column has one shape, so any piece is exact
// where the column is. False, `label` unchanged, when the grid has fewer
// than k quads.
inline bool split_columns_to(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t k)
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

// The sweep of the rings a..b of a full grid (`run_of`: the run of each of
// its rows, numbered from 0 at row a; one run when empty), as swept_section()
// gives it for those rings alone.
inline Swept_section group_swept_section(const std::vector<Eigen::Matrix3Xd>& ring,
                                         const std::vector<Eigen::ArrayXd>& present,
                                         const std::vector<std::size_t>& run_of, std::size_t a, std::size_t b)
{
  const std::vector<Eigen::Matrix3Xd> group_ring(ring.begin() + a, ring.begin() + b + 1);
  const std::vector<Eigen::ArrayXd> group_present(present.begin() + a, present.begin() + b + 1);
  return swept_section(group_ring, run_of.empty() ? std::vector<std::size_t>(b - a, 0) : run_of, false, group_present);
}

// How far the one-run sweep of the rings a..b of a full grid lies from them:
// the largest distance of a swept point from its ring point.
inline double sweep_group_deviation(const std::vector<Eigen::Matrix3Xd>& ring,
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

// Rows [first, end) of a group of sweep rows, and how far its one-run sweep
// lies from its rings (sweep_group_deviation()).
struct Sweep_group
{
  std::size_t first, end;
  double deviation;
};

// The rows [first, end) of `groups` one-run sweeps of a full grid's `ring`,
// separated by single transition rows, whose largest deviation from the
// rings (sweep_group_deviation()) is least: a dynamic program over
// transition rows taken every rows / tuning::transition_row_choices rows.
// Empty when the rows are too few for groups of two rows or more.
inline std::vector<Sweep_group>
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

// The first row of every run of the sweep clustering `label` of `grid`
// (a new run gives column 0 a new cluster), and `rows` last.
inline std::vector<std::size_t> sweep_run_first_rows(const Quad_grid& grid, const std::vector<std::size_t>& label)
{
  std::vector<std::size_t> first_row(1, 0);
  for(std::size_t r = 1; r < grid.rows; ++r)
    if(label[grid.face_at[r * grid.columns]] != label[grid.face_at[(r - 1) * grid.columns]])
      first_row.push_back(r);
  first_row.push_back(grid.rows);
  return first_row;
}

// `left` more molds for the sweep clustering `label` (clusters numbered
// below `used`): columns spread evenly over the row, each split in two at the
// middle row of the longest run. False when that run has a single row.
inline bool add_leftover_molds(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t used,
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

// The transition sweep clustering of a full open grid with `slots` molds per
// column (slots x columns clusters, slots >= 3): (slots + 1) / 2 one-run
// sweeps (transition_groups()), each column of a group one mold, separated
// by single rows whose every quad is a mold (the section may turn and grow
// there: sweep_start.h builds each group from its own section); with an
// even number of slots the group farthest from its rings is cut into two
// runs at its middle row. Empty when there is none.
inline std::vector<std::size_t> transition_sweep(const Quad_grid& grid, std::size_t slots)
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

// Coaxial transitions. On a grid closed around its rings whose rings are
// near regular polygons (a tube of round section), the transition row
// between two groups may be a band between two regular polygons on one
// axis, in parallel planes, with the same phase: the rotation by
// 2 pi / columns about that axis maps each of its quads onto the next, so
// the row is one mold while the section's radius changes across it. Each
// group of such a coaxial transition sweep costs a row of molds, each
// transition one (coaxial_transition_sweep(); sweep_start.h builds it).

// A regular polygon: its centre, the unit normal about which it turns
// counterclockwise, its radius and the unit direction of its point 0.
struct Regular_polygon
{
  Eigen::Vector3d center, normal, first;
  double radius;

  // Its `width` points.
  Eigen::Matrix3Xd points(Eigen::Index width) const
  {
    const Eigen::Vector3d second = normal.cross(first);
    Eigen::Matrix3Xd p(3, width);
    for(Eigen::Index j = 0; j < width; ++j)
    {
      const double angle = 2 * CGAL_PI * double(j) / double(width);
      p.col(j) = center + radius * (std::cos(angle) * first + std::sin(angle) * second);
    }
    return p;
  }
};

// The regular polygon near the closed ring `ring`: its centroid, the normal
// of its area vector, the mean in-plane radius, and the phase that best
// matches the angles of its points.
inline Regular_polygon fit_regular_polygon(const Eigen::Matrix3Xd& ring)
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

// Whether every ring of `ring` (closed rings) lies within
// tuning::round_ring_deviation of its mean edge length from its regular
// polygon (fit_regular_polygon()).
inline bool rings_are_round(const std::vector<Eigen::Matrix3Xd>& ring)
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

// The coaxial transition sweep clustering of a full grid closed around its
// round rings (rings_are_round()) with k molds: as many one-run sweep groups
// (transition_groups()) as fit in k, each column of a group one mold,
// separated by single rows that are one mold each (see above); the molds
// left split columns (add_leftover_molds()). Empty when there is none.
inline std::vector<std::size_t> coaxial_transition_sweep(const Quad_grid& grid, std::size_t k)
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

// Sweep clusterings with k clusters: the rows cut into the k / columns runs
// of least spread, every column of a run one mold, and the k mod columns
// molds left split the columns of the longest run in two at its middle row;
// and the transition sweeps with as many molds (transition_sweep(),
// coaxial_transition_sweep()).
// Each is exact at a swept surface built directly (sweep_start.h), which the
// segments of several groups above are not: it freezes the section's size
// and shape, and keeps its bends and twists. With more columns than k, one
// run of rows whose columns are cut into k screw column runs (see above).
// A trimmed grid sweeps as one run, and a grid closed across its rows as one
// run that closes up (a rotation, close_up()): with more columns than k the
// screw column runs, else every column cut into pieces of consecutive
// quads (split_columns_to()). One per grid direction; none when the
// leftover molds cannot be placed. With `closed_only`, only the sweeps of
// grids closed across their rows.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
quad_grid_sweep_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, std::size_t k,
                            Orientation_policy policy, bool closed_only)
{
  std::vector<std::vector<std::size_t> > result;
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  for(int row_direction = 0; row_direction < 2; ++row_direction)
  {
    Trimmed_grid_points points;
    const Quad_grid grid = full_or_trimmed_grid(pm, fim, vpm, strips, row_direction, points);
    const std::size_t rows = grid.rows, columns = grid.columns;
    const bool trimmed = !points.cell.empty();
    if(rows == 0 || (closed_only && !closed_across_rows(grid, points)))
      continue;
    // Runs of rows need every row whole (run_option()): a trimmed grid is
    // one run, as a closed one is.
    if(columns > k || trimmed || closed_across_rows(grid, points))
    {
      std::vector<std::size_t> label = screw_column_sweep(grid, points, (std::min)(k, columns));
      if(!label.empty() && (columns >= k || split_columns_to(label, grid, k)))
        result.push_back(label);
      continue;
    }
    const std::size_t runs = (std::min)(rows, k / columns), left = k - runs * columns;
    if(double(rows) * double(rows) * double(runs) > tuning::sweep_runs_work)
      continue;
    std::vector<std::size_t> all_columns(columns);
    std::iota(all_columns.begin(), all_columns.end(), std::size_t(0));
    const Run_option option = run_option(grid, all_columns, columns, policy);
    std::vector<std::size_t> label = best_runs(grid, {&option}, runs * columns, true);
    if(!label.empty() && add_leftover_molds(label, grid, runs * columns, left))
      result.push_back(label);
    std::vector<std::size_t> transition = transition_sweep(grid, k / columns);
    if(!transition.empty() && add_leftover_molds(transition, grid, k - left, left))
      result.push_back(transition);
    std::vector<std::size_t> coaxial = coaxial_transition_sweep(grid, k);
    if(!coaxial.empty())
      result.push_back(coaxial);
  }
  return result;
}

// The sweep clusterings with k clusters of a quad grid
// (quad_grid_sweep_clusterings()), or of a grid closed across its rows
// capped by pole fans (pole_fans.h): the quads' sweeps with one cluster
// fewer per fan, and each fan one cluster. None for other meshes.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
sweep_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, std::size_t k,
                  Orientation_policy policy)
{
  Pole_fans fans;
  const Triangle_layout layout = pole_fans(pm, fim, CGAL::get_initialized_vertex_index_map(pm), vpm, fans);
  if(layout == Triangle_layout::NONE)
    return quad_grid_sweep_clusterings(pm, fim, vpm, k, policy, false);
  const std::size_t fan_molds = fans.pole.size();
  std::vector<std::vector<std::size_t> > result;
  if(layout == Triangle_layout::OTHER || k <= fan_molds)
    return result;
  const Pole_fans::Quad_part& quads = fans.quads;
  for(const std::vector<std::size_t>& label :
      quad_grid_sweep_clusterings(quads, get(CGAL::face_index, quads), get(CGAL::vertex_point, quads),
                                  k - fan_molds, policy, true))
    result.push_back(with_fan_clusters(fans, label, num_faces(pm)));
  return result;
}

// The sweep candidate generator (CandidateGenerator, origin GRID_SWEEPS):
// with `use_segment_candidates`, the sweep clusterings (sweep_clusterings(),
// also of meshes with triangles as fans around poles), each with an exact
// start (sweep_start()) and its faces oriented by their best match.
struct Sweep_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!context.settings.use_segments)
      return std::vector<typename Context::Candidate>();
    std::vector<typename Context::Candidate> result = best_match_candidates<typename Context::Candidate>(
      sweep_clusterings(context.mesh, context.face_index, context.vertex_point, context.k, context.policy),
      Context::GRID_SWEEPS);
    for(typename Context::Candidate& candidate : result)
      candidate.has_exact_start = true;
    return result;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_H
