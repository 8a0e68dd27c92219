// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_IMPL_H

// The bodies of the non-template functions declared in segment_candidates.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix<double, 6, 1> corner_distances(const Panel& q)
{
  Eigen::Matrix<double, 6, 1> d;
  d << (q[1] - q[0]).norm(), (q[2] - q[1]).norm(), (q[3] - q[2]).norm(), (q[0] - q[3]).norm(),
       (q[2] - q[0]).norm(), (q[3] - q[1]).norm();
  return d;
}

CGAL_TILABLE_SURFACES_INLINE
Run_option run_option(const Quad_grid& grid, const std::vector<std::size_t>& column_group,
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

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix<double, 6, 1> reoriented(const Eigen::Matrix<double, 6, 1>& d, Panel_orientation o)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> group_columns(const Quad_grid& grid, std::size_t groups,
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> best_runs(const Quad_grid& grid,
                                   const std::vector<const Run_option*>& options, std::size_t k,
                                   bool segments_may_touch)
{
  return Run_partitions(grid, options, k, segments_may_touch).label(k);
}

CGAL_TILABLE_SURFACES_INLINE
void add_run_options(Segment_options& s, std::size_t k, Orientation_policy policy)
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

CGAL_TILABLE_SURFACES_INLINE
Run_partitions::Run_partitions(const Quad_grid& grid, const std::vector<const Run_option*>& options, std::size_t k,
               bool segments_may_touch)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> Run_partitions::label(std::size_t m) const
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

CGAL_TILABLE_SURFACES_INLINE
double Run_option::cost(std::size_t a, std::size_t b) const
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_SEGMENT_CANDIDATES_IMPL_H
