// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H

// A faster `best_match()`, with the same result: the clustering evaluates the
// dissimilarity millions of times. `best_match()` calls `Eigen::umeyama()` on
// 3x4 matrices for each of the 8 correspondences; here the source is centred
// once, the 8 targets share their centroid, and only the 3x3 SVD of Umeyama's
// closed form remains per correspondence (same formula, same tie-breaks).

#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <Eigen/SVD>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The best proper rigid motion of centred `src` (centroid `src_mean`) onto
// `dst` (centroid `dst_mean`), by Umeyama's formula as `Eigen::umeyama()`
// evaluates it without scaling.
inline Rigid_fit umeyama_fit(const Quad& src_centred, const Eigen::Vector3d& src_mean,
                             const Quad& dst, const Eigen::Vector3d& dst_mean)
{
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for(int i = 0; i < 4; ++i)
    sigma.noalias() += (dst[i] - dst_mean) * src_centred[i].transpose();
  sigma *= 0.25;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(sigma, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
  if(svd.matrixU().determinant() * svd.matrixV().determinant() < 0)
    s(2) = -1;
  Rigid_fit fit;
  fit.rotation = svd.matrixU() * s.asDiagonal() * svd.matrixV().transpose();
  fit.translation = dst_mean - fit.rotation * src_mean;
  return fit;
}

// `best_match(p, q, policy)`, computed faster; equal up to rounding.
inline Quad_match fast_best_match(const Quad& p, const Quad& q,
                                  Orientation_policy policy = PROPER_RIGID_MOTIONS)
{
  const bool allow_mirror = (policy == ALLOW_MIRRORED_PANELS);
  const int number_of_orientations = (policy == NO_TURNED_OVER_PANELS) ? 4 : 8;

  const Eigen::Vector3d p_mean = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  const Eigen::Vector3d q_mean = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  Quad p_centred, p_mirrored;
  for(int i = 0; i < 4; ++i)
  {
    p_centred[i] = p[i] - p_mean;
    p_mirrored[i] = Eigen::Vector3d(p[i].x(), p[i].y(), -p[i].z());
  }
  const Eigen::Vector3d mirrored_mean(p_mean.x(), p_mean.y(), -p_mean.z());
  for(int i = 0; i < 4; ++i)
    p_mirrored[i] -= mirrored_mean;

  auto squared_residual = [&](const Quad& target, const Rigid_fit& f) {
    double r = 0;
    for(int i = 0; i < 4; ++i) r += (target[i] - f(p[i])).squaredNorm();
    return r;
  };

  Quad_match best;
  for(int o = 0; o < number_of_orientations; ++o)
  {
    const Quad_orientation orientation(o);
    const Quad target = reoriented(q, orientation);
    Rigid_fit fit = umeyama_fit(p_centred, p_mean, target, q_mean);
    if(allow_mirror)
    {
      // As in best_rigid_fit(): an improper motion is a proper one after z -> -z.
      Rigid_fit mirror_fit = umeyama_fit(p_mirrored, mirrored_mean, target, q_mean);
      mirror_fit.rotation = mirror_fit.rotation * Eigen::Vector3d(1, 1, -1).asDiagonal();
      mirror_fit.is_mirrored = true;
      if(squared_residual(target, mirror_fit) < squared_residual(target, fit))
        fit = mirror_fit;
    }
    double sum = 0;
    for(int i = 0; i < 4; ++i)
      sum += (target[i] - fit(p[i])).norm();
    if(sum < best.dissimilarity)
    {
      best.dissimilarity = sum;
      best.orientation = orientation;
      best.fit = fit;
    }
  }
  return best;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FAST_MATCH_H
