// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_K_SET_TILABLE_RESULT_H
#define CGAL_TILABLE_SURFACES_K_SET_TILABLE_RESULT_H

/// \file K_set_tilable_result.h
/// What the one-call function and the curve return: the result of each
/// stage, the tile catalog and every K tried. Apart from the one-call function
/// so that writers of reports (`IO/report.h`) need not include the pipeline.

#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// One K tried by the deviation search of `make_k_set_tilable()` or by
/// `k_set_tilable_curve()`: what the whole pipeline gave at that K.
struct Tile_count_trial
{
  std::size_t number_of_tiles = 0;        ///< K
  std::size_t degree_of_flexibility = 0;  ///< DOF of the result's clustering
  double congruence_error = 0;            ///< of the result, relative to its mean edge length
  /// Symmetric Hausdorff distance of the result to the input, relative to
  /// the input's bounding-box diagonal.
  double hausdorff_distance = 0;
  double max_displacement = 0;            ///< largest vertex displacement, mesh units
  double seconds = 0;                     ///< time of this K's clustering and optimization
  bool is_tilable = false;                ///< congruence within `congruence_tolerance`
  /// Pairs of panels of the result that cross each other
  /// (`Tilability_measure::self_intersecting_face_pairs`).
  std::size_t self_intersecting_face_pairs = 0;
  /// The smaller K whose result, refined to this K
  /// (`K_set_tilable_surface::refine_to()`), ended better than this K's own
  /// search and is the result here (`k_set_tilable_curve()`, the deviation
  /// search of `make_k_set_tilable()`); 0 when it is this K's own.
  std::size_t refined_from = 0;
  /// Whether this K is tilable within the deviation budget `max_deviation`,
  /// by a result that does not cross itself (it could not be built).
  bool meets(double max_deviation) const
  {
    return is_tilable && self_intersecting_face_pairs == 0 && hausdorff_distance <= max_deviation;
  }
};

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
  std::vector<Tile> tiles;
  /// With `max_deviation`: every K tried, in the order tried (empty when K
  /// was given).
  std::vector<Tile_count_trial> trials;
  double validation_time = 0;  ///< seconds spent checking the input
  double clustering_time = 0;  ///< seconds spent clustering
  double total_time = 0;       ///< seconds in total
  /// Whether every face fits its S-quad within `congruence_tolerance`, as
  /// measured on the result (`optimization.converged`).
  bool is_tilable() const { return optimization.converged; }
};

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_K_SET_TILABLE_RESULT_H
