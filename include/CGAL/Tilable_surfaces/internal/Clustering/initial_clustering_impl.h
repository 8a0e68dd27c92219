// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_IMPL_H

// The bodies of the non-template functions declared in initial_clustering.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
bool leader_clustering(const std::vector<Panel>& quads,
                       const std::vector<Quad_descriptor>& descriptors,
                       const Descriptor_index& index, double tau,
                       Orientation_policy policy, std::size_t max_clusters,
                       Initial_clustering& out)
{
  const std::size_t n = quads.size();
  out.cluster.assign(n, no_index());
  out.orientation.assign(n, Panel_orientation());
  out.leaders.clear();
  std::vector<std::size_t> candidates;
  std::vector<Quad_match> matches;
  for(std::size_t leader = 0; leader < n; ++leader)
  {
    if(out.cluster[leader] != no_index())
      continue;
    if(out.leaders.size() == max_clusters)
      return false;
    const std::size_t c = out.leaders.size();
    out.leaders.push_back(leader);
    out.cluster[leader] = c;

    candidates.clear();
    for(std::size_t q : index.in_box(descriptors[leader], tau))
      if(out.cluster[q] == no_index())
        candidates.push_back(q);
    matches.resize(candidates.size());
    parallel_for(candidates.size(), [&](std::size_t i) {
      matches[i] = fast_best_match(quads[leader], quads[candidates[i]], policy);
    });
    for(std::size_t i = 0; i < candidates.size(); ++i)
      if(matches[i].dissimilarity < tau)
      {
        out.cluster[candidates[i]] = c;
        out.orientation[candidates[i]] = matches[i].orientation;
      }
  }
  return true;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_IMPL_H
