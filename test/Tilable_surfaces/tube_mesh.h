// Test helper: open tubes swept along a line or a circle, whose rings and
// sections are known by construction.
#ifndef TILABLE_SURFACES_TEST_TUBE_MESH_H
#define TILABLE_SURFACES_TEST_TUBE_MESH_H

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <vector>

// `rings` rings of `around` quads between rings + 1 closed vertex loops;
// vertex j of loop i is at loop_point(i, j). Face (i, j) has vertices
// (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j) and index i * around + j;
// vertex (i, j) has index i * around + j. `welded`: a torus instead, of
// `rings` loops, the last ring joining loop rings - 1 to loop 0.
template <typename Mesh, typename LoopPoint>
Mesh swept_tube(int rings, int around, LoopPoint loop_point, bool welded = false)
{
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  const int loops = welded ? rings : rings + 1;
  for(int i = 0; i < loops; ++i)
    for(int j = 0; j < around; ++j)
      v.push_back(m.add_vertex(loop_point(i, j)));
  auto id = [&](int i, int j) { return v[(i % loops) * around + (j % around)]; };
  for(int i = 0; i < rings; ++i)
    for(int j = 0; j < around; ++j)
      m.add_face(id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j));
  return m;
}

// A tube of revolution about the z axis: loop i at height i * 0.25 with
// radius radius(i). Each ring is one quad shape, fixed by its two radii.
template <typename Mesh, typename Radius>
Mesh tube(int rings, int around, Radius radius)
{
  typedef typename Mesh::Point Point;
  return swept_tube<Mesh>(rings, around, [&](int i, int j) {
    const double a = 2 * CGAL_PI * j / around;
    return Point(radius(i) * std::cos(a), radius(i) * std::sin(a), 0.25 * i);
  });
}

// A horn: a tube bent along the circle of radius `bend` about the z axis
// (loop i in the plane at angle turn * i / rings), with circular sections of
// radius radius(i). Vertex j sits at angle 2 pi j / around from the outer
// side, so the plane z = 0 maps face (i, j) onto face (i, around - 1 - j).
template <typename Mesh, typename Radius>
Mesh horn(int rings, int around, double bend, double turn, Radius radius)
{
  typedef typename Mesh::Point Point;
  return swept_tube<Mesh>(rings, around, [&](int i, int j) {
    const double t = turn * i / rings, a = 2 * CGAL_PI * j / around;
    const double out = bend + radius(i) * std::cos(a);
    return Point(out * std::cos(t), out * std::sin(t), radius(i) * std::sin(a));
  });
}

// A welded tube of radius `radius` about the trefoil knot
// (sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t): `rings` rings of `around`
// quads, each loop a circle in the plane normal to the knot, started on the
// Frenet normal (the knot's curvature never vanishes, and the frame closes).
template <typename Mesh>
Mesh trefoil_tube(int rings, int around, double radius)
{
  typedef typename Mesh::Point Point;
  return swept_tube<Mesh>(rings, around, [&](int i, int j) {
    const double t = 2 * CGAL_PI * i / rings, a = 2 * CGAL_PI * j / around;
    const Eigen::Vector3d c(std::sin(t) + 2 * std::sin(2 * t), std::cos(t) - 2 * std::cos(2 * t), -std::sin(3 * t));
    const Eigen::Vector3d d1(std::cos(t) + 4 * std::cos(2 * t), -std::sin(t) + 4 * std::sin(2 * t), -3 * std::cos(3 * t));
    const Eigen::Vector3d d2(-std::sin(t) - 8 * std::sin(2 * t), -std::cos(t) + 8 * std::cos(2 * t), 9 * std::sin(3 * t));
    const Eigen::Vector3d b = d1.cross(d2).normalized(), n = b.cross(d1).normalized();
    const Eigen::Vector3d p = c + radius * (std::cos(a) * n + std::sin(a) * b);
    return Point(p.x(), p.y(), p.z());
  }, true);
}

#endif
