// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MEASURE_IMPL_H
#define CGAL_TILABLE_SURFACES_MEASURE_IMPL_H

// The bodies of the non-template functions declared in measure.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/measure.h>

namespace CGAL {
namespace Tilable_surfaces {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> buildability_warnings(const Tilability_measure& m,
                                               double congruence_tolerance,
                                               double flattened_warning_fraction)
{
  std::vector<std::string> w;
  std::size_t faces = 0;
  for(std::size_t n : m.cluster_sizes) faces += n;
  if(m.panel_tolerance > 0 && !m.within_panel_tolerance())
    w.push_back("not tilable: a panel deviates " + std::to_string(m.worst_panel_deviation) +
                " (model units) from its mold, above the panel tolerance " + std::to_string(m.panel_tolerance));
  else if(m.panel_tolerance == 0 && m.congruence_error > congruence_tolerance)
    w.push_back("not tilable: the congruence error " + std::to_string(m.congruence_error) +
                " (mean edge lengths) is above the tolerance " + std::to_string(congruence_tolerance));
  if(m.self_intersecting_face_pairs > 0)
    w.push_back("the result crosses itself: " + std::to_string(m.self_intersecting_face_pairs) +
                " pairs of panels intersect; it cannot be built as it is");
  if(faces > 0 && double(m.flattened_panels) >= flattened_warning_fraction * double(faces))
    w.push_back(std::to_string(m.flattened_panels) + " of " + std::to_string(faces) +
                " panels were flattened (twisted in the input, planar in the result): the surface changed its "
                "shape to make them congruent");
  if(2 * m.number_of_distinct_molds < m.number_of_clusters)
    w.push_back("only " + std::to_string(m.number_of_distinct_molds) + " distinct molds for K = " +
                std::to_string(m.number_of_clusters) + ": clusters collapsed onto the same shapes");
  return w;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<Tile> tile_catalog(const Tilability_measure& m)
{
  std::vector<Tile> tiles(m.s_quads.size());
  for(std::size_t c = 0; c < tiles.size(); ++c)
  {
    tiles[c].id = c;
    tiles[c].instance_count = m.cluster_sizes[c];
    tiles[c].mirrored_count = m.cluster_mirrored_counts[c];
    tiles[c].corners = m.s_quads[c];
    tiles[c].worst_deviation = m.cluster_congruence_errors[c] * m.mean_edge_length;
    tiles[c].mold = c < m.cluster_molds.size() ? m.cluster_molds[c] : c;
    tiles[c].panel_tolerance = m.panel_tolerance;
  }
  for(std::size_t f = 0; f < m.panel_clusters.size() && f < m.panel_deviations.size(); ++f)
    if(m.panel_clusters[f] < tiles.size())
    {
      tiles[m.panel_clusters[f]].instance_faces.push_back(f);
      tiles[m.panel_clusters[f]].instance_deviations.push_back(m.panel_deviations[f]);
    }
  return tiles;
}

namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::size_t flattened_panels(const Tilable_problem& problem, const Point_matrix& input,
                             const Point_matrix& result)
{
  std::size_t flattened = 0;
  for(std::size_t f = 0; f < problem.face_corners.size(); ++f)
  {
    const double before = std::abs(relative_twist(instance(problem, input, f)));
    const double after = std::abs(relative_twist(instance(problem, result, f)));
    if(before >= Tilability_measure::flattening_input_twist &&
       after <= Tilability_measure::flattening_fraction * before)
      ++flattened;
  }
  return flattened;
}

CGAL_TILABLE_SURFACES_INLINE
Tilability_measure measure_tilability(const Tilable_problem& problem,
                                      const Eigen::SparseMatrix<double>& D,
                                      const Point_matrix& input, const Point_matrix& result,
                                      double panel_tolerance)
{
  Tilability_measure m;
  m.panel_tolerance = panel_tolerance;
  m.number_of_clusters = problem.number_of_clusters;
  m.degree_of_flexibility = problem.degree_of_flexibility;

  const Cluster_congruence congruence = cluster_congruence(problem, result);
  m.mean_edge_length = mean_edge_length(problem, result);
  m.cluster_sizes = congruence.sizes;
  m.allows_mirrored_panels = problem.allow_mirror;
  m.requires_planar_tiles = problem.planar;
  m.cluster_mirrored_counts = congruence.mirrored;
  m.s_quads = congruence.s_quads;
  m.panel_deviations = congruence.face_errors;
  m.panel_clusters = problem.face_cluster;
  for(double e : congruence.face_errors)
    m.worst_panel_deviation = (std::max)(m.worst_panel_deviation, e);
  for(double e : congruence.errors)
  {
    m.cluster_congruence_errors.push_back(e / m.mean_edge_length);
    m.congruence_error = (std::max)(m.congruence_error, m.cluster_congruence_errors.back());
  }

  m.cluster_molds = cluster_molds(m.s_quads, m.cluster_sizes, problem.allow_mirror,
                                  defaults::congruence_tolerance * m.mean_edge_length);
  for(std::size_t mold : m.cluster_molds)
    if(mold < m.cluster_molds.size())
      m.number_of_distinct_molds = (std::max)(m.number_of_distinct_molds, mold + 1);
  m.planarity_error = worst_diagonal_distance(problem, result) / m.mean_edge_length;

  const Eigen::RowVector3d extent = input.colwise().maxCoeff() - input.colwise().minCoeff();
  m.input_bbox_diagonal = extent.norm();
  m.input_mean_edge_length = mean_edge_length(problem, input);
  const double diagonal = m.input_bbox_diagonal > 0 ? m.input_bbox_diagonal : 1.0;
  const Distance_summary to_input = one_sided_distance(problem, input, result);
  const Distance_summary from_input = one_sided_distance(problem, result, input);
  m.max_approximation_error = to_input.max / diagonal;
  m.mean_approximation_error = to_input.mean / diagonal;
  m.max_coverage_error = from_input.max / diagonal;
  m.mean_coverage_error = from_input.mean / diagonal;
  m.hausdorff_distance = (std::max)(m.max_approximation_error, m.max_coverage_error);
  m.mean_symmetric_distance = 0.5 * (m.mean_approximation_error + m.mean_coverage_error);
  m.self_intersecting_face_pairs = self_intersecting_face_pairs(problem, result);
  m.flattened_panels = flattened_panels(problem, input, result);

  const Eigen::VectorXd displacement = (result - input).rowwise().norm();
  m.max_displacement = displacement.maxCoeff();
  m.mean_displacement = displacement.mean();

  const double unit_cube = 1.0 / extent.maxCoeff();
  const Energy_terms e = paper_energy(problem, D, unit_cube * result, unit_cube * input);
  const double V = double(problem.number_of_vertices()), E = double(problem.edges.size()),
               F = double(problem.face_corners.size());
  m.normalized_terms.distance = e.distance / V;
  m.normalized_terms.fairness = e.fairness / V;
  m.normalized_terms.edge_length = e.edge_length / E;
  m.normalized_terms.diagonal = e.diagonal / F;
  m.normalized_terms.volume = e.volume / F;
  return m;
}

CGAL_TILABLE_SURFACES_INLINE
void use_mesh_face_order(Tilability_measure& m, const std::vector<std::size_t>& index)
{
  std::vector<double> deviations(m.panel_deviations.size());
  std::vector<std::size_t> clusters(m.panel_clusters.size());
  for(std::size_t i = 0; i < index.size() && i < deviations.size() && i < clusters.size(); ++i)
  {
    deviations[index[i]] = m.panel_deviations[i];
    clusters[index[i]] = m.panel_clusters[i];
  }
  m.panel_deviations = std::move(deviations);
  m.panel_clusters = std::move(clusters);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_MEASURE_IMPL_H
