// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_H

// Second derivatives of the quantities of congruence_quantities.h, as 12 x 12
// matrices over the item's 4 vertices (3 x 3 block (i, j) =
// d^2 q / dx_i dx_j), for the exact Lagrangian Hessian of the default solver.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

typedef Eigen::Matrix<double, 12, 12> Item_hessian;

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a);

// V = u . (v x w) / 6 with u, v, w = x1 - x0, x2 - x0, x3 - x0 is linear in
// each of u, v, w; the blocks of x0 follow from translation invariance.
CGAL_TILABLE_SURFACES_INLINE
Item_hessian signed_volume_hessian(const std::array<int, 4>& item, const Point_matrix& X);

// w = V / S^(3/2) (scale_free_volume()), S the mean of the 6 squared pair
// distances: the product rule on V and S^(-3/2).
CGAL_TILABLE_SURFACES_INLINE
Item_hessian scale_free_volume_hessian(const std::array<int, 4>& item, const Point_matrix& X);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/quantity_hessian_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_H
