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
typedef Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> SPD_solver;
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> SPD_solver;
#endif

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H
