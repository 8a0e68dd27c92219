// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_IMPL_H

// The bodies of the non-template functions declared in Tilable_problem.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Panel instance(const Tilable_problem& problem, const Point_matrix& points, std::size_t face)
{
  const auto& c = problem.face_corners[face];
  auto corner = [&](int i) -> Eigen::Vector3d { return points.row(c[std::size_t(i)]).transpose(); };
  if(corner_count(problem, face) == 3)
    return Panel(corner(0), corner(1), corner(2));
  return Panel{{corner(0), corner(1), corner(2), corner(3)}};
}

CGAL_TILABLE_SURFACES_INLINE
void add_cluster_groups(Tilable_problem& problem)
{
  std::vector<std::vector<std::size_t>> by_cluster(problem.number_of_clusters);
  for(std::size_t i = 0; i < problem.face_cluster.size(); ++i)
    by_cluster[problem.face_cluster[i]].push_back(i);
  for(const auto& members : by_cluster)
  {
    // The kinds are never mixed in a cluster (read_face_clustering() checks).
    if(!members.empty() && corner_count(problem, members.front()) == 3)
      continue;
    for(int d = 0; d < 2; ++d)
    {
      for(std::size_t i : members)
      {
        const auto& c = problem.face_corners[i];
        problem.diagonal_groups.items.push_back({{c[d], c[d + 2], -1, -1}});
      }
      problem.diagonal_groups.close_group();
    }
    for(std::size_t i : members)
    {
      const auto& c = problem.face_corners[i];
      if(problem.allow_mirror && signed_volume(instance(problem, problem.points, i)) < 0)
        problem.volume_groups.items.push_back({{c[0], c[3], c[2], c[1]}});
      else
        problem.volume_groups.items.push_back(c);
    }
    problem.volume_groups.close_group();
  }
}

CGAL_TILABLE_SURFACES_INLINE
double mean_edge_length(const Tilable_problem& problem, const Point_matrix& points)
{
  double sum = 0;
  for(const auto& e : problem.edges)
    sum += (points.row(e[0]) - points.row(e[1])).norm();
  return problem.edges.empty() ? 0.0 : sum / double(problem.edges.size());
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_IMPL_H
