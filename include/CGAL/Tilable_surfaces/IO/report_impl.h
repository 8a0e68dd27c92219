// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_REPORT_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_REPORT_IMPL_H

// The bodies of the non-template functions declared in report.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/report.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json energy_terms_json(const Energy_terms& t)
{
  return {{"distance", t.distance}, {"fairness", t.fairness}, {"edge_length", t.edge_length},
          {"diagonal", t.diagonal}, {"volume", t.volume}};
}

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tile_count_trials_json(const std::vector<Tile_count_trial>& trials)
{
  nlohmann::json rows = nlohmann::json::array();
  for(const Tile_count_trial& t : trials)
    rows.push_back({{"K", t.number_of_tiles},
                    {"degree_of_flexibility", t.degree_of_flexibility},
                    {"congruence_error", t.congruence_error},
                    {"hausdorff_distance", t.hausdorff_distance},
                    {"max_displacement", t.max_displacement},
                    {"seconds", t.seconds},
                    {"tilable", t.is_tilable},
                    {"self_intersecting_face_pairs", t.self_intersecting_face_pairs},
                    {"refined_from", t.refined_from}});
  return rows;
}

namespace internal {

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json fidelity_json(const Tilability_measure& m)
{
  return {{"hausdorff", {{"max", m.hausdorff_distance}, {"mean", m.mean_symmetric_distance}}},
          {"result_to_input", {{"max", m.max_approximation_error}, {"mean", m.mean_approximation_error}}},
          {"input_to_result", {{"max", m.max_coverage_error}, {"mean", m.mean_coverage_error}}},
          {"hausdorff_in_edge_lengths",
           {{"max", m.in_input_edge_lengths(m.hausdorff_distance)},
            {"mean", m.in_input_edge_lengths(m.mean_symmetric_distance)}}},
          {"length_scale", "input bounding-box diagonal"},
          {"input_bbox_diagonal", m.input_bbox_diagonal},
          {"input_mean_edge_length", m.input_mean_edge_length},
          {"self_intersecting_face_pairs", m.self_intersecting_face_pairs}};
}

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json panel_deviation_json(const Tilability_measure& m)
{
  return {{"tolerance", m.panel_tolerance},
          {"worst", m.worst_panel_deviation},
          {"within_tolerance", m.within_panel_tolerance()},
          {"per_face", m.panel_deviations},
          {"length_scale", "model units"}};
}

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json clustering_json(const K_set_tilable_result& r)
{
  return {{"path", r.clustering.path == EXACT_PATH ? "exact" : "descriptor"},
          {"initial_clusters", r.clustering.number_of_initial_clusters},
          {"total_weight", r.clustering.total_weight},
          {"weights_are_exact", r.clustering.weights_are_exact},
          {"degree_of_flexibility", r.clustering.degree_of_flexibility},
          {"choice", r.clustering.choice_reason},
          {"edit_rounds", r.clustering.number_of_edit_rounds}};
}

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json time_json(const K_set_tilable_result& r)
{
  return {{"validation", r.validation_time},
          {"clustering", r.clustering_time},
          {"optimization_setup", r.optimization.setup_time},
          {"optimization_solve", r.optimization.solve_time},
          {"measurement", r.optimization.measure_time},
          {"total", r.total_time}};
}

} // namespace internal

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tilability_report_json(const K_set_tilable_result& r,
                                       double congruence_tolerance)
{
  const Tilability_measure& m = r.optimization.measure;
  std::vector<std::string> kinds;
  std::size_t triangles = 0;
  for(const Panel& s : m.s_quads)
  {
    kinds.push_back(s.is_triangle() ? "triangle" : "quad");
    triangles += s.is_triangle() ? 1 : 0;
  }
  return {
    {"K", m.number_of_clusters},
    {"distinct_molds", m.number_of_distinct_molds},
    {"buildability",
     {{"tilable", r.is_tilable()},
      {"self_intersecting_face_pairs", m.self_intersecting_face_pairs},
      {"flattened_panels", m.flattened_panels},
      {"distinct_molds", m.number_of_distinct_molds},
      {"K", m.number_of_clusters},
      {"warnings", buildability_warnings(m, congruence_tolerance)}}},
    {"degree_of_flexibility", m.degree_of_flexibility},
    {"cluster_sizes", m.cluster_sizes},
    {"tile_kinds", kinds},
    {"tiles_by_kind", {{"quad", kinds.size() - triangles}, {"triangle", triangles}}},
    {"planar_panels",
     {{"required", m.requires_planar_tiles}, {"planarity_error", m.planarity_error},
      {"length_scale", "mean edge length"}}},
    {"mirrored_panels",
     {{"allowed", m.allows_mirrored_panels}, {"per_cluster", m.cluster_mirrored_counts}}},
    {"congruence_error",
     {{"worst", m.congruence_error},
      {"per_cluster", m.cluster_congruence_errors},
      {"tolerance", m.panel_tolerance > 0 ? m.panel_tolerance / m.mean_edge_length : congruence_tolerance},
      {"length_scale", "mean edge length"},
      {"mean_edge_length", m.mean_edge_length}}},
    {"panel_deviation", internal::panel_deviation_json(m)},
    {"fidelity", internal::fidelity_json(m)},
    {"displacement", {{"max", m.max_displacement}, {"mean", m.mean_displacement}}},
    {"normalized_terms", energy_terms_json(m.normalized_terms)},
    {"tilable", r.is_tilable()},
    {"optimization",
     {{"iterations", r.optimization.iterations},
      {"converged", r.optimization.converged},
      {"ending", r.optimization.ending()},
      {"objective", r.optimization.objective}}},
    {"clustering", internal::clustering_json(r)},
    {"tried_K", tile_count_trials_json(r.trials)},
    {"time_seconds", internal::time_json(r)}};
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_REPORT_IMPL_H
