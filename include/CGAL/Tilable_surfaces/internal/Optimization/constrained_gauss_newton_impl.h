// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_IMPL_H

// The bodies of the non-template functions declared in constrained_gauss_newton.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/constrained_gauss_newton.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Eigen::VectorXd multiplier_step(const SPD_solver& solver, const Eigen::SparseMatrix<double>& J,
                                double b, const Eigen::VectorXd& gradient,
                                const Eigen::VectorXd& target, Eigen::VectorXd& multipliers,
                                double eta)
{
  Eigen::VectorXd step;
  for(int pass = 0; pass < tuning::multiplier_passes; ++pass)
  {
    step = solver.solve(-(gradient + J.transpose() * (multipliers + b * target)));
    const Eigen::VectorXd linear_residual = target + J * step;
    multipliers += b * linear_residual;
    if(linear_residual.norm() <= eta * target.norm())
      break;
  }
  return step;
}

CGAL_TILABLE_SURFACES_INLINE
void pull_back_toward_input(const Solver_input& in, const Solver_settings& settings, Point_matrix& X,
                            Solver_report& report)
{
  double inside = 1, outside = 0; // fractions of the move kept: within, and not known to be
  Point_matrix best = X;
  for(int i = 0; i < tuning::pull_back_bisections; ++i)
  {
    const double kept = 0.5 * (inside + outside);
    const Point_matrix Y = in.X0 + kept * (X - in.X0);
    const double error = congruence_error(in.problem, Y);
    if(error <= settings.congruence_tolerance)
    {
      inside = kept;
      best = Y;
      report.congruence_error = error;
    }
    else
      outside = kept;
  }
  X = best;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONSTRAINED_GAUSS_NEWTON_IMPL_H
