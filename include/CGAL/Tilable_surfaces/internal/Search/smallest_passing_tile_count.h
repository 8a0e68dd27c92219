// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_SMALLEST_PASSING_TILE_COUNT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_SMALLEST_PASSING_TILE_COUNT_H

// The search of a deviation budget over K, apart from what a trial costs:
// each trial is a whole clustering and optimization, so K is galloped from a
// first guess, then bisected, and no K is tried twice.

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The smallest K in [k_min, k_max] (k_min >= 1: a mesh of quads and
// triangles needs 2 tiles) for which `passes(K)` holds, if passing is
// monotone in K (more molds, closer surface): halving down from `k_first`
// while it passes, or doubling up while it fails, then bisecting. Whatever
// `passes` does, the K returned passed and K - 1 was tried and failed (or
// K = k_min). Returns k_max + 1 if k_max fails.
template <typename Passes>
std::size_t smallest_passing_tile_count(std::size_t k_first, std::size_t k_min, std::size_t k_max,
                                        Passes passes)
{
  k_min = (std::max)(k_min, std::size_t(1));
  if(k_max < k_min)
    return k_min;
  std::size_t failed = k_min - 1;  // the largest K tried that failed, k_min - 1 if none
  std::size_t passed = k_max + 1;  // the smallest K tried that passed
  const std::size_t first = (std::min)((std::max)(k_first, k_min), k_max);
  if(passes(first))
  {
    passed = first;
    while(passed > k_min && failed == k_min - 1)
    {
      const std::size_t k = (std::max)(passed / 2, k_min);
      if(passes(k))
        passed = k;
      else
        failed = k;
    }
  }
  else
  {
    failed = first;
    while(passed == k_max + 1 && failed < k_max)
    {
      const std::size_t k = (std::min)(k_max, 2 * failed);
      if(passes(k))
        passed = k;
      else
        failed = k;
    }
  }
  while(passed <= k_max && passed - failed > 1)
  {
    const std::size_t k = failed + (passed - failed) / 2;
    if(passes(k))
      passed = k;
    else
      failed = k;
  }
  return passed;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_SMALLEST_PASSING_TILE_COUNT_H
