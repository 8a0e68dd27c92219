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
inline Eigen::Matrix3d optimal_rotation(const Eigen::Matrix3d& s, double upper_bound)
{
  const double xx = s(0, 0), xy = s(0, 1), xz = s(0, 2), yx = s(1, 0), yy = s(1, 1),
               yz = s(1, 2), zx = s(2, 0), zy = s(2, 1), zz = s(2, 2);
  Eigen::Matrix4d n;
  n << xx + yy + zz, yz - zy, zx - xz, xy - yx,
       yz - zy, xx - yy - zz, xy + yx, zx + xz,
       zx - xz, xy + yx, -xx + yy - zz, yz + zy,
       xy - yx, zx + xz, yz + zy, -xx - yy + zz;

  // Characteristic polynomial l^4 + c2 l^2 + c1 l + c0 (N is traceless). All
  // its roots are real, so Newton's method from above the largest root
  // decreases monotonically to it.
  const double c2 = -2 * s.squaredNorm(), c1 = -8 * s.determinant(), c0 = n.determinant();
  double lambda = upper_bound;
  for(int it = 0; it < tuning::quaternion_newton_iterations; ++it)
  {
    const double l2 = lambda * lambda;
    const double p = (l2 + c2) * l2 + c1 * lambda + c0;
    const double dp = (4 * l2 + 2 * c2) * lambda + c1;
    if(!(dp > 0))
      break;
    const double step = p / dp;
    lambda -= step;
    if(!(std::abs(step) > tuning::quaternion_newton_step * upper_bound))
      break;
  }

  const Eigen::Matrix4d a = n - lambda * Eigen::Matrix4d::Identity();
  Eigen::Vector4d q = Eigen::Vector4d::Zero();
  for(int j = 0; j < 4; ++j)
  {
    const Eigen::Vector4d v = cross4(a.row((j + 1) & 3), a.row((j + 2) & 3), a.row((j + 3) & 3));
    if(v.squaredNorm() > q.squaredNorm()) q = v;
  }
  // |adj(N - lambda I)| is the product of the gaps to the other eigenvalues:
  // a small one means a (nearly) repeated eigenvalue.
  const double scale = upper_bound * upper_bound * upper_bound;
  if(!(q.norm() > tuning::repeated_eigenvalue_gap * scale))
  {
    if(!(upper_bound > 0))
      return Eigen::Matrix3d::Identity();
    q = Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d>(n).eigenvectors().col(3);
  }
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3)).normalized().toRotationMatrix();
}

// The best proper rigid motion of `p` onto the corners of `q` listed in the
// order of `o`; the same motion as `best_rigid_fit(p.corners, reoriented(q.corners, o))`.
inline Rigid_fit fast_rigid_fit(const Prepared_quad& p, const Panel& p_centred,
                                const Eigen::Vector3d& p_mean, const Prepared_quad& q,
                                Panel_orientation o)
{
  const int n = p_centred.size();
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for(int i = 0; i < n; ++i)
    s.noalias() += p_centred[i] * q.centred[o(i, n)].transpose();
  Rigid_fit fit;
  fit.rotation = optimal_rotation(s, std::sqrt(p.squared_size * q.squared_size));
  fit.translation = q.mean - fit.rotation * p_mean;
  return fit;
}

// The sum of corner distances after the best rigid fit of `p` onto `q`
// relabelled by `o` (the better of the proper and the improper fit with
// `allow_mirror`, as `best_rigid_fit()` chooses), and that fit.
inline std::pair<double, Rigid_fit> correspondence_match(const Prepared_quad& p,
                                                         const Prepared_quad& q,
                                                         Panel_orientation o, bool allow_mirror)
{
  const Panel target = reoriented(q.corners, o);
  auto residual = [&](const Rigid_fit& f, bool squared) {
    double r = 0;
    for(int i = 0; i < target.size(); ++i)
    {
      const double d2 = (target[i] - f(p.corners[i])).squaredNorm();
      r += squared ? d2 : std::sqrt(d2);
    }
    return r;
  };
  Rigid_fit fit = fast_rigid_fit(p, p.centred, p.mean, q, o);
  if(allow_mirror)
  {
    // An improper motion is a proper one after the mirror z -> -z.
    const Eigen::DiagonalMatrix<double, 3> mirror(1, 1, -1);
    Panel mirrored = p.centred;
    for(Eigen::Vector3d& c : mirrored) c = mirror * c;
    Rigid_fit mirror_fit = fast_rigid_fit(p, mirrored, mirror * p.mean, q, o);
    mirror_fit.rotation = mirror_fit.rotation * mirror;
    mirror_fit.is_mirrored = true;
    if(residual(mirror_fit, true) < residual(fit, true))
      fit = mirror_fit;
  }
  return {residual(fit, false), fit};
}

// The correspondences `policy` admits between panels of `n` corners, by
// increasing index.
inline Bounded_list<Panel_orientation, 8> admissible_orientations(int n, Orientation_policy policy)
{
  Bounded_list<Panel_orientation, 8> r;
  for(int o = 0; o < 8; ++o)
    if(is_admissible(Panel_orientation(o), n, policy))
      r.push_back(Panel_orientation(o));
  return r;
}

// `best_match(p, q, policy)` on prepared quads, computed faster; equal up to
// rounding.
inline Quad_match fast_best_match(const Prepared_quad& p, const Prepared_quad& q,
                                  Orientation_policy policy = PROPER_RIGID_MOTIONS)
{
  const int n = p.corners.size();
  if(q.corners.size() != n)
    return Quad_match();
  // Correspondences by increasing lower bound; a stable order keeps the tie
  // rule of `best_match()` (smallest index) among equal bounds.
  std::array<std::pair<double, int>, 8> order;
  int m = 0;
  for(Panel_orientation orientation : admissible_orientations(n, policy))
  {
    double bound = 0;
    for(int i = 0; i < n; ++i) bound += std::abs(q.radius[orientation(i, n)] - p.radius[i]);
    order[m++] = {bound, orientation.index()};
  }
  std::sort(order.begin(), order.begin() + m);

  Quad_match best;
  for(int rank = 0; rank < m; ++rank)
  {
    // The slack keeps correspondences whose bound ties the best up to rounding.
    if(order[rank].first > best.dissimilarity * (1 + tuning::match_bound_slack))
      break;
    const Panel_orientation orientation(order[rank].second);
    const std::pair<double, Rigid_fit> match =
      correspondence_match(p, q, orientation, policy == ALLOW_MIRRORED_PANELS);
    if(match.first < best.dissimilarity ||
       (match.first == best.dissimilarity && orientation.index() < best.orientation.index()))
    {
      best.dissimilarity = match.first;
      best.orientation = orientation;
      best.fit = match.second;
    }
  }
  return best;
}

// `best_match(p, q, policy)`, computed faster; equal up to rounding.
inline Quad_match fast_best_match(const Panel& p, const Panel& q,
                                  Orientation_policy policy = PROPER_RIGID_MOTIONS)
{
  return fast_best_match(Prepared_quad(p), Prepared_quad(q), policy);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H
