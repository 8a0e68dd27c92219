// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H
#define CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H

/// \file tile_catalog.h
/// The tile catalog a fabricator cuts from: one row per S-quad with its
/// corners in a canonical frame, its lengths, volume, planarity, instance
/// count and the worst deviation of an instance, all in the mesh's units.
/// CSV, or JSON (with nlohmann::json, Debian's `nlohmann-json3-dev`).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/measure.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

namespace internal {

// The derived quantities of a tile, shared by both formats so they agree.
struct Tile_row
{
  std::array<double, 4> edges;
  std::array<double, 2> diagonals;
  double signed_volume;
  double planarity;
  bool is_planar; // has_flat_mold()
};

// Whether the tile can be cut from a flat mold. Exact mode (no panel
// tolerance): its diagonals lie within the default congruence tolerance of
// its mean edge of each other. With a panel tolerance T: every instance lies
// within T of a flat mold. Moving the two diagonals half their distance d
// toward each other flattens the S-quad with no corner moving more than d / 2,
// so an instance within `worst_deviation` of the S-quad is within
// `worst_deviation` + d / 2 of that flat mold.
CGAL_TILABLE_SURFACES_INLINE
bool has_flat_mold(const Tile& t, const std::array<double, 4>& edges);

inline Tile_row tile_row(const Tile& t)
{
  const std::array<double, 4> edges = edge_lengths(t.corners);
  return Tile_row{edges, diagonal_lengths(t.corners), Tilable_surfaces::signed_volume(t.corners),
                  planarity_defect(t.corners), has_flat_mold(t, edges)};
}

// Refuses a catalog with a non-finite number, before anything is written.
CGAL_TILABLE_SURFACES_INLINE
void check_tiles(const std::vector<Tile>& tiles);

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Writes the catalog as CSV with a header line: `id, instances, mirrored`
/// (instances cut from the mirrored mold), the 12
/// corner coordinates `t0x ... t3z`, the edge lengths `e01, e12, e23, e30`,
/// the diagonals `d02, d13`, `signed_volume`, `planarity` (distance of t3 to
/// the plane of t0, t1, t2), `planar` (1 if the tile can be cut from a flat
/// mold: its diagonals within 1e-6 of its mean edge length of each other, or
/// with a panel tolerance T (`Tile::panel_tolerance`), `worst_deviation` plus
/// half the distance between the diagonals at most T, so that every instance
/// is within T of the S-quad flattened by that half) and
/// `worst_deviation`, then `kind` (`quad` or `triangle`) and `mold` (tiles
/// whose S-quads are congruent share one, `Tile::mold`). An S-triangle's
/// row leaves `t3x, t3y, t3z`, `e30`, `d02` and `d13` empty, and its `e23`
/// is the edge t2t0. Full double precision.
/// \throws Invalid_input if a tile has a non-finite number; nothing is
/// written then.
CGAL_TILABLE_SURFACES_INLINE
bool write_tile_catalog_CSV(std::ostream& os, const std::vector<Tile>& tiles);

/// \ingroup PkgTilableSurfacesRef
/// The catalog as a JSON array, one object per tile with the fields of
/// `write_tile_catalog_CSV()` (`corners` as 4 arrays of 3 numbers, 3 for an
/// S-triangle, `edges` and `diagonals` as arrays, an S-triangle's 3 edges and
/// no diagonal).
/// \throws Invalid_input if a tile has a non-finite number.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tile_catalog_json(const std::vector<Tile>& tiles);

/// \ingroup PkgTilableSurfacesRef
/// Writes `tile_catalog_json(tiles)` to `os`, indented.
CGAL_TILABLE_SURFACES_INLINE
bool write_tile_catalog_JSON(std::ostream& os, const std::vector<Tile>& tiles);

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/tile_catalog_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H
