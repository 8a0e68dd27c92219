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

#include <CGAL/Tilable_surfaces/internal/config.h>
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

CGAL_TILABLE_SURFACES_INLINE
Displacement_estimate linearized_displacement(const Solver_input& in, const Solver_settings& settings);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/displacement_estimate_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_DISPLACEMENT_ESTIMATE_H
