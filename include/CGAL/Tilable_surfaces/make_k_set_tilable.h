// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
#define CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H

/// \file make_k_set_tilable.h
/// The one-call function: validate, cluster, optimize, measure; at a given K,
/// or at the smallest K within a deviation budget.

#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/K_set_tilable_surface.h>
#include <CGAL/Tilable_surfaces/internal/Search/smallest_passing_tile_count.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

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

// The clustering and optimization of make_k_set_tilable() at the K of `np`.
template <typename Surface, typename NamedParameters, typename Visitor>
void cluster_and_optimize(Surface& surface, const NamedParameters& np, Visitor& visitor,
                          K_set_tilable_result& result)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto stage_np = with_visitor(np, visitor);
  CGAL::Real_timer phase;
  phase.start();
  result.clustering = surface.cluster(stage_np);
  result.clustering_time = phase.time();
  visitor.phase("clustering", result.clustering_time);

  const bool paper_method = choose_parameter(get_parameter(np, internal_np::solver),
                                            defaults::solver) == PAPER_CONJUGATE_GRADIENT;
  result.optimization = paper_method ? surface.optimize(stage_np) : surface.optimize_closest(stage_np);
  result.clustering = surface.clustering();
  result.tiles = tile_catalog(result.optimization.measure);
  visitor.phase("optimization", result.optimization.setup_time + result.optimization.solve_time +
                                  result.optimization.measure_time);
}

inline Tile_count_trial tile_count_trial(const K_set_tilable_result& r, double seconds)
{
  const Tilability_measure& m = r.optimization.measure;
  Tile_count_trial t;
  t.number_of_tiles = m.number_of_clusters;
  t.degree_of_flexibility = m.degree_of_flexibility;
  t.congruence_error = m.congruence_error;
  t.hausdorff_distance = m.hausdorff_distance;
  t.max_displacement = m.max_displacement;
  t.seconds = seconds;
  t.is_tilable = r.is_tilable();
  t.self_intersecting_face_pairs = m.self_intersecting_face_pairs;
  return t;
}

// The deviation search of make_k_set_tilable(): the smallest K, at most the
// `number_of_tiles` of `np` (default: the number of faces), whose result is
// tilable within `max_deviation`; else the result at the largest K tried.
// The mesh and the output maps get the result returned.
template <typename PolygonMesh, typename Surface, typename VertexPointMap,
          typename NamedParameters, typename Visitor>
K_set_tilable_result search_tile_count(PolygonMesh& pm, Surface& surface, VertexPointMap vpm,
                                       const NamedParameters& np, Visitor& visitor)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double budget = get_parameter(np, internal_np::max_deviation);
  if(!(budget >= 0))
    throw Invalid_input("max_deviation is " + std::to_string(budget) + ", it must be >= 0",
                        Invalid_input::PARAMETER);
  const std::size_t n = num_faces(pm);
  const long long largest = choose_parameter(get_parameter(np, internal_np::number_of_tiles), (long long)(n));
  if(largest < 1)
    throw Invalid_input("number_of_tiles (the largest K tried) is " + std::to_string(largest) +
                        ", it must be at least 1", Invalid_input::PARAMETER);
  const std::size_t k_max = (std::min)(n, std::size_t(largest));

  // The smallest K that meets the budget; until one does, the largest K.
  K_set_tilable_result kept;
  bool kept_meets = false;
  std::vector<typename boost::property_traits<VertexPointMap>::value_type> kept_points;
  std::vector<int> kept_cluster(n), kept_orientation(n);
  const auto fim = CGAL::get_initialized_face_index_map(pm);
  std::vector<Tile_count_trial> trials;
  bool stopped = false;
  auto passes = [&](std::size_t k) {
    if(stopped)
      return false; // the visitor ended the search: nothing more is tried
    CGAL::Real_timer timer;
    timer.start();
    K_set_tilable_result r;
    cluster_and_optimize(surface, parameters::extend(np).number_of_tiles(int(k)), visitor, r);
    trials.push_back(tile_count_trial(r, timer.time()));
    stopped = r.optimization.stopped_by_visitor;
    const bool meets = trials.back().meets(budget);
    const std::size_t kept_k = kept_points.empty() ? 0 : kept.optimization.measure.number_of_clusters;
    if(kept_points.empty() || (meets && (!kept_meets || k < kept_k)) || (!meets && !kept_meets && k > kept_k))
    {
      kept = r;
      kept_meets = meets;
      kept_points.clear();
      for(auto v : vertices(pm)) kept_points.push_back(get(vpm, v));
      for(auto f : faces(pm))
      {
        kept_cluster[get(fim, f)] = get(surface.face_cluster_map(), f);
        kept_orientation[get(fim, f)] = get(surface.face_orientation_map(), f);
      }
    }
    return meets;
  };
  smallest_passing_tile_count((std::max)(std::size_t(2), n / 25), number_of_panel_kinds(face_quads(pm, fim, np)),
                              k_max, passes);

  auto point = kept_points.begin();
  for(auto v : vertices(pm)) put(vpm, v, *point++);
  copy_face_output(pm, get_parameter(np, internal_np::face_cluster),
                   boost::make_iterator_property_map(kept_cluster.begin(), fim));
  copy_face_output(pm, get_parameter(np, internal_np::face_orientation),
                   boost::make_iterator_property_map(kept_orientation.begin(), fim));
  kept.trials = trials;
  return kept;
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
///   \cgalParamNBegin{number_of_tiles} K; required unless `max_deviation` is
///     given, and then the largest K tried (default: the number of faces). \cgalParamNEnd
///   \cgalParamNBegin{max_deviation} a deviation budget instead of K: the
///     largest symmetric Hausdorff distance to the input allowed, as a
///     fraction of its bounding-box diagonal (`Tilability_measure::hausdorff_distance`).
///     K is then the smallest whose result is tilable within it and does not
///     cross itself (`Tilability_measure::self_intersecting_face_pairs`): galloped
///     from max(2, faces / 25) by halving or doubling, then bisected, each
///     K run once through the whole pipeline on the object validated once
///     (`K_set_tilable_result::trials`). The K returned met the budget and
///     K - 1 was tried and missed it (or K = 1); a smaller K may still meet
///     it where the deviation is not monotone in K. If no K up to the
///     largest does, the result is that of the largest K tried. A visitor
///     that stops a solve ends the search. \cgalParamNEnd
///   \cgalParamNBegin{face_cluster_map} optional output: cluster id 0..K-1 of
///     every face. \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} optional output: orientation 0..7 of
///     every face relative to its S-quad (user manual, section Definitions). \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm`; moved. \cgalParamNEnd
///   \cgalParamNBegin{visitor} a `Default_visitor` (or a class with its
///     interface), by value or as `std::ref`: every stage calls the same object. \cgalParamNEnd
///   \cgalParamNBegin{...} the parameters of `cluster_quads()` and
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
  auto&& visitor = internal::visitor_of(np);

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
    result = internal::search_tile_count(pm, surface, surface_vpm, np, visitor);
    result.validation_time = validation_time;
  }
  else
  {
    result.validation_time = validation_time;
    internal::cluster_and_optimize(surface, np, visitor, result);
    internal::copy_face_output(pm, get_parameter(np, internal_np::face_cluster), surface.face_cluster_map());
    internal::copy_face_output(pm, get_parameter(np, internal_np::face_orientation),
                               surface.face_orientation_map());
  }
  result.total_time = total.time();
  return result;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_MAKE_K_SET_TILABLE_H
