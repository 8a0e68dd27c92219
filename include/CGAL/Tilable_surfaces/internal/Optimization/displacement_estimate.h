// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_H

// How far a clustering will move the surface, before optimizing it: the
// least-norm linearized step from the input,
//   min 1/2 delta^T H delta  s.t.  c(X0) + J delta = 0,
// in the default solver's metric H (closeness_objective.h), with its own
// constraint Jacobian. It is the first step of constrained_gauss_newton()
// (the objective's gradient vanishes at the input), and costs one sparse
// factorization. Shape dissimilarity and DOF do not predict the displacement
// a clustering forces; this does, to first order.

#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/constrained_gauss_newton.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Displacement_estimate
{
  Point_matrix step;   // per vertex, in the solver's normalized units
  double max = 0;      // largest sqrt(delta_v^T M_v delta_v): off-surface move
  double rms = 0;      // root mean square of the same
};

inline Displacement_estimate linearized_displacement(const Solver_input& in, const Solver_settings& settings)
{
  typedef Eigen::SparseMatrix<double> Matrix;
  std::vector<int> variable;
  const int n = number_free_unknowns(in.fixed, variable);
  Displacement_estimate estimate;
  estimate.step = Point_matrix::Zero(in.X0.rows(), 3);
  const Congruence_constraints constraints(in.problem, mean_edge_length(in.problem, in.X0));
  if(n == 0 || constraints.number_of_rows() == 0)
    return estimate;
  const Closeness_objective objective(in.problem, in.X0, in.metric,
                                      settings.weights.fairness / settings.weights.distance, variable, n);
  Eigen::VectorXd c;
  Matrix J;
  constraints.evaluate(in.X0, variable, n, c, &J);
  const double b = tuning::kkt_regularization;
  SPD_solver solver;
  if(!solver.factorize(Matrix(objective.hessian() + b * Matrix(J.transpose() * J))))
    return estimate;
  Eigen::VectorXd multipliers = Eigen::VectorXd::Zero(c.size());
  const Eigen::VectorXd delta =
    multiplier_step(solver, J, b, Eigen::VectorXd::Zero(n), c, multipliers, tuning::multiplier_accuracy);
  double sum = 0;
  for(int v = 0; v < int(variable.size()); ++v)
  {
    if(variable[v] < 0)
      continue;
    const Eigen::Vector3d dv = delta.segment<3>(variable[v]);
    estimate.step.row(v) = dv.transpose();
    const double move = std::sqrt((std::max)(dv.dot(in.metric[v] * dv), 0.0));
    estimate.max = (std::max)(estimate.max, move);
    sum += move * move;
  }
  estimate.rms = std::sqrt(sum / double(in.X0.rows()));
  return estimate;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_H
