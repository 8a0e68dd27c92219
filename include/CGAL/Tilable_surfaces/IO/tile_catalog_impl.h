// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_IMPL_H

// The bodies of the non-template functions declared in tile_catalog.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
bool has_flat_mold(const Tile& t, const std::array<double, 4>& edges)
{
  const double d = diagonal_distance(t.corners);
  if(t.panel_tolerance > 0)
    return t.worst_deviation + d / 2 <= t.panel_tolerance;
  const double mean_edge = (edges[0] + edges[1] + edges[2] + edges[3]) / double(t.corners.size());
  return d <= defaults::congruence_tolerance * mean_edge;
}

CGAL_TILABLE_SURFACES_INLINE
void check_tiles(const std::vector<Tile>& tiles)
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

CGAL_TILABLE_SURFACES_INLINE
bool write_tile_catalog_CSV(std::ostream& os, const std::vector<Tile>& tiles)
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

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tile_catalog_json(const std::vector<Tile>& tiles)
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

CGAL_TILABLE_SURFACES_INLINE
bool write_tile_catalog_JSON(std::ostream& os, const std::vector<Tile>& tiles)
{
  os << std::setw(2) << tile_catalog_json(tiles) << '\n';
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_TILE_CATALOG_IMPL_H
