// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_IMPL_H
#define CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_IMPL_H

// The bodies of the non-template functions declared in optimize_tilable_surface.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
bool is_better(const Optimization_result& a, const Optimization_result& b)
{
  if(a.converged != b.converged)
    return a.converged;
  if(!a.converged)
    return a.measure.congruence_error < b.measure.congruence_error;
  const bool a_crosses = a.measure.self_intersecting_face_pairs > 0,
             b_crosses = b.measure.self_intersecting_face_pairs > 0;
  if(a_crosses != b_crosses)
    return b_crosses;
  return a.measure.hausdorff_distance < b.measure.hausdorff_distance;
}

CGAL_TILABLE_SURFACES_INLINE
bool normalized_exact_start(const Optimization_setup& setup, const Point_matrix& start, Point_matrix& S)
{
  S = (start.rowwise() - setup.centre) / setup.scale;
  for(Eigen::Index i = 0; i < S.rows(); ++i)
    if(setup.fixed[std::size_t(i)])
      S.row(i) = setup.X0.row(i);
  return congruence_error(setup.problem, S) <= setup.settings.congruence_tolerance;
}

CGAL_TILABLE_SURFACES_INLINE
Point_matrix moved_points(const Optimization_setup& setup, const Point_matrix& Y)
{
  Point_matrix moved = setup.problem.points;
  for(std::size_t i = 0; i < setup.fixed.size(); ++i)
    if(!setup.fixed[i])
      moved.row(Eigen::Index(i)) += setup.scale * (Y.row(Eigen::Index(i)) - setup.X0.row(Eigen::Index(i)));
  return moved;
}

CGAL_TILABLE_SURFACES_INLINE
void measure_result(const Optimization_setup& setup, const Point_matrix& Y, Optimization_result& result)
{
  const Tilable_problem& problem = setup.problem;
  const double tolerance = setup.settings.congruence_tolerance;
  result.measure = measure_tilability(problem, setup.D, problem.points, moved_points(setup, Y), setup.panel_tolerance);
  use_mesh_face_order(result.measure, setup.mesh_face_index);
  result.converged = setup.panel_tolerance > 0
                       ? result.measure.within_panel_tolerance()
                       : result.measure.congruence_error <= tolerance &&
                           (!problem.planar || result.measure.planarity_error <= tolerance);
}

CGAL_TILABLE_SURFACES_INLINE
void measure_better_result(const Optimization_setup& setup, const Point_matrix& S,
                           bool compare_with_start, Point_matrix& X, Optimization_result& result)
{
  measure_result(setup, X, result);
  if(!compare_with_start)
    return;
  const Optimization_result solved = result;
  measure_result(setup, S, result);
  if(is_better(solved, result))
  {
    result.measure = solved.measure;
    result.converged = solved.converged;
  }
  else
  {
    X = S;
    result.energy = paper_energy(setup.problem, setup.D, X, setup.X0);
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_OPTIMIZE_TILABLE_SURFACE_IMPL_H
