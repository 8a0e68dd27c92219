// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_IMPL_H

// The bodies of the non-template functions declared in tolerance_candidates.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/tolerance_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> tolerance_groups(const std::vector<Panel>& panels,
                                          const std::vector<Quad_descriptor>& descriptors,
                                          double tolerance, Orientation_policy policy, std::size_t k)
{
  Initial_clustering groups;
  if(!leader_clustering(panels, descriptors, Descriptor_index(descriptors), 0.5 * tolerance, policy, k, groups))
    return {};
  std::vector<std::vector<std::size_t>> members(groups.leaders.size());
  for(std::size_t f = 0; f < panels.size(); ++f) members[groups.cluster[f]].push_back(f);
  while(members.size() < k)
  {
    // The largest group (the first of equal size), halved in face order.
    auto largest = std::max_element(members.begin(), members.end(),
                                    [](const auto& a, const auto& b) { return a.size() < b.size(); });
    const std::size_t half = largest->size() / 2;
    std::vector<std::size_t> second(largest->begin() + std::ptrdiff_t(half), largest->end());
    largest->resize(half);
    members.push_back(std::move(second));
  }
  std::vector<std::size_t> label(panels.size());
  for(std::size_t c = 0; c < members.size(); ++c)
    for(std::size_t f : members[c]) label[f] = c;
  return label;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_IMPL_H
