// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_H

// The equality constraints c(X) = 0 of the default solver, one row per
// consecutive pair (a, b) of a group of congruence_quantities.h, in length
// units with the length scale `ell`:
// - squared lengths: ell (q_a - q_b) / (q_a + q_b);
// - volumes: 6 ell (w_a - w_b), w = scale_free_volume(), or ell (w_a - w_b),
//   w = volume_shape() (Volume_quantity);
// - with planar tiles, one more row per cluster, the volume of its first
//   instance against 0: with the others' equal to it, every panel is planar.
// Both are invariant under scaling of the surface (user manual, section
// Optimization): with
// absolute differences, shrinking the mesh lowers every residual, and far
// from a solution the Gauss-Newton steps head for a collapsed surface. With
// the edges and diagonals of instances equal, equal w means equal volume.
//
// lagrangian_hessian() gives sum_r lambda_r d^2 c_r / dX^2: the constraints'
// curvature, without which the SQP steps converge only linearly.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/quantity_hessian.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <array>
#include <tuple>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The SQP phase needs the constraints' exact Hessian, available for
// scale_free_volume() only; the projection phase needs constraints whose
// residual bounds the congruence error, which volume_shape() gives on slivers
// too (congruence_quantities.h).
enum Volume_quantity { SCALE_FREE_VOLUME, VOLUME_SHAPE };

class Congruence_constraints
{
  struct Row
  {
    Quantity_kind kind;
    const std::array<int, 4>* a;
    const std::array<int, 4>* b; // null: q_a against 0 (planarity)
  };
  // A row touches at most 8 vertices, 3 unknowns each.
  static constexpr int max_entries = 24;
  // A row's Hessian: two 12 x 12 blocks (volumes) or one (squared lengths).
  static constexpr int max_hessian_entries = 288;

public:
  Congruence_constraints(const Tilable_problem& problem, double ell,
                         Volume_quantity volume = SCALE_FREE_VOLUME);

  int number_of_rows() const { return int(m_rows.size()); }

  // The residuals c(X) and, with `jacobian`, their Jacobian with respect to
  // the free unknowns (`number_of_unknowns` columns); `variable[v]` is the
  // first of the 3 unknowns of vertex v, or -1 if it is fixed. Rows are
  // evaluated in parallel into their own slots, then gathered in row order:
  // the result does not depend on the number of threads.
  void evaluate(const Point_matrix& X, const std::vector<int>& variable, int number_of_unknowns,
                Eigen::VectorXd& c, Eigen::SparseMatrix<double>* jacobian) const;

  // sum_r lambda_r d^2 c_r / dX^2 on the free unknowns (n x n, both
  // triangles). Same row-parallel, order-preserving assembly as evaluate().
  // Constraints built with SCALE_FREE_VOLUME only.
  Eigen::SparseMatrix<double> lagrangian_hessian(const Point_matrix& X, const std::vector<int>& variable,
                                                 int number_of_unknowns, const Eigen::VectorXd& lambda) const;

private:
  // d^2 c / dX^2 of a row of squared lengths over the 4 vertices
  // (a0, a1, b0, b1): c = f(q_a, q_b), q = |x0 - x1|^2.
  Item_hessian distance_row_hessian(const Row& row, const Point_matrix& X) const;

  // c = f(q_a, q_b) and its first and second derivatives.
  struct Row_function
  {
    double value, da, db, daa, dbb, dab;
  };

  Row_function row_function(Quantity_kind kind, double qa, double qb) const
  {
    if(kind == SIGNED_VOLUME)
    {
      const double scale = m_volume == VOLUME_SHAPE ? m_ell : 6 * m_ell;
      return Row_function{scale * (qa - qb), scale, -scale, 0, 0, 0};
    }
    const double s = qa + qb, s2 = s * s, s3 = s2 * s;
    return Row_function{m_ell * (qa - qb) / s, 2 * m_ell * qb / s2, -2 * m_ell * qa / s2,
                        -4 * m_ell * qb / s3, 4 * m_ell * qa / s3, 2 * m_ell * (qa - qb) / s3};
  }

  double m_ell;
  Volume_quantity m_volume;
  std::vector<Row> m_rows;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_H
