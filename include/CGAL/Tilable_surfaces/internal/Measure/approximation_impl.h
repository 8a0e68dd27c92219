// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_IMPL_H

// The bodies of the non-template functions declared in approximation.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Measure/approximation.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Distance_summary one_sided_distance(const Tilable_problem& problem,
                                    const Point_matrix& reference,
                                    const Point_matrix& sampled)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_triangle_primitive<K, Iterator> Primitive;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>> Tree;

  auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::vector<K::Triangle_3> triangles;
  for(std::size_t f = 0; f < problem.face_corners.size(); ++f)
  {
    const Panel q = instance(problem, reference, f);
    const K::Point_3 centre = point(q.centroid());
    for(int i = 0; i < q.size(); ++i)
      triangles.emplace_back(point(q[i]), point(q[(i + 1) % q.size()]), centre);
  }
  Tree tree(triangles.begin(), triangles.end());
  tree.accelerate_distance_queries();

  auto distance = [&](const Eigen::Vector3d& p) { return std::sqrt(tree.squared_distance(point(p))); };
  // The vertices of the faces: an isolated vertex is no part of the surface.
  std::vector<bool> on_surface(std::size_t(sampled.rows()), false);
  for(const auto& corners : problem.face_corners)
    for(int v : corners)
      if(v >= 0) on_surface[std::size_t(v)] = true;
  // Distances by slot, in parallel, summed in slot order afterwards: the
  // same mean whatever the threads. A face has at most 1 + 2 * 4 samples.
  const std::size_t vertices = std::size_t(sampled.rows()), per_face = 9;
  std::vector<double> d(vertices + per_face * problem.face_corners.size(), -1.0);
  parallel_for(vertices, [&](std::size_t v) {
    if(on_surface[v])
      d[v] = distance(sampled.row(Eigen::Index(v)).transpose());
  });
  parallel_for(problem.face_corners.size(), [&](std::size_t f) {
    const Panel q = instance(problem, sampled, f);
    const Eigen::Vector3d centre = q.centroid();
    double* slot = &d[vertices + per_face * f];
    *slot++ = distance(centre);
    for(int i = 0; i < q.size(); ++i)
    {
      *slot++ = distance(0.5 * (q[i] + q[(i + 1) % q.size()]));
      *slot++ = distance((q[i] + q[(i + 1) % q.size()] + centre) / 3.0);
    }
  });
  Distance_summary s;
  std::size_t count = 0;
  for(double x : d)
    if(x >= 0)
    {
      s.max = (std::max)(s.max, x);
      s.mean += x;
      ++count;
    }
  s.mean /= double(count);
  return s;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_IMPL_H
