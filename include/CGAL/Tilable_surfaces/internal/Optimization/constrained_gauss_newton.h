// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H

// The default solver: the surface closest to the input subject to the
// congruence constraints c(X) = 0 of congruence_quantities.h, held as hard
// constraints.
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
// over-determined: user manual, section Optimization). Globalization: a trust region on the
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

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The step of the quadratic model with gradient `gradient` subject to
// J step = -`target`, by the method of multipliers on the regularized KKT
// system H + b J^T J factorized in `solver`: each pass is one
// back-substitution. `multipliers` is the starting guess and receives the new
// multipliers. Passes stop once the linearized residual is below
// `eta` |target|.
CGAL_TILABLE_SURFACES_INLINE
Eigen::VectorXd multiplier_step(const SPD_solver& solver, const Eigen::SparseMatrix<double>& J,
                                double b, const Eigen::VectorXd& gradient,
                                const Eigen::VectorXd& target, Eigen::VectorXd& multipliers,
                                double eta);

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
// + 1; `stopped` tells whether the visitor stopped it. The first attempt of a
// solve (`shows_start`) also shows the visitor its starting point. Phase 1 uses the
// exact Lagrangian Hessian or only H (Gauss-Newton), as `variant` says.
template <typename Visitor>
class Sqp_attempt
{
  typedef Eigen::SparseMatrix<double> Matrix;

public:
  Sqp_attempt(const Solver_input& in, const Solver_settings& settings, Sqp_variant variant, bool shows_start,
              int first_iteration, Point_matrix& X, Visitor& visitor, bool& stopped)
    : m_in(in), m_settings(settings), m_variant(variant), m_shows_start(shows_start)
    , m_exact_hessian(variant == EXACT_HESSIAN)
    , m_n(number_free_unknowns(in.fixed, m_variable)), m_ell(mean_edge_length(in.problem, in.X0))
    , m_tolerance(settings.congruence_tolerance), m_constraints(in.problem, m_ell)
    , m_isotropic(variant == ISOTROPIC_GAUSS_NEWTON ? in.metric.size() : 0, Eigen::Matrix3d::Identity())
    , m_objective(in.problem, in.X0, variant == ISOTROPIC_GAUSS_NEWTON ? m_isotropic : in.metric,
                  settings.weights.fairness / settings.weights.distance, m_variable, m_n)
    , m_X(X), m_visitor(visitor), m_stopped(stopped), m_it(first_iteration)
  {}

  Solver_report run()
  {
    m_d = Eigen::VectorXd::Zero(m_n);
    if(m_in.start != nullptr)
      for(int v = 0; v < int(m_variable.size()); ++v)
        if(m_variable[v] >= 0)
          m_d.segment<3>(m_variable[v]) = (m_in.start->row(v) - m_in.X0.row(v)).transpose();
    m_X = positions(m_d);
    m_report.congruence_error = congruence_error(m_in.problem, m_X);
    m_measured = true;
    if(m_n == 0 || m_constraints.number_of_rows() == 0 || (m_settings.within_tolerance_suffices && congruent()))
      return m_report;
    m_constraints.evaluate(m_X, m_variable, m_n, m_c, nullptr);
    m_stopped = false;
    // Iteration 0: a caller out of time can stop before any step.
    if(m_shows_start &&
       !m_visitor.iteration(0, m_report.congruence_error, m_settings.weights.distance * m_objective.value(m_X)))
    {
      m_stopped = true;
      return m_report;
    }
    if(sqp_phase() || projection_phase())
      return m_report;
    if(!m_measured)
      m_report.congruence_error = congruence_error(m_in.problem, m_X);
    return m_report;
  }

private:
  Point_matrix positions(const Eigen::VectorXd& d) const
  {
    Point_matrix Y = m_in.X0;
    for(int v = 0; v < int(m_variable.size()); ++v)
      if(m_variable[v] >= 0)
        Y.row(v) += d.segment<3>(m_variable[v]).transpose();
    return Y;
  }

  double largest_move(const Eigen::VectorXd& delta) const
  {
    double m = 0;
    for(int k = 0; k < m_n; k += 3)
      m = (std::max)(m, delta.segment<3>(k).norm());
    return m;
  }

  // After an accepted step: the congruence estimate, measured when it may
  // meet the tolerance; false when the visitor stops the solver.
  bool record()
  {
    ++m_it;
    m_report.iterations = m_it;
    m_report.objective = m_settings.weights.distance * m_objective.value(m_X);
    const double residual = m_c.cwiseAbs().maxCoeff() / m_ell;
    m_measured = residual <= m_tolerance || m_it % tuning::sqp_measure_period == 0;
    m_report.congruence_error = m_measured ? congruence_error(m_in.problem, m_X) : residual;
    m_stopped = !m_visitor.iteration(m_it, m_report.congruence_error, m_report.objective);
    return !m_stopped;
  }

  bool congruent() const { return m_measured && m_report.congruence_error <= m_tolerance; }

  Eigen::VectorXd kkt_step(const Eigen::VectorXd& gradient, const Eigen::VectorXd& target,
                           Eigen::VectorXd& multipliers, double eta) const
  {
    return multiplier_step(m_solver, m_J, tuning::kkt_regularization, gradient, target, multipliers, eta);
  }

  // Factorizes K + shift I, raising the shift until it is positive definite;
  // false when it cannot be.
  bool factorize_shifted(const Matrix& K, double& shift)
  {
    if(m_identity.rows() != m_n)
    {
      m_identity.resize(m_n, m_n);
      m_identity.setIdentity();
    }
    shift = shift == 0 ? 0 : (std::max)(shift / tuning::sqp_shift_decay, tuning::sqp_min_shift);
    while(!m_solver.factorize(Matrix(K + shift * m_identity)) && shift < tuning::sqp_max_shift)
      shift = shift == 0 ? tuning::sqp_first_shift : tuning::sqp_shift_growth * shift;
    return m_solver.positive_definite() && shift < tuning::sqp_max_shift;
  }

  // Phase 1: SQP steps, with the exact Lagrangian Hessian
  // W = H + sum lambda_i d^2 c_i shifted by shift I until the KKT matrix has
  // the inertia of a minimum (inertia control, as in IPOPT), while they
  // make progress. True when the attempt is over.
  bool sqp_phase()
  {
    const Matrix& H = m_objective.hessian();
    const double b = tuning::kkt_regularization;
    double nu = 0, radius = tuning::sqp_initial_radius, shift = 0,
           best_error = std::numeric_limits<double>::infinity();
    int iterations_since_best = 0;
    Eigen::VectorXd lambda = Eigen::VectorXd::Zero(m_c.size());
    while(m_it < m_settings.max_iterations)
    {
      m_constraints.evaluate(m_X, m_variable, m_n, m_c, &m_J);
      const Eigen::VectorXd Hd = m_objective.gradient(m_X);
      Matrix K = H + b * Matrix(m_J.transpose() * m_J);
      if(m_exact_hessian)
        K += m_constraints.lagrangian_hessian(m_X, m_variable, m_n, lambda);
      if(!factorize_shifted(K, shift))
        break;
      // Progress: the optimality error (stationarity at the current
      // multipliers) with the exact Hessian, else the largest residual.
      const double residual = m_c.cwiseAbs().maxCoeff() / m_ell;
      const double error = m_exact_hessian
                         ? (std::max)(residual, (Hd + m_J.transpose() * lambda).cwiseAbs().maxCoeff())
                         : residual;
      if(error < tuning::solver_progress * best_error)
      {
        best_error = error;
        iterations_since_best = 0;
      }
      else if(++iterations_since_best >=
              (m_exact_hessian ? tuning::exact_hessian_patience : tuning::gauss_newton_patience))
        break;
      // With the exact Hessian, inexact multiplier passes warm-started from the
      // previous multipliers, with a relative accuracy that tightens as |c|
      // falls, keep the local convergence quadratic. Gauss-Newton converges
      // linearly anyway; there, passes from zero at a fixed accuracy measured
      // as good or better (decocube K = 15: 10 iterations instead of 44).
      const double eta =
        m_exact_hessian ? (std::min)(tuning::multiplier_accuracy, residual) : tuning::multiplier_accuracy;
      Eigen::VectorXd lambda_trial = m_exact_hessian ? lambda : Eigen::VectorXd::Zero(m_c.size());
      m_delta = kkt_step(Hd, m_c, lambda_trial, eta);
      nu = (std::max)(nu, tuning::sqp_merit_margin * lambda_trial.norm());
      const Step step = line_search(Hd, nu, radius, eta);
      if(!step.accepted) // the merit refuses the step: leave it to the projection
        break;
      update_radius(step, radius);
      // Multipliers of the full step; those of a shortened step are blended.
      lambda += (std::min)(step.alpha, 1.0) * (lambda_trial - lambda);
      const double step_length = largest_move(step.d - m_d);
      m_d = step.d;
      m_X = positions(m_d);
      m_c = m_c_trial;
      if(!record())
        return true;
      if(congruent() && step_length <= m_settings.convergence_tolerance * m_ell)
        return true;
    }
    return false;
  }

  struct Step
  {
    Eigen::VectorXd d;
    double alpha, alpha_max;
    bool accepted;
  };

  // The trust region after an accepted step: it grows after a full step and
  // shrinks after a shortened one, which Gauss-Newton tolerates down to half
  // (Sqp_variant).
  void update_radius(const Step& step, double& radius) const
  {
    if(step.alpha == step.alpha_max)
      radius *= tuning::sqp_radius_growth;
    else if(m_variant == CAUTIOUS_GAUSS_NEWTON || m_variant == EXACT_HESSIAN ||
            step.alpha < tuning::sqp_backtracking * step.alpha_max)
      radius = (std::max)(tuning::sqp_radius_shrink * radius, tuning::sqp_min_radius);
  }

  // Backtracking along m_delta on the l2 merit f + nu |c| (nu above
  // |lambda|), within the trust region on the largest vertex move, in edge
  // lengths: far from a solution the linearization is poor and a full step
  // can fold the mesh. Leaves the constraints at the step's end in m_c_trial.
  Step line_search(const Eigen::VectorXd& Hd, double nu, double radius, double eta)
  {
    const double merit_now = m_objective.value(m_X) + nu * m_c.norm();
    const double slope = (std::min)(m_delta.dot(Hd) - nu * m_c.norm(), 0.0);
    auto acceptable = [&](const Eigen::VectorXd& dd, double alpha) {
      const Point_matrix Y = positions(dd);
      m_constraints.evaluate(Y, m_variable, m_n, m_c_trial, nullptr);
      return m_objective.value(Y) + nu * m_c_trial.norm() <=
             merit_now + tuning::sqp_armijo * alpha * slope;
    };
    Step step;
    step.alpha_max = (std::min)(1.0, radius * m_ell / largest_move(m_delta));
    step.alpha = step.alpha_max;
    step.d = m_d + step.alpha * m_delta;
    step.accepted = acceptable(step.d, step.alpha);
    if(!step.accepted && step.alpha == 1.0 && m_exact_hessian)
    {
      // Second-order correction against the Maratos effect: the full step
      // plus the least-W-norm move back onto the constraints' linearization
      // at its end point. Only with the exact Hessian: with Gauss-Newton it
      // gains nothing measurable.
      Eigen::VectorXd correction_multipliers = Eigen::VectorXd::Zero(m_c.size());
      const Eigen::VectorXd correction =
        kkt_step(Eigen::VectorXd::Zero(m_n), m_c_trial, correction_multipliers, eta);
      step.d = m_d + m_delta + correction;
      step.accepted = acceptable(step.d, step.alpha);
    }
    for(step.alpha *= tuning::sqp_backtracking; !step.accepted && step.alpha >= tuning::sqp_min_step_fraction;
        step.alpha *= tuning::sqp_backtracking)
    {
      step.d = m_d + step.alpha * m_delta;
      step.accepted = acceptable(step.d, step.alpha);
    }
    return step;
  }

  // Phase 2: Levenberg-Marquardt projection onto c = 0, mu = theta |c|_inf / ell,
  // theta adapted by the ratio of actual to predicted decrease of |c|^2.
  // True when the visitor stopped the attempt.
  bool projection_phase()
  {
    const Congruence_constraints projection(m_in.problem, m_ell, VOLUME_SHAPE);
    projection.evaluate(m_X, m_variable, m_n, m_c, nullptr);
    double theta = tuning::lm_initial_theta, best_residual = m_c.cwiseAbs().maxCoeff();
    int iterations_since_best = 0;
    while(m_it < m_settings.max_iterations && theta < tuning::lm_max_theta)
    {
      projection.evaluate(m_X, m_variable, m_n, m_c, &m_J);
      const double mu = (std::max)(theta * m_c.cwiseAbs().maxCoeff() / m_ell, tuning::lm_min_damping);
      if(!m_solver.factorize(Matrix(Matrix(m_J.transpose() * m_J) + mu * m_objective.isotropic_hessian())))
      { // mu too small for round-off: damp more
        theta *= tuning::lm_damping_factor;
        continue;
      }
      m_delta = m_solver.solve(-(m_J.transpose() * m_c));
      const Eigen::VectorXd d_trial = m_d + m_delta;
      const Point_matrix X_trial = positions(d_trial);
      projection.evaluate(X_trial, m_variable, m_n, m_c_trial, nullptr);
      const double predicted = m_c.squaredNorm() - (m_c + m_J * m_delta).squaredNorm();
      const double rho = (m_c.squaredNorm() - m_c_trial.squaredNorm()) / predicted;
      if(!(predicted > 0 && rho > tuning::lm_min_gain_ratio))
      {
        theta *= tuning::lm_damping_factor;
        continue;
      }
      theta = rho > tuning::lm_good_gain_ratio
                ? (std::max)(theta / tuning::lm_damping_factor, tuning::lm_min_damping)
                : (rho < tuning::lm_poor_gain_ratio ? tuning::lm_damping_factor * theta : theta);
      m_d = d_trial;
      m_X = X_trial;
      m_c = m_c_trial;
      if(!record())
        return true;
      const double residual = m_c.cwiseAbs().maxCoeff();
      // Once congruent, a few more cheap quadratic steps reach round-off.
      if(congruent() && (residual <= tuning::lm_round_off_residual * m_tolerance * m_ell ||
                         largest_move(m_delta) <= m_settings.convergence_tolerance * m_ell))
        break;
      if(residual < tuning::solver_progress * best_residual)
      {
        best_residual = residual;
        iterations_since_best = 0;
      }
      else if(++iterations_since_best >= tuning::projection_patience)
        break;
    }
    return false;
  }

  const Solver_input& m_in;
  const Solver_settings& m_settings;
  const Sqp_variant m_variant;
  const bool m_shows_start;
  const bool m_exact_hessian;
  std::vector<int> m_variable;
  const int m_n;
  const double m_ell, m_tolerance;
  const Congruence_constraints m_constraints;
  const std::vector<Eigen::Matrix3d> m_isotropic;
  const Closeness_objective m_objective;
  Point_matrix& m_X;
  Visitor& m_visitor;
  bool& m_stopped;
  int m_it;
  bool m_measured = false;
  Solver_report m_report;
  SPD_solver m_solver;
  Matrix m_identity;  // n x n, made once for the shifts
  Matrix m_J;
  Eigen::VectorXd m_d, m_c, m_c_trial, m_delta;
};

// Within a panel tolerance, the result X pulled back toward the input X0:
// the largest fraction of the move X - X0 that bisection can take back while
// the congruence error stays within the tolerance, measured at every trial.
// X is the closest (near-)exact surface the steps converged to, and carries
// the part of the move that only exactness needed. Stopping the steps as soon
// as they are within the tolerance ends farther instead: the SQP steps first
// reach the constraints, then slide along them toward the input (cmc1.obj,
// K = 9: 1.31% of the diagonal exact, 1.94% stopped within 1e-3 of an edge).
CGAL_TILABLE_SURFACES_INLINE
void pull_back_toward_input(const Solver_input& in, const Solver_settings& settings, Point_matrix& X,
                            Solver_report& report);

// Each variant in turn from the input while the previous ones end short of
// the tolerance, within the remaining iterations. They reach different local
// solutions of the over-determined problem (user manual, section
// Optimization) and none always
// succeeds; the best result is kept.
template <typename Visitor>
Solver_report constrained_gauss_newton(const Solver_input& in, const Solver_settings& settings,
                                       Point_matrix& X, Visitor& visitor)
{
  bool stopped = false;
  Solver_report report = Sqp_attempt<Visitor>(in, settings, GAUSS_NEWTON, true, 0, X, visitor, stopped).run();
  for(Sqp_variant variant : {ISOTROPIC_GAUSS_NEWTON, CAUTIOUS_GAUSS_NEWTON, EXACT_HESSIAN})
  {
    if(stopped || report.congruence_error <= settings.congruence_tolerance ||
       report.iterations >= settings.max_iterations)
      break;
    Point_matrix Y;
    const Solver_report other =
      Sqp_attempt<Visitor>(in, settings, variant, false, report.iterations, Y, visitor, stopped).run();
    const int iterations = (std::max)(report.iterations, other.iterations);
    if(other.congruence_error < report.congruence_error)
    {
      X = Y;
      report = other;
    }
    report.iterations = iterations;
  }
  report.stopped_by_visitor = stopped;
  if(settings.within_tolerance_suffices && !stopped && report.congruence_error <= settings.congruence_tolerance)
    pull_back_toward_input(in, settings, X, report);
  return report;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/constrained_gauss_newton_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H
