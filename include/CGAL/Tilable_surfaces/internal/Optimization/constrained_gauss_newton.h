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

#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/energy_terms.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename Visitor>
Solver_report constrained_gauss_newton(const Solver_input& in, const Solver_settings& settings,
                                       Point_matrix& X, Visitor& visitor)
{
  typedef Eigen::SparseMatrix<double> Matrix;
  std::vector<int> variable;
  const int n = number_free_unknowns(in.fixed, variable);
  const double ell = mean_edge_length(in.problem, in.X0);
  const Congruence_constraints constraints(in.problem, ell);
  // b relative to H's unit diagonal; constraint rows are O(1) per unit move.
  const double b = 1e6;

  // H / mu1 = I + (mu2 / mu1) D^T D on the free unknowns.
  Matrix H(n, n);
  {
    const Matrix L = Matrix(in.D.transpose() * in.D);
    const double ratio = settings.weights.fairness / settings.weights.distance;
    std::vector<Eigen::Triplet<double>> t;
    for(int v = 0; v < int(variable.size()); ++v)
      if(variable[v] >= 0)
        for(int d = 0; d < 3; ++d)
          t.emplace_back(variable[v] + d, variable[v] + d, 1.0);
    for(int k = 0; k < L.outerSize(); ++k)
      for(Matrix::InnerIterator it(L, k); it; ++it)
        if(variable[it.row()] >= 0 && variable[it.col()] >= 0)
          for(int d = 0; d < 3; ++d)
            t.emplace_back(variable[it.row()] + d, variable[it.col()] + d, ratio * it.value());
    H.setFromTriplets(t.begin(), t.end());
  }

  auto positions = [&](const Eigen::VectorXd& d) {
    Point_matrix Y = in.X0;
    for(int v = 0; v < int(variable.size()); ++v)
      if(variable[v] >= 0)
        Y.row(v) += d.segment<3>(variable[v]).transpose();
    return Y;
  };

  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  double nu = 0, radius = 0.5;
  Eigen::VectorXd c, c_trial;
  Matrix J;
  SPD_solver solver;
  Solver_report report;
  X = in.X0;
  report.congruence_error = congruence_error(in.problem, X);
  double best_congruence = report.congruence_error;
  int iterations_since_best = 0;

  for(int it = 1; it <= settings.max_iterations && n > 0 && constraints.number_of_rows() > 0; ++it)
  {
    constraints.evaluate(X, variable, n, c, &J);
    const Eigen::VectorXd Hd = H * d;
    const Matrix A = Matrix(H + b * Matrix(J.transpose() * J));
    solver.compute(A);
    if(solver.info() != Eigen::Success)
      break;
    // The SQP step of the linearized constraints, by the method of
    // multipliers on the regularized KKT system: each pass is one more
    // back-substitution with the same factorization.
    Eigen::VectorXd delta, lambda = Eigen::VectorXd::Zero(c.size());
    for(int pass = 0; pass < 20; ++pass)
    {
      delta = solver.solve(-(Hd + J.transpose() * (lambda + b * c)));
      const Eigen::VectorXd linear_residual = c + J * delta;
      lambda += b * linear_residual;
      if(linear_residual.norm() <= 1e-3 * c.norm())
        break;
    }
    // Line search on the l2 merit 1/2 d^T H d + nu |c|, nu above |lambda|.
    nu = (std::max)(nu, 2 * lambda.norm());
    auto merit = [&](const Eigen::VectorXd& dd, const Eigen::VectorXd& cc) {
      return 0.5 * dd.dot(H * dd) + nu * cc.norm();
    };
    const double merit_now = merit(d, c);
    const double slope = delta.dot(Hd) - nu * c.norm();
    // Trust region on the largest vertex move, in edge lengths: far from a
    // solution the linearization is poor and a full step can fold the mesh.
    // It doubles after a step the line search accepts at once, halves otherwise.
    double largest_move = 0;
    for(int k = 0; k < n; k += 3)
      largest_move = (std::max)(largest_move, delta.segment<3>(k).norm());
    const double alpha_max = (std::min)(1.0, radius * ell / largest_move);
    double alpha = alpha_max;
    Eigen::VectorXd d_trial;
    Point_matrix X_trial;
    for(;; alpha *= 0.5)
    {
      d_trial = d + alpha * delta;
      X_trial = positions(d_trial);
      constraints.evaluate(X_trial, variable, n, c_trial, nullptr);
      if(merit(d_trial, c_trial) <= merit_now + 1e-4 * alpha * (std::min)(slope, 0.0) || alpha < 1e-8)
        break;
    }
    radius = (alpha == alpha_max) ? 2 * radius : (std::max)(0.5 * radius, 1e-3);
    d = d_trial;
    X = X_trial;

    report.iterations = it;
    report.congruence_error = congruence_error(in.problem, X);
    report.objective = settings.weights.distance * d.dot(H * d);
    if(!visitor.iteration(it, report.congruence_error, report.objective))
      break;

    const bool congruent = report.congruence_error <= settings.congruence_tolerance;
    const double step = alpha * delta.cwiseAbs().maxCoeff() / ell;
    if(congruent && step <= settings.convergence_tolerance)
      break;
    // Stagnation: the constraints cannot be met from here.
    if(report.congruence_error < 0.99 * best_congruence)
    {
      best_congruence = report.congruence_error;
      iterations_since_best = 0;
    }
    else if(!congruent && ++iterations_since_best >= 20)
      break;
  }
  report.objective = settings.weights.distance * d.dot(H * d);
  return report;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_H
