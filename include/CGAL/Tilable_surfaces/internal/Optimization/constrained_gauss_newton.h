// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H

// The default solver: the surface closest to the input subject to the
// congruence constraints c(X) = 0 of energy_terms.h, held as hard constraints.
//
//   min_d  1/2 d^T H d,  H = mu1 I + mu2 D^T D (per coordinate),  X = X0 + d,
//   s.t.   c(X0 + d) = 0.
//
// The fairness acts on the displacement d, not on X: with no constraint the
// input is the solution, so a clustering that is already exact does not move.
// Each iteration is a Gauss-Newton SQP step: the minimum of the quadratic
// model subject to the linearized constraints J delta = -c, computed on the
// regularized KKT system
//   [H  J^T ] [delta ]   [-H d]
//   [J  -I/b] [lambda] = [-c  ]
// in its primal form (H + b J^T J) delta = -(H d + J^T lambda + b J^T c), a
// sparse SPD system (rows of J touch at most 8 vertices; there is no
// auxiliary target variable, hence no dense row), with a few multiplier
// passes on the same factorization to remove the regularization's bias. The
// regularization makes redundant constraints harmless (K << F is
// over-determined, method notes §4b). Globalization: a trust region on the
// largest vertex move and a backtracking line search on the l2 merit
// 1/2 d^T H d + nu |c|.
//
// With H alone (Gauss-Newton) these steps approach the optimum only
// linearly, and near it the merit rejects the tangential steps (Maratos
// effect). The exact variant adds the constraints' curvature
// sum lambda_i d^2 c_i (congruence_constraints.h) with inertia control, and
// tries a second-order correction before cutting a full step. But K << F
// makes the constraints redundant, so no solution is regular: far from
// feasibility the linearization is inconsistent, lambda is then b times its
// residual (|lambda| ~ 1e4), and the curvature term needs a large shift. In
// measurements no variant dominates (they reach different local solutions),
// hence Gauss-Newton attempts first and an exact-Hessian attempt from the
// input when they fall short (Sqp_variant).
//
// Once phase 1 stops making progress, a projection phase takes over:
// Levenberg-Marquardt on min |c(X)|^2 in the metric H,
// (J^T J + mu H) delta = -J^T c with mu ~ |c|, quadratic to a zero residual
// where J has full rank, linear (rho ~ 0.9) where it does not. Its volume
// rows are those of volume_shape() (Volume_quantity): the SQP phase's rows
// miss the out-of-plane error of slivers (seashell K = 44: residual 1.2e-6,
// congruence error 3e-4).
//
// The congruence error (Procrustes on every cluster) is only measured when
// the largest residual, in mean edge lengths, says it may be within the
// tolerance, and every few iterations for the visitor; in between the
// visitor sees that residual as an estimate.

#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// b relative to H's unit diagonal; constraint rows are O(1) per unit move.
constexpr double kkt_regularization() { return 1e6; }

// The step of the quadratic model with gradient `gradient` subject to
// J step = -`target`, by the method of multipliers on the regularized KKT
// system H + b J^T J factorized in `solver`: each pass is one
// back-substitution. `multipliers` is the starting guess and receives the new
// multipliers. Passes stop once the linearized residual is below
// `eta` |target|.
inline Eigen::VectorXd multiplier_step(const SPD_solver& solver, const Eigen::SparseMatrix<double>& J,
                                       double b, const Eigen::VectorXd& gradient,
                                       const Eigen::VectorXd& target, Eigen::VectorXd& multipliers,
                                       double eta)
{
  Eigen::VectorXd step;
  for(int pass = 0; pass < 20; ++pass)
  {
    step = solver.solve(-(gradient + J.transpose() * (multipliers + b * target)));
    const Eigen::VectorXd linear_residual = target + J * step;
    multipliers += b * linear_residual;
    if(linear_residual.norm() <= eta * target.norm())
      break;
  }
  return step;
}

// The phase-1 variants, in the order they are tried. The cautious one halves
// the trust region whenever the line search shortens a step; the other keeps
// it when half the step is accepted, since the Maratos effect rejects most
// full Gauss-Newton steps even near a solution and halving then shrinks the
// steps to nothing (tunnel K = 12: 164 iterations instead of 14).
// The isotropic one measures closeness with M_v = I instead of the
// closeness metric (closeness_objective.h): slides in the surface are then
// as dear as leaving it, which converges where cheap slides shear the quads
// into slivers (monkey saddle, K = 24: 3.1e-5 after 300 iterations with the
// metric alone).
enum Sqp_variant { GAUSS_NEWTON, ISOTROPIC_GAUSS_NEWTON, CAUTIOUS_GAUSS_NEWTON, EXACT_HESSIAN };

// One solve from the input, numbering its iterations from `first_iteration`
// + 1; `stopped` tells whether the visitor stopped it. Phase 1 uses the
// exact Lagrangian Hessian or only H (Gauss-Newton), as `variant` says.
template <typename Visitor>
Solver_report constrained_gauss_newton_attempt(const Solver_input& in, const Solver_settings& settings,
                                               Sqp_variant variant, int first_iteration,
                                               Point_matrix& X, Visitor& visitor, bool& stopped)
{
  const bool exact_hessian = variant == EXACT_HESSIAN;
  typedef Eigen::SparseMatrix<double> Matrix;
  std::vector<int> variable;
  const int n = number_free_unknowns(in.fixed, variable);
  const double ell = mean_edge_length(in.problem, in.X0);
  const double tolerance = settings.congruence_tolerance;
  const Congruence_constraints constraints(in.problem, ell);
  const std::vector<Eigen::Matrix3d> isotropic(variant == ISOTROPIC_GAUSS_NEWTON ? in.metric.size() : 0,
                                               Eigen::Matrix3d::Identity());
  const Closeness_objective objective(in.problem, in.X0,
                                      variant == ISOTROPIC_GAUSS_NEWTON ? isotropic : in.metric,
                                      settings.weights.fairness / settings.weights.distance, variable, n);
  const Matrix& H = objective.hessian();
  const double b = kkt_regularization();
  const int measure_period = 10;

  auto positions = [&](const Eigen::VectorXd& d) {
    Point_matrix Y = in.X0;
    for(int v = 0; v < int(variable.size()); ++v)
      if(variable[v] >= 0)
        Y.row(v) += d.segment<3>(variable[v]).transpose();
    return Y;
  };
  auto largest_move = [&](const Eigen::VectorXd& delta) {
    double m = 0;
    for(int k = 0; k < n; k += 3)
      m = (std::max)(m, delta.segment<3>(k).norm());
    return m;
  };

  Eigen::VectorXd d = Eigen::VectorXd::Zero(n), c, c_trial, delta;
  Matrix J, identity(n, n);
  identity.setIdentity();
  SPD_solver solver;
  Solver_report report;
  X = in.X0;
  report.congruence_error = congruence_error(in.problem, X);
  if(n == 0 || constraints.number_of_rows() == 0)
    return report;
  constraints.evaluate(X, variable, n, c, nullptr);

  // After an accepted step: the congruence estimate, measured when it may
  // meet the tolerance; false when the visitor stops the solver.
  int it = first_iteration;
  bool measured = false;
  stopped = false;
  auto record = [&]() {
    ++it;
    report.iterations = it;
    report.objective = settings.weights.distance * objective.value(X);
    const double residual = c.cwiseAbs().maxCoeff() / ell;
    measured = residual <= tolerance || it % measure_period == 0;
    report.congruence_error = measured ? congruence_error(in.problem, X) : residual;
    stopped = !visitor.iteration(it, report.congruence_error, report.objective);
    return !stopped;
  };
  auto congruent = [&]() { return measured && report.congruence_error <= tolerance; };

  auto kkt_step = [&](const Eigen::VectorXd& gradient, const Eigen::VectorXd& target,
                      Eigen::VectorXd& multipliers, double eta) {
    return multiplier_step(solver, J, b, gradient, target, multipliers, eta);
  };

  // Phase 1: SQP steps, with the exact Lagrangian Hessian
  // W = H + sum lambda_i d^2 c_i shifted by shift I until the KKT matrix has
  // the inertia of a minimum (inertia control, as in IPOPT), while they
  // make progress.
  double nu = 0, radius = 0.5, shift = 0, best_error = std::numeric_limits<double>::infinity();
  int iterations_since_best = 0;
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(c.size());
  while(it < settings.max_iterations)
  {
    constraints.evaluate(X, variable, n, c, &J);
    const Eigen::VectorXd Hd = objective.gradient(X);
    Matrix K = H + b * Matrix(J.transpose() * J);
    if(exact_hessian)
      K += constraints.lagrangian_hessian(X, variable, n, lambda);
    shift = shift == 0 ? 0 : (std::max)(shift / 3, 1e-8);
    while(!solver.factorize(Matrix(K + shift * identity)) && shift < 1e8)
      shift = shift == 0 ? 1e-4 : 10 * shift;
    if(!solver.positive_definite() || shift >= 1e8)
      break;
    // Progress: the optimality error (stationarity at the current
    // multipliers) with the exact Hessian, else the largest residual.
    const double residual = c.cwiseAbs().maxCoeff() / ell;
    const double error =
      exact_hessian ? (std::max)(residual, (Hd + J.transpose() * lambda).cwiseAbs().maxCoeff()) : residual;
    if(error < 0.9 * best_error)
    {
      best_error = error;
      iterations_since_best = 0;
    }
    else if(++iterations_since_best >= (exact_hessian ? 10 : 5))
      break;
    // With the exact Hessian, inexact multiplier passes warm-started from the
    // previous multipliers, with a relative accuracy that tightens as |c|
    // falls, keep the local convergence quadratic. Gauss-Newton converges
    // linearly anyway; there, passes from zero at a fixed accuracy measured
    // as good or better (decocube K = 15: 10 iterations instead of 44).
    const double eta = exact_hessian ? (std::min)(1e-3, residual) : 1e-3;
    Eigen::VectorXd lambda_trial = exact_hessian ? lambda : Eigen::VectorXd::Zero(c.size());
    delta = kkt_step(Hd, c, lambda_trial, eta);
    // Line search on the l2 merit f + nu |c|, nu above |lambda|.
    nu = (std::max)(nu, 2 * lambda_trial.norm());
    const double merit_now = objective.value(X) + nu * c.norm();
    const double slope = (std::min)(delta.dot(Hd) - nu * c.norm(), 0.0);
    auto acceptable = [&](const Eigen::VectorXd& dd, double alpha) {
      const Point_matrix Y = positions(dd);
      constraints.evaluate(Y, variable, n, c_trial, nullptr);
      return objective.value(Y) + nu * c_trial.norm() <= merit_now + 1e-4 * alpha * slope;
    };
    // Trust region on the largest vertex move, in edge lengths: far from a
    // solution the linearization is poor and a full step can fold the mesh.
    // It doubles after a step the line search accepts at once, halves
    // otherwise (see Sqp_variant).
    const double alpha_max = (std::min)(1.0, radius * ell / largest_move(delta));
    double alpha = alpha_max;
    Eigen::VectorXd d_trial = d + alpha * delta;
    bool accepted = acceptable(d_trial, alpha);
    if(!accepted && alpha == 1.0 && exact_hessian)
    {
      // Second-order correction against the Maratos effect: the full step
      // plus the least-W-norm move back onto the constraints' linearization
      // at its end point. Only with the exact Hessian: with Gauss-Newton it
      // measured no gain.
      Eigen::VectorXd correction_multipliers = Eigen::VectorXd::Zero(c.size());
      const Eigen::VectorXd correction =
        kkt_step(Eigen::VectorXd::Zero(n), c_trial, correction_multipliers, eta);
      d_trial = d + delta + correction;
      accepted = acceptable(d_trial, alpha);
    }
    for(alpha *= 0.5; !accepted && alpha >= 1e-6; alpha *= 0.5)
    {
      d_trial = d + alpha * delta;
      accepted = acceptable(d_trial, alpha);
    }
    if(!accepted) // the merit refuses the step: leave it to the projection
      break;
    if(alpha == alpha_max)
      radius *= 2;
    else if(variant == CAUTIOUS_GAUSS_NEWTON || variant == EXACT_HESSIAN || alpha < 0.5 * alpha_max)
      radius = (std::max)(0.5 * radius, 1e-3);
    // Multipliers of the full step; those of a shortened step are blended.
    lambda += (std::min)(alpha, 1.0) * (lambda_trial - lambda);
    const double step_length = largest_move(d_trial - d);
    d = d_trial;
    X = positions(d);
    c = c_trial;
    if(!record())
      return report;
    if(congruent() && step_length <= settings.convergence_tolerance * ell)
      return report;
  }

  // Phase 2: Levenberg-Marquardt projection onto c = 0, mu = theta |c|_inf / ell,
  // theta adapted by the ratio of actual to predicted decrease of |c|^2.
  const Congruence_constraints projection(in.problem, ell, VOLUME_SHAPE);
  projection.evaluate(X, variable, n, c, nullptr);
  double theta = 1, best_residual = c.cwiseAbs().maxCoeff();
  iterations_since_best = 0;
  while(it < settings.max_iterations && theta < 1e12)
  {
    projection.evaluate(X, variable, n, c, &J);
    // The floor bounds the conditioning, so that round-off is not amplified.
    const double mu = (std::max)(theta * c.cwiseAbs().maxCoeff() / ell, 1e-8);
    if(!solver.factorize(Matrix(Matrix(J.transpose() * J) + mu * objective.isotropic_hessian())))
    { // mu too small for round-off: damp more
      theta *= 4;
      continue;
    }
    delta = solver.solve(-(J.transpose() * c));
    const Eigen::VectorXd d_trial = d + delta;
    const Point_matrix X_trial = positions(d_trial);
    projection.evaluate(X_trial, variable, n, c_trial, nullptr);
    const double predicted = c.squaredNorm() - (c + J * delta).squaredNorm();
    const double rho = (c.squaredNorm() - c_trial.squaredNorm()) / predicted;
    if(!(predicted > 0 && rho > 1e-4))
    {
      theta *= 4;
      continue;
    }
    theta = rho > 0.75 ? (std::max)(theta / 4, 1e-8) : (rho < 0.25 ? 4 * theta : theta);
    d = d_trial;
    X = X_trial;
    c = c_trial;
    if(!record())
      return report;
    const double residual = c.cwiseAbs().maxCoeff();
    // Once congruent, a few more cheap quadratic steps reach round-off.
    if(congruent() && (residual <= 1e-3 * tolerance * ell ||
                       largest_move(delta) <= settings.convergence_tolerance * ell))
      break;
    if(residual < 0.9 * best_residual)
    {
      best_residual = residual;
      iterations_since_best = 0;
    }
    else if(++iterations_since_best >= 10)
      break;
  }
  if(!measured)
    report.congruence_error = congruence_error(in.problem, X);
  return report;
}

// Each variant in turn from the input while the previous ones end short of
// the tolerance, within the remaining iterations. They reach different local
// solutions of the over-determined problem (method notes §4b) and none always
// succeeds; the best result is kept.
template <typename Visitor>
Solver_report constrained_gauss_newton(const Solver_input& in, const Solver_settings& settings,
                                       Point_matrix& X, Visitor& visitor)
{
  bool stopped = false;
  Solver_report report = constrained_gauss_newton_attempt(in, settings, GAUSS_NEWTON, 0, X, visitor, stopped);
  for(Sqp_variant variant : {ISOTROPIC_GAUSS_NEWTON, CAUTIOUS_GAUSS_NEWTON, EXACT_HESSIAN})
  {
    if(stopped || report.congruence_error <= settings.congruence_tolerance ||
       report.iterations >= settings.max_iterations)
      break;
    Point_matrix Y;
    const Solver_report other =
      constrained_gauss_newton_attempt(in, settings, variant, report.iterations, Y, visitor, stopped);
    const int iterations = (std::max)(report.iterations, other.iterations);
    if(other.congruence_error < report.congruence_error)
    {
      X = Y;
      report = other;
    }
    report.iterations = iterations;
  }
  report.stopped_by_visitor = stopped;
  return report;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H
