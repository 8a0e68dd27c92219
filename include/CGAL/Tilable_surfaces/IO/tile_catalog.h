// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H
#define CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H

/// \file tile_catalog.h
/// The tile catalog a fabricator cuts from: one row per S-quad with its
/// corners in a canonical frame, its lengths, volume, planarity, instance
/// count and the worst deviation of an instance, all in the mesh's units.
/// CSV, or JSON (with nlohmann::json, Debian's `nlohmann-json3-dev`).

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
inline bool has_flat_mold(const Tile& t, const std::array<double, 4>& edges)
{
  const double d = diagonal_distance(t.corners);
  if(t.panel_tolerance > 0)
    return t.worst_deviation + d / 2 <= t.panel_tolerance;
  const double mean_edge = (edges[0] + edges[1] + edges[2] + edges[3]) / double(t.corners.size());
  return d <= defaults::congruence_tolerance * mean_edge;
}

inline Tile_row tile_row(const Tile& t)
{
  const std::array<double, 4> edges = edge_lengths(t.corners);
  return Tile_row{edges, diagonal_lengths(t.corners), Tilable_surfaces::signed_volume(t.corners),
                  planarity_defect(t.corners), has_flat_mold(t, edges)};
}

// Refuses a catalog with a non-finite number, before anything is written.
inline void check_tiles(const std::vector<Tile>& tiles)
{
  for(std::size_t i = 0; i < tiles.size(); ++i)
  {
    bool finite = std::isfinite(tiles[i].worst_deviation);
    for(const Eigen::Vector3d& p : tiles[i].corners) finite = finite && p.allFinite();
    if(!finite)
      throw Invalid_input("tile " + std::to_string(i) + " (id " + std::to_string(tiles[i].id) +
                          ") has a non-finite corner or deviation", Invalid_input::PARAMETER, i);
  }
}

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
inline bool write_tile_catalog_CSV(std::ostream& os, const std::vector<Tile>& tiles)
{
  internal::check_tiles(tiles);
  os << "id,instances,mirrored,t0x,t0y,t0z,t1x,t1y,t1z,t2x,t2y,t2z,t3x,t3y,t3z,"
        "e01,e12,e23,e30,d02,d13,signed_volume,planarity,planar,worst_deviation,kind,mold\n";
  os << std::setprecision(std::numeric_limits<double>::max_digits10);
  for(const Tile& t : tiles)
  {
    const internal::Tile_row r = internal::tile_row(t);
    os << t.id << ',' << t.instance_count << ',' << t.mirrored_count;
    const bool triangle = t.corners.is_triangle();
    for(const Eigen::Vector3d& p : t.corners)
      os << ',' << p.x() << ',' << p.y() << ',' << p.z();
    if(triangle) os << ",,,";
    for(int k = 0; k < 4; ++k)
    {
      os << ',';
      if(k < t.corners.size()) os << r.edges[std::size_t(k)];
    }
    for(double d : r.diagonals)
    {
      os << ',';
      if(!triangle) os << d;
    }
    os << ',' << r.signed_volume << ',' << r.planarity << ',' << (r.is_planar ? 1 : 0) << ','
       << t.worst_deviation << ',' << (triangle ? "triangle" : "quad") << ',' << t.mold << '\n';
  }
  return bool(os);
}

/// \ingroup PkgTilableSurfacesRef
/// The catalog as a JSON array, one object per tile with the fields of
/// `write_tile_catalog_CSV()` (`corners` as 4 arrays of 3 numbers, 3 for an
/// S-triangle, `edges` and `diagonals` as arrays, an S-triangle's 3 edges and
/// no diagonal).
/// \throws Invalid_input if a tile has a non-finite number.
inline nlohmann::json tile_catalog_json(const std::vector<Tile>& tiles)
{
  internal::check_tiles(tiles);
  nlohmann::json catalog = nlohmann::json::array();
  for(const Tile& t : tiles)
  {
    const internal::Tile_row r = internal::tile_row(t);
    nlohmann::json corners = nlohmann::json::array();
    for(const Eigen::Vector3d& p : t.corners)
      corners.push_back({p.x(), p.y(), p.z()});
    catalog.push_back({{"id", t.id},
                       {"instances", t.instance_count},
                       {"mirrored", t.mirrored_count},
                       {"mold", t.mold},
                       {"kind", t.corners.is_triangle() ? "triangle" : "quad"},
                       {"corners", corners},
                       {"edges", std::vector<double>(r.edges.begin(), r.edges.begin() + t.corners.size())},
                       {"diagonals", t.corners.is_triangle() ? std::vector<double>()
                                                             : std::vector<double>(r.diagonals.begin(), r.diagonals.end())},
                       {"signed_volume", r.signed_volume},
                       {"planarity", r.planarity},
                       {"planar", r.is_planar},
                       {"worst_deviation", t.worst_deviation},
                       {"panel_tolerance", t.panel_tolerance},
                       {"instance_faces", t.instance_faces},
                       {"instance_deviations", t.instance_deviations}});
  }
  return catalog;
}

/// \ingroup PkgTilableSurfacesRef
/// Writes `tile_catalog_json(tiles)` to `os`, indented.
inline bool write_tile_catalog_JSON(std::ostream& os, const std::vector<Tile>& tiles)
{
  os << std::setw(2) << tile_catalog_json(tiles) << '\n';
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_H
