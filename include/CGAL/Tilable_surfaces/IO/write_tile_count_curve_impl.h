// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_IMPL_H

// The bodies of the non-template functions declared in write_tile_count_curve.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/write_tile_count_curve.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

CGAL_TILABLE_SURFACES_INLINE
bool write_tile_count_curve_CSV(std::ostream& os, const std::vector<Tile_count_trial>& trials)
{
  os << "K,DOF,congruence_error,hausdorff_distance,max_displacement,seconds,tilable,crossing_face_pairs,"
        "refined_from\n";
  os << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(const Tile_count_trial& t : trials)
    os << t.number_of_tiles << ',' << t.degree_of_flexibility << ',' << t.congruence_error << ','
       << t.hausdorff_distance << ',' << t.max_displacement << ',' << t.seconds << ','
       << (t.is_tilable ? 1 : 0) << ',' << t.self_intersecting_face_pairs << ',' << t.refined_from << '\n';
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_IMPL_H
