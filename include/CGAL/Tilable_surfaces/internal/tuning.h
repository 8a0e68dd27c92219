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

// Guards a division or a relative test against a zero denominator; far below
// any value the normalized positions produce.
constexpr double division_guard = 1e-300;

// The paper's conjugate gradient (conjugate_gradient.h), on positions
// normalized to a unit bounding-box diagonal.

// First trial step, as the largest vertex move in mean edge lengths: a small
// move to start the bracketing from; later searches start from the last step.
constexpr double cg_first_step = 0.01;
// Energy evaluations of one line search at most: bounds its cost near
// round-off, where the Wolfe conditions may not be met.
constexpr int cg_line_search_evaluations = 40;
// Strong Wolfe sufficient decrease c1 (Nocedal & Wright's usual value).
constexpr double cg_sufficient_decrease = 1e-4;
// Strong Wolfe curvature condition c2: 0.1, as accurate as Polak-Ribiere needs.
constexpr double cg_curvature_condition = 0.1;
// Growth of the trial step until the minimum is bracketed.
constexpr int cg_bracket_growth = 4;
// The zoom's trial step stays this fraction of the bracket away from its ends
// (the inner 80%), so the bracket keeps shrinking.
constexpr double cg_bracket_margin = 0.1;
// A bracket narrower than this fraction of its best step is at round-off.
constexpr double cg_min_bracket_width = 1e-15;

// The default solver (constrained_gauss_newton.h, displacement_estimate.h).

// b of the regularized KKT system, relative to H's unit diagonal (constraint
// rows are O(1) per unit move): large, so that the constraints dominate, and
// finite, so that redundant rows are harmless.
constexpr double kkt_regularization = 1e6;
// Multiplier passes on one factorization at most; they stop earlier once the
// linearized residual meets the accuracy asked.
constexpr int multiplier_passes = 20;
// Relative accuracy of the multiplier passes (at most, with the exact
// Hessian, where it tightens with |c|), and of the displacement prediction.
constexpr double multiplier_accuracy = 1e-3;
// The congruence error is measured for the visitor every so many iterations:
// a Procrustes fit per cluster is too dear for every one.
constexpr int sqp_measure_period = 10;
// Bisections of the pull back toward the input within a panel tolerance
// (pull_back_toward_input()): each costs one congruence measurement, and 10
// place the result within 1e-3 of the move's length from the boundary of
// the tolerance along that line.
constexpr int pull_back_bisections = 10;
// The share of the panel tolerance the solvers aim at: their congruence
// error is relative to the mean edge of the current positions, the
// certificate is absolute, and a result whose edges grew by up to
// 1 / this factor stays within the tolerance.
constexpr double panel_tolerance_solver_share = 0.9;
// Starting trust region on the largest vertex move, in mean edge lengths: far
// from a solution a full step can fold the mesh.
constexpr double sqp_initial_radius = 0.5;
// Floor of the trust region, in mean edge lengths.
constexpr double sqp_min_radius = 1e-3;
// The trust region grows by this factor after a full step.
constexpr int sqp_radius_growth = 2;
// ... and shrinks by this factor after a shortened one.
constexpr double sqp_radius_shrink = 0.5;
// Inertia control: the first shift of an indefinite KKT matrix.
constexpr double sqp_first_shift = 1e-4;
// Inertia control: growth of the shift until the matrix is positive definite.
constexpr double sqp_shift_growth = 10;
// Inertia control: the shift at which the SQP phase gives up.
constexpr double sqp_max_shift = 1e8;
// Inertia control: decay of the shift from one iteration to the next.
constexpr double sqp_shift_decay = 3;
// Inertia control: below this, the decayed shift is floored.
constexpr double sqp_min_shift = 1e-8;
// Progress of a phase: an error below this fraction of the best so far.
constexpr double solver_progress = 0.9;
// Gauss-Newton iterations without progress that end the SQP phase.
constexpr int gauss_newton_patience = 5;
// Exact-Hessian iterations without progress that end the SQP phase: its error
// (stationarity included) falls less steadily.
constexpr int exact_hessian_patience = 10;
// Projection iterations without progress that end the projection.
constexpr int projection_patience = 10;
// Armijo's sufficient decrease of the l2 merit function.
constexpr double sqp_armijo = 1e-4;
// Backtracking factor of the line search; a step shortened below half keeps
// the trust region of Gauss-Newton from growing.
constexpr double sqp_backtracking = 0.5;
// The shortest step fraction the line search tries before it refuses.
constexpr double sqp_min_step_fraction = 1e-6;
// The merit's penalty nu stays at least this times |lambda|, above the exact
// penalty threshold.
constexpr int sqp_merit_margin = 2;
// Levenberg-Marquardt: starting theta in mu = theta |c|_inf / ell.
constexpr double lm_initial_theta = 1;
// Levenberg-Marquardt: floor of mu and of theta, so that round-off is not
// amplified.
constexpr double lm_min_damping = 1e-8;
// Levenberg-Marquardt: theta grows or shrinks by this factor.
constexpr double lm_damping_factor = 4;
// Levenberg-Marquardt: theta that ends the projection (no step decreases |c|).
constexpr double lm_max_theta = 1e12;
// Levenberg-Marquardt: a gain ratio rho (actual over predicted decrease)
// below this rejects the step.
constexpr double lm_min_gain_ratio = 1e-4;
// Levenberg-Marquardt: rho below this raises theta.
constexpr double lm_poor_gain_ratio = 0.25;
// Levenberg-Marquardt: rho above this lowers theta.
constexpr double lm_good_gain_ratio = 0.75;
// Once congruent, the projection stops at this fraction of the tolerance
// (times the mean edge): a few cheap quadratic steps reach round-off.
constexpr double lm_round_off_residual = 1e-3;

// Input checks (validation.h), relative to a double's range and precision.

// Largest accepted coordinate magnitude: squares (lengths, areas) of larger
// ones overflow a double.
constexpr double coordinate_limit = 1e150;
// Smallest accepted bounding-box diagonal: squares of smaller ones underflow.
constexpr double extent_limit = 1e-140;
// Smallest accepted diagonal relative to the largest coordinate: below it,
// doubles resolve the shape to less than the congruence tolerance.
constexpr double relative_extent_limit = 1e-7;
// Shortest accepted edge, relative to the bounding-box diagonal: far below any
// modelled detail, far above round-off.
constexpr double min_edge_length = 1e-12;
// Smallest accepted vector area of a face, relative to the squared diagonal.
constexpr double min_face_area = 1e-12;

// Shape quantities and measurements (quad_shape.h, congruence_quantities.h,
// Measure/congruence.h).

// planarity_defect() takes the largest corner triangle as its base when the
// base t0 t1 t2 has twice its area below this times the longest squared edge:
// t0, t1, t2 are then nearly collinear and the height would be meaningless.
constexpr double collinear_base = 1e-8;
// epsilon in P = |N|^2 S + epsilon S^3 of volume_shape(): keeps P > 0 on a
// collapsed quad, small against |N|^2 / S^2 of any quad of fair shape.
constexpr double volume_shape_epsilon = 1e-4;
// A cluster's mean S-quad with a planarity defect below this times its
// diagonal t0t2 is planar: its mold is its own mirror image, so no instance
// counts as mirrored.
constexpr double planar_mold_defect = 1e-9;

// The colours of the clusters (IO/cluster_colors.h): hues by the golden
// angle, saturation and value stepping through a few levels so that large
// counts stay distinct and every colour stays vivid and light enough.

// Saturation of the first colours.
constexpr double palette_saturation = 0.85;
// Saturation drops by this much per level.
constexpr double palette_saturation_step = 0.25;
// Value (brightness) of the first colours.
constexpr double palette_value = 0.95;
// Value drops by this much per level.
constexpr double palette_value_step = 0.2;
// Levels of saturation and of value, cycled.
constexpr int palette_levels = 3;
// Consecutive ids that share a saturation level.
constexpr int palette_saturation_period = 7;
// Consecutive ids that share a value level: a full cycle of saturations.
constexpr int palette_value_period = 21;


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
// The twist-sign rule (twist_sign.h) of the twist separation and the
// patch-segment candidates: a cluster mixes twists when some
// of its quads twist beyond this fraction of its largest twist one way and
// some the other way...
constexpr double twist_sign_fraction = 0.05;
// ... and beyond this relative twist (6 x signed volume / mean edge^3): a
// flatter quad is planar as far as its mold is concerned.
constexpr double planar_twist = 1e-3;
// Patch-segment candidates split a cluster that mixes twists by moving out
// the quads twisted against its larger sign by this many times the
// significance: at 1, the decocube at K = 9 (paper_table) keeps 11 degrees
// of flexibility instead of 16 and ends 12% farther.
constexpr double twist_split_margin = 6.0;
// The search optimizes ceil(optimized / this) twist-separated candidates,
// in pool order, beside the ranked candidates of the other origins, which
// they do not displace: they keep their shape where they can be solved, but
// lower the DOF and stall more often.
constexpr std::size_t twist_separated_extra_quota_divisor = 4;
// Patch-segment candidates: rounds of twist splits and merges, and splits
// per round, at most. A split changes the S-quads, and with them the
// labelling of near-symmetric quads, so splits repeat until none mixes; a
// candidate that still mixes twists after the last round is left out.
constexpr int patch_twist_passes = 8;
// Patch-segment candidates: the molds spread over the patches, times K, one
// candidate each; the merges across patches bring them to K.
constexpr std::size_t patch_mold_factors[3] = {1, 2, 4};
// The search optimizes ceil(optimized / this) patch-segment candidates
// beyond the ranked ones: as for grid segments, the patches' structure is
// worth more than the prediction ranks.
constexpr std::size_t patch_segment_extra_quota_divisor = 4;
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
// Transition sweeps: the transition rows between their groups are chosen
// among this many rows spread evenly (the dynamic program fits a sweep per
// pair of them).
constexpr std::size_t transition_row_choices = 64;
// Coaxial transition sweeps: a ring farther from its regular polygon than
// this many of its mean edge lengths is not round.
constexpr double round_ring_deviation = 0.05;
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

// Iterations polishing a sweep's exact start: a solve that leaves exact surfaces returns slowly.
constexpr int sweep_polish_iterations = 10;
// Multilevel start: a 2 x 2 refinement is coarsened while it has more faces than this, and is
// solved only if it then has at most this many: the whole search there takes about a minute.
constexpr std::size_t multilevel_coarsest_faces = 2000;
// Times the best result's iterations a later candidate may take: one slower is unlikely closer.
constexpr int iteration_cap_factor = 3;
// The least iteration cap of a later candidate, so that a quickly converged best does not starve it.
constexpr int minimum_iteration_cap = 30;
// Rounds beyond number_of_improvement_rounds that repair a result that is not tilable.
constexpr int repair_rounds = 4;
// Merges (least length spread first) an improvement round predicts: each one factorizes the matrix.
constexpr std::size_t predicted_merge_pairs = 4;
// Faces per tile of the deviation search's first K: a guess the gallop corrects in a few trials.
constexpr std::size_t faces_per_first_tile = 25;
// The least first K of the deviation search: one tile fits only a mesh of congruent faces.
constexpr std::size_t smallest_first_tile_count = 2;

} // namespace tuning
} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
