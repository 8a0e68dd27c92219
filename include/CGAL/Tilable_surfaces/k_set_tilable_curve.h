// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_K_SET_TILABLE_CURVE_H
#define CGAL_TILABLE_SURFACES_K_SET_TILABLE_CURVE_H

/// \file k_set_tilable_curve.h
/// What each extra mold buys: the pipeline of `make_k_set_tilable()` at a
/// range of K, one `Tile_count_trial` per K.

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Runs the clustering and optimization of `make_k_set_tilable()` at every K
/// of `tile_counts`, in that order, on `pm` checked once, and returns what
/// each K gave: DOF, congruence, Hausdorff distance to the input,
/// displacement and time. `pm` keeps its input positions.
///
/// More molds never end farther than fewer: when the best result of fewer
/// clusters so far (tilable and not crossing itself, then closest to the
/// input) is better than a K's own, it is refined to that K
/// (`K_set_tilable_surface::refine_to()`: its largest clusters split, an
/// exact result stays exact, then solved closer to the input),
/// and the better of the two is that K's result
/// (`Tile_count_trial::refined_from`). Measured: the monkey saddle at K = 14
/// to 21 gave 22.9% to 31.6% of the diagonal on its own, and K = 13 5.1%.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{...} the parameters of `make_k_set_tilable()` except
///     `number_of_tiles`, `max_deviation` and the output maps. \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \tparam ConcurrencyTag as for `make_k_set_tilable()`.
///
/// \throws Invalid_input if `pm` is not a valid quad mesh, or a K is 0 or
/// more than the number of faces; `pm` is untouched then.
template <typename ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
std::vector<Tile_count_trial> k_set_tilable_curve(PolygonMesh& pm,
                                                  const std::vector<std::size_t>& tile_counts,
                                                  const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::type Vertex_point_map;
  internal::panel_tolerance_of(np); // refused before anything is done
  auto&& user_visitor = internal::visitor_of(np);
  internal::Visitor_ref visitor(user_visitor);
  const auto cnp = internal::canonical_inputs(internal::with_visitor(np, visitor));

  for(std::size_t k : tile_counts)
    if(k < 1 || k > num_faces(pm))
      throw Invalid_input("K = " + std::to_string(k) + " is out of range: the mesh has " +
                          std::to_string(num_faces(pm)) + " faces", Invalid_input::PARAMETER);
  const Vertex_point_map vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                get_property_map(CGAL::vertex_point, pm));
  K_set_tilable_surface<ConcurrencyTag, PolygonMesh, Vertex_point_map> surface(pm, vpm);

  typedef typename boost::property_traits<Vertex_point_map>::value_type Point;
  const auto fim = CGAL::get_initialized_face_index_map(pm);
  internal::Refinement_sources<Point> sources;
  std::vector<Tile_count_trial> trials;
  for(std::size_t k : tile_counts)
  {
    bool stopped = false;
    const internal::Kept_result<Point> r =
      internal::result_at(k, surface, pm, vpm, fim, sources, cnp, visitor, stopped);
    trials.push_back(r.trial);
    sources.offer(r);
    if(stopped)
      break;
  }
  surface.restore_input();
  return trials;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#ifdef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Search/compiled_pipeline.h>
#endif

#endif // CGAL_TILABLE_SURFACES_K_SET_TILABLE_CURVE_H
