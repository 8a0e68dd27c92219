// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_IMPL_H

// The bodies of the non-template functions declared in displacement_estimate.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/displacement_estimate.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Displacement_estimate linearized_displacement(const Solver_input& in, const Solver_settings& settings)
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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_IMPL_H
