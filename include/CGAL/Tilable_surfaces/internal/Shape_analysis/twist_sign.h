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

// The least relative twist (relative_twist()) that counts as a sign beside
// twists up to `largest` in magnitude: tuning::twist_sign_fraction of it,
// and at least the planar level tuning::planar_twist.
inline double significant_twist(double largest)
{
  return (std::max)(tuning::planar_twist, tuning::twist_sign_fraction * largest);
}

// Whether relative twists `a` and `b` have opposite signs, both significant
// beside the larger magnitude.
inline bool twists_oppose(double a, double b)
{
  const double significant = significant_twist((std::max)(std::abs(a), std::abs(b)));
  return (a > significant && b < -significant) || (a < -significant && b > significant);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_TWIST_SIGN_H
