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
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The weighted paper energy at Y and its gradient in `g`, the gradient zeroed
// on fixed vertices.
inline double weighted_paper_energy(const Solver_input& in, const Solver_settings& settings,
                                    const Point_matrix& Y, Point_matrix& g)
{
  const double f = paper_energy(in.problem, in.D, Y, in.X0, settings.weights, &g)
                     .weighted_sum(settings.weights);
  for(std::size_t v = 0; v < in.fixed.size(); ++v)
    if(in.fixed[v])
      g.row(v).setZero();
  return f;
}

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
inline double safeguarded_parabola_step(double lo, double f_lo, double slope_lo, double hi, double f_hi)
{
  const double width = hi - lo;
  const double curvature = 2 * (f_hi - f_lo - slope_lo * width);
  const double a = curvature > 0 ? lo - slope_lo * width * width / curvature : lo + 0.5 * width;
  return (std::min)((std::max)(a, (std::min)(lo, hi) + tuning::cg_bracket_margin * std::abs(width)),
                    (std::max)(lo, hi) - tuning::cg_bracket_margin * std::abs(width));
}

// A step along `direction` from (X, f, g) satisfying the strong Wolfe
// conditions, phi(a) = f(X + a direction): bracket, then zoom (Nocedal &
// Wright, Algorithms 3.5 and 3.6), starting from `alpha_guess`. `slope0` is
// phi'(0) < 0. Returns the best step found.
inline Line_search_point strong_wolfe_search(const Solver_input& in, const Solver_settings& settings,
                                             const Point_matrix& X, double f, const Point_matrix& g,
                                             const Point_matrix& direction, double slope0, double alpha_guess)
{
  double lo = 0, f_lo = f, slope_lo = slope0, hi = 0, f_hi = f, alpha = alpha_guess;
  bool bracketed = false, accepted = false;
  Point_matrix X_lo = X, g_lo = g, X_new, g_new(X.rows(), 3);
  for(int evaluation = 0; evaluation < tuning::cg_line_search_evaluations && !accepted; ++evaluation)
  {
    X_new = X + alpha * direction;
    const double f_new = weighted_paper_energy(in, settings, X_new, g_new);
    const double slope = g_new.cwiseProduct(direction).sum();
    if(f_new > f + tuning::cg_sufficient_decrease * alpha * slope0 || f_new >= f_lo)
    {
      hi = alpha; f_hi = f_new; bracketed = true;
    }
    else
    {
      accepted = std::abs(slope) <= tuning::cg_curvature_condition * std::abs(slope0);
      if(!accepted && (bracketed ? slope * (hi - lo) >= 0 : slope >= 0))
      {
        hi = lo; f_hi = f_lo; bracketed = true;
      }
      lo = alpha; f_lo = f_new; slope_lo = slope; X_lo = X_new; g_lo = g_new;
    }
    if(!bracketed)
      alpha *= tuning::cg_bracket_growth;
    else
    {
      alpha = safeguarded_parabola_step(lo, f_lo, slope_lo, hi, f_hi);
      if(std::abs(hi - lo) <= tuning::cg_min_bracket_width * std::abs(lo))
        break;
    }
  }
  return Line_search_point{lo, f_lo, X_lo, g_lo};
}

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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_H
