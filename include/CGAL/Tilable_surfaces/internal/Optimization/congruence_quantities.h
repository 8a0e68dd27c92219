// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_H

// The five terms of the paper's energy (§4) and the quantities they compare
// (congruence_constraints.h turns them into the default solver's constraints).
//
// F_e, F_a and F_o all say "the quantities of a group are equal": squared
// lengths of the mesh edges of an edge-sharing component, squared diagonals
// of the instances of a cluster, signed volumes of those instances. The
// paper sums (q_i - q_{i+1 mod n})^2 cyclically over each group; the
// constraints are the n - 1 differences q_i - q_{i+1}, i < n - 1, which
// state the same equalities without an auxiliary target variable (so no
// dense row or column: user manual, section Optimization).

#include <CGAL/Tilable_surfaces/Energy_terms.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

enum Quantity_kind { SQUARED_DISTANCE, SIGNED_VOLUME };

// The quantity of `item` and its gradient with respect to its vertices.
struct Quantity
{
  double value;
  std::array<Eigen::Vector3d, 4> gradient;
  int arity;
};

inline Quantity evaluate(Quantity_kind kind, const std::array<int, 4>& item, const Point_matrix& X)
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

// The paper's cyclic sum over the groups, sum (q_i - q_{i+1 mod n})^2; adds
// `weight` times its gradient to `gradient` when given.
inline double cyclic_equality_energy(Quantity_kind kind, const Equality_groups& groups,
                                     const Point_matrix& X, double weight = 0,
                                     Point_matrix* gradient = nullptr)
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

// F_d = |X - X0|^2, F_f = |D X|^2 and the three cyclic sums; with `gradient`,
// also the gradient of the weighted sum (overwritten).
inline Energy_terms paper_energy(const Tilable_problem& problem, const Eigen::SparseMatrix<double>& D,
                                const Point_matrix& X, const Point_matrix& X0,
                                const Energy_terms& w = Energy_terms(),
                                Point_matrix* gradient = nullptr)
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

// S, the mean of the 6 squared pair distances of a quad's corners, and its
// gradient over the 4 corners: the size that makes volumes scale free.
struct Mean_squared_pair_distance
{
  double value = 0;
  Eigen::Matrix<double, 12, 1> gradient;

  Mean_squared_pair_distance(const std::array<int, 4>& item, const Point_matrix& X)
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
};

// w = V / S^(3/2): the volume quantity of the SQP phase, whose exact Hessian
// quantity_hessian.h provides. A shape quantity that does not change with scale.
inline Quantity scale_free_volume(const std::array<int, 4>& item, const Point_matrix& X)
{
  Quantity q = evaluate(SIGNED_VOLUME, item, X);
  const Mean_squared_pair_distance S(item, X);
  const double factor = 1.0 / std::pow(S.value, 1.5);
  for(int i = 0; i < 4; ++i)
    q.gradient[i] = factor * q.gradient[i] - 1.5 * q.value * factor / S.value * S.gradient.segment<3>(3 * i);
  q.value *= factor;
  return q;
}

// w = 6V / sqrt(P), P = |N|^2 S + epsilon S^3, N = (x2 - x0) x (x3 - x1) (so
// that 6V = N . (x1 - x0)): the volume quantity of the projection phase,
// about the distance of x1 from the plane through x0 parallel to both
// diagonals, over sqrt(S). It does not change with scale, and a unit move of
// a corner out of that plane changes it by about 1 / sqrt(S) whatever the
// quad's proportions. V / S^(3/2) does not have this: on a sliver (seashell
// K = 44: two edges of 0.17, two of 4e-4) it moves by width / sqrt(S) times
// less, so a residual of 1e-6 lets the instances keep mirrored heights
// (congruence error 3e-4). With the edges and diagonals of instances equal,
// so are S and |N|, and equal w means equal volume.
inline Quantity volume_shape(const std::array<int, 4>& item, const Point_matrix& X)
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_H
