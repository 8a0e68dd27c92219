// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_DEFAULTS_H
#define CGAL_TILABLE_SURFACES_DEFAULTS_H

/// \file defaults.h
/// The defaults of the package's named parameters, in one place, and the
/// enumerations some parameters take. The functions, the command-line
/// program and the Python module read them here; `test_defaults` checks the
/// user manual's table against them.

#include <algorithm>
#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Which instances count as copies of one S-quad (user manual, section
/// "Mirrored molds").
enum Orientation_policy
{
  /// All 8 correspondences, proper rigid motions only (the paper's setting).
  PROPER_RIGID_MOTIONS = 0,
  /// Only the 4 correspondences that keep the cyclic order: panels with a
  /// finished face are never turned over.
  NO_TURNED_OVER_PANELS,
  /// All 8 correspondences and mirror images too (molds symmetric by a plane).
  ALLOW_MIRRORED_PANELS
};

/// \ingroup PkgTilableSurfacesRef
/// How `cluster_panels()` evaluates the weights of clusters.
enum Clustering_path
{
  /// `EXACT_PATH` for meshes with at most `exact_clustering_limit` faces,
  /// `DESCRIPTOR_PATH` above.
  AUTOMATIC_PATH = 0,
  /// The paper's method: the n x n affinity matrix of dissimilarities;
  /// O(n^2) time and memory, exact weights.
  EXACT_PATH,
  /// Scalable: dissimilarities only between quads whose descriptors are
  /// close (kd-tree), merge costs from descriptor statistics; linear memory.
  DESCRIPTOR_PATH
};

/// \ingroup PkgTilableSurfacesRef
/// The solvers of `optimize_tilable_surface()`.
enum Solver_type
{
  /// Default. The surface closest to the input in the metric
  /// mu1 |X - X0|^2 + mu2 |D (X - X0)|^2 (D the fairness operator, applied to
  /// the displacement), subject to equal edge lengths per edge-sharing
  /// component and equal diagonals and signed volume per cluster as *hard*
  /// constraints: Gauss-Newton SQP steps on the regularized sparse KKT system
  /// with multiplier updates and a line search on an l2 merit function, then,
  /// once the constraint residuals stop decreasing, a Levenberg-Marquardt
  /// projection onto the constraints in the same metric. If that ends short
  /// of `congruence_tolerance`, it is run again from the input with an
  /// isotropic closeness metric (sliding within the surface as dear as leaving
  /// it), then with a more cautious trust region, then with the exact
  /// Lagrangian Hessian (with inertia control and second-order corrections),
  /// within the remaining iterations, and the best result is kept.
  /// Only the ratio mu2 / mu1 matters; mu3..mu5 are not used.
  CONSTRAINED_GAUSS_NEWTON,
  /// The paper's method, as a reference: Polak-Ribiere nonlinear conjugate
  /// gradient on the weighted sum mu1 F_d + mu2 F_f + mu3 F_e + mu4 F_a +
  /// mu5 F_o of the paper's terms, on the input normalized to a unit
  /// bounding-box diagonal. It stops when the energy stalls, congruent or not.
  PAPER_CONJUGATE_GRADIENT
};

/// \ingroup PkgTilableSurfacesRef
/// The defaults of the named parameters that do not depend on the mesh or on
/// the solver.
namespace defaults {
/// `number_of_candidates`: the width of the clustering's beam.
constexpr std::size_t number_of_candidates = 10;
/// `similarity_threshold`, relative to the mean edge length.
constexpr double similarity_threshold = 0.01;
/// `flexibility_penalty` (the paper's lambda).
constexpr double flexibility_penalty = 0.5;
/// `structure_penalty`.
constexpr double structure_penalty = 1.0;
/// `use_kmeans_candidate`: every kind of candidate clustering is made.
constexpr bool use_kmeans_candidate = true;
/// `use_auto_merge`.
constexpr bool use_auto_merge = true;
/// `use_strip_candidates`.
constexpr bool use_strip_candidates = true;
/// `use_segment_candidates`.
constexpr bool use_segment_candidates = true;
/// `exact_clustering_limit`: the paper's largest mesh.
constexpr std::size_t exact_clustering_limit = 1500;
/// `clustering_path`.
constexpr Clustering_path clustering_path = AUTOMATIC_PATH;
/// `orientation_policy`: the paper's setting.
constexpr Orientation_policy orientation_policy = PROPER_RIGID_MOTIONS;
/// `random_seed`.
constexpr unsigned int random_seed = 0;
/// `solver`.
constexpr Solver_type solver = CONSTRAINED_GAUSS_NEWTON;
/// `distance_weight` (mu1), the paper's.
constexpr double distance_weight = 1e-4;
/// `tangential_weight`: sliding within the input surface costs a tenth of
/// leaving it.
constexpr double tangential_weight = 0.1;
/// `edge_length_weight` (mu3), the paper's.
constexpr double edge_length_weight = 1.0;
/// `diagonal_weight` (mu4), the paper's.
constexpr double diagonal_weight = 1.0;
/// `volume_weight` (mu5), the paper's.
constexpr double volume_weight = 1.0;
/// `congruence_tolerance`: fabrication grade is 1e-4.
constexpr double congruence_tolerance = 1e-6;
/// `panel_tolerance`, in model units: 0 is the exact mode, where every
/// instance fits its mold within `congruence_tolerance` of the mean edge.
constexpr double panel_tolerance = 0.0;
/// `planar_tiles`.
constexpr bool planar_tiles = false;
/// `number_of_improvement_rounds`.
constexpr int number_of_improvement_rounds = 2;
/// `feature_angle`, in degrees.
constexpr double feature_angle = 60.0;
/// `use_binary_mode` of the PLY writers.
constexpr bool use_binary_mode = true;
/// `stream_precision` of the PLY writers: every double exactly.
constexpr int stream_precision = 17;
/// `fairness_weight` (mu2) of `CONSTRAINED_GAUSS_NEWTON`: the weight of the
/// as-rigid-as-possible energy of the displacement relative to
/// `distance_weight`.
constexpr double gauss_newton_fairness_weight = 1e-6;
/// `fairness_weight` (mu2) of `PAPER_CONJUGATE_GRADIENT`: the paper's weight
/// of its fairness term F_f.
constexpr double paper_fairness_weight = 1e-4;
/// `number_of_iterations` of `CONSTRAINED_GAUSS_NEWTON`.
constexpr int gauss_newton_iterations = 300;
/// `number_of_iterations` of `PAPER_CONJUGATE_GRADIENT`.
constexpr int paper_iterations = 5000;
/// `convergence_tolerance` of `CONSTRAINED_GAUSS_NEWTON`: the largest step,
/// relative to the mean edge length, below which a congruent result stops.
constexpr double gauss_newton_convergence_tolerance = 1e-9;
/// `convergence_tolerance` of `PAPER_CONJUGATE_GRADIENT`: the relative
/// decrease of the energy below which it stops.
constexpr double paper_convergence_tolerance = 1e-12;
/// `number_of_optimized_candidates`: at most this many.
constexpr std::size_t max_optimized_candidates = 12;
/// `number_of_optimized_candidates`: at least this many, at most 5000 faces.
constexpr int min_optimized_candidates = 2;
/// `number_of_optimized_candidates`: one more per this many faces fewer.
constexpr int faces_per_optimized_candidate = 10000;
} // namespace defaults

/// \ingroup PkgTilableSurfacesRef
/// The default of `fairness_weight` (mu2) for `solver`: for the default
/// solver the weight of the as-rigid-as-possible energy of the displacement
/// relative to `distance_weight` 1e-4; for the paper's conjugate gradient the
/// paper's weight of its fairness term F_f.
inline double default_fairness_weight(Solver_type solver)
{
  return solver == CONSTRAINED_GAUSS_NEWTON ? defaults::gauss_newton_fairness_weight
                                            : defaults::paper_fairness_weight;
}

/// \ingroup PkgTilableSurfacesRef
/// The default of `number_of_iterations` for `solver`: 300 Gauss-Newton
/// iterations, or 5000 of the paper's conjugate gradient.
inline int default_number_of_iterations(Solver_type solver)
{
  return solver == CONSTRAINED_GAUSS_NEWTON ? defaults::gauss_newton_iterations : defaults::paper_iterations;
}

/// \ingroup PkgTilableSurfacesRef
/// The default of `convergence_tolerance` for `solver`: for the default
/// solver, the largest step, in mean edge lengths, below which a congruent
/// result stops; for the paper's conjugate gradient, the relative decrease of
/// the energy below which it stops.
inline double default_convergence_tolerance(Solver_type solver)
{
  return solver == CONSTRAINED_GAUSS_NEWTON ? defaults::gauss_newton_convergence_tolerance
                                            : defaults::paper_convergence_tolerance;
}

/// \ingroup PkgTilableSurfacesRef
/// Above this many faces, a solve from the input takes minutes and may not
/// end exact: `default_number_of_optimized_candidates()` is 0, and a sweep
/// clustering's exact start is not polished by the solver (10 iterations
/// never ended exact on the grids of 900 to 10,000 quads measured, and cost
/// 9 s at 10,000).
constexpr std::size_t large_mesh_faces = 5000;

/// \ingroup PkgTilableSurfacesRef
/// The default of `number_of_optimized_candidates` for a mesh of
/// `number_of_faces` quads: 2 + 10000 / `number_of_faces`, at most 12, and 0
/// above 5000 faces (`large_mesh_faces`).
/// Solves of small meshes take a second or less, and there the ranking of the
/// candidates is least reliable (tunnel stand-in, 1152 quads, K = 8: the
/// best candidate ranks 8th and ends 1.6 times closer than the first).
/// Above 5000 faces a solve from the input takes minutes and may not end
/// exact (seashell parametrization, 10,000 quads, K = 100: the candidates and
/// rounds stalled at 2.8e-3 after 1,397 s), so 0: an exact sweep
/// clustering, found in seconds, ends the search
/// (`K_set_tilable_surface::optimize_closest()`); without one, 0 counts as 1.
inline std::size_t default_number_of_optimized_candidates(std::size_t number_of_faces)
{
  if(number_of_faces > large_mesh_faces)
    return 0;
  return (std::min)(defaults::max_optimized_candidates,
                    defaults::min_optimized_candidates +
                      defaults::faces_per_optimized_candidate / (std::max)(number_of_faces, std::size_t(1)));
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_DEFAULTS_H
