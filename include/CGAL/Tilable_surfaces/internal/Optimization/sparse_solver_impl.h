// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_IMPL_H

// The bodies of the non-template functions declared in sparse_solver.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
SPD_solver::SPD_solver()
{
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
  // Quiet: a failed factorization is an expected answer of the inertia test.
  m_factorization.cholmod().print = 0;
#endif
}

CGAL_TILABLE_SURFACES_INLINE
bool SPD_solver::factorize(const Matrix& A)
{
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
  Serial_cholmod_scope serial;
#endif
  if(!has_analyzed_pattern_of(A))
  {
    m_factorization.analyzePattern(A);
    m_outer.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.outerSize() + 1);
    m_inner.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
  }
  m_factorization.factorize(A);
  m_positive_definite = m_factorization.info() == Eigen::Success;
#ifndef CGAL_TILABLE_SURFACES_USE_CHOLMOD // Cholesky itself fails on an indefinite matrix
  m_positive_definite = m_positive_definite && (m_factorization.vectorD().array() > 0).all();
#endif
  return m_positive_definite;
}

CGAL_TILABLE_SURFACES_INLINE
Eigen::VectorXd SPD_solver::solve(const Eigen::VectorXd& b) const
{
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
  Serial_cholmod_scope serial;
#endif
  return m_factorization.solve(b);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_IMPL_H
