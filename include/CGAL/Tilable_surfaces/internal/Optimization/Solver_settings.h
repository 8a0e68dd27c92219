// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_H

// What both solvers receive and return. They work on positions normalized to
// a unit bounding-box diagonal, so every tolerance below is relative.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The defaults are those of the default solver (defaults.h);
// Optimization_setup sets every field from the named parameters.
struct Solver_settings
{
  Energy_terms weights;             // mu1..mu5
  int max_iterations = default_number_of_iterations(defaults::solver);
  double congruence_tolerance = defaults::congruence_tolerance;
  // With a panel tolerance (panel_tolerance.h) the default solver does not
  // move a start already within congruence_tolerance, and pulls its
  // converged result back toward the input while it stays within it.
  bool within_tolerance_suffices = false;
  double convergence_tolerance = default_convergence_tolerance(defaults::solver);
};

// The data of one solve: X0 and D are fixed, X is updated in place.
struct Solver_input
{
  const Tilable_problem& problem;
  const Eigen::SparseMatrix<double>& D; // fairness operator
  const Point_matrix& X0;               // normalized input positions
  const std::vector<bool>& fixed;       // vertices that must not move
  const std::vector<Eigen::Matrix3d>& metric; // closeness metric per vertex (closeness_objective.h)
  // Where the default solver starts, normalized like X0; X0 when null. The
  // closeness is still measured to X0.
  const Point_matrix* start = nullptr;
};

struct Solver_report
{
  int iterations = 0;
  double congruence_error = 0; // as measured after the last iteration
  double objective = 0;        // the solver's own objective at the end
  bool stopped_by_visitor = false;
};

// Free unknowns: variable[v] is 3 * (rank of v among the free vertices), or
// -1 for a fixed vertex; returns the number of unknowns.
CGAL_TILABLE_SURFACES_INLINE
int number_free_unknowns(const std::vector<bool>& fixed, std::vector<int>& variable);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SOLVER_SETTINGS_H
