// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_IMPL_H

// The bodies of the non-template functions declared in multilevel_start.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Search/multilevel_start.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
void split_in_halves_to(Face_clustering& fc, std::size_t k)
{
  while(fc.number_of_clusters < k)
  {
    std::vector<std::vector<std::size_t> > members = cluster_members(fc.label, fc.number_of_clusters);
    auto largest = std::max_element(members.begin(), members.end(), [](const auto& a, const auto& b) {
      return a.size() < b.size();
    });
    if(largest->size() < 2)
      return;
    for(std::size_t i = largest->size() / 2; i < largest->size(); ++i)
      fc.label[(*largest)[i]] = fc.number_of_clusters;
    ++fc.number_of_clusters;
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_IMPL_H
