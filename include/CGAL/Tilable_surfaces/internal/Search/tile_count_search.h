// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_H

// The pipeline of make_k_set_tilable() at one K on a K_set_tilable_surface,
// and the choice among the results of several K: each K's result refined
// from a better one of fewer clusters (k_set_tilable_curve() and the
// deviation search), and the deviation search itself.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds.h>
#include <CGAL/Tilable_surfaces/internal/Search/kept_results.h>
#include <CGAL/Tilable_surfaces/internal/Search/smallest_passing_tile_count.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
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
  const auto stage_np = with_visitor(np, visitor);
  CGAL::Real_timer phase;
  phase.start();
  result.clustering = surface.cluster(stage_np);
  result.clustering_time = phase.time();
  visitor.phase("clustering", result.clustering_time);

  const bool paper_method = parameter_or(np, internal_np::solver, defaults::solver) == PAPER_CONJUGATE_GRADIENT;
  result.optimization = paper_method ? surface.optimize(stage_np) : surface.optimize_closest(stage_np);
  result.clustering = surface.clustering();
  result.tiles = tile_catalog(result.optimization.measure);
  visitor.phase("optimization", result.optimization.setup_time + result.optimization.solve_time +
                                  result.optimization.measure_time);
}

CGAL_TILABLE_SURFACES_INLINE
Tile_count_trial tile_count_trial(const K_set_tilable_result& r, double seconds);

// The pipeline at K (`surface` holds the result), then, if `sources` has a
// better result of fewer clusters, that result refined to K
// (K_set_tilable_surface::refine_to()) when it ends better still: the
// result of K, set aside with its trial. `stopped` tells whether the
// visitor stopped a solve.
template <typename Surface, typename PolygonMesh, typename VertexPointMap, typename FaceIndexMap, typename Point,
          typename NamedParameters, typename Visitor>
Kept_result<Point> result_at(std::size_t k, Surface& surface, PolygonMesh& pm, VertexPointMap vpm,
                             FaceIndexMap fim, const Refinement_sources<Point>& sources,
                             const NamedParameters& np, Visitor& visitor, bool& stopped)
{
  CGAL::Real_timer timer;
  timer.start();
  Kept_result<Point> kept;
  kept.k = k;
  cluster_and_optimize(surface, parameters::extend(np).number_of_tiles(int(k)), visitor, kept.result);
  kept.save(pm, vpm, surface, fim);
  stopped = kept.result.optimization.stopped_by_visitor;
  std::size_t refined_from = 0;
  const Kept_result<Point>* source = sources.best_below(k);
  if(!stopped && source != nullptr && is_better(source->result.optimization, kept.result.optimization))
  {
    source->put_points(pm, vpm);
    surface.set_clustering(source->cluster_map(fim), source->orientation_map(fim), surface.orientation_policy());
    const Optimization_result& refined = surface.refine_to(k, with_visitor(np, visitor));
    stopped = refined.stopped_by_visitor;
    if(is_better(refined, kept.result.optimization))
    {
      kept.result.optimization = refined;
      kept.result.clustering = surface.clustering();
      kept.result.tiles = tile_catalog(refined.measure);
      kept.save(pm, vpm, surface, fim);
      refined_from = source->k;
    }
  }
  kept.trial = tile_count_trial(kept.result, timer.time());
  kept.trial.refined_from = refined_from;
  return kept;
}

// The deviation search of make_k_set_tilable(): the smallest K, at most the
// `number_of_tiles` of `np` (default: the number of faces), whose result is
// tilable within `max_deviation`; else the result at the largest K tried.
// Each K's result is refined from the best of fewer clusters tried when that
// is better (result_at()), so that the deviation falls with K as the
// gallop and bisection assume. The mesh and the output maps of `outputs`
// get the result returned.
template <typename PolygonMesh, typename Surface, typename VertexPointMap,
          typename NamedParameters, typename OutputParameters, typename Visitor>
K_set_tilable_result search_tile_count(PolygonMesh& pm, Surface& surface, VertexPointMap vpm,
                                       const NamedParameters& np, const OutputParameters& outputs, Visitor& visitor)
{
  using parameters::get_parameter;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  const double budget = parameter_or(np, internal_np::max_deviation, std::numeric_limits<double>::quiet_NaN());
  if(!(budget >= 0))
    throw Invalid_input("max_deviation is " + std::to_string(budget) + ", it must be >= 0",
                        Invalid_input::PARAMETER);
  const std::size_t n = num_faces(pm);
  const long long largest = parameter_or(np, internal_np::number_of_tiles, (long long)(n));
  if(largest < 1)
    throw Invalid_input("number_of_tiles (the largest K tried) is " + std::to_string(largest) +
                        ", it must be at least 1", Invalid_input::PARAMETER);
  const std::size_t k_max = (std::min)(n, std::size_t(largest));

  // The smallest K that meets the budget; until one does, the largest K.
  std::optional<Kept_result<Point> > kept;
  bool kept_meets = false;
  Refinement_sources<Point> sources;
  const auto fim = CGAL::get_initialized_face_index_map(pm);
  std::vector<Tile_count_trial> trials;
  bool stopped = false;
  auto passes = [&](std::size_t k) {
    if(stopped)
      return false; // the visitor ended the search: nothing more is tried
    Kept_result<Point> r = result_at(k, surface, pm, vpm, fim, sources, np, visitor, stopped);
    trials.push_back(r.trial);
    sources.offer(r);
    const bool meets = r.trial.meets(budget);
    if(!kept || (meets && (!kept_meets || k < kept->k)) || (!meets && !kept_meets && k > kept->k))
    {
      kept = std::move(r);
      kept_meets = meets;
    }
    return meets;
  };
  const std::size_t k_min = number_of_panel_kinds(face_quads(pm, fim, np));
  if(k_max < k_min)
    throw Invalid_input("number_of_tiles (the largest K tried) is " + std::to_string(largest) +
                          ": a mesh of quads and triangles needs at least 2 tiles", Invalid_input::PARAMETER);
  smallest_passing_tile_count((std::max)(tuning::smallest_first_tile_count, n / tuning::faces_per_first_tile), k_min,
                              k_max, passes);

  kept->put_points(pm, vpm);
  copy_face_output(pm, get_parameter(outputs, internal_np::face_cluster), kept->cluster_map(fim));
  copy_face_output(pm, get_parameter(outputs, internal_np::face_orientation), kept->orientation_map(fim));
  K_set_tilable_result result = std::move(kept->result);
  result.trials = trials;
  return result;
}

} // namespace internal

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Search/tile_count_search_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_TILE_COUNT_SEARCH_H
