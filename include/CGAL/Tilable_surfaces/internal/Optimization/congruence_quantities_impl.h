// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_IMPL_H

// The bodies of the non-template functions declared in congruence_quantities.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Quantity evaluate(Quantity_kind kind, const std::array<int, 4>& item, const Point_matrix& X)
{
  Quantity q;
  const Eigen::Vector3d a = X.row(item[0]).transpose(), b = X.row(item[1]).transpose();
  if(kind == SQUARED_DISTANCE)
  {
    q.arity = 2;
    q.value = (a - b).squaredNorm();
    q.gradient[0] = 2.0 * (a - b);
    q.gradient[1] = -q.gradient[0];
    return q;
  }
  q.arity = 4;
  const Eigen::Vector3d u = b - a, v = X.row(item[2]).transpose() - a, w = X.row(item[3]).transpose() - a;
  q.value = u.dot(v.cross(w)) / 6.0;
  q.gradient[1] = v.cross(w) / 6.0;
  q.gradient[2] = w.cross(u) / 6.0;
  q.gradient[3] = u.cross(v) / 6.0;
  q.gradient[0] = -(q.gradient[1] + q.gradient[2] + q.gradient[3]);
  return q;
}

CGAL_TILABLE_SURFACES_INLINE
double cyclic_equality_energy(Quantity_kind kind, const Equality_groups& groups,
                              const Point_matrix& X, double weight,
                              Point_matrix* gradient)
{
  double energy = 0;
  std::vector<Quantity> q;
  for(std::size_t g = 0; g < groups.number_of_groups(); ++g)
  {
    const std::size_t first = groups.begin[g], n = groups.begin[g + 1] - first;
    if(n < 2)
      continue;
    q.clear();
    for(std::size_t i = 0; i < n; ++i)
      q.push_back(evaluate(kind, groups.items[first + i], X));
    for(std::size_t i = 0; i < n; ++i)
    {
      const std::size_t j = (i + 1) % n;
      const double r = q[i].value - q[j].value;
      energy += r * r;
      if(gradient == nullptr)
        continue;
      for(int k = 0; k < q[i].arity; ++k)
      {
        gradient->row(groups.items[first + i][k]) += 2.0 * weight * r * q[i].gradient[k].transpose();
        gradient->row(groups.items[first + j][k]) -= 2.0 * weight * r * q[j].gradient[k].transpose();
      }
    }
  }
  return energy;
}

CGAL_TILABLE_SURFACES_INLINE
Energy_terms paper_energy(const Tilable_problem& problem, const Eigen::SparseMatrix<double>& D,
                         const Point_matrix& X, const Point_matrix& X0,
                         const Energy_terms& w,
                         Point_matrix* gradient)
{
  Energy_terms e;
  const Point_matrix DX = D * X;
  e.distance = (X - X0).squaredNorm();
  e.fairness = DX.squaredNorm();
  if(gradient != nullptr)
  {
    *gradient = 2.0 * w.distance * (X - X0);
    *gradient += 2.0 * w.fairness * (D.transpose() * DX);
  }
  e.edge_length = cyclic_equality_energy(SQUARED_DISTANCE, problem.edge_groups, X, w.edge_length, gradient);
  e.diagonal = cyclic_equality_energy(SQUARED_DISTANCE, problem.diagonal_groups, X, w.diagonal, gradient);
  e.volume = cyclic_equality_energy(SIGNED_VOLUME, problem.volume_groups, X, w.volume, gradient);
  return e;
}

CGAL_TILABLE_SURFACES_INLINE
Quantity scale_free_volume(const std::array<int, 4>& item, const Point_matrix& X)
{
  Quantity q = evaluate(SIGNED_VOLUME, item, X);
  const Mean_squared_pair_distance S(item, X);
  const double factor = 1.0 / std::pow(S.value, 1.5);
  for(int i = 0; i < 4; ++i)
    q.gradient[i] = factor * q.gradient[i] - 1.5 * q.value * factor / S.value * S.gradient.segment<3>(3 * i);
  q.value *= factor;
  return q;
}

CGAL_TILABLE_SURFACES_INLINE
Quantity volume_shape(const std::array<int, 4>& item, const Point_matrix& X)
{
  const double epsilon = tuning::volume_shape_epsilon;
  Quantity q = evaluate(SIGNED_VOLUME, item, X);
  const Mean_squared_pair_distance S(item, X);
  const Eigen::Vector3d a = (X.row(item[2]) - X.row(item[0])).transpose(),
                        b = (X.row(item[3]) - X.row(item[1])).transpose();
  const double M = a.cross(b).squaredNorm();
  const Eigen::Vector3d ga = 2 * (b.squaredNorm() * a - a.dot(b) * b),
                        gb = 2 * (a.squaredNorm() * b - a.dot(b) * a);
  Eigen::Matrix<double, 12, 1> gM;
  gM << -ga, -gb, ga, gb;
  const double P = M * S.value + epsilon * S.value * S.value * S.value;
  const Eigen::Matrix<double, 12, 1> gP = S.value * gM + (M + 3 * epsilon * S.value * S.value) * S.gradient;
  const double r = 1 / std::sqrt(P);
  for(int i = 0; i < 4; ++i)
    q.gradient[i] = 6 * r * q.gradient[i] - 3 * q.value * r / P * gP.segment<3>(3 * i);
  q.value *= 6 * r;
  return q;
}

CGAL_TILABLE_SURFACES_INLINE
Mean_squared_pair_distance::Mean_squared_pair_distance(const std::array<int, 4>& item, const Point_matrix& X)
{
  for(int i = 0; i < 4; ++i)
  {
    gradient.segment<3>(3 * i).setZero();
    for(int j = 0; j < 4; ++j)
    {
      const Eigen::Vector3d e = (X.row(item[i]) - X.row(item[j])).transpose();
      value += e.squaredNorm() / 12.0; // each pair twice
      gradient.segment<3>(3 * i) += e / 3.0;
    }
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_IMPL_H
