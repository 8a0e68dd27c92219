// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H

// The tuning values of the pipeline that the user does not set, each under a
// name that the code and the user manual cite. Values the user can set are in
// defaults.h. Grouped by the stage of the pipeline that reads them.

#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {
namespace tuning {

// ---------------------------------------------------------------------------
// Shape analysis, optimization and measurement
// ---------------------------------------------------------------------------



// ---------------------------------------------------------------------------
// Clustering: candidate generators and their selection by score
// ---------------------------------------------------------------------------

// Threshold clustering on the descriptor path: the threshold doubles until
// at most max(this, 4K) initial clusters remain (the beam's cost grows with N).
constexpr std::size_t descriptor_path_initial_clusters = 1000;
// Threshold clustering: a zero threshold restarts at this fraction of the
// mean edge length before doubling.
constexpr double restart_threshold = 1e-3;
// Threshold clustering with fewer than K clusters: the threshold is divided
// by 4 while above this fraction of the mean edge length (round-off level).
constexpr double smallest_threshold = 1e-9;
// How many segment clusterings of fewer molds, split to K, join the pool:
// those of least length deviation (split_segment_clusterings()).
constexpr std::size_t split_segment_candidates = 4;
// The search optimizes ceil(optimized / this) grid-segment candidates beyond
// the ranked ones (origin_traits()): grids gain from their structure more
// than the prediction ranks.
constexpr std::size_t grid_segment_extra_quota_divisor = 4;
// Canonical face order: start faces whose distances to the centroid differ
// by at most this relative amount tie (round-off), the larger face first.
constexpr double canonical_start_tie = 1e-9;
// Procrustes passes of a cluster's S-quad (cluster_shapes()): the mean moves
// little after 3 on clusters of near-congruent quads.
constexpr int procrustes_passes = 3;
// Procrustes mean of congruent instances run to convergence
// (converged_procrustes_mean()): at most this many passes, stopping when the
// mean moves by less than the tolerance below.
constexpr int converged_procrustes_passes = 10;
constexpr double converged_procrustes_tolerance = 1e-14;
// Newton's method for the largest root of the quaternion characteristic
// polynomial (fast_match.h): at most this many steps, ending at a step below
// the relative size below (it converges monotonically in a few steps).
constexpr int quaternion_newton_iterations = 60;
constexpr double quaternion_newton_step = 1e-15;
// Below this fraction of the cubed bound the adjugate of N - lambda I is
// treated as zero (a nearly repeated eigenvalue), and an eigen-solver is used.
constexpr double repeated_eigenvalue_gap = 1e-4;
// Correspondences whose lower bound exceeds the best dissimilarity by at most
// this relative slack are still matched (ties up to rounding).
constexpr double match_bound_slack = 1e-12;
// Lloyd iterations of k-means (the k-means candidate and the 2-means splits).
constexpr int kmeans_iterations = 30;
// Beam of merges: up to this many groups every pair of groups is proposed
// (the paper's exhaustive search); above, each group's cheapest partner.
constexpr int beam_exhaustive_groups = 128;
// Strip candidates: a direction with more strips is left out (the greedy
// merges cost O(S^3)).
constexpr int strip_max_strips = 400;
// Strip candidates: the numbers of groups b of one direction tried, with
// ceil(K / b) groups of the other.
constexpr std::size_t strip_group_counts[8] = {1, 2, 3, 4, 6, 8, 12, 16};
// Segment candidates: grids with more rows or columns are left out (the
// dynamic program's tables grow with both).
constexpr int segment_grid_max_rows = 400;
constexpr int segment_grid_max_columns = 400;
// Segment candidates: the dynamic program takes about 4 rows^2 K steps; a
// grid direction above this many is left out.
constexpr double segment_runs_work = 1e8;
// Sweep candidates: a grid whose rows^2 x runs exceeds this is not cut into
// runs of rows (the same dynamic program).
constexpr double sweep_runs_work = 1e8;
// Screw column runs: runs of at most sqrt(this / columns) columns, so that
// the O(columns^3 / 8) search stays near this many steps.
constexpr double screw_column_runs_work = 1e8;
// Screw column runs: a run whose steps shrink to less than this fraction of
// their mean length is left out (a section running straight away from the
// axis would collapse onto one point).
constexpr double screw_run_min_step = 0.5;
// Below this angle (radians) the motion of a one-run sweep with column runs
// is taken as its translation: the helices' axis would be far away and
// ill-conditioned, and a translation commutes with the straight runs.
constexpr double screw_angle_min = 1e-6;
// Trimmed grids: a bounding box of more cells per face is not a trimmed grid
// worth sweeping (an outline with few faces inside).
constexpr double trimmed_grid_max_cells_per_face = 16.0;
// Pole fans: the triangles of a fan are congruent when their edge lengths
// agree within this fraction of the mean edge length (round-off).
constexpr double pole_fan_congruence = 1e-9;


// ---------------------------------------------------------------------------
// Search: which candidates are solved, how far, and the rounds after them
// ---------------------------------------------------------------------------



} // namespace tuning
} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
