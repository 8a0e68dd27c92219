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
  double cost(std::size_t a, std::size_t b) const
  {
    double c = 0;
    for(std::size_t g = 0; g < groups; ++g)
    {
      const Eigen::Matrix<double, 6, 1> s1 = sum[b * groups + g] - sum[a * groups + g];
      const double s2 = squared_sum[b * groups + g] - squared_sum[a * groups + g];
      c += s2 - s1.squaredNorm() / double((b - a) * count[g]);
    }
    return (std::max)(c, 0.);
  }
};

inline Eigen::Matrix<double, 6, 1> corner_distances(const Panel& q)
{
  Eigen::Matrix<double, 6, 1> d;
  d << (q[1] - q[0]).norm(), (q[2] - q[1]).norm(), (q[3] - q[2]).norm(), (q[0] - q[3]).norm(),
       (q[2] - q[0]).norm(), (q[3] - q[1]).norm();
  return d;
}

// The option with the columns grouped by `column_group` (groups numbered
// 0..groups-1); each column is put in the corner order of its group's
// first column by their best match on the middle row.
inline Run_option run_option(const Quad_grid& grid, const std::vector<std::size_t>& column_group,
                             std::size_t groups, Orientation_policy policy)
{
  Run_option o;
  o.groups = groups;
  o.column_group = column_group;
  o.count.assign(groups, 0);
  const std::size_t middle = grid.rows / 2;
  std::vector<std::size_t> first(groups, no_index());
  std::vector<Panel_orientation> orientation(grid.columns);
  for(std::size_t c = 0; c < grid.columns; ++c)
  {
    const std::size_t g = column_group[c];
    ++o.count[g];
    if(first[g] == no_index())
      first[g] = c;
    else
      orientation[c] = fast_best_match(grid.corners[grid.face_at[middle * grid.columns + first[g]]],
                                       grid.corners[grid.face_at[middle * grid.columns + c]], policy)
                         .orientation;
  }
  o.sum.assign((grid.rows + 1) * groups, Eigen::Matrix<double, 6, 1>::Zero());
  o.squared_sum.assign((grid.rows + 1) * groups, 0.);
  for(std::size_t r = 0; r < grid.rows; ++r)
  {
    for(std::size_t g = 0; g < groups; ++g)
    {
      o.sum[(r + 1) * groups + g] = o.sum[r * groups + g];
      o.squared_sum[(r + 1) * groups + g] = o.squared_sum[r * groups + g];
    }
    for(std::size_t c = 0; c < grid.columns; ++c)
    {
      const Eigen::Matrix<double, 6, 1> d =
        corner_distances(reoriented(grid.corners[grid.face_at[r * grid.columns + c]], orientation[c]));
      o.sum[(r + 1) * groups + column_group[c]] += d;
      o.squared_sum[(r + 1) * groups + column_group[c]] += d.squaredNorm();
    }
  }
  return o;
}

// The corner distances of a quad listed in the order of template corners
// matched with orientation `o`: d'(i, j) = d(o(i), o(j)). The 8 index
// permutations are tabulated once: the column grouping calls this in its
// inner loop.
inline Eigen::Matrix<double, 6, 1> reoriented(const Eigen::Matrix<double, 6, 1>& d, Panel_orientation o)
{
  typedef std::array<std::array<int, 6>, 8> Table;
  static const Table permutation = [] {
    const int pair[6][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 2}, {1, 3}};
    Table t{};
    for(int index = 0; index < 8; ++index)
    {
      const Panel_orientation to(index);
      for(int p = 0; p < 6; ++p)
        for(int q = 0; q < 6; ++q)
        {
          const int i = to(pair[p][0]), j = to(pair[p][1]);
          if((pair[q][0] == i && pair[q][1] == j) || (pair[q][0] == j && pair[q][1] == i))
            t[index][p] = q;
        }
    }
    return t;
  }();
  Eigen::Matrix<double, 6, 1> r;
  for(int p = 0; p < 6; ++p)
    r[p] = d[permutation[o.index()][p]];
  return r;
}

// The columns in `groups` groups, merged greedily by least increase of the
// run cost over all rows (Ward's criterion on the corner distances), each
// group in the corner order of its first column, the others matched to it
// on the middle row. On a section symmetric by a plane the mirror columns
// pair up first.
inline std::vector<std::size_t> group_columns(const Quad_grid& grid, std::size_t groups,
                                              Orientation_policy policy)
{
  typedef Eigen::Matrix<double, 6, 1> Distances;
  const std::size_t rows = grid.rows, columns = grid.columns, middle = rows / 2;
  std::vector<std::vector<Distances> > sum(columns, std::vector<Distances>(rows));
  for(std::size_t c = 0; c < columns; ++c)
    for(std::size_t r = 0; r < rows; ++r)
      sum[c][r] = corner_distances(grid.corners[grid.face_at[r * columns + c]]);
  std::vector<Panel_orientation> match(columns * columns);
  parallel_for(columns, [&](std::size_t a) {
    for(std::size_t b = a + 1; b < columns; ++b)
      match[a * columns + b] = fast_best_match(grid.corners[grid.face_at[middle * columns + a]],
                                               grid.corners[grid.face_at[middle * columns + b]], policy)
                                 .orientation;
  });
  std::vector<std::size_t> size(columns, 1), parent(columns);
  for(std::size_t c = 0; c < columns; ++c) parent[c] = c;
  auto increase = [&](std::size_t a, std::size_t b) {
    double d = 0;
    for(std::size_t r = 0; r < rows; ++r)
      d += (sum[a][r] / double(size[a]) - reoriented(sum[b][r], match[a * columns + b]) / double(size[b]))
             .squaredNorm();
    return d * double(size[a] * size[b]) / double(size[a] + size[b]);
  };
  std::vector<double> cost(columns * columns, 0.);
  parallel_for(columns, [&](std::size_t a) {
    for(std::size_t b = a + 1; b < columns; ++b) cost[a * columns + b] = increase(a, b);
  });
  for(std::size_t count = columns; count > groups; --count)
  {
    std::size_t kept = 0, removed = 0;
    double best = (std::numeric_limits<double>::max)();
    for(std::size_t a = 0; a < columns; ++a)
      for(std::size_t b = a + 1; parent[a] == a && b < columns; ++b)
        if(parent[b] == b && cost[a * columns + b] < best)
        {
          best = cost[a * columns + b];
          kept = a;
          removed = b;
        }
    for(std::size_t r = 0; r < rows; ++r)
      sum[kept][r] += reoriented(sum[removed][r], match[kept * columns + removed]);
    size[kept] += size[removed];
    parent[removed] = kept;
    for(std::size_t c = 0; c < columns; ++c)
      if(parent[c] == c && c != kept)
        cost[(std::min)(c, kept) * columns + (std::max)(c, kept)] =
          c < kept ? increase(c, kept) : increase(kept, c);
  }
  std::vector<std::size_t> group(columns);
  for(std::size_t c = 0; c < columns; ++c)
  {
    std::size_t g = c;
    while(parent[g] != g) g = parent[g];
    group[c] = g;
  }
  relabel_by_first_face(group);
  return group;
}

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
                 bool segments_may_touch = false)
    : m_grid(grid), m_options(options), m_k(k),
      m_best((grid.rows + 1) * (k + 1) * 2, infinity()), m_choice(m_best.size())
  {
    const std::size_t rows = grid.rows;
    m_best[state(0, 0, false)] = 0;
    for(std::size_t b = 1; b <= rows; ++b)
      for(std::size_t a = 0; a < b; ++a)
        for(std::size_t i = 0; i < options.size(); ++i)
        {
          const std::size_t m = options[i]->groups;
          if(m > k) continue;
          const bool segment = !segments_may_touch && m > 1 && b - a > 1;
          const double run = options[i]->cost(a, b);
          for(std::size_t used = 0; used + m <= k; ++used)
            for(bool before_segment : {false, true})
            {
              const double before = m_best[state(a, used, before_segment)];
              if(before == infinity() || (segment && before_segment))
                continue;
              double& after = m_best[state(b, used + m, segment)];
              if(before + run >= after)
                continue;
              after = before + run;
              m_choice[state(b, used + m, segment)] = {a, i, before_segment};
            }
        }
  }

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
  std::vector<std::size_t> label(std::size_t m) const
  {
    std::vector<std::size_t> label;
    if(m > m_k)
      return label;
    std::size_t b = m_grid.rows;
    bool segment = m_best[state(b, m, true)] < m_best[state(b, m, false)];
    if(m_best[state(b, m, segment)] == infinity())
      return label;
    label.assign(m_grid.face_at.size(), 0);
    while(b > 0)
    {
      const Choice c = m_choice[state(b, m, segment)];
      const Run_option& o = *m_options[c.option];
      m -= o.groups;
      for(std::size_t r = c.start; r < b; ++r)
        for(std::size_t col = 0; col < m_grid.columns; ++col)
          label[m_grid.face_at[r * m_grid.columns + col]] = m + o.column_group[col];
      b = c.start;
      segment = c.segment_before;
    }
    relabel_by_first_face(label);
    return label;
  }

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
inline std::vector<std::size_t> best_runs(const Quad_grid& grid,
                                          const std::vector<const Run_option*>& options, std::size_t k,
                                          bool segments_may_touch = false)
{
  return Run_partitions(grid, options, k, segments_may_touch).label(k);
}

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
inline void add_run_options(Segment_options& s, std::size_t k, Orientation_policy policy)
{
  const Quad_grid& grid = s.grid;
  std::vector<Run_option>& options = s.options;
  options.reserve(4); // at most 4: the sets' pointers stay valid
  options.push_back(run_option(grid, std::vector<std::size_t>(grid.columns, 0), 1, policy));
  for(std::size_t groups : {grid.columns, (grid.columns + 1) / 2, (grid.columns + 3) / 4})
  {
    if(groups < 2 || groups > k || options.back().groups == groups)
      continue;
    std::vector<std::size_t> column_group(grid.columns);
    if(groups < grid.columns)
      column_group = group_columns(grid, groups, policy);
    else
      std::iota(column_group.begin(), column_group.end(), std::size_t(0));
    options.push_back(run_option(grid, column_group, groups, policy));
  }
  for(std::size_t i = 1; i < options.size(); ++i)
    s.sets.push_back({&options[0], &options[i]});
  // All options together, unless that is the one set above.
  if(options.size() != 2)
  {
    s.sets.push_back({});
    for(const Run_option& o : options)
      s.sets.back().push_back(&o);
  }
}

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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_H
