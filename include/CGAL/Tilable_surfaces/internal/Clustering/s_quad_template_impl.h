// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_IMPL_H

// The bodies of the non-template functions declared in s_quad_template.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Panel pulled_back(const Panel& target, const Rigid_fit& fit)
{
  Panel r = target;
  for(Eigen::Vector3d& p : r)
    p = fit.rotation.transpose() * (p - fit.translation);
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
Panel centred(Panel q)
{
  const Eigen::Vector3d c = q.centroid();
  for(auto& p : q) p -= c;
  return q;
}

CGAL_TILABLE_SURFACES_INLINE
double relative_move(const Panel& a, const Panel& b)
{
  double change = 0, size = 0;
  for(int k = 0; k < a.size(); ++k)
  {
    change = (std::max)(change, (b[k] - a[k]).norm());
    size = (std::max)(size, (a[k] - a[0]).norm());
  }
  return change == 0 ? 0.0 : change / size;
}

CGAL_TILABLE_SURFACES_INLINE
Panel procrustes_mean(const std::vector<Panel>& quads,
                     const std::vector<std::size_t>& members,
                     Orientation_policy policy,
                     const std::vector<Panel_orientation>* orientations,
                     int max_passes, double tolerance)
{
  const std::size_t m = members.size();
  Panel reference = centred(orientations ? reoriented(quads[members[0]], (*orientations)[0])
                                        : quads[members[0]]);
  const bool allow_mirror = (policy == ALLOW_MIRRORED_PANELS);
  std::vector<Panel> aligned(m);
  bool moving = true;
  for(int pass = 0; pass < max_passes && moving; ++pass)
  {
    parallel_for(m, [&](std::size_t i) {
      const Panel& q = quads[members[i]];
      if(orientations)
      {
        const Panel target = reoriented(q, (*orientations)[i]);
        aligned[i] = pulled_back(target, best_rigid_fit(reference, target, allow_mirror));
      }
      else
      {
        const Quad_match match = fast_best_match(reference, q, policy);
        aligned[i] = pulled_back(reoriented(q, match.orientation), match.fit);
      }
    });
    Panel mean = Panel::zero(reference.size());
    for(const Panel& a : aligned)
      for(int k = 0; k < a.size(); ++k) mean[k] += a[k];
    for(auto& p : mean) p /= double(m);
    mean = centred(mean);
    moving = relative_move(reference, mean) > tolerance;
    reference = mean;
  }
  return reference;
}

CGAL_TILABLE_SURFACES_INLINE
Panel converged_procrustes_mean(const std::vector<Panel>& instances, bool allow_mirror)
{
  std::vector<std::size_t> members(instances.size());
  for(std::size_t i = 0; i < members.size(); ++i) members[i] = i;
  const std::vector<Panel_orientation> as_labelled(instances.size());
  return procrustes_mean(instances, members, allow_mirror ? ALLOW_MIRRORED_PANELS : PROPER_RIGID_MOTIONS,
                         &as_labelled, tuning::converged_procrustes_passes,
                         tuning::converged_procrustes_tolerance);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_IMPL_H
