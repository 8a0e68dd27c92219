// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_IMPL_H

// The bodies of the non-template functions declared in pole_fans.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/pole_fans.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> with_fan_clusters(const Pole_fans& fans, const std::vector<std::size_t>& quad_label,
                                           std::size_t face_count)
{
  std::vector<std::size_t> label(face_count, 0);
  const std::size_t quad_clusters = *std::max_element(quad_label.begin(), quad_label.end()) + 1;
  for(std::size_t f = 0; f < quad_label.size(); ++f)
    label[fans.face_of[f]] = quad_label[f];
  for(std::size_t fan = 0; fan < fans.triangles.size(); ++fan)
    for(std::size_t f : fans.triangles[fan])
      label[f] = quad_clusters + fan;
  relabel_by_first_face(label);
  return label;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> quad_part_label(const Pole_fans& fans, const std::vector<std::size_t>& label)
{
  std::vector<std::size_t> fan_cluster;
  for(const std::vector<std::size_t>& triangles : fans.triangles)
  {
    fan_cluster.push_back(label[triangles.front()]);
    for(std::size_t f : triangles)
      if(label[f] != fan_cluster.back())
        return {};
  }
  std::vector<std::size_t> quad_label(fans.face_of.size());
  for(std::size_t f = 0; f < quad_label.size(); ++f)
  {
    quad_label[f] = label[fans.face_of[f]];
    if(std::count(fan_cluster.begin(), fan_cluster.end(), quad_label[f]) > 0)
      return {};
  }
  std::vector<std::size_t> sorted = fan_cluster;
  std::sort(sorted.begin(), sorted.end());
  if(std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
    return {};
  return quad_label;
}

CGAL_TILABLE_SURFACES_INLINE
bool put_poles_on_axes(const Pole_fans& fans, Point_matrix& points, const Point_matrix& input, double length)
{
  auto point = [&](std::size_t v) { return Eigen::Vector3d(points.row(Eigen::Index(v)).transpose()); };
  for(std::size_t fan = 0; fan < fans.pole.size(); ++fan)
  {
    const std::vector<std::array<std::size_t, 3> >& triangles = fans.corners[fan];
    Eigen::Matrix3Xd rim(3, Eigen::Index(triangles.size()));
    for(std::size_t t = 0; t < triangles.size(); ++t)
      rim.col(Eigen::Index(t)) = point(triangles[t][1]);
    const Eigen::Vector3d centre = rim.rowwise().mean();
    const Eigen::Matrix3Xd centred = rim.colwise() - centre;
    const Eigen::Vector3d normal = Eigen::JacobiSVD<Eigen::Matrix3d>(centred * centred.transpose(),
                                                                     Eigen::ComputeFullU).matrixU().col(2);
    const Eigen::Vector3d input_pole = input.row(Eigen::Index(fans.pole[fan])).transpose();
    const Eigen::Vector3d pole = centre + normal.dot(input_pole - centre) * normal;
    points.row(Eigen::Index(fans.pole[fan])) = pole.transpose();
    auto edges = [&](const std::array<std::size_t, 3>& t) {
      return Eigen::Vector3d((point(t[1]) - point(t[0])).norm(), (point(t[2]) - point(t[1])).norm(),
                             (point(t[0]) - point(t[2])).norm());
    };
    const Eigen::Vector3d first = edges(triangles.front());
    for(const std::array<std::size_t, 3>& t : triangles)
      if((edges(t) - first).cwiseAbs().maxCoeff() > tuning::pole_fan_congruence * length)
        return false;
  }
  return true;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_IMPL_H
