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

#include <CGAL/Tilable_surfaces/internal/config.h>
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

CGAL_TILABLE_SURFACES_INLINE
Quantity evaluate(Quantity_kind kind, const std::array<int, 4>& item, const Point_matrix& X);

// The paper's cyclic sum over the groups, sum (q_i - q_{i+1 mod n})^2; adds
// `weight` times its gradient to `gradient` when given.
CGAL_TILABLE_SURFACES_INLINE
double cyclic_equality_energy(Quantity_kind kind, const Equality_groups& groups,
                              const Point_matrix& X, double weight = 0,
                              Point_matrix* gradient = nullptr);

// F_d = |X - X0|^2, F_f = |D X|^2 and the three cyclic sums; with `gradient`,
// also the gradient of the weighted sum (overwritten).
CGAL_TILABLE_SURFACES_INLINE
Energy_terms paper_energy(const Tilable_problem& problem, const Eigen::SparseMatrix<double>& D,
                         const Point_matrix& X, const Point_matrix& X0,
                         const Energy_terms& w = Energy_terms(),
                         Point_matrix* gradient = nullptr);

// S, the mean of the 6 squared pair distances of a quad's corners, and its
// gradient over the 4 corners: the size that makes volumes scale free.
struct Mean_squared_pair_distance
{
  double value = 0;
  Eigen::Matrix<double, 12, 1> gradient;

  Mean_squared_pair_distance(const std::array<int, 4>& item, const Point_matrix& X);
};

// w = V / S^(3/2): the volume quantity of the SQP phase, whose exact Hessian
// quantity_hessian.h provides. A shape quantity that does not change with scale.
CGAL_TILABLE_SURFACES_INLINE
Quantity scale_free_volume(const std::array<int, 4>& item, const Point_matrix& X);

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
CGAL_TILABLE_SURFACES_INLINE
Quantity volume_shape(const std::array<int, 4>& item, const Point_matrix& X);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CONGRUENCE_QUANTITIES_H
