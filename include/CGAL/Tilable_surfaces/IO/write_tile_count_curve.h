// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H

/// \file write_tile_count_curve.h
/// The K / deviation curve (`k_set_tilable_curve()`, or the K tried by a
/// deviation search) as CSV, for a spreadsheet or `scripts/plot_curve.sh`.

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <iomanip>
#include <limits>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// Writes one row per trial, in the given order, under the header line
/// `K,DOF,congruence_error,hausdorff_distance,max_displacement,seconds,tilable,crossing_face_pairs,refined_from`:
/// the congruence error relative to the result's mean edge length, the
/// symmetric Hausdorff distance relative to the input's bounding-box
/// diagonal, the displacement in mesh units, `tilable` 1 or 0, the pairs
/// of panels of the result that cross each other, and the smaller K whose
/// refined result this is (`Tile_count_trial::refined_from`, 0 if none).
inline bool write_tile_count_curve_CSV(std::ostream& os, const std::vector<Tile_count_trial>& trials)
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

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H
