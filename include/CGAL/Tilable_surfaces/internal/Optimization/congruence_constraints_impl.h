// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_IMPL_H

// The bodies of the non-template functions declared in congruence_constraints.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Congruence_constraints::Congruence_constraints(const Tilable_problem& problem, double ell,
                       Volume_quantity volume)
  : m_ell(ell)
  , m_volume(volume)
{
  auto add = [&](Quantity_kind kind, const Equality_groups& groups) {
    for(std::size_t g = 0; g < groups.number_of_groups(); ++g)
      for(std::size_t i = groups.begin[g] + 1; i < groups.begin[g + 1]; ++i)
        m_rows.push_back(Row{kind, &groups.items[i - 1], &groups.items[i]});
  };
  add(SQUARED_DISTANCE, problem.edge_groups);
  add(SQUARED_DISTANCE, problem.diagonal_groups);
  add(SIGNED_VOLUME, problem.volume_groups);
  if(problem.planar)
    for(std::size_t g = 0; g < problem.volume_groups.number_of_groups(); ++g)
      if(problem.volume_groups.begin[g] < problem.volume_groups.begin[g + 1])
        m_rows.push_back(
          Row{SIGNED_VOLUME, &problem.volume_groups.items[problem.volume_groups.begin[g]], nullptr});
}

CGAL_TILABLE_SURFACES_INLINE
void Congruence_constraints::evaluate(const Point_matrix& X, const std::vector<int>& variable, int number_of_unknowns,
              Eigen::VectorXd& c, Eigen::SparseMatrix<double>* jacobian) const
{
  const std::size_t m = m_rows.size();
  c.resize(Eigen::Index(m));
  std::vector<Eigen::Triplet<double>> slots(jacobian != nullptr ? m * max_entries : 0);
  std::vector<int> counts(jacobian != nullptr ? m : 0, 0);
  parallel_for(m, [&](std::size_t r) {
    const Row& row = m_rows[r];
    auto quantity = [&](const std::array<int, 4>& item) {
      if(row.kind == SQUARED_DISTANCE)
        return internal::evaluate(row.kind, item, X);
      return m_volume == VOLUME_SHAPE ? volume_shape(item, X) : scale_free_volume(item, X);
    };
    const Quantity qa = quantity(*row.a), qb = row.b != nullptr ? quantity(*row.b) : Quantity{0, {}, 0};
    const Row_function f = row_function(row.kind, qa.value, qb.value);
    c[r] = f.value;
    const double da = f.da, db = f.db;
    if(jacobian == nullptr)
      return;
    Eigen::Triplet<double>* out = &slots[r * max_entries];
    int& count = counts[r];
    for(const auto& [item, q, scale] : {std::make_tuple(row.a, &qa, da), std::make_tuple(row.b, &qb, db)})
      for(int k = 0; k < q->arity; ++k)
      {
        const int first = variable[(*item)[k]];
        if(first >= 0)
          for(int d = 0; d < 3; ++d)
            out[count++] = Eigen::Triplet<double>(int(r), first + d, scale * q->gradient[k][d]);
      }
  });
  if(jacobian == nullptr)
    return;
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(slots.size());
  for(std::size_t r = 0; r < m; ++r)
    triplets.insert(triplets.end(), slots.begin() + r * max_entries,
                    slots.begin() + r * max_entries + counts[r]);
  jacobian->resize(Eigen::Index(m), number_of_unknowns);
  jacobian->setFromTriplets(triplets.begin(), triplets.end());
}

CGAL_TILABLE_SURFACES_INLINE
Eigen::SparseMatrix<double> Congruence_constraints::lagrangian_hessian(const Point_matrix& X, const std::vector<int>& variable,
                                               int number_of_unknowns, const Eigen::VectorXd& lambda) const
{
  const std::size_t m = m_rows.size();
  std::vector<Eigen::Triplet<double>> slots(m * max_hessian_entries);
  std::vector<int> counts(m, 0);
  parallel_for(m, [&](std::size_t r) {
    const Row& row = m_rows[r];
    Eigen::Triplet<double>* out = &slots[r * max_hessian_entries];
    int& count = counts[r];
    // Adds lambda_r times the 12 x 12 block `B` over the vertices `vi`.
    auto emit = [&](const std::array<int, 4>& vi, const Item_hessian& B) {
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
        {
          const int fi = variable[vi[i]], fj = variable[vi[j]];
          if(fi < 0 || fj < 0)
            continue;
          for(int a = 0; a < 3; ++a)
            for(int b = 0; b < 3; ++b)
              if(B(3 * i + a, 3 * j + b) != 0)
                out[count++] = Eigen::Triplet<double>(fi + a, fj + b, lambda[r] * B(3 * i + a, 3 * j + b));
        }
    };
    if(row.kind == SIGNED_VOLUME)
    {
      // c is linear in (w_a, w_b): no cross term.
      emit(*row.a, 6 * m_ell * scale_free_volume_hessian(*row.a, X));
      if(row.b != nullptr)
        emit(*row.b, -6 * m_ell * scale_free_volume_hessian(*row.b, X));
      return;
    }
    // The 4 vertices (a0, a1, b0, b1).
    const std::array<int, 4> vi{{(*row.a)[0], (*row.a)[1], (*row.b)[0], (*row.b)[1]}};
    emit(vi, distance_row_hessian(row, X));
  });
  std::vector<Eigen::Triplet<double>> triplets;
  for(std::size_t r = 0; r < m; ++r)
    triplets.insert(triplets.end(), slots.begin() + r * max_hessian_entries,
                    slots.begin() + r * max_hessian_entries + counts[r]);
  Eigen::SparseMatrix<double> W(number_of_unknowns, number_of_unknowns);
  W.setFromTriplets(triplets.begin(), triplets.end());
  return W;
}

CGAL_TILABLE_SURFACES_INLINE
Item_hessian Congruence_constraints::distance_row_hessian(const Row& row, const Point_matrix& X) const
{
  typedef Eigen::Matrix<double, 12, 1> Vector12;
  const Quantity qa = internal::evaluate(SQUARED_DISTANCE, *row.a, X),
                 qb = internal::evaluate(SQUARED_DISTANCE, *row.b, X);
  const Row_function f = row_function(row.kind, qa.value, qb.value);
  Vector12 ga = Vector12::Zero(), gb = Vector12::Zero();
  ga << qa.gradient[0], qa.gradient[1], Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero();
  gb << Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), qb.gradient[0], qb.gradient[1];
  Item_hessian B = f.daa * ga * ga.transpose() + f.dbb * gb * gb.transpose() +
                   f.dab * (ga * gb.transpose() + gb * ga.transpose());
  const Eigen::Matrix3d I2 = 2 * Eigen::Matrix3d::Identity(); // d^2 |x0 - x1|^2
  for(int k = 0; k < 2; ++k)
  {
    const double dq = k == 0 ? f.da : f.db;
    B.block<3, 3>(6 * k, 6 * k) += dq * I2;
    B.block<3, 3>(6 * k + 3, 6 * k + 3) += dq * I2;
    B.block<3, 3>(6 * k, 6 * k + 3) -= dq * I2;
    B.block<3, 3>(6 * k + 3, 6 * k) -= dq * I2;
  }
  return B;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_CONSTRAINTS_IMPL_H
