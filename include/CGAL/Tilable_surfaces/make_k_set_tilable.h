// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
#define CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H

/// \file make_k_set_tilable.h
/// The one-call function: validate, cluster, optimize, measure; at a given K,
/// or at the smallest K within a deviation budget.

#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/K_set_tilable_surface.h>
#include <CGAL/Tilable_surfaces/internal/Search/tile_count_search.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/panel_tolerance.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Turns the quad mesh `pm` into a K-set tilable surface: checks it, clusters
/// its faces into K S-quads (`cluster_panels()`), moves its vertices so that
/// every face is congruent to its S-quad while the surface stays as close to
/// the input as it can (`optimize_tilable_surface()`), and measures the
/// result against the input (`measure_tilability()`).
///
/// Every named parameter of `cluster_panels()` and of
/// `optimize_tilable_surface()` is accepted and passed on; the two maps are
/// outputs here. Whether the result is exactly tilable is measured, not
/// assumed: see `K_set_tilable_result::is_tilable()`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_tiles} K; required unless `max_deviation` is
///     given, and then the largest K tried (default: the number of faces). \cgalParamNEnd
///   \cgalParamNBegin{max_deviation} a deviation budget instead of K: the
///     largest symmetric Hausdorff distance to the input allowed, as a
///     fraction of its bounding-box diagonal (`Tilability_measure::hausdorff_distance`).
///     K is then the smallest whose result is tilable within it and does not
///     cross itself (`Tilability_measure::self_intersecting_face_pairs`): galloped
///     from max(2, faces / 25) by halving or doubling, then bisected, each
///     K run once through the whole pipeline on the object validated once
///     (`K_set_tilable_result::trials`), and refined from the best result
///     of fewer clusters tried when that is better, as in
///     `k_set_tilable_curve()`. The K returned met the budget and
///     K - 1 was tried and missed it (or K = 1); a smaller K may still meet
///     it where the deviation is not monotone in K. If no K up to the
///     largest does, the result is that of the largest K tried. A visitor
///     that stops a solve ends the search. \cgalParamNEnd
///   \cgalParamNBegin{panel_tolerance} T in model units (default 0, exact
///     mode): every instance within T of its mold suffices (see
///     `optimize_tilable_surface()`); the clustering also offers the panels
///     that already fit one mold within T grouped, and with `max_deviation`
///     K is the smallest that meets both. \cgalParamNEnd
///   \cgalParamNBegin{face_cluster_map} optional output: cluster id 0..K-1 of
///     every face. \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} optional output: orientation 0..7 of
///     every face relative to its S-quad (user manual, section Definitions). \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm`; moved. \cgalParamNEnd
///   \cgalParamNBegin{visitor} a `Default_visitor` (or a class with its
///     interface), by value or as `std::ref`: every stage calls the same object. \cgalParamNEnd
///   \cgalParamNBegin{...} the parameters of `cluster_panels()` and
///     `optimize_tilable_surface()`. \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (default), `CGAL::Parallel_tag`
///   or `CGAL::Parallel_if_available_tag`: whether the steps may use several
///   threads (TBB), as in Polygon_mesh_processing. The result is the same.
///
/// \throws Invalid_input if `pm` or a parameter cannot be processed; `pm` and
/// the maps are untouched then.
template <typename ConcurrencyTag = CGAL::Sequential_tag, class PolygonMesh,
          typename CGAL_NP_TEMPLATE_PARAMETERS>
K_set_tilable_result make_k_set_tilable(PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::type Vertex_point_map;
  internal::panel_tolerance_of(np); // refused before anything is done
  auto&& user_visitor = internal::visitor_of(np);
  internal::Visitor_ref visitor(user_visitor);
  const auto cnp = internal::canonical_inputs(internal::with_visitor(np, visitor));

  K_set_tilable_result result;
  CGAL::Real_timer total;
  total.start();
  const Vertex_point_map surface_vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                        get_property_map(CGAL::vertex_point, pm));
  K_set_tilable_surface<ConcurrencyTag, PolygonMesh, Vertex_point_map> surface(pm, surface_vpm);
  const double validation_time = total.time();
  visitor.phase("validation", validation_time);

  if constexpr(!parameters::is_default_parameter<CGAL_NP_CLASS, internal_np::max_deviation_t>::value)
  {
    result = internal::search_tile_count(pm, surface, surface_vpm, cnp, np, visitor);
    result.validation_time = validation_time;
  }
  else
  {
    result.validation_time = validation_time;
    internal::cluster_and_optimize(surface, cnp, visitor, result);
    internal::copy_face_output(pm, get_parameter(np, internal_np::face_cluster), surface.face_cluster_map());
    internal::copy_face_output(pm, get_parameter(np, internal_np::face_orientation),
                               surface.face_orientation_map());
  }
  result.total_time = total.time();
  return result;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#ifdef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Search/compiled_pipeline.h>
#endif

#endif // CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
