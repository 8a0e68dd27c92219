// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H

/// \file write_tile_count_curve.h
/// The K / deviation curve (`k_set_tilable_curve()`, or the K tried by a
/// deviation search) as CSV, for a spreadsheet or `scripts/plot_curve.sh`.

#include <CGAL/Tilable_surfaces/internal/config.h>
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
CGAL_TILABLE_SURFACES_INLINE
bool write_tile_count_curve_CSV(std::ostream& os, const std::vector<Tile_count_trial>& trials);

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/write_tile_count_curve_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_TILE_COUNT_CURVE_H
