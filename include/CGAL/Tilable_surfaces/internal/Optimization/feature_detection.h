// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FEATURE_DETECTION_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FEATURE_DETECTION_H

// Vertices on sharp features and boundary corners, which the fairness term
// leaves alone (paper §4: "vertices that are not on sharp features, such as
// corners and crest lines").

#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Unit vector area of a face (Panel::doubled_vector_area()).
template <typename PolygonMesh, typename VertexIndexMap>
Eigen::Vector3d face_normal(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                            const PolygonMesh& pm, const VertexIndexMap& vim,
                            const Point_matrix& points)
{
  std::array<Eigen::Vector3d, 4> p;
  int n = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
    p[std::size_t(n++)] = points.row(get(vim, v)).transpose();
  const Panel face = n == 3 ? Panel(p[0], p[1], p[2]) : Panel(p);
  return face.doubled_vector_area().normalized();
}

// Flags the vertices excluded from fairness: the ends of feature edges and
// the corners of the boundary. Feature edges are those of
// `edge_is_constrained_map` when the user gives one (`use_edge_map`), else
// the edges whose dihedral angle (between the face normals) exceeds
// `feature_angle_degrees`. A boundary vertex is a corner if it has at most
// 2 incident edges, or (without a user map) if the boundary turns there by
// more than the feature angle.
template <typename PolygonMesh, typename VertexIndexMap, typename EdgeIsConstrainedMap>
std::vector<bool> fairness_exclusions(const PolygonMesh& pm, const VertexIndexMap& vim,
                                      const Point_matrix& points, double feature_angle_degrees,
                                      bool use_edge_map, const EdgeIsConstrainedMap& ecm)
{
  const double cos_feature = std::cos(feature_angle_degrees * CGAL_PI / 180.0);
  std::vector<bool> excluded(num_vertices(pm), false);
  auto at = [&](auto v) { return Eigen::Vector3d(points.row(get(vim, v)).transpose()); };

  for(auto e : edges(pm))
  {
    const auto h = halfedge(e, pm);
    bool feature = false;
    if(use_edge_map)
      feature = get(ecm, e);
    else if(!is_border_edge(h, pm))
      feature = face_normal(face(h, pm), pm, vim, points)
                  .dot(face_normal(face(opposite(h, pm), pm), pm, vim, points)) < cos_feature;
    if(feature)
      excluded[get(vim, source(e, pm))] = excluded[get(vim, target(e, pm))] = true;
  }

  for(auto h : halfedges(pm))
  {
    if(!is_border(h, pm))
      continue;
    // h runs along the boundary into target(h); next(h) leaves it.
    const auto v = target(h, pm);
    bool corner = degree(v, pm) <= 2;
    if(!corner && !use_edge_map)
    {
      const Eigen::Vector3d in = (at(v) - at(source(h, pm))).normalized();
      const Eigen::Vector3d out = (at(target(next(h, pm), pm)) - at(v)).normalized();
      corner = in.dot(out) < cos_feature;
    }
    if(corner)
      excluded[get(vim, v)] = true;
  }
  return excluded;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FEATURE_DETECTION_H
