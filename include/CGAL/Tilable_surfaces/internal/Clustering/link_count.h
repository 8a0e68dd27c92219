// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H

// How many components a few new links of the edge-sharing graph join.

#include <CGAL/Tilable_surfaces/internal/Union_find.h>

#include <array>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The number of unions that the first `count` (at most 4) links between
// component ids perform, i.e. by how much they lower the number of
// components.
inline std::size_t number_of_joins(const std::array<std::pair<std::size_t, std::size_t>, 4>& links,
                                   std::size_t count)
{
  Small_union_find<8> components;
  std::size_t joins = 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    const std::size_t a = components.slot(links[i].first).first, b = components.slot(links[i].second).first;
    if(components.sets().unite(a, b))
      ++joins;
  }
  return joins;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H
