// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
#define CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H

/// \file make_k_set_tilable.h
/// The one-call function: validate, cluster, optimize, measure.

#include <CGAL/Tilable_surfaces/K_set_tilable_surface.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// What `make_k_set_tilable()` did and measured.
struct K_set_tilable_result
{
  /// The clustering (K, DOF, S-quads before optimization, candidates).
  Clustering_result clustering;
  /// The optimization; its `measure` is the measurement of the result
  /// against the input (congruence, approximation, displacement, F̃ terms,
  /// final S-quads).
  Optimization_result optimization;
  /// The tile catalog of the result (one S-quad per cluster, mesh units).
  std::vector<IO::Tile> tiles;
  double validation_time = 0;  ///< seconds spent checking the input
  double clustering_time = 0;  ///< seconds spent clustering
  double total_time = 0;       ///< seconds in total
  /// Whether every face fits its S-quad within `congruence_tolerance`, as
  /// measured on the result (`optimization.converged`).
  bool is_tilable() const { return optimization.converged; }
};

namespace internal {

// An output map that was not asked for costs nothing.
template <typename PolygonMesh, typename Map>
void copy_face_output(const PolygonMesh&, CGAL::internal_np::Param_not_found, Map) {}

template <typename PolygonMesh, typename OutputMap, typename Map>
void copy_face_output(const PolygonMesh& pm, OutputMap output, Map map)
{
  typedef typename boost::property_traits<OutputMap>::value_type Value;
  for(auto f : faces(pm))
    put(output, f, Value(get(map, f)));
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Turns the quad mesh `pm` into a K-set tilable surface: checks it, clusters
/// its faces into K S-quads (`cluster_quads()`), moves its vertices so that
/// every face is congruent to its S-quad while the surface stays as close to
/// the input as it can (`optimize_tilable_surface()`), and measures the
/// result against the input (`measure_tilability()`).
///
/// Every named parameter of `cluster_quads()` and of
/// `optimize_tilable_surface()` is accepted and passed on; the two maps are
/// outputs here. Whether the result is exactly tilable is measured, not
/// assumed: see `K_set_tilable_result::is_tilable()`.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_tiles} K, required. \cgalParamNEnd
///   \cgalParamNBegin{face_cluster_map} optional output: cluster id 0..K-1 of
///     every face. \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} optional output: orientation 0..7 of
///     every face relative to its S-quad (method notes §1). \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm`; moved. \cgalParamNEnd
///   \cgalParamNBegin{visitor} a model of the visitor of
///     `optimize_tilable_surface()`; if it also has a member
///     `phase(const char* name, double seconds)`, that is called after each of
///     the phases "validation", "clustering" and "optimization". \cgalParamNEnd
///   \cgalParamNBegin{...} the parameters of `cluster_quads()` and
///     `optimize_tilable_surface()`. \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if `pm` or a parameter cannot be processed; `pm` and
/// the maps are untouched then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
K_set_tilable_result make_k_set_tilable(PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, CGAL_NP_CLASS>::type Vertex_point_map;

  typedef typename CGAL::internal_np::Lookup_named_param_def<
    CGAL::internal_np::visitor_t, CGAL_NP_CLASS, Default_optimization_visitor>::type Visitor;
  Visitor visitor = choose_parameter<Visitor>(get_parameter(np, CGAL::internal_np::visitor));

  K_set_tilable_result result;
  CGAL::Real_timer total, phase;
  total.start();
  phase.start();
  K_set_tilable_surface<PolygonMesh, Vertex_point_map> surface(
    pm, choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                         get_property_map(CGAL::vertex_point, pm)));
  result.validation_time = phase.time();
  internal::notify_phase(visitor, "validation", result.validation_time, 0);

  phase.reset();
  result.clustering = surface.cluster(np);
  result.clustering_time = phase.time();
  internal::notify_phase(visitor, "clustering", result.clustering_time, 0);

  const bool paper_method = choose_parameter(get_parameter(np, internal_np::solver),
                                            CONSTRAINED_GAUSS_NEWTON) == PAPER_CONJUGATE_GRADIENT;
  result.optimization = paper_method ? surface.optimize(np) : surface.optimize_closest(np);
  result.clustering = surface.clustering();
  result.tiles = surface.tile_catalog(result.optimization.measure);
  internal::notify_phase(visitor, "optimization",
                         result.optimization.setup_time + result.optimization.solve_time +
                           result.optimization.measure_time, 0);

  internal::copy_face_output(pm, get_parameter(np, internal_np::face_cluster), surface.face_cluster_map());
  internal::copy_face_output(pm, get_parameter(np, internal_np::face_orientation),
                             surface.face_orientation_map());
  result.total_time = total.time();
  return result;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
