// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H

// The sparse symmetric positive definite solver of the Gauss-Newton steps:
// CHOLMOD's supernodal Cholesky when the build found SuiteSparse, Eigen's
// SimplicialLDLT otherwise.
//
// A solve factorizes matrices of one pattern hundreds of times, so the
// pattern is analyzed (fill-reducing ordering, symbolic factorization) only
// when it changes.
//
// CHOLMOD runs serially: Debian's CHOLMOD opens an OpenMP region of a fixed
// 4 threads on every supernode, and its BLAS may be a threaded OpenBLAS. On
// our systems (a few thousand unknowns, factorized hundreds of times) waking
// the threads costs more than the work (seashell, K = 60, 2 cores: 96 s, of
// which a third in futex calls; 30 s serial; 20 s serial with OpenBLAS
// instead of the reference BLAS), and a threaded BLAS would make the
// round-off depend on the number of cores. The OpenMP runtime and OpenBLAS
// are reached through dlsym, so nothing is linked for them and the
// process's own settings are restored once no factorization runs.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cstddef>
#include <vector>
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
#include <Eigen/CholmodSupport>
#include <dlfcn.h>
#include <mutex>
#endif

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
// While an object lives, OpenMP regions (max active levels 0) and OpenBLAS
// run on one thread. Nested and concurrent scopes count: the first saves the
// process's settings, the last restores them.
class Serial_cholmod_scope
{
  struct Runtime
  {
    typedef int (*Getter)();
    typedef void (*Setter)(int);
    Getter get_levels = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
    Setter set_levels = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
    Getter get_blas_threads = reinterpret_cast<Getter>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    Setter set_blas_threads = reinterpret_cast<Setter>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    std::mutex mutex;
    int users = 0, saved_levels = 0, saved_blas_threads = 0;
  };
  static Runtime& runtime()
  {
    static Runtime r;
    return r;
  }

public:
  Serial_cholmod_scope()
  {
    Runtime& r = runtime();
    std::lock_guard<std::mutex> lock(r.mutex);
    if(r.users++ > 0)
      return;
    if(r.get_levels && r.set_levels)
    {
      r.saved_levels = r.get_levels();
      r.set_levels(0);
    }
    if(r.get_blas_threads && r.set_blas_threads)
    {
      r.saved_blas_threads = r.get_blas_threads();
      r.set_blas_threads(1);
    }
  }
  ~Serial_cholmod_scope()
  {
    Runtime& r = runtime();
    std::lock_guard<std::mutex> lock(r.mutex);
    if(--r.users > 0)
      return;
    if(r.get_levels && r.set_levels)
      r.set_levels(r.saved_levels);
    if(r.get_blas_threads && r.set_blas_threads)
      r.set_blas_threads(r.saved_blas_threads);
  }
  Serial_cholmod_scope(const Serial_cholmod_scope&) = delete;
  Serial_cholmod_scope& operator=(const Serial_cholmod_scope&) = delete;
};
#endif

class SPD_solver
{
  typedef Eigen::SparseMatrix<double> Matrix;
#ifdef CGAL_TILABLE_SURFACES_USE_CHOLMOD
  typedef Eigen::CholmodSupernodalLLT<Matrix, Eigen::Lower> Factorization;
#else
  typedef Eigen::SimplicialLDLT<Matrix, Eigen::Lower> Factorization;
#endif

public:
  SPD_solver();

  // Factorizes `A`; true iff `A` is numerically positive definite. The SQP
  // steps use this as their inertia test: the regularized KKT matrix has the
  // right inertia iff its primal form is positive definite.
  bool factorize(const Matrix& A);

  // The last factorization succeeded and may be solved with.
  bool positive_definite() const { return m_positive_definite; }

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

private:
  bool has_analyzed_pattern_of(const Matrix& A) const
  {
    if(!A.isCompressed() || std::size_t(A.outerSize()) + 1 != m_outer.size() ||
       std::size_t(A.nonZeros()) != m_inner.size())
      return false;
    return std::equal(m_outer.begin(), m_outer.end(), A.outerIndexPtr()) &&
           std::equal(m_inner.begin(), m_inner.end(), A.innerIndexPtr());
  }

  Factorization m_factorization;
  std::vector<Matrix::StorageIndex> m_outer, m_inner;
  bool m_positive_definite = false;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SPARSE_SOLVER_H
