// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_IMPL_H

// The bodies of the non-template functions declared in strip_candidates.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
void split_to(std::size_t k, const std::vector<Panel>& quads,
              const std::vector<Quad_descriptor>& descriptors, Orientation_policy policy,
              CGAL::Random& random, Initial_clustering& init)
{
  while(init.leaders.size() < k)
  {
    std::vector<std::vector<std::size_t> > members =
      cluster_members(init.cluster, init.leaders.size());
    std::size_t largest = 0;
    for(std::size_t c = 1; c < members.size(); ++c)
      if(members[c].size() > members[largest].size()) largest = c;
    const std::vector<bool> second =
      split_in_two(quads, descriptors, members[largest], policy, random);
    const std::size_t c = init.leaders.size();
    std::size_t leader = no_index();
    for(std::size_t i = 0; i < second.size(); ++i)
    {
      if(!second[i]) continue;
      const std::size_t f = members[largest][i];
      if(leader == no_index()) leader = f;
      init.cluster[f] = c;
      init.orientation[f] = fast_best_match(quads[leader], quads[f], policy).orientation;
    }
    init.leaders.push_back(leader);
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_IMPL_H
