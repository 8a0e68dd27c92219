// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_PARAMETERS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_PARAMETERS_H

// The named parameters that a public function hands to the pipeline below
// it, in one type whatever value parameters the caller chained, and in
// whatever order: each value parameter read into a std::optional of its
// own type (empty when not given), each map and the visitor passed on as
// given. The pipeline's templates are then instantiated once per kind of
// maps and visitor, not once per combination of values: a program (or a
// test) that calls the pipeline with many different parameter lists
// compiles it once.
//
// Value parameters are read with parameter_or(), which takes the user's
// parameters, canonical ones, or a mix.

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>

#include <cstddef>
#include <optional>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename D>
D value_or(const CGAL::internal_np::Param_not_found&, const D& d)
{
  return d;
}

template <typename T, typename D>
T value_or(const std::optional<T>& value, const D& d)
{
  return value ? *value : static_cast<T>(d);
}

template <typename T, typename D>
T value_or(const T& value, const D&)
{
  return value;
}

// The value parameter `tag` of `np` (given by the user, or canonical), else `d`.
template <typename NamedParameters, typename Tag, typename D>
auto parameter_or(const NamedParameters& np, Tag tag, const D& d)
{
  return value_or(parameters::get_parameter(np, tag), d);
}

// A value parameter as a std::optional<T>: given as it is, or canonical already, or not given.
template <typename T>
std::optional<T> given(const CGAL::internal_np::Param_not_found&)
{
  return std::nullopt;
}

template <typename T>
std::optional<T> given(const std::optional<T>& value)
{
  return value;
}

template <typename T, typename U>
std::optional<T> given(const U& value)
{
  return static_cast<T>(value);
}

// The package's value parameters, in one type. The same type whether `np`
// gives them or not: so parameter lists that differ only in values share it.
template <typename NamedParameters>
auto canonical_values(const NamedParameters& np)
{
  namespace ts = CGAL::Tilable_surfaces::internal_np;
  using parameters::get_parameter;
  return parameters::number_of_tiles(given<long long>(get_parameter(np, ts::number_of_tiles)))
    .number_of_candidates(given<std::size_t>(get_parameter(np, ts::number_of_candidates)))
    .similarity_threshold(given<double>(get_parameter(np, ts::similarity_threshold)))
    .flexibility_penalty(given<double>(get_parameter(np, ts::flexibility_penalty)))
    .structure_penalty(given<double>(get_parameter(np, ts::structure_penalty)))
    .use_kmeans_candidate(given<bool>(get_parameter(np, ts::use_kmeans_candidate)))
    .use_auto_merge(given<bool>(get_parameter(np, ts::use_auto_merge)))
    .use_strip_candidates(given<bool>(get_parameter(np, ts::use_strip_candidates)))
    .use_segment_candidates(given<bool>(get_parameter(np, ts::use_segment_candidates)))
    .clustering_path(given<Clustering_path>(get_parameter(np, ts::clustering_path)))
    .exact_clustering_limit(given<std::size_t>(get_parameter(np, ts::exact_clustering_limit)))
    .orientation_policy(given<Orientation_policy>(get_parameter(np, ts::orientation_policy)))
    .distance_weight(given<double>(get_parameter(np, ts::distance_weight)))
    .fairness_weight(given<double>(get_parameter(np, ts::fairness_weight)))
    .edge_length_weight(given<double>(get_parameter(np, ts::edge_length_weight)))
    .diagonal_weight(given<double>(get_parameter(np, ts::diagonal_weight)))
    .volume_weight(given<double>(get_parameter(np, ts::volume_weight)))
    .solver(given<Solver_type>(get_parameter(np, ts::solver)))
    .congruence_tolerance(given<double>(get_parameter(np, ts::congruence_tolerance)))
    .panel_tolerance(given<double>(get_parameter(np, ts::panel_tolerance)))
    .convergence_tolerance(given<double>(get_parameter(np, ts::convergence_tolerance)))
    .feature_angle(given<double>(get_parameter(np, ts::feature_angle)))
    .tangential_weight(given<double>(get_parameter(np, ts::tangential_weight)))
    .number_of_optimized_candidates(given<std::size_t>(get_parameter(np, ts::number_of_optimized_candidates)))
    .number_of_improvement_rounds(given<int>(get_parameter(np, ts::number_of_improvement_rounds)))
    .planar_tiles(given<bool>(get_parameter(np, ts::planar_tiles)))
    .max_deviation(given<double>(get_parameter(np, ts::max_deviation)))
    .number_of_iterations(given<int>(get_parameter(np, CGAL::internal_np::number_of_iterations)))
    .random_seed(given<unsigned int>(get_parameter(np, CGAL::internal_np::random_seed)));
}

// `np` in canonical form but for the output maps: canonical_values(), then
// the input maps and the visitor as given (CGAL's Param_not_found where not
// given, which every reader takes as absent). What make_k_set_tilable()
// hands to the pipeline, which writes the user's output maps only at the
// end: so their types do not multiply its instantiations either.
template <typename NamedParameters>
auto canonical_inputs(const NamedParameters& np)
{
  using parameters::get_parameter;
  return canonical_values(np)
    .vertex_point_map(get_parameter(np, CGAL::internal_np::vertex_point))
    .vertex_index_map(get_parameter(np, CGAL::internal_np::vertex_index))
    .face_index_map(get_parameter(np, CGAL::internal_np::face_index))
    .edge_index_map(get_parameter(np, CGAL::internal_np::edge_index))
    .halfedge_index_map(get_parameter(np, CGAL::internal_np::halfedge_index))
    .vertex_is_constrained_map(get_parameter(np, CGAL::internal_np::vertex_is_constrained))
    .edge_is_constrained_map(get_parameter(np, CGAL::internal_np::edge_is_constrained))
    .visitor(get_parameter(np, CGAL::internal_np::visitor));
}

// `np` in canonical form: canonical_inputs() and the face cluster and
// orientation maps as given.
template <typename NamedParameters>
auto canonical_parameters(const NamedParameters& np)
{
  using parameters::get_parameter;
  return canonical_inputs(np)
    .face_cluster_map(get_parameter(np, internal_np::face_cluster))
    .face_orientation_map(get_parameter(np, internal_np::face_orientation));
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_PARAMETERS_H
