// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_H

// The paper's solver (§4), kept as a reference: Polak-Ribiere nonlinear
// conjugate gradient on the weighted sum mu1 F_d + ... + mu5 F_o, with the
// stopping rule of Numerical Recipes' frprmn (relative decrease of the energy
// below the tolerance). The line search finds a step satisfying the strong
// Wolfe conditions (c1 = 1e-4, c2 = 0.1) by bracketing and safeguarded
// secant steps, as accurate as PR needs; PR+ (beta clamped at 0) restarts
// along the steepest descent when conjugacy is lost.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The weighted paper energy at Y and its gradient in `g`, the gradient zeroed
// on fixed vertices.
CGAL_TILABLE_SURFACES_INLINE
double weighted_paper_energy(const Solver_input& in, const Solver_settings& settings,
                             const Point_matrix& Y, Point_matrix& g);

// The best point of a line search along a direction: its step `alpha`
// (0 when no step decreased the energy), energy, positions and gradient.
struct Line_search_point
{
  double alpha;
  double f;
  Point_matrix X;
  Point_matrix g;
};

// The next trial step within the bracket [lo, hi]: the minimizer of the
// parabola through (lo, f_lo, slope_lo) and (hi, f_hi), kept in the inner
// part of the bracket.
CGAL_TILABLE_SURFACES_INLINE
double safeguarded_parabola_step(double lo, double f_lo, double slope_lo, double hi, double f_hi);

// A step along `direction` from (X, f, g) satisfying the strong Wolfe
// conditions, phi(a) = f(X + a direction): bracket, then zoom (Nocedal &
// Wright, Algorithms 3.5 and 3.6), starting from `alpha_guess`. `slope0` is
// phi'(0) < 0. Returns the best step found.
CGAL_TILABLE_SURFACES_INLINE
Line_search_point strong_wolfe_search(const Solver_input& in, const Solver_settings& settings,
                                      const Point_matrix& X, double f, const Point_matrix& g,
                                      const Point_matrix& direction, double slope0, double alpha_guess);

template <typename Visitor>
Solver_report polak_ribiere(const Solver_input& in, const Solver_settings& settings,
                            Point_matrix& X, Visitor& visitor)
{
  const double ell = mean_edge_length(in.problem, in.X0);
  Solver_report report;
  X = in.X0;
  Point_matrix g(X.rows(), 3);
  double f = weighted_paper_energy(in, settings, X, g);
  Point_matrix direction = -g;
  double alpha_guess = tuning::cg_first_step * ell /
                       (std::max)(direction.cwiseAbs().maxCoeff(), tuning::division_guard);
  report.congruence_error = congruence_error(in.problem, X);
  report.stopped_by_visitor = !visitor.iteration(0, report.congruence_error, f);

  for(int it = 1; it <= settings.max_iterations && !report.stopped_by_visitor; ++it)
  {
    const double slope0 = g.cwiseProduct(direction).sum();
    if(!(slope0 < 0))
    {
      direction = -g;
      if(!(g.squaredNorm() > 0))
        break;
      continue;
    }
    const Line_search_point best = strong_wolfe_search(in, settings, X, f, g, direction, slope0, alpha_guess);
    if(!(best.alpha > 0))
      break; // no decrease along a descent direction: at the precision limit
    X = best.X;
    const double f_old = f;
    f = best.f;
    // PR+: beta clamped at 0 restarts along the steepest descent.
    const double beta = (std::max)(0.0, best.g.cwiseProduct(best.g - g).sum() / g.squaredNorm());
    g = best.g;
    direction = -g + beta * direction;
    alpha_guess = best.alpha;

    report.iterations = it;
    report.congruence_error = congruence_error(in.problem, X);
    report.objective = f;
    if(!visitor.iteration(it, report.congruence_error, f))
    {
      report.stopped_by_visitor = true;
      break;
    }
    if(2 * std::abs(f_old - f) <=
       settings.convergence_tolerance * (std::abs(f_old) + std::abs(f) + tuning::division_guard))
      break;
  }
  // The loop may end before its first evaluation (a zero gradient).
  report.objective = f;
  report.congruence_error = congruence_error(in.problem, X);
  return report;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/conjugate_gradient_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_H
