// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// X-macro list of the named parameters of the package.  Each line is
// CGAL_TS_add_named_parameter(tag_type, tag_value, function_name).
// It is included several times with different definitions of the macro
// (see named_parameters.h); it has no include guard on purpose.

// clustering
CGAL_TS_add_named_parameter(number_of_tiles_t, number_of_tiles, number_of_tiles)
CGAL_TS_add_named_parameter(number_of_candidates_t, number_of_candidates, number_of_candidates)
CGAL_TS_add_named_parameter(similarity_threshold_t, similarity_threshold, similarity_threshold)
CGAL_TS_add_named_parameter(flexibility_penalty_t, flexibility_penalty, flexibility_penalty)
CGAL_TS_add_named_parameter(structure_penalty_t, structure_penalty, structure_penalty)
CGAL_TS_add_named_parameter(use_kmeans_candidate_t, use_kmeans_candidate, use_kmeans_candidate)
CGAL_TS_add_named_parameter(use_auto_merge_t, use_auto_merge, use_auto_merge)
CGAL_TS_add_named_parameter(use_strip_candidates_t, use_strip_candidates, use_strip_candidates)
CGAL_TS_add_named_parameter(use_segment_candidates_t, use_segment_candidates, use_segment_candidates)
CGAL_TS_add_named_parameter(clustering_path_t, clustering_path, clustering_path)
CGAL_TS_add_named_parameter(exact_clustering_limit_t, exact_clustering_limit, exact_clustering_limit)
CGAL_TS_add_named_parameter(orientation_policy_t, orientation_policy, orientation_policy)

// outputs of the clustering, read by the graph analysis and the optimization
CGAL_TS_add_named_parameter(face_cluster_t, face_cluster, face_cluster_map)
CGAL_TS_add_named_parameter(face_orientation_t, face_orientation, face_orientation_map)

// optimization: weights mu1..mu5 of the paper's energy
CGAL_TS_add_named_parameter(distance_weight_t, distance_weight, distance_weight)
CGAL_TS_add_named_parameter(fairness_weight_t, fairness_weight, fairness_weight)
CGAL_TS_add_named_parameter(edge_length_weight_t, edge_length_weight, edge_length_weight)
CGAL_TS_add_named_parameter(diagonal_weight_t, diagonal_weight, diagonal_weight)
CGAL_TS_add_named_parameter(volume_weight_t, volume_weight, volume_weight)

// optimization: solver and tolerances
CGAL_TS_add_named_parameter(solver_t, solver, solver)
CGAL_TS_add_named_parameter(congruence_tolerance_t, congruence_tolerance, congruence_tolerance)
CGAL_TS_add_named_parameter(panel_tolerance_t, panel_tolerance, panel_tolerance)
CGAL_TS_add_named_parameter(convergence_tolerance_t, convergence_tolerance, convergence_tolerance)
CGAL_TS_add_named_parameter(feature_angle_t, feature_angle, feature_angle)
CGAL_TS_add_named_parameter(tangential_weight_t, tangential_weight, tangential_weight)

// fidelity search (K_set_tilable_surface::optimize_closest())
CGAL_TS_add_named_parameter(number_of_optimized_candidates_t, number_of_optimized_candidates,
                            number_of_optimized_candidates)
CGAL_TS_add_named_parameter(number_of_improvement_rounds_t, number_of_improvement_rounds,
                            number_of_improvement_rounds)
CGAL_TS_add_named_parameter(planar_tiles_t, planar_tiles, planar_tiles)
CGAL_TS_add_named_parameter(max_deviation_t, max_deviation, max_deviation)
