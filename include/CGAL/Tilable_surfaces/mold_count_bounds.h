// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MOLD_COUNT_BOUNDS_H
#define CGAL_TILABLE_SURFACES_MOLD_COUNT_BOUNDS_H

/// \file mold_count_bounds.h
/// How many molds a panel mesh needs before an exact result can stay near it:
/// the count below which a clustering needs structure, and the count that
/// sweeping every grid patch of its quad layout alone takes (user manual,
/// section "How many molds a mesh needs").

#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Mold counts of a panel mesh, from its connectivity alone (`mold_count_bounds()`).
struct Mold_count_bounds
{
  /// The smallest K at which a clustering without structure has as many
  /// unknowns as equations: a cluster of n quads asks 6(n - 1) equations and
  /// one of n triangles 3(n - 1), against the 3V - 6 coordinates of V
  /// vertices free up to a rigid motion. About half the quads of a closed
  /// mesh. Below it, an exact result near the input needs panels that repeat
  /// in the input, or a structure such as a sweep.
  std::size_t unstructured_molds = 0;
  /// The patches of the quad layout (grids of quads cut along the
  /// separatrices of irregular vertices and border corners) that are grids.
  std::size_t grid_patches = 0;
  /// The molds of a sweep of every grid patch alone, one per column of its
  /// shorter side, plus one per face outside the grid patches.
  std::size_t patch_sweep_molds = 0;
};

namespace internal {

// The smallest K whose clusters' equations (6 per extra quad, 3 per extra
// triangle) are at most the 3V - 6 free coordinates; molds go to quads first,
// each saving the most equations.
inline std::size_t unstructured_mold_count(std::size_t quads, std::size_t triangles, std::size_t vertices)
{
  const long long free_coordinates = 3 * (long long)vertices - 6;
  long long excess = 6 * (long long)quads + 3 * (long long)triangles - free_coordinates;
  if(excess <= 0) return (std::min)(std::size_t(1), quads + triangles);
  const long long quad_molds = (std::min)((long long)quads, (excess + 5) / 6);
  excess -= 6 * quad_molds;
  const long long triangle_molds = excess <= 0 ? 0 : (excess + 2) / 3;
  return std::size_t(quad_molds + (std::min)((long long)triangles, triangle_molds));
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The mold counts of `pm` (see `Mold_count_bounds`): where K lies below both,
/// an exact result is near the input only if its panels repeat (a symmetric
/// design), and otherwise is far from it, or is not found.
///
/// \tparam PolygonMesh a model of `FaceListGraph`, quads and triangles
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map} the property map with the points
///     associated to the vertices of `pm` \cgalParamNEnd
///   \cgalParamNBegin{face_index_map} a property map giving each face an index
///     in [0, `num_faces(pm)`) \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_input if `pm` is not a valid panel mesh (`validate_panel_mesh()`).
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Mold_count_bounds mold_count_bounds(const PolygonMesh& pm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  validate_panel_mesh(pm, np);
  std::size_t quads = 0, triangles = 0;
  for(auto f : faces(pm))
    (internal::face_corner_count(f, pm) == 4 ? quads : triangles) += 1;
  Mold_count_bounds bounds;
  bounds.unstructured_molds = internal::unstructured_mold_count(quads, triangles, num_vertices(pm));
  const internal::Quad_layout layout =
    internal::quad_layout(pm, CGAL::get_initialized_face_index_map(pm, np), internal::const_vertex_point_map(pm, np));
  const auto patches = internal::patch_faces(layout.patch_of_face);
  for(std::size_t p = 0; p < patches.size(); ++p)
  {
    const internal::Quad_grid& grid = layout.grids[p];
    if(grid.rows == 0)
      bounds.patch_sweep_molds += patches[p].size();
    else
    {
      ++bounds.grid_patches;
      bounds.patch_sweep_molds += (std::min)(grid.rows, grid.columns);
    }
  }
  return bounds;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_MOLD_COUNT_BOUNDS_H
