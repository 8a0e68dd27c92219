// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_IMPL_H

// The bodies of the non-template functions declared in Solver_settings.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
int number_free_unknowns(const std::vector<bool>& fixed, std::vector<int>& variable)
{
  variable.assign(fixed.size(), -1);
  int n = 0;
  for(std::size_t v = 0; v < fixed.size(); ++v)
    if(!fixed[v])
    {
      variable[v] = n;
      n += 3;
    }
  return n;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_IMPL_H
