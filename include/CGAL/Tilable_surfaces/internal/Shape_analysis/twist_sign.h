// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_TWIST_SIGN_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_TWIST_SIGN_H

// When quads twist both ways: the one rule of the clusterings that keep the
// sign of the twist (twist_separation.h, patch_candidates.h). Quads twisted
// both ways become congruent only by flattening them.

#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <cmath>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The least twist that counts as a sign beside twists up to `largest` in
// magnitude: tuning::twist_sign_fraction of it, and at least the twist of a
// quad planar as far as its mold is concerned, `planar`
// (tuning::planar_twist for relative twists, relative_twist(); that times
// the cube of the mean edge for 6 x signed volumes).
inline double significant_twist(double largest, double planar = tuning::planar_twist)
{
  return (std::max)(planar, tuning::twist_sign_fraction * largest);
}

// Whether twists `a` and `b` have opposite signs, both significant beside
// the larger magnitude.
inline bool twists_oppose(double a, double b, double planar = tuning::planar_twist)
{
  const double significant = significant_twist((std::max)(std::abs(a), std::abs(b)), planar);
  return (a > significant && b < -significant) || (a < -significant && b > significant);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_TWIST_SIGN_H
