// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H

// A faster `best_match()`, with the same result: the clustering evaluates the
// dissimilarity millions of times. Three savings:
// - each quad is centred once (`Prepared_quad`), and the 8 targets share their
//   centroid;
// - the optimal proper rotation comes from Horn's quaternion closed form: the
//   unit quaternion maximising q^T N q, N the 4x4 symmetric matrix of the
//   cross-covariance. Its largest eigenvalue is found by Newton's method on the
//   characteristic polynomial (Theobald's QCP), its eigenvector as a column of
//   the adjugate of N - lambda I; only when that eigenvalue is (nearly)
//   repeated, where the rotation is ill-determined anyway, a full symmetric
//   eigensolver is used. This replaces a 3x3 SVD per correspondence;
// - a lower bound skips correspondences that cannot win. The fit maps the
//   source centroid c_p onto the target centroid c_q, so by the triangle
//   inequality |q_i - T(p_i)| >= | |q_i - c_q| - |p_i - c_p| |: the sum of the
//   differences of the corners' distances to their centroids bounds the sum of
//   the corner distances from below.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// A quad with what every match of it needs, computed once.
struct Prepared_quad
{
  Panel corners;
  Panel centred;
  Eigen::Vector3d mean;
  std::array<double, 4> radius;  // |corner - mean|, for the first corners.size()
  double squared_size;           // sum of radius^2

  Prepared_quad() = default;
  explicit Prepared_quad(const Panel& q)
    : corners(q), centred(q), mean(q.centroid()), squared_size(0)
  {
    for(int i = 0; i < q.size(); ++i)
    {
      centred[i] = q[i] - mean;
      radius[i] = centred[i].norm();
      squared_size += centred[i].squaredNorm();
    }
  }
};

// 4-vector orthogonal to a, b, c (the generalized cross product): a column of
// the adjugate of the matrix whose other rows are a, b, c.
inline Eigen::Vector4d cross4(const Eigen::Vector4d& a, const Eigen::Vector4d& b,
                              const Eigen::Vector4d& c)
{
  auto minor3 = [&](int i, int j, int k) {
    return a(i) * (b(j) * c(k) - b(k) * c(j)) - a(j) * (b(i) * c(k) - b(k) * c(i)) +
           a(k) * (b(i) * c(j) - b(j) * c(i));
  };
  return Eigen::Vector4d(minor3(1, 2, 3), -minor3(0, 2, 3), minor3(0, 1, 3), -minor3(0, 1, 2));
}

// The proper rotation R maximising sum_i d_i . R s_i, i.e. minimising
// sum_i |d_i - R s_i|^2 for centred s_i and d_i, given the cross-covariance
// `s` = sum_i s_i d_i^T and an upper bound of the optimum (sqrt(Gs Gd), G the
// sums of squared norms: by Cauchy-Schwarz). Horn's method, see the file comment.
CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3d optimal_rotation(const Eigen::Matrix3d& s, double upper_bound);

// The best proper rigid motion of `p` onto the corners of `q` listed in the
// order of `o`; the same motion as `best_rigid_fit(p.corners, reoriented(q.corners, o))`.
CGAL_TILABLE_SURFACES_INLINE
Rigid_fit fast_rigid_fit(const Prepared_quad& p, const Panel& p_centred,
                         const Eigen::Vector3d& p_mean, const Prepared_quad& q,
                         Panel_orientation o);

// The sum of corner distances after the best rigid fit of `p` onto `q`
// relabelled by `o` (the better of the proper and the improper fit with
// `allow_mirror`, as `best_rigid_fit()` chooses), and that fit.
CGAL_TILABLE_SURFACES_INLINE
std::pair<double, Rigid_fit> correspondence_match(const Prepared_quad& p,
                                                  const Prepared_quad& q,
                                                  Panel_orientation o, bool allow_mirror);

// The correspondences `policy` admits between panels of `n` corners, by
// increasing index.
CGAL_TILABLE_SURFACES_INLINE
Bounded_list<Panel_orientation, 8> admissible_orientations(int n, Orientation_policy policy);

// `best_match(p, q, policy)` on prepared quads, computed faster; equal up to
// rounding.
CGAL_TILABLE_SURFACES_INLINE
Quad_match fast_best_match(const Prepared_quad& p, const Prepared_quad& q,
                           Orientation_policy policy = PROPER_RIGID_MOTIONS);

// `best_match(p, q, policy)`, computed faster; equal up to rounding.
inline Quad_match fast_best_match(const Panel& p, const Panel& q,
                                  Orientation_policy policy = PROPER_RIGID_MOTIONS)
{
  return fast_best_match(Prepared_quad(p), Prepared_quad(q), policy);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H
