// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_PANEL_TOLERANCE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_PANEL_TOLERANCE_H

// The named parameter `panel_tolerance` (user manual, section "Within a
// panel tolerance"): T in model units, every instance within T of its mold
// (largest corner distance after the best rigid fit). 0 is the exact mode.
// Read and checked here only, so that every entry point refuses a bad T with
// the same message before it touches the mesh.

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>

#include <cmath>
#include <sstream>
#include <string>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Throws Invalid_input naming the parameter unless `t` is finite and >= 0.
inline double checked_panel_tolerance(double t)
{
  if(!(std::isfinite(t) && t >= 0))
  {
    std::ostringstream text;
    text << "invalid parameter: panel_tolerance is " << t
         << ", it must be a finite length >= 0 in model units (0: exact congruence)";
    throw Invalid_input(text.str(), Invalid_input::PARAMETER);
  }
  return t;
}

template <typename NamedParameters>
double panel_tolerance_of(const NamedParameters& np)
{
  return checked_panel_tolerance(
    parameter_or(np, CGAL::Tilable_surfaces::internal_np::panel_tolerance, defaults::panel_tolerance));
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_PANEL_TOLERANCE_H
