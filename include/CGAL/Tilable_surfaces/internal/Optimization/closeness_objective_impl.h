// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_IMPL_H

// The bodies of the non-template functions declared in closeness_objective.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Closeness_objective::Closeness_objective(const Tilable_problem& problem, const Point_matrix& X0,
                    const std::vector<Eigen::Matrix3d>& metric, double rigidity,
                    const std::vector<int>& variable, int number_of_unknowns)
  : m_X0(X0), m_metric(metric), m_rigidity(rigidity), m_variable(variable)
  , m_neighbours(X0.rows())
{
  for(const auto& e : problem.edges)
  {
    m_neighbours[e[0]].push_back(e[1]);
    m_neighbours[e[1]].push_back(e[0]);
  }
  // H = M + 2 r L, and the same with I for M.
  std::vector<Eigen::Triplet<double> > closeness, identity, rigidity_part;
  for(int v = 0; v < int(variable.size()); ++v)
  {
    if(variable[v] < 0)
      continue;
    for(int a = 0; a < 3; ++a)
    {
      identity.emplace_back(variable[v] + a, variable[v] + a, 1.0);
      for(int b = 0; b < 3; ++b)
        if(metric[v](a, b) != 0)
          closeness.emplace_back(variable[v] + a, variable[v] + b, metric[v](a, b));
    }
    for(int w : m_neighbours[v])
      for(int a = 0; a < 3; ++a)
      {
        rigidity_part.emplace_back(variable[v] + a, variable[v] + a, 2 * rigidity);
        if(variable[w] >= 0)
          rigidity_part.emplace_back(variable[v] + a, variable[w] + a, -2 * rigidity);
      }
  }
  closeness.insert(closeness.end(), rigidity_part.begin(), rigidity_part.end());
  identity.insert(identity.end(), rigidity_part.begin(), rigidity_part.end());
  m_hessian.resize(number_of_unknowns, number_of_unknowns);
  m_hessian.setFromTriplets(closeness.begin(), closeness.end());
  m_isotropic_hessian.resize(number_of_unknowns, number_of_unknowns);
  m_isotropic_hessian.setFromTriplets(identity.begin(), identity.end());
}

CGAL_TILABLE_SURFACES_INLINE
double Closeness_objective::value(const Point_matrix& X) const
{
  double f = 0;
  const std::vector<Eigen::Matrix3d> R = rotations(X);
  for(Eigen::Index v = 0; v < X.rows(); ++v)
  {
    const Eigen::Vector3d d = (X.row(v) - m_X0.row(v)).transpose();
    f += 0.5 * d.dot(m_metric[v] * d);
    for(int w : m_neighbours[v])
      f += 0.5 * m_rigidity * (edge(X, v, w) - R[v] * edge(m_X0, v, w)).squaredNorm();
  }
  return f;
}

CGAL_TILABLE_SURFACES_INLINE
Eigen::VectorXd Closeness_objective::gradient(const Point_matrix& X) const
{
  Eigen::VectorXd g = Eigen::VectorXd::Zero(m_hessian.rows());
  const std::vector<Eigen::Matrix3d> R = rotations(X);
  for(int v = 0; v < int(m_variable.size()); ++v)
  {
    if(m_variable[v] < 0)
      continue;
    const Eigen::Vector3d d = (X.row(v) - m_X0.row(v)).transpose();
    Eigen::Vector3d gv = m_metric[v] * d;
    for(int w : m_neighbours[v])
      gv += m_rigidity * (2 * edge(X, v, w) - (R[v] + R[w]) * edge(m_X0, v, w));
    g.segment<3>(m_variable[v]) = gv;
  }
  return g;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<Eigen::Matrix3d> Closeness_objective::rotations(const Point_matrix& X) const
{
  std::vector<Eigen::Matrix3d> R(std::size_t(X.rows()), Eigen::Matrix3d::Identity());
  if(m_rigidity == 0)
    return R;
  for(Eigen::Index v = 0; v < X.rows(); ++v)
  {
    Eigen::Matrix3d S = Eigen::Matrix3d::Zero();
    for(int w : m_neighbours[v])
      S += edge(X, v, w) * edge(m_X0, v, w).transpose();
    if(S.isZero(0))
      continue;
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(S, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d D = Eigen::Matrix3d::Identity();
    D(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1.0 : 1.0;
    R[v] = svd.matrixU() * D * svd.matrixV().transpose();
  }
  return R;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_IMPL_H
