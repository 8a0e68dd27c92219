// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_IMPL_H

// The bodies of the non-template functions declared in tile_count_search.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Search/tile_count_search.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Tile_count_trial tile_count_trial(const K_set_tilable_result& r, double seconds)
{
  const Tilability_measure& m = r.optimization.measure;
  Tile_count_trial t;
  t.number_of_tiles = m.number_of_clusters;
  t.degree_of_flexibility = m.degree_of_flexibility;
  t.congruence_error = m.congruence_error;
  t.hausdorff_distance = m.hausdorff_distance;
  t.max_displacement = m.max_displacement;
  t.seconds = seconds;
  t.is_tilable = r.is_tilable();
  t.self_intersecting_face_pairs = m.self_intersecting_face_pairs;
  return t;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_IMPL_H
