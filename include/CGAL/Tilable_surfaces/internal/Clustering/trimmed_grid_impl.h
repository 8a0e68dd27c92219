// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_IMPL_H

// The bodies of the non-template functions declared in trimmed_grid.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/trimmed_grid.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
void lattice_bounds(const std::vector<std::array<long, 2> >& cell, long low[2], long high[2])
{
  low[0] = high[0] = cell[0][0];
  low[1] = high[1] = cell[0][1];
  for(const std::array<long, 2>& c : cell)
    for(int d = 0; d < 2; ++d)
    {
      low[d] = (std::min)(low[d], c[std::size_t(d)]);
      high[d] = (std::max)(high[d], c[std::size_t(d)]);
    }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_IMPL_H
