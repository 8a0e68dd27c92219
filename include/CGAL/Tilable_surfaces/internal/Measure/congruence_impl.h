// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_IMPL_H

// The bodies of the non-template functions declared in congruence.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Panel canonical_frame(const Panel& q)
{
  const Eigen::Vector3d x = (q[1] - q[0]).normalized();
  const Eigen::Vector3d z = x.cross(q[2] - q[0]).normalized();
  Eigen::Matrix3d R;
  R.row(0) = x.transpose();
  R.row(1) = z.cross(x).transpose();
  R.row(2) = z.transpose();
  Panel r = q;
  for(Eigen::Vector3d& p : r)
    p = R * (p - q[0]);
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
Cluster_congruence cluster_congruence(const Tilable_problem& problem, const Point_matrix& X)
{
  const std::size_t K = problem.number_of_clusters;
  std::vector<std::vector<Panel>> members(K);
  std::vector<std::vector<std::size_t>> faces(K);
  for(std::size_t f = 0; f < problem.face_corners.size(); ++f)
  {
    members[problem.face_cluster[f]].push_back(instance(problem, X, f));
    faces[problem.face_cluster[f]].push_back(f);
  }

  Cluster_congruence result;
  result.s_quads.assign(K, Panel::zero(4));
  result.errors.assign(K, 0.0);
  result.sizes.assign(K, 0);
  result.mirrored.assign(K, 0);
  result.face_errors.assign(problem.face_corners.size(), 0.0);
  for(std::size_t c = 0; c < K; ++c)
  {
    result.sizes[c] = members[c].size();
    if(members[c].empty())
      continue;
    const Panel mean = converged_procrustes_mean(members[c], problem.allow_mirror);
    result.s_quads[c] = canonical_frame(mean);
    // The mold of a planar S-quad is its own mirror image.
    const bool count_mirrored = problem.allow_mirror &&
                                planarity_defect(mean) > tuning::planar_mold_defect * (mean[2] - mean[0]).norm();
    for(std::size_t i = 0; i < members[c].size(); ++i)
    {
      const Panel& q = members[c][i];
      const double deviation = rigid_fit_deviation(mean, q, problem.allow_mirror);
      result.face_errors[faces[c][i]] = deviation;
      result.errors[c] = (std::max)(result.errors[c], deviation);
      if(count_mirrored && best_rigid_fit(mean, q, true).is_mirrored)
        ++result.mirrored[c];
    }
  }
  return result;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> cluster_molds(const std::vector<Panel>& s_quads, const std::vector<std::size_t>& sizes,
                                       bool allow_mirror, double tolerance)
{
  const Orientation_policy policy = allow_mirror ? ALLOW_MIRRORED_PANELS : PROPER_RIGID_MOTIONS;
  std::vector<std::size_t> mold(s_quads.size(), s_quads.size());
  std::vector<std::size_t> first_cluster; // per mold, the cluster whose S-quad stands for it
  std::vector<Quad_descriptor> mold_descriptors;
  for(std::size_t c = 0; c < s_quads.size(); ++c)
  {
    if(sizes[c] == 0)
      continue;
    const Quad_descriptor d = shape_descriptor(s_quads[c]);
    for(std::size_t m = 0; m < first_cluster.size() && mold[c] == s_quads.size(); ++m)
    {
      const Panel& s = s_quads[first_cluster[m]];
      bool close = s.size() == s_quads[c].size();
      for(std::size_t i = 0; i < 6 && close; ++i) close = std::abs(d[i] - mold_descriptors[m][i]) <= 2 * tolerance;
      if(!close)
        continue;
      const Panel target = reoriented(s_quads[c], best_match(s, s_quads[c], policy).orientation);
      if(rigid_fit_deviation(s, target, allow_mirror) <= tolerance)
        mold[c] = m;
    }
    if(mold[c] == s_quads.size())
    {
      mold[c] = first_cluster.size();
      first_cluster.push_back(c);
      mold_descriptors.push_back(d);
    }
  }
  return mold;
}

CGAL_TILABLE_SURFACES_INLINE
double worst_diagonal_distance(const Tilable_problem& problem, const Point_matrix& X)
{
  double worst = 0;
  for(std::size_t f = 0; f < problem.face_corners.size(); ++f)
    worst = (std::max)(worst, diagonal_distance(instance(problem, X, f)));
  return worst;
}

CGAL_TILABLE_SURFACES_INLINE
double congruence_error(const Tilable_problem& problem, const Point_matrix& X)
{
  const std::vector<double> errors = cluster_congruence(problem, X).errors;
  double worst = errors.empty() ? 0.0 : *std::max_element(errors.begin(), errors.end());
  if(problem.planar)
    worst = (std::max)(worst, worst_diagonal_distance(problem, X));
  return worst / mean_edge_length(problem, X);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_IMPL_H
