// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_IMPL_H

// The bodies of the non-template functions declared in conjugate_gradient.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/conjugate_gradient.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
double weighted_paper_energy(const Solver_input& in, const Solver_settings& settings,
                             const Point_matrix& Y, Point_matrix& g)
{
  const double f = paper_energy(in.problem, in.D, Y, in.X0, settings.weights, &g)
                     .weighted_sum(settings.weights);
  for(std::size_t v = 0; v < in.fixed.size(); ++v)
    if(in.fixed[v])
      g.row(v).setZero();
  return f;
}

CGAL_TILABLE_SURFACES_INLINE
double safeguarded_parabola_step(double lo, double f_lo, double slope_lo, double hi, double f_hi)
{
  const double width = hi - lo;
  const double curvature = 2 * (f_hi - f_lo - slope_lo * width);
  const double a = curvature > 0 ? lo - slope_lo * width * width / curvature : lo + 0.5 * width;
  return (std::min)((std::max)(a, (std::min)(lo, hi) + tuning::cg_bracket_margin * std::abs(width)),
                    (std::max)(lo, hi) - tuning::cg_bracket_margin * std::abs(width));
}

CGAL_TILABLE_SURFACES_INLINE
Line_search_point strong_wolfe_search(const Solver_input& in, const Solver_settings& settings,
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONJUGATE_GRADIENT_IMPL_H
