// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_H

// Segment clusterings of quad grids, for the final pool of cluster_panels().
//
// When the quads form a grid, rows x columns (every strip of one direction,
// a row, crosses every strip of the other, a column, exactly once: a tube, a
// shell, a patch), a bent and growing tube can be kept with few molds by
// cutting its rows into runs of consecutive rows:
// - a *segment*: the columns are put into G groups, and every group is one
//   mold across the run. Rows of congruent quads position by position make a
//   piece of a swept surface of constant section (on a bent tube, a piece of
//   a torus): the bend is kept, the growth is frozen.
// - a *band*: the whole run is one mold. A ring of congruent quads is a
//   frustum; it changes the section's size from one segment to the next.
// - a one-row segment: a ring with a mold per column group, where the
//   section can both turn and change size.
// A shell made of these keeps its spiral and its growth, where whole rings
// (bands only) straighten it and whole columns (one segment) freeze it
// (seashell stand-in, K = 60: three segments and three one-row segments,
// 2.2% of the diagonal and the spiral kept, against a boxy torus at 5.7%
// from the other candidates and a straight tube of rings at 22%).
//
// The runs are chosen by dynamic programming with exactly K molds, the cost
// of a run being the spread of the shapes it makes congruent: per mold, the
// sum of squared differences of the six corner distances (four edges, two
// diagonals) of its quads from their mean, in corresponding corner order.
// Prefix sums over the rows make every run's cost O(G).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// One way to make a run of rows congruent: the columns in `groups` groups,
// each one mold over the run, with per face the six corner distances in the
// corner order of its group (prefix sums over the rows).
struct Run_option
{
  std::size_t groups = 1;
  std::vector<std::size_t> column_group;
  std::vector<Eigen::Matrix<double, 6, 1> > sum;  // [(row + 1) * groups + g], prefix over rows
  std::vector<double> squared_sum;                // same
  std::vector<std::size_t> count;                 // per group: columns in it

  // The spread of the shapes made congruent over rows [a, b).
  double cost(std::size_t a, std::size_t b) const;
};

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix<double, 6, 1> corner_distances(const Panel& q);

// The option with the columns grouped by `column_group` (groups numbered
// 0..groups-1); each column is put in the corner order of its group's
// first column by their best match on the middle row.
CGAL_TILABLE_SURFACES_INLINE
Run_option run_option(const Quad_grid& grid, const std::vector<std::size_t>& column_group,
                      std::size_t groups, Orientation_policy policy);

// The corner distances of a quad listed in the order of template corners
// matched with orientation `o`: d'(i, j) = d(o(i), o(j)). The 8 index
// permutations are tabulated once: the column grouping calls this in its
// inner loop.
CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix<double, 6, 1> reoriented(const Eigen::Matrix<double, 6, 1>& d, Panel_orientation o);

// The columns in `groups` groups, merged greedily by least increase of the
// run cost over all rows (Ward's criterion on the corner distances), each
// group in the corner order of its first column, the others matched to it
// on the middle row. On a section symmetric by a plane the mirror columns
// pair up first.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> group_columns(const Quad_grid& grid, std::size_t groups,
                                       Orientation_policy policy);

// The runs of rows, each with one of `options`, that use exactly m molds
// with the least total cost, for every m up to k (one dynamic program).
// Refers to `grid` and to the options, which must outlive it.
//
// Unless `segments_may_touch`, two segments of several rows never follow
// each other: in such a segment every quad has equal edges on its two row
// sides, so both would share one section and tie the lengths of the whole
// chain together, which the per-run cost does not see. A band or a one-row
// segment between them lets the section change. A sweep wants exactly that
// one section (sweep_clusterings()).
class Run_partitions
{
public:
  Run_partitions(const Quad_grid& grid, const std::vector<const Run_option*>& options, std::size_t k,
                 bool segments_may_touch = false);

  // The least total cost with exactly m molds; infinity when no partition
  // uses exactly m molds (or m > k).
  double cost(std::size_t m) const
  {
    if(m > m_k)
      return infinity();
    return (std::min)(m_best[state(m_grid.rows, m, true)], m_best[state(m_grid.rows, m, false)]);
  }

  // The cluster of every face with exactly m molds, numbered by first face,
  // or an empty vector when no partition uses exactly m molds (or m > k).
  std::vector<std::size_t> label(std::size_t m) const;

private:
  struct Choice { std::size_t start = 0, option = 0; bool segment_before = false; };
  static double infinity() { return (std::numeric_limits<double>::max)(); }
  // State (r, m, s): rows [0, r) with m molds, s whether the last run is a
  // segment of several rows.
  std::size_t state(std::size_t r, std::size_t m, bool s) const { return (r * (m_k + 1) + m) * 2 + (s ? 1 : 0); }

  const Quad_grid& m_grid;
  std::vector<const Run_option*> m_options;
  std::size_t m_k;
  std::vector<double> m_best;
  std::vector<Choice> m_choice;
};

// The runs of rows, each with one of `options`, that use exactly k molds
// with the least total cost (Run_partitions).
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> best_runs(const Quad_grid& grid,
                                   const std::vector<const Run_option*>& options, std::size_t k,
                                   bool segments_may_touch = false);

// A quad grid with its ways to make a run of rows congruent: bands with
// segments of the columns in G groups, for G the number of columns, half
// and a quarter of it (`group_columns()`), then with all of them.
struct Segment_options
{
  Quad_grid grid;
  std::vector<Run_option> options;
  std::vector<std::vector<const Run_option*> > sets;
};

// Fills the options and sets of `s` from its grid, for up to k molds.
CGAL_TILABLE_SURFACES_INLINE
void add_run_options(Segment_options& s, std::size_t k, Orientation_policy policy);

// The segment options for both choices of the rows, for up to k molds.
// None when the quads do not form a grid, or it has more than `max_rows`
// rows or `max_columns` columns. Held by unique_ptr: the sets point into
// the options.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::unique_ptr<Segment_options> >
segment_options(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, std::size_t k,
                Orientation_policy policy, std::size_t max_rows, std::size_t max_columns)
{
  std::vector<std::unique_ptr<Segment_options> > result;
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  for(int row_direction = 0; row_direction < 2; ++row_direction)
  {
    std::unique_ptr<Segment_options> s(new Segment_options);
    s->grid = quad_grid(pm, fim, vpm, strips, row_direction);
    const Quad_grid& grid = s->grid;
    // The dynamic program takes about 4 rows^2 K steps.
    if(grid.rows == 0 || grid.rows > max_rows || grid.columns > max_columns ||
       double(grid.rows) * double(grid.rows) * double(k) > tuning::segment_runs_work)
      continue;
    add_run_options(*s, k, policy);
    result.push_back(std::move(s));
  }
  return result;
}

// The segment clusterings with k clusters, for both choices of the rows and
// every set of segment options.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
segment_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, std::size_t k,
                    Orientation_policy policy, std::size_t max_rows = tuning::segment_grid_max_rows,
                    std::size_t max_columns = tuning::segment_grid_max_columns)
{
  std::vector<std::vector<std::size_t> > result;
  for(const std::unique_ptr<Segment_options>& s : segment_options(pm, fim, vpm, k, policy, max_rows, max_columns))
    for(const std::vector<const Run_option*>& set : s->sets)
    {
      std::vector<std::size_t> label = best_runs(s->grid, set, k);
      if(!label.empty() && std::find(result.begin(), result.end(), label) == result.end())
        result.push_back(label);
    }
  return result;
}

// Segment clusterings of fewer molds, m from k / 2 to k - 1, with their
// largest clusters split by shape until k (bring_to()); the `count` of
// least length deviation (Edge_sharing_graph::length_deviation()), in that
// order. Adding molds to a segment clustering that fits the grid keeps its
// structure, where the best runs with exactly k molds may change it
// (seashell stand-in, K = 96: those that end exact and uncrossed end at
// 4.8% of the diagonal or farther, the one of 80 molds split to 96 at
// 1.6%); the length
// deviation tells the structures that fit (there, 80 and 60 molds rank
// first by it, as by the predicted displacement). The splits of each
// partition draw from a generator of their own, seeded by `seed`, so the
// result does not depend on the order or the threads.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
split_segment_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                          const std::vector<Panel>& quads, const std::vector<Quad_descriptor>& descriptors,
                          std::size_t k, Orientation_policy policy, unsigned int seed, std::size_t count,
                          std::size_t max_rows = tuning::segment_grid_max_rows,
                          std::size_t max_columns = tuning::segment_grid_max_columns)
{
  std::vector<std::vector<std::size_t> > labels;
  std::vector<std::size_t> molds;
  for(const std::unique_ptr<Segment_options>& s : segment_options(pm, fim, vpm, k, policy, max_rows, max_columns))
    for(const std::vector<const Run_option*>& set : s->sets)
    {
      const Run_partitions partitions(s->grid, set, k);
      for(std::size_t m = (std::max)(std::size_t(1), k / 2); m < k; ++m)
      {
        std::vector<std::size_t> label = partitions.label(m);
        if(!label.empty() && std::find(labels.begin(), labels.end(), label) == labels.end())
        {
          labels.push_back(std::move(label));
          molds.push_back(m);
        }
      }
    }
  std::vector<double> deviation(labels.size());
  parallel_for(labels.size(), [&](std::size_t i) {
    CGAL::Random random(seed);
    bring_to(k, pm, fim, vpm, quads, descriptors, policy, random, labels[i], molds[i]);
    const Cluster_shapes shapes = cluster_shapes(quads, labels[i], k, policy);
    deviation[i] = edge_sharing_graph(pm, fim, vpm, labels[i], shapes.orientation, k).length_deviation();
  });
  std::vector<std::size_t> order(labels.size());
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return deviation[a] < deviation[b]; });
  std::vector<std::vector<std::size_t> > result;
  for(std::size_t i = 0; i < order.size() && result.size() < count; ++i)
    if(std::find(result.begin(), result.end(), labels[order[i]]) == result.end())
      result.push_back(labels[order[i]]);
  return result;
}

// The candidates of clusterings by labels (the segment, split segment and
// sweep generators): each face oriented by its best match.
template <typename Candidate, typename Origin>
std::vector<Candidate> best_match_candidates(std::vector<std::vector<std::size_t> > labels, Origin origin)
{
  std::vector<Candidate> result(labels.size());
  for(std::size_t i = 0; i < labels.size(); ++i)
  {
    result[i].origin = origin;
    result[i].label = std::move(labels[i]);
  }
  return result;
}

// The grid-segment candidate generator (CandidateGenerator, origin
// GRID_SEGMENTS): with `use_segment_candidates`, K > 1 and no triangle (a
// quad grid has none), the segment clusterings with K molds
// (segment_clusterings()).
struct Grid_segment_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!context.settings.use_segments || context.k <= 1 || context.has_triangles)
      return std::vector<typename Context::Candidate>();
    return best_match_candidates<typename Context::Candidate>(
      segment_clusterings(context.mesh, context.face_index, context.vertex_point, context.k, context.policy),
      Context::GRID_SEGMENTS);
  }
};

// The split-segment candidate generator (CandidateGenerator, origin
// GRID_SEGMENTS): as Grid_segment_generator, up to large_mesh_faces faces,
// the `tuning::split_segment_candidates` segment clusterings of fewer molds
// split to K of least length deviation (split_segment_clusterings(), each
// drawing from a generator of its own seeded by `random_seed`). They cost
// about 1 ms per face at K = 100 (10,000 faces: 11 s on 2 cores); above
// large_mesh_faces the sweeps serve grids.
struct Split_segment_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!context.settings.use_segments || context.k <= 1 || context.has_triangles ||
       context.panels.size() > large_mesh_faces)
      return std::vector<typename Context::Candidate>();
    return best_match_candidates<typename Context::Candidate>(
      split_segment_clusterings(context.mesh, context.face_index, context.vertex_point, context.panels,
                                context.descriptors, context.k, context.policy, context.seed,
                                tuning::split_segment_candidates),
      Context::GRID_SEGMENTS);
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_H
