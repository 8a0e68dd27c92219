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

#include <CGAL/Tilable_surfaces/internal/config.h>
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
CGAL_TILABLE_SURFACES_INLINE
bool closed_across_rows(const Quad_grid& grid, const Trimmed_grid_points& points);

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
CGAL_TILABLE_SURFACES_INLINE
bool close_up(Eigen::Matrix4d& m, std::size_t rows);

// `ring`: the input rings, `run_of`: the run of each row, `present`: per
// ring, 1 or 0 per point (present_grid_rings()). With `column_runs`, a single
// run whose motion hardly turns is made a translation (tuning::screw_angle_min).
// With `closed` (the last ring is the first), a single run whose motion is
// made to close up (close_up()).
CGAL_TILABLE_SURFACES_INLINE
Swept_section swept_section(const std::vector<Eigen::Matrix3Xd>& ring, const std::vector<std::size_t>& run_of,
                            bool column_runs, const std::vector<Eigen::ArrayXd>& present, bool closed = false);

// Coordinates about the axis of a screw motion: (radius, angle, height), or
// the Cartesian ones when the motion is a translation.
class Screw_coordinates
{
public:
  explicit Screw_coordinates(const Eigen::Matrix4d& m);

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
CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3Xd screw_run(const Eigen::Matrix3Xd& section, const Screw_coordinates& coordinates,
                           std::size_t first, std::size_t length);

// screw_column_runs() with the ring opened at column `cut` (left alone
// when the ring is closed), given `cost[c * (longest + 1) + l]`, the move of
// the run of l columns from column c; `total` is set to the least move.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_runs_from(const std::vector<double>& cost, std::size_t longest,
                                                std::size_t columns, std::size_t groups, bool closed,
                                                std::size_t cut, double& total);

// The columns of a one-run sweep cut into exactly `groups` runs of
// consecutive columns, with the least squared move of the section's vertices
// onto their runs' helices (screw_run()); two runs of several columns never
// meet, since they would share a vertex. The run of every column, numbered
// along the ring; empty when no such cut exists. A closed ring is opened at
// a column left alone: of the three whose vertices bend most (the cost of a
// run of two columns through each), the one with the least total move.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_runs(const Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
                                           std::size_t columns, std::size_t groups);

// The section of a one-run sweep moved onto the helices of its column runs:
// `run_of_column` numbers them, each a set of consecutive columns. False,
// and the section unchanged, when a run is not one set of consecutive
// columns or takes the whole of a closed ring.
CGAL_TILABLE_SURFACES_INLINE
bool fit_screw_column_runs(Eigen::Matrix3Xd& section, const Eigen::Matrix4d& motion,
                           const std::vector<std::size_t>& run_of_column);

// The rings of `grid` (present_grid_rings()) as point matrices, from the
// corners of its quads; empty when its rows do not share rings.
CGAL_TILABLE_SURFACES_INLINE
std::vector<Eigen::Matrix3Xd> grid_ring_points(const Quad_grid& grid, const Trimmed_grid_points& points,
                                               std::vector<Eigen::ArrayXd>& present);

// The one-run sweep clustering of `grid` whose columns are cut into k screw
// column runs; empty when there is none.
// `points`: those of a trimmed grid, else empty.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> screw_column_sweep(const Quad_grid& grid, const Trimmed_grid_points& points,
                                            std::size_t k);

// `label`, one cluster per column of `grid` (fewer than k), with its
// columns cut into pieces of consecutive quads until there are k clusters,
// each new piece going to the column with the most quads per piece. On a
// one-run sweep every quad of a column has one shape, so any piece is exact
// where the column is. False, `label` unchanged, when the grid has fewer
// than k quads.
CGAL_TILABLE_SURFACES_INLINE
bool split_columns_to(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t k);

// The sweep of the rings a..b of a full grid (`run_of`: the run of each of
// its rows, numbered from 0 at row a; one run when empty), as swept_section()
// gives it for those rings alone.
CGAL_TILABLE_SURFACES_INLINE
Swept_section group_swept_section(const std::vector<Eigen::Matrix3Xd>& ring,
                                  const std::vector<Eigen::ArrayXd>& present,
                                  const std::vector<std::size_t>& run_of, std::size_t a, std::size_t b);

// How far the one-run sweep of the rings a..b of a full grid lies from them:
// the largest distance of a swept point from its ring point.
CGAL_TILABLE_SURFACES_INLINE
double sweep_group_deviation(const std::vector<Eigen::Matrix3Xd>& ring,
                             const std::vector<Eigen::ArrayXd>& present, std::size_t a, std::size_t b);

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
CGAL_TILABLE_SURFACES_INLINE
std::vector<Sweep_group>
transition_groups(const std::vector<Eigen::Matrix3Xd>& ring, const std::vector<Eigen::ArrayXd>& present,
           std::size_t groups);

// The first row of every run of the sweep clustering `label` of `grid`
// (a new run gives column 0 a new cluster), and `rows` last.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> sweep_run_first_rows(const Quad_grid& grid, const std::vector<std::size_t>& label);

// `left` more molds for the sweep clustering `label` (clusters numbered
// below `used`): columns spread evenly over the row, each split in two at the
// middle row of the longest run. False when that run has a single row.
CGAL_TILABLE_SURFACES_INLINE
bool add_leftover_molds(std::vector<std::size_t>& label, const Quad_grid& grid, std::size_t used,
                        std::size_t left);

// The transition sweep clustering of a full open grid with `slots` molds per
// column (slots x columns clusters, slots >= 3): (slots + 1) / 2 one-run
// sweeps (transition_groups()), each column of a group one mold, separated
// by single rows whose every quad is a mold (the section may turn and grow
// there: sweep_start.h builds each group from its own section); with an
// even number of slots the group farthest from its rings is cut into two
// runs at its middle row. Empty when there is none.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> transition_sweep(const Quad_grid& grid, std::size_t slots);

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
CGAL_TILABLE_SURFACES_INLINE
Regular_polygon fit_regular_polygon(const Eigen::Matrix3Xd& ring);

// Whether every ring of `ring` (closed rings) lies within
// tuning::round_ring_deviation of its mean edge length from its regular
// polygon (fit_regular_polygon()).
CGAL_TILABLE_SURFACES_INLINE
bool rings_are_round(const std::vector<Eigen::Matrix3Xd>& ring);

// The coaxial transition sweep clustering of a full grid closed around its
// round rings (rings_are_round()) with k molds: as many one-run sweep groups
// (transition_groups()) as fit in k, each column of a group one mold,
// separated by single rows that are one mold each (see above); the molds
// left split columns (add_leftover_molds()). Empty when there is none.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> coaxial_transition_sweep(const Quad_grid& grid, std::size_t k);

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

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SWEEP_CANDIDATES_H
