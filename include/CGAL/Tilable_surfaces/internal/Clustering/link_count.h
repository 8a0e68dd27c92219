// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H

// How many components a few new links of the edge-sharing graph join.

#include <array>
#include <cstddef>
#include <utility>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The number of unions that the first `count` (at most 4) links between
// component ids perform, i.e. by how much they lower the number of
// components. At most 8 ids take part, so a union-find over linear scans is
// the cheapest structure.
inline std::size_t number_of_joins(const std::array<std::pair<std::size_t, std::size_t>, 4>& links,
                                   std::size_t count)
{
  std::array<std::size_t, 8> id, up;
  std::size_t n = 0;
  auto local = [&](std::size_t c) {
    for(std::size_t i = 0; i < n; ++i) if(id[i] == c) return i;
    id[n] = c; up[n] = n; return n++;
  };
  auto root = [&](std::size_t i) { while(up[i] != i) i = up[i]; return i; };
  std::size_t joins = 0;
  for(std::size_t i = 0; i < count; ++i)
  {
    const std::size_t a = root(local(links[i].first)), b = root(local(links[i].second));
    if(a != b) { up[b] = a; ++joins; }
  }
  return joins;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_LINK_COUNT_H
