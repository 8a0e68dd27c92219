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

#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename Visitor>
Solver_report polak_ribiere(const Solver_input& in, const Solver_settings& settings,
                            Point_matrix& X, Visitor& visitor)
{
  const double ell = mean_edge_length(in.problem, in.X0);
  // Energy and gradient, the gradient zeroed on fixed vertices.
  auto energy = [&](const Point_matrix& Y, Point_matrix& g) {
    const double f = paper_energy(in.problem, in.D, Y, in.X0, settings.weights, &g)
                       .weighted_sum(settings.weights);
    for(std::size_t v = 0; v < in.fixed.size(); ++v)
      if(in.fixed[v])
        g.row(v).setZero();
    return f;
  };

  Solver_report report;
  X = in.X0;
  Point_matrix g(X.rows(), 3), g_new(X.rows(), 3), X_new;
  double f = energy(X, g);
  Point_matrix direction = -g;
  // First trial step: move by about a hundredth of an edge.
  double alpha_guess = 0.01 * ell / (std::max)(direction.cwiseAbs().maxCoeff(), 1e-300);
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
    // phi(a) = f(X + a direction): bracket, then zoom (Nocedal & Wright,
    // Algorithms 3.5 and 3.6). `lo` is the best step so far.
    double lo = 0, f_lo = f, slope_lo = slope0, hi = 0, f_hi = f, alpha = alpha_guess;
    bool bracketed = false, accepted = false;
    Point_matrix X_lo = X, g_lo = g;
    for(int evaluation = 0; evaluation < 40 && !accepted; ++evaluation)
    {
      X_new = X + alpha * direction;
      const double f_new = energy(X_new, g_new);
      const double slope = g_new.cwiseProduct(direction).sum();
      if(f_new > f + 1e-4 * alpha * slope0 || f_new >= f_lo)
      {
        hi = alpha; f_hi = f_new; bracketed = true;
      }
      else
      {
        accepted = std::abs(slope) <= 0.1 * std::abs(slope0);
        if(!accepted && (bracketed ? slope * (hi - lo) >= 0 : slope >= 0))
        {
          hi = lo; f_hi = f_lo; bracketed = true;
        }
        lo = alpha; f_lo = f_new; slope_lo = slope; X_lo = X_new; g_lo = g_new;
      }
      if(!bracketed)
        alpha *= 4;
      else
      {
        // Minimizer of the parabola through (lo, f_lo, slope_lo) and
        // (hi, f_hi), kept in the inner 80% of the bracket.
        const double width = hi - lo;
        const double curvature = 2 * (f_hi - f_lo - slope_lo * width);
        const double a = curvature > 0 ? lo - slope_lo * width * width / curvature : lo + 0.5 * width;
        alpha = (std::min)((std::max)(a, (std::min)(lo, hi) + 0.1 * std::abs(width)),
                           (std::max)(lo, hi) - 0.1 * std::abs(width));
        if(std::abs(width) <= 1e-15 * std::abs(lo))
          break;
      }
    }
    if(!(lo > 0))
      break; // no decrease along a descent direction: at the precision limit
    const double f_new = f_lo;
    X_new = X_lo;
    g_new = g_lo;
    alpha = lo;
    const double step_length = alpha;
    X = X_new;
    const double f_old = f;
    f = f_new;
    const double beta = (std::max)(0.0, g_new.cwiseProduct(g_new - g).sum() / g.squaredNorm());
    g = g_new;
    direction = -g + beta * direction;
    alpha_guess = step_length;

    report.iterations = it;
    report.congruence_error = congruence_error(in.problem, X);
    report.objective = f;
    if(!visitor.iteration(it, report.congruence_error, f))
    {
      report.stopped_by_visitor = true;
      break;
    }
    if(2 * std::abs(f_old - f) <= settings.convergence_tolerance * (std::abs(f_old) + std::abs(f) + 1e-300))
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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_H
