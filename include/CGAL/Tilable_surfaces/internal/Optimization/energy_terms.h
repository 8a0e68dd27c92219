// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_ENERGY_TERMS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_ENERGY_TERMS_H

// The five terms of the paper's energy (§4) and the equality constraints the
// default solver derives from F_e, F_a and F_o.
//
// F_e, F_a and F_o all say "the quantities of a group are equal": squared
// lengths of the mesh edges of an edge-sharing component, squared diagonals
// of the instances of a cluster, signed volumes of those instances. The
// paper sums (q_i - q_{i+1 mod n})^2 cyclically over each group; the
// constraints are the n - 1 differences q_i - q_{i+1}, i < n - 1, which
// state the same equalities without an auxiliary target variable (so no
// dense row or column, method notes §4b).

#include <CGAL/Tilable_surfaces/internal/Optimization/Tilable_problem.h>

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

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Values of the five terms of the paper's energy (§4): F_d (distance to the
/// input positions), F_f (fairness), F_e (edge lengths), F_a (diagonals) and
/// F_o (signed volumes); or their weights mu1..mu5.
struct Energy_terms
{
  double distance = 0;    ///< F_d, or mu1
  double fairness = 0;    ///< F_f, or mu2
  double edge_length = 0; ///< F_e, or mu3
  double diagonal = 0;    ///< F_a, or mu4
  double volume = 0;      ///< F_o, or mu5

  /// The weighted sum sum_k weights_k * F_k.
  double weighted_sum(const Energy_terms& weights) const
  {
    return weights.distance * distance + weights.fairness * fairness +
           weights.edge_length * edge_length + weights.diagonal * diagonal +
           weights.volume * volume;
  }
};

namespace internal {

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

// The signed volume of a quad divided by S^(3/2), S the mean of its 6 squared
// edge and diagonal lengths: a shape quantity that does not change with scale.
inline Quantity scale_free_volume(const std::array<int, 4>& item, const Point_matrix& X)
{
  Quantity q = evaluate(SIGNED_VOLUME, item, X);
  double S = 0;
  std::array<Eigen::Vector3d, 4> grad_S;
  for(int i = 0; i < 4; ++i)
  {
    grad_S[i].setZero();
    for(int j = 0; j < 4; ++j)
    {
      const Eigen::Vector3d e = X.row(item[i]).transpose() - X.row(item[j]).transpose();
      S += e.squaredNorm() / 12.0; // each pair twice
      grad_S[i] += e / 3.0;
    }
  }
  const double factor = 1.0 / std::pow(S, 1.5);
  for(int i = 0; i < 4; ++i)
    q.gradient[i] = factor * q.gradient[i] - 1.5 * q.value * factor / S * grad_S[i];
  q.value *= factor;
  return q;
}

// The equality constraints of every group, one row per consecutive pair
// (a, b) of a group, in length units with the length scale `ell`:
// - squared lengths: ell (q_a - q_b) / (q_a + q_b);
// - volumes: 6 ell (w_a - w_b), w = scale_free_volume().
// Both are invariant under scaling of the surface (method notes §4b): with
// absolute differences, shrinking the mesh lowers every residual, and far
// from a solution the Gauss-Newton steps head for a collapsed surface. With
// the edges and diagonals of instances equal, equal w means equal volume.
// `variable[v]` is the first of the 3 unknowns of vertex v, or -1 if it is
// fixed. Rows are numbered in a fixed order, so the sparsity pattern of the
// Jacobian does not change between calls.
class Congruence_constraints
{
public:
  Congruence_constraints(const Tilable_problem& problem, double ell)
    : m_problem(problem), m_ell(ell)
  {
    m_rows = 0;
    for(const Equality_groups* groups : {&problem.edge_groups, &problem.diagonal_groups,
                                         &problem.volume_groups})
      for(std::size_t g = 0; g < groups->number_of_groups(); ++g)
      {
        const std::size_t n = groups->begin[g + 1] - groups->begin[g];
        m_rows += n > 1 ? int(n - 1) : 0;
      }
  }

  int number_of_rows() const { return m_rows; }

  // The residuals c(X) and, with `jacobian`, their Jacobian with respect to
  // the free unknowns (number_of_unknowns columns).
  void evaluate(const Point_matrix& X, const std::vector<int>& variable, int number_of_unknowns,
                Eigen::VectorXd& c, Eigen::SparseMatrix<double>* jacobian) const
  {
    c.resize(m_rows);
    std::vector<Eigen::Triplet<double>> triplets;
    int row = 0;
    auto add = [&](Quantity_kind kind, const Equality_groups& groups) {
      auto quantity = [&](const std::array<int, 4>& item) {
        return kind == SQUARED_DISTANCE ? internal::evaluate(kind, item, X) : scale_free_volume(item, X);
      };
      for(std::size_t g = 0; g < groups.number_of_groups(); ++g)
      {
        const std::size_t first = groups.begin[g], last = groups.begin[g + 1];
        if(last - first < 2)
          continue;
        Quantity previous = quantity(groups.items[first]);
        for(std::size_t i = first + 1; i < last; ++i, ++row)
        {
          const Quantity current = quantity(groups.items[i]);
          // r = ell f(a, b); d r / d q_a and d r / d q_b.
          double da = 6 * m_ell, db = -6 * m_ell;
          if(kind == SQUARED_DISTANCE)
          {
            const double sum = previous.value + current.value;
            c[row] = m_ell * (previous.value - current.value) / sum;
            da = 2 * m_ell * current.value / (sum * sum);
            db = -2 * m_ell * previous.value / (sum * sum);
          }
          else
            c[row] = 6 * m_ell * (previous.value - current.value);
          if(jacobian != nullptr)
          {
            append(triplets, row, groups.items[i - 1], previous, da, variable);
            append(triplets, row, groups.items[i], current, db, variable);
          }
          previous = current;
        }
      }
    };
    add(SQUARED_DISTANCE, m_problem.edge_groups);
    add(SQUARED_DISTANCE, m_problem.diagonal_groups);
    add(SIGNED_VOLUME, m_problem.volume_groups);
    if(jacobian != nullptr)
    {
      jacobian->resize(m_rows, number_of_unknowns);
      jacobian->setFromTriplets(triplets.begin(), triplets.end());
    }
  }

private:
  static void append(std::vector<Eigen::Triplet<double>>& triplets, int row,
                     const std::array<int, 4>& item, const Quantity& q, double scale,
                     const std::vector<int>& variable)
  {
    for(int k = 0; k < q.arity; ++k)
    {
      const int first = variable[item[k]];
      if(first < 0)
        continue;
      for(int d = 0; d < 3; ++d)
        triplets.emplace_back(row, first + d, scale * q.gradient[k][d]);
    }
  }

  const Tilable_problem& m_problem;
  double m_ell;
  int m_rows;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_ENERGY_TERMS_H
