// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H

// The sparse symmetric positive definite solver of the Gauss-Newton steps:
// CHOLMOD's supernodal Cholesky when the build found SuiteSparse, Eigen's
// SimplicialLDLT otherwise.

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
// Quiet: a failed factorization is an expected answer of the inertia test.
class SPD_solver : public Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower>
{
public:
  SPD_solver() { this->cholmod().print = 0; }
};
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> SPD_solver;
#endif

// Factorizes `A` (whose pattern `solver` has analyzed); true iff `A` is
// numerically positive definite. The SQP steps use this as their inertia
// test: the regularized KKT matrix has the right inertia iff its primal form
// is positive definite.
inline bool factorize_positive_definite(SPD_solver& solver, const Eigen::SparseMatrix<double>& A)
{
  solver.factorize(A);
  if(solver.info() != Eigen::Success)
    return false;
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
  return true; // Cholesky fails on a matrix that is not positive definite
#else
  return (solver.vectorD().array() > 0).all();
#endif
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H
