// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_H
#define CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_H

/// \file optimize_tilable_surface.h
/// Moves the vertices of a clustered quad mesh so that the instances of every
/// cluster become congruent (paper §4; user manual, section Optimization).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/conjugate_gradient.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/constrained_gauss_newton.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/displacement_estimate.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/fairness_operator.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/panel_tolerance.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/visitor.h>

#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// What `optimize_tilable_surface()` did and what it achieved.
struct Optimization_result
{
  /// Iterations performed.
  int iterations = 0;
  /// Whether the visitor stopped the solver (its `iteration()` returned
  /// `false`); `make_k_set_tilable()` then optimizes no further candidate.
  bool stopped_by_visitor = false;
  /// Whether the *measured* congruence error (`measure.congruence_error`)
  /// is at most `congruence_tolerance`, and with `planar_tiles` the measured
  /// `measure.planarity_error` too; never set from the solver's energy.
  bool converged = false;
  /// Whether the result is not tilable although the solver ended before its
  /// iteration limit, unstopped: its congruence error had stopped decreasing
  /// (in every attempt of `CONSTRAINED_GAUSS_NEWTON`, see `Solver_type`). The
  /// clustering then has no exact realization that the solver, which keeps
  /// close to the input, reaches: more iterations would not help; another
  /// clustering (the repair rounds of `make_k_set_tilable()`) or a larger K
  /// may. Not tilable, unstopped and not stalled means the iterations ran out.
  bool stalled = false;
  /// Why the solve ended, in words: "tilable", "stopped by the visitor",
  /// "stalled" (see `stalled`) or "iteration limit".
  const char* ending() const
  {
    return converged ? "tilable"
                     : (stopped_by_visitor ? "stopped by the visitor" : (stalled ? "stalled" : "iteration limit"));
  }
  /// The paper's five terms at the result, on positions normalized like the
  /// solver's (centred, unit bounding-box diagonal of the input).
  Energy_terms energy;
  /// The solver's own objective at the end (see `Solver_type`).
  double objective = 0;
  /// Seconds spent checking the input and setting the problem up.
  double setup_time = 0;
  /// Seconds spent in the solver.
  double solve_time = 0;
  /// Seconds spent measuring the result.
  double measure_time = 0;
  /// The measurements of the result against the input (`measure_tilability()`).
  Tilability_measure measure;
};

namespace internal {

// Whether result `a` is better than `b`: tilable before not, then one that
// does not cross itself (it could not be built otherwise), then closer to
// the input (symmetric Hausdorff distance), or, neither being tilable, the
// smaller congruence error.
CGAL_TILABLE_SURFACES_INLINE
bool is_better(const Optimization_result& a, const Optimization_result& b);

inline void check_parameter(bool ok, const std::string& what)
{
  if(!ok)
    throw Invalid_input("invalid parameter: " + what, Invalid_input::PARAMETER);
}

// Everything a solve needs, read from the mesh and the named parameters and
// checked: the problem, the solver settings, the fixed vertices, the
// normalized input X0 (centre of the bounding box at the origin, unit
// diagonal), the fairness operator and the closeness metric.
struct Optimization_setup
{
  Tilable_problem problem;
  Solver_type solver = CONSTRAINED_GAUSS_NEWTON;
  Solver_settings settings;
  double panel_tolerance = 0; // model units; 0: exact mode
  std::vector<std::size_t> mesh_face_index; // per problem face (mesh_face_indices())
  std::vector<bool> fixed;
  Eigen::RowVector3d centre;
  double scale = 1;
  Point_matrix X0;
  Eigen::SparseMatrix<double> D;
  std::vector<Eigen::Matrix3d> metric;

  template <typename PolygonMesh, typename NamedParameters>
  Optimization_setup(Validated_mesh, const PolygonMesh& pm, const NamedParameters& np)
  {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    namespace TS_np = CGAL::Tilable_surfaces::internal_np;
    typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;

    panel_tolerance = panel_tolerance_of(np);
    problem = make_tilable_problem(pm, np);
    mesh_face_index = mesh_face_indices(pm, np);
    solver = parameter_or(np, TS_np::solver, defaults::solver);
    const bool gauss_newton = (solver == CONSTRAINED_GAUSS_NEWTON);
    settings.weights.distance = parameter_or(np, TS_np::distance_weight, defaults::distance_weight);
    settings.weights.fairness = parameter_or(np, TS_np::fairness_weight, default_fairness_weight(solver));
    const double tangential = parameter_or(np, TS_np::tangential_weight, defaults::tangential_weight);
    settings.weights.edge_length = parameter_or(np, TS_np::edge_length_weight, defaults::edge_length_weight);
    settings.weights.diagonal = parameter_or(np, TS_np::diagonal_weight, defaults::diagonal_weight);
    settings.weights.volume = parameter_or(np, TS_np::volume_weight, defaults::volume_weight);
    settings.congruence_tolerance = parameter_or(np, TS_np::congruence_tolerance, defaults::congruence_tolerance);
    settings.convergence_tolerance =
      parameter_or(np, TS_np::convergence_tolerance, default_convergence_tolerance(solver));
    settings.max_iterations =
      parameter_or(np, CGAL::internal_np::number_of_iterations, default_number_of_iterations(solver));

    check_parameter(solver == CONSTRAINED_GAUSS_NEWTON || solver == PAPER_CONJUGATE_GRADIENT,
                    "unknown solver");
    const Energy_terms& w = settings.weights;
    for(double mu : {w.distance, w.fairness, w.edge_length, w.diagonal, w.volume})
      check_parameter(std::isfinite(mu) && mu >= 0, "the weights must be finite and >= 0");
    check_parameter(!gauss_newton || w.distance > 0,
                    "distance_weight must be > 0 for the constrained solver");
    check_parameter(settings.congruence_tolerance > 0 && settings.convergence_tolerance >= 0,
                    "the tolerances must be > 0");
    check_parameter(settings.max_iterations >= 0, "number_of_iterations must be >= 0");
    check_parameter(gauss_newton || !problem.planar,
                    "planar_tiles needs the default solver (CONSTRAINED_GAUSS_NEWTON)");
    check_parameter(tangential > 0 && tangential <= 1, "tangential_weight must be in (0, 1]");
    if(panel_tolerance > 0)
      hold_to_panel_tolerance();

    const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
    const auto vcm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_is_constrained),
                                      CGAL::Static_boolean_property_map<vertex_descriptor, false>());
    fixed.assign(problem.number_of_vertices(), false);
    for(vertex_descriptor v : vertices(pm))
      fixed[get(vim, v)] = get(vcm, v);

    const Eigen::RowVector3d lo = problem.points.colwise().minCoeff();
    const Eigen::RowVector3d hi = problem.points.colwise().maxCoeff();
    centre = 0.5 * (lo + hi);
    scale = (hi - lo).norm();
    X0 = (problem.points.rowwise() - centre) / scale;
    const std::vector<bool> features = feature_vertices(pm, problem.points, np);
    D = fairness_operator(pm, vim, features);
    metric = closeness_metrics(pm, vim, problem.points, features, tangential);
  }

  Solver_input input() const { return Solver_input{problem, D, X0, fixed, metric}; }

private:
  // A panel tolerance replaces congruence_tolerance: the solvers' error is
  // relative to the mean edge, T absolute, so they aim at a share of T over
  // the input's mean edge (tuning::panel_tolerance_solver_share) and
  // measure_result() certifies T itself.
  void hold_to_panel_tolerance()
  {
    const double ell = mean_edge_length(problem, problem.points);
    settings.congruence_tolerance = tuning::panel_tolerance_solver_share * panel_tolerance / ell;
    settings.within_tolerance_suffices = true;
  }
};

// The positions `start` (by vertex index, in mesh units) normalized like the
// solver's input, the fixed vertices at their input positions, in `S`; true
// when the clustering is exact there, so the default solver may start there.
CGAL_TILABLE_SURFACES_INLINE
bool normalized_exact_start(const Optimization_setup& setup, const Point_matrix& start, Point_matrix& S);

// The input points moved by the displacement of the normalized positions Y
// from X0, scaled back to mesh units; fixed vertices keep their input point.
CGAL_TILABLE_SURFACES_INLINE
Point_matrix moved_points(const Optimization_setup& setup, const Point_matrix& Y);

// Measures the normalized positions Y against the input into `result`, and
// whether they meet the tolerance.
CGAL_TILABLE_SURFACES_INLINE
void measure_result(const Optimization_setup& setup, const Point_matrix& Y, Optimization_result& result);

// Measures the solver's result X; with `compare_with_start`, also the exact
// start S, and keeps in X, and in `result`, the better of the two.
CGAL_TILABLE_SURFACES_INLINE
void measure_better_result(const Optimization_setup& setup, const Point_matrix& S,
                           bool compare_with_start, Point_matrix& X, Optimization_result& result);

// Writes back the points of the vertices that moved, as their input position
// plus the displacement in mesh units; fixed vertices are never written.
template <class PolygonMesh, typename NamedParameters>
void write_moved_points(PolygonMesh& pm, const NamedParameters& np, const Optimization_setup& setup,
                        const Point_matrix& X)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename GetVertexPointMap<PolygonMesh, NamedParameters>::type VertexPointMap;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  VertexPointMap vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                        get_property_map(CGAL::vertex_point, pm));
  for(vertex_descriptor v : vertices(pm))
  {
    const std::size_t i = get(vim, v);
    const Eigen::RowVector3d displacement = X.row(i) - setup.X0.row(i);
    if(setup.fixed[i] || displacement.isZero(0))
      continue;
    const Eigen::RowVector3d p = setup.problem.points.row(i) + setup.scale * displacement;
    put(vpm, v, Point(p(0), p(1), p(2)));
  }
}

// optimize_tilable_surface() on a mesh validate_panel_mesh() accepted. With
// `start` (positions by vertex index, in mesh units) at which the clustering
// is exact, the default solver starts there instead of at the input, and the
// start is the result unless the solve's result is better by is_better():
// tilable, not crossing itself where the start does, or else closer to the
// input (symmetric Hausdorff distance): the solve lowers its own
// closeness objective, which may move the surface away in the Hausdorff
// sense (enneper2.obj, K = 36: 16.9% -> 17.8% after 40 iterations). A start
// that is not exact is ignored.
template <class PolygonMesh, typename NamedParameters>
Optimization_result optimize_tilable_surface(Validated_mesh, PolygonMesh& pm, const NamedParameters& np,
                                             const Point_matrix* start = nullptr)
{
  Optimization_result result;
  CGAL::Real_timer timer;
  timer.start();
  const Optimization_setup setup(Validated_mesh(true), pm, np);
  result.setup_time = timer.time();

  timer.reset();
  Solver_input input = setup.input();
  Point_matrix S;
  if(start != nullptr && setup.solver == CONSTRAINED_GAUSS_NEWTON && !setup.problem.planar &&
     normalized_exact_start(setup, *start, S))
    input.start = &S;
  auto&& visitor = visitor_of(np);
  Point_matrix X;
  const Solver_report report =
    setup.solver == CONSTRAINED_GAUSS_NEWTON
      ? constrained_gauss_newton(input, setup.settings, X, visitor)
      : polak_ribiere(input, setup.settings, X, visitor);
  // A solve that made no step from the start (stopped there by the visitor,
  // or given no iteration) returns the start itself, measured once.
  const bool compare_with_start = input.start != nullptr && report.iterations > 0;
  if(input.start != nullptr && !compare_with_start)
    X = S;
  result.iterations = report.iterations;
  result.stopped_by_visitor = report.stopped_by_visitor;
  result.objective = report.objective;
  result.energy = paper_energy(setup.problem, setup.D, X, setup.X0);
  result.solve_time = timer.time();

  timer.reset();
  measure_better_result(setup, S, compare_with_start, X, result);
  result.stalled = !result.converged && !result.stopped_by_visitor &&
                   report.iterations < setup.settings.max_iterations;
  result.measure_time = timer.time();
  write_moved_points(pm, np, setup, X);
  return result;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Moves the vertices of `pm` so that it becomes tilable by the S-quads of
/// the clustering given in `np`: the instances of each cluster congruent up to
/// proper rigid motions (or any rigid motion, mirrors included, with
/// `orientation_policy` `ALLOW_MIRRORED_PANELS`), within
/// `congruence_tolerance` (user manual, section Definitions).
///
/// The input is checked first (`validate_panel_mesh()`, cluster ids and
/// orientations) and nothing is modified when it is refused. The solvers work
/// on a copy of the points centred and scaled to a unit bounding-box
/// diagonal, so the result commutes with similarities of the input and every
/// tolerance is relative. Only the vertices that moved are written back, as
/// their input position plus the displacement: a vertex that does not move
/// keeps its exact coordinates, and constrained vertices are never written.
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `MutableFaceGraph`
///   whose faces are quads.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} (required) cluster of every face,
///     0..K-1; K = 1 + the largest id \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} (required) orientation of every
///     face's instance, 0..7 or `Panel_orientation` (see `quad_shape.h`) \cgalParamNEnd
///   \cgalParamNBegin{orientation_policy} with `ALLOW_MIRRORED_PANELS`, an
///     instance may be the mirror image of its S-quad: the signed volumes are
///     then left free, since the edges and diagonals alone fix a quad up to a
///     proper or improper motion; default `PROPER_RIGID_MOTIONS` \cgalParamNEnd
///   \cgalParamNBegin{planar_tiles} every panel planar as well as congruent:
///     the distance between the diagonals of every face within
///     `congruence_tolerance` of the mean edge length
///     (`Tilability_measure::planarity_error`); default solver only; default
///     `false` \cgalParamNEnd
///   \cgalParamNBegin{solver} a `Solver_type`; default `CONSTRAINED_GAUSS_NEWTON` \cgalParamNEnd
///   \cgalParamNBegin{distance_weight} mu1, default 1e-4 (must be > 0 for the
///     default solver) \cgalParamNEnd
///   \cgalParamNBegin{fairness_weight} mu2, default 1e-6 (Gauss-Newton) or 1e-4
///     (conjugate gradient) \cgalParamNEnd
///   \cgalParamNBegin{edge_length_weight} mu3, default 1 (conjugate gradient only) \cgalParamNEnd
///   \cgalParamNBegin{diagonal_weight} mu4, default 1 (conjugate gradient only) \cgalParamNEnd
///   \cgalParamNBegin{volume_weight} mu5, default 1 (conjugate gradient only) \cgalParamNEnd
///   \cgalParamNBegin{congruence_tolerance} target congruence error, default 1e-6 \cgalParamNEnd
///   \cgalParamNBegin{panel_tolerance} T in model units: every instance
///     within T of its mold (largest corner distance after the best rigid
///     fit) suffices, replacing `congruence_tolerance`; the default solver
///     leaves a start already within T unmoved, and pulls its result back
///     toward the input while it stays within T; a finite length >= 0,
///     default 0 (exact mode) \cgalParamNEnd
///   \cgalParamNBegin{convergence_tolerance} Gauss-Newton: stop once congruent
///     and the largest step is below this fraction of the mean edge length,
///     default 1e-9; conjugate gradient: stop when the relative decrease of
///     the energy is below it, default 1e-12 \cgalParamNEnd
///   \cgalParamNBegin{number_of_iterations} at most this many iterations,
///     default 300 (Gauss-Newton) or 5000 (conjugate gradient) \cgalParamNEnd
///   \cgalParamNBegin{feature_angle} dihedral angle in degrees above which an
///     edge is a sharp feature left out of the fairness term, default 60 \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map} feature edges, replacing the
///     detection by angle \cgalParamNEnd
///   \cgalParamNBegin{vertex_is_constrained_map} vertices that must not move \cgalParamNEnd
///   \cgalParamNBegin{visitor} a `Default_visitor` (or a class with its
///     interface), by value or as `std::ref` \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of the vertices \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} indices of the vertices, for messages
///     and internal arrays \cgalParamNEnd
///   \cgalParamNBegin{face_index_map} indices of the faces, likewise \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the iterations, whether the measured congruence error reached the
///   tolerance, the energy terms, timings and the full `Tilability_measure`.
///   When the constraints cannot be met (the solver stagnates), `converged`
///   is `false` and the measure says how far the result is.
/// \throws Invalid_input for an invalid mesh, clustering or parameter.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Optimization_result optimize_tilable_surface(PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  validate_panel_mesh(pm, np);
  return internal::optimize_tilable_surface(internal::Validated_mesh(true), pm, internal::canonical_parameters(np));
}

/// \ingroup PkgTilableSurfacesRef
/// How far a clustering is predicted to move the surface (see
/// `predict_displacement()`), as fractions of the input's bounding-box
/// diagonal.
struct Displacement_prediction
{
  /// The largest predicted move of a vertex off the input surface, measured
  /// in the default solver's closeness metric (a move along the input's
  /// normal counts fully, a slide in it by `tangential_weight`).
  double max = 0;
  /// The root mean square of the same moves over the vertices.
  double rms = 0;
  /// The largest predicted move of a vertex, in plain distance.
  double max_euclidean = 0;
};

namespace internal {

// predict_displacement() on a mesh validate_panel_mesh() accepted.
template <class PolygonMesh, typename NamedParameters>
Displacement_prediction predict_displacement(Validated_mesh, const PolygonMesh& pm, const NamedParameters& np)
{
  const Optimization_setup setup(Validated_mesh(true), pm, np);
  const Displacement_estimate e =
    linearized_displacement(setup.input(), setup.settings);
  Displacement_prediction p;
  p.max = e.max;
  p.rms = e.rms;
  p.max_euclidean = e.step.rowwise().norm().maxCoeff();
  return p;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Predicts how far the default solver of `optimize_tilable_surface()` will
/// move `pm` to make it tilable by the clustering in `np`, without moving
/// it: the least-norm linearized step from the input, the smallest move (in
/// the solver's metric) that meets the congruence constraints linearized at
/// the input. It is the solver's first step before any line search, and costs one
/// sparse factorization: use it to compare clusterings by what they cost
/// rather than by their shapes.
///
/// Takes the named parameters of `optimize_tilable_surface()` (the two maps
/// are required) and throws as it does.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Displacement_prediction predict_displacement(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  validate_panel_mesh(pm, np);
  return internal::predict_displacement(internal::Validated_mesh(true), pm, internal::canonical_parameters(np));
}

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/optimize_tilable_surface_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_H
