// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_IMPL_H

// The bodies of the non-template functions declared in self_intersections.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Measure/self_intersections.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::size_t self_intersecting_face_pairs(const Tilable_problem& problem, const Point_matrix& x)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Triangle_mesh;
  typedef Triangle_mesh::Face_index Triangle;

  auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  Triangle_mesh fans;
  std::vector<Triangle_mesh::Vertex_index> vertex;
  for(Eigen::Index v = 0; v < x.rows(); ++v)
    vertex.push_back(fans.add_vertex(point(x.row(v).transpose())));
  std::vector<std::size_t> face_of; // by triangle index, consecutive in Surface_mesh
  for(std::size_t f = 0; f < problem.face_corners.size(); ++f)
  {
    const Panel q = instance(problem, x, f);
    const Triangle_mesh::Vertex_index centre = fans.add_vertex(point(q.centroid()));
    const auto& corners = problem.face_corners[f];
    for(int i = 0; i < q.size(); ++i)
    {
      if(fans.add_face(vertex[std::size_t(corners[std::size_t(i)])],
                       vertex[std::size_t(corners[std::size_t((i + 1) % q.size())])], centre) !=
         Triangle_mesh::null_face())
        face_of.push_back(f);
    }
  }

  std::vector<std::pair<Triangle, Triangle>> crossing;
  Polygon_mesh_processing::self_intersections<CGAL::Parallel_if_available_tag>(fans, std::back_inserter(crossing));
  std::vector<std::pair<std::size_t, std::size_t>> face_pairs;
  for(const auto& t : crossing)
  {
    const std::size_t a = face_of[std::size_t(t.first)], b = face_of[std::size_t(t.second)];
    if(a != b)
      face_pairs.emplace_back((std::min)(a, b), (std::max)(a, b));
  }
  std::sort(face_pairs.begin(), face_pairs.end());
  return std::size_t(std::unique(face_pairs.begin(), face_pairs.end()) - face_pairs.begin());
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_IMPL_H
