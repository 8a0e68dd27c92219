// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_IMPL_H

// The bodies of the non-template functions declared in quantity_hessian.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/quantity_hessian.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& a)
{
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

CGAL_TILABLE_SURFACES_INLINE
Item_hessian signed_volume_hessian(const std::array<int, 4>& item, const Point_matrix& X)
{
  std::array<Eigen::Vector3d, 3> e; // u, v, w
  for(int i = 0; i < 3; ++i)
    e[i] = (X.row(item[i + 1]) - X.row(item[0])).transpose();
  Item_hessian H = Item_hessian::Zero();
  // d/de_j of dV/de_i = e_j' x e_k' / 6 for the cyclic (i, j, k): -[e_k]_x / 6.
  for(int i = 0; i < 3; ++i)
  {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    H.block<3, 3>(3 * (i + 1), 3 * (j + 1)) = -cross_matrix(e[k]) / 6.0;
    H.block<3, 3>(3 * (j + 1), 3 * (i + 1)) = cross_matrix(e[k]) / 6.0;
  }
  for(int i = 1; i < 4; ++i)
  {
    Eigen::Matrix3d row_sum = Eigen::Matrix3d::Zero();
    for(int j = 1; j < 4; ++j)
      row_sum += H.block<3, 3>(3 * i, 3 * j);
    H.block<3, 3>(3 * i, 0) = -row_sum;
    H.block<3, 3>(0, 3 * i) = -row_sum.transpose();
  }
  for(int j = 1; j < 4; ++j)
    H.block<3, 3>(0, 0) -= H.block<3, 3>(0, 3 * j);
  return H;
}

CGAL_TILABLE_SURFACES_INLINE
Item_hessian scale_free_volume_hessian(const std::array<int, 4>& item, const Point_matrix& X)
{
  const Quantity V = evaluate(SIGNED_VOLUME, item, X);
  const Mean_squared_pair_distance mean(item, X);
  const double S = mean.value;
  const Eigen::Matrix<double, 12, 1>& gS = mean.gradient;
  Eigen::Matrix<double, 12, 1> gV;
  Item_hessian HS;
  for(int i = 0; i < 4; ++i)
  {
    gV.segment<3>(3 * i) = V.gradient[i];
    for(int j = 0; j < 4; ++j)
      HS.block<3, 3>(3 * i, 3 * j) = ((i == j ? 4.0 : 0.0) - 1.0) / 3.0 * Eigen::Matrix3d::Identity();
  }
  const double p = std::pow(S, -1.5); // S^(-3/2)
  return p * signed_volume_hessian(item, X) - 1.5 * p / S * (gV * gS.transpose() + gS * gV.transpose()) +
         3.75 * V.value * p / (S * S) * gS * gS.transpose() - 1.5 * V.value * p / S * HS;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_QUANTITY_HESSIAN_IMPL_H
