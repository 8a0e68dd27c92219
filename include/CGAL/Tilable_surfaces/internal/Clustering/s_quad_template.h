// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H

// The S-quad of a cluster: the mean shape of its instances in a common frame
// (generalized Procrustes analysis). Each instance is brought onto the current
// reference by its best match (orientation and rigid fit), the aligned copies
// are averaged, and the mean becomes the next reference.

#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Inverse motion of `fit` applied to `target`: the instance in the frame of
// the template.
inline Quad pulled_back(const Quad& target, const Rigid_fit& fit)
{
  Quad r;
  for(int i = 0; i < 4; ++i)
    r[i] = fit.rotation.transpose() * (target[i] - fit.translation);
  return r;
}

inline Quad centred(Quad q)
{
  const Eigen::Vector3d c = 0.25 * (q[0] + q[1] + q[2] + q[3]);
  for(auto& p : q) p -= c;
  return q;
}

// The mean shape of quads[members[i]], centred at the origin. With
// `orientations`, instance i is taken in the labelling orientations[i] (only
// the rigid fit is searched); otherwise the best orientation is searched too,
// starting from the first member as reference.
inline Quad procrustes_mean(const std::vector<Quad>& quads,
                            const std::vector<std::size_t>& members,
                            Orientation_policy policy,
                            const std::vector<Quad_orientation>* orientations = nullptr,
                            int iterations = 3)
{
  const std::size_t m = members.size();
  Quad reference = centred(orientations ? reoriented(quads[members[0]], (*orientations)[0])
                                        : quads[members[0]]);
  const bool allow_mirror = (policy == ALLOW_MIRRORED_PANELS);
  std::vector<Quad> aligned(m);
  for(int it = 0; it < iterations; ++it)
  {
    parallel_for(m, [&](std::size_t i) {
      const Quad& q = quads[members[i]];
      if(orientations)
      {
        const Quad target = reoriented(q, (*orientations)[i]);
        aligned[i] = pulled_back(target, best_rigid_fit(reference, target, allow_mirror));
      }
      else
      {
        const Quad_match match = fast_best_match(reference, q, policy);
        aligned[i] = pulled_back(reoriented(q, match.orientation), match.fit);
      }
    });
    Quad mean{{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
               Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}};
    for(const Quad& a : aligned)
      for(int k = 0; k < 4; ++k) mean[k] += a[k];
    for(auto& p : mean) p /= double(m);
    reference = centred(mean);
  }
  return reference;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
