// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_IMPL_H

// The bodies of the non-template functions declared in cluster_analysis.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Cluster_shapes cluster_shapes(const std::vector<Panel>& quads,
                              const std::vector<std::size_t>& label, std::size_t k,
                              Orientation_policy policy)
{
  Cluster_shapes r;
  const std::vector<std::vector<std::size_t> > members = cluster_members(label, k);
  r.s_quads.resize(k);
  for(std::size_t c = 0; c < k; ++c)
    r.s_quads[c] = procrustes_mean(quads, members[c], policy);
  r.orientation.resize(quads.size());
  r.distance.resize(quads.size());
  parallel_for(quads.size(), [&](std::size_t f) {
    const Quad_match m = fast_best_match(r.s_quads[label[f]], quads[f], policy);
    r.orientation[f] = m.orientation;
    r.distance[f] = m.dissimilarity;
  });
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<bool> split_in_two(const std::vector<Panel>& quads,
                               const std::vector<Quad_descriptor>& descriptors,
                               const std::vector<std::size_t>& members,
                               Orientation_policy policy, CGAL::Random& random)
{
  const std::size_t m = members.size();
  std::vector<bool> second(m, false);
  const std::vector<std::size_t> two = kmeans(descriptors, members, 2, random);
  if(two.empty())
  {
    for(std::size_t i = m / 2; i < m; ++i) second[i] = true;
    return second;
  }
  for(std::size_t i = 0; i < m; ++i) second[i] = (two[i] != two[0]);

  for(int round = 0; round < 2; ++round)
  {
    std::vector<std::size_t> part[2];
    for(std::size_t i = 0; i < m; ++i) part[second[i] ? 1 : 0].push_back(members[i]);
    const Panel t0 = procrustes_mean(quads, part[0], policy);
    const Panel t1 = procrustes_mean(quads, part[1], policy);
    std::vector<bool> next(m);
    std::vector<char> to_second(m);
    parallel_for(m, [&](std::size_t i) {
      to_second[i] = fast_best_match(t1, quads[members[i]], policy).dissimilarity <
                     fast_best_match(t0, quads[members[i]], policy).dissimilarity;
    });
    std::size_t count = 0;
    for(std::size_t i = 0; i < m; ++i)
    {
      next[i] = (to_second[i] != 0) != (to_second[0] != 0);
      count += next[i];
    }
    if(count == 0 || count == m || next == second)
      break;
    second.swap(next);
  }
  return second;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_IMPL_H
