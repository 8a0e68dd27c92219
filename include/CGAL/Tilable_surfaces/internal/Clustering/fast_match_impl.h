// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_IMPL_H

// The bodies of the non-template functions declared in fast_match.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix3d optimal_rotation(const Eigen::Matrix3d& s, double upper_bound)
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

CGAL_TILABLE_SURFACES_INLINE
Rigid_fit fast_rigid_fit(const Prepared_quad& p, const Panel& p_centred,
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

CGAL_TILABLE_SURFACES_INLINE
std::pair<double, Rigid_fit> correspondence_match(const Prepared_quad& p,
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

CGAL_TILABLE_SURFACES_INLINE
Bounded_list<Panel_orientation, 8> admissible_orientations(int n, Orientation_policy policy)
{
  Bounded_list<Panel_orientation, 8> r;
  for(int o = 0; o < 8; ++o)
    if(is_admissible(Panel_orientation(o), n, policy))
      r.push_back(Panel_orientation(o));
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
Quad_match fast_best_match(const Prepared_quad& p, const Prepared_quad& q,
                           Orientation_policy policy)
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_IMPL_H
