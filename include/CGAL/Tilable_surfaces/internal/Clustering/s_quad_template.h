// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H

// The S-quad of a cluster: the mean shape of its instances in a common frame
// (generalized Procrustes analysis). Each instance is brought onto the current
// reference by its best match (orientation and rigid fit), the aligned copies
// are averaged, and the mean becomes the next reference.

#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Inverse motion of `fit` applied to `target`: the instance in the frame of
// the template.
inline Panel pulled_back(const Panel& target, const Rigid_fit& fit)
{
  Panel r = target;
  for(Eigen::Vector3d& p : r)
    p = fit.rotation.transpose() * (p - fit.translation);
  return r;
}

inline Panel centred(Panel q)
{
  const Eigen::Vector3d c = q.centroid();
  for(auto& p : q) p -= c;
  return q;
}

// How far the corners of `b` are from those of `a`, relative to the size of
// `a` (0 when they coincide, even for a degenerate `a`).
inline double relative_move(const Panel& a, const Panel& b)
{
  double change = 0, size = 0;
  for(int k = 0; k < a.size(); ++k)
  {
    change = (std::max)(change, (b[k] - a[k]).norm());
    size = (std::max)(size, (a[k] - a[0]).norm());
  }
  return change == 0 ? 0.0 : change / size;
}

// The mean shape of quads[members[i]], centred at the origin: the package's
// one Procrustes mean. With `orientations`, instance i is taken in the
// labelling orientations[i] (only the rigid fit is searched, a mirror too under
// ALLOW_MIRRORED_PANELS); otherwise the best orientation is searched too,
// starting from the first member as reference. At most `max_passes` passes;
// with a `tolerance`, they stop once the mean moves by at most that fraction
// of its size. The clustering takes 3 passes: the mean only has to rank and
// match shapes there. The measure runs to 1e-14: its error is judged against
// the mean, and congruent instances give it exactly.
inline Panel procrustes_mean(const std::vector<Panel>& quads,
                            const std::vector<std::size_t>& members,
                            Orientation_policy policy,
                            const std::vector<Panel_orientation>* orientations = nullptr,
                            int max_passes = tuning::procrustes_passes, double tolerance = 0)
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

// The S-quad of instances congruent up to proper rigid motions (and mirrors
// with `allow_mirror`), in their labelling: their Procrustes mean, to
// convergence.
inline Panel converged_procrustes_mean(const std::vector<Panel>& instances, bool allow_mirror)
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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
