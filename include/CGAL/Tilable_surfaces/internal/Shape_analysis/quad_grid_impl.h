// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_IMPL_H

// The bodies of the non-template functions declared in quad_grid.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::size_t relabel_by_first_face(std::vector<std::size_t>& label)
{
  std::vector<std::size_t> id;
  std::size_t next = 0;
  for(std::size_t& l : label)
  {
    if(l >= id.size()) id.resize(l + 1, no_index());
    if(id[l] == no_index()) id[l] = next++;
    l = id[l];
  }
  return next;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_IMPL_H
