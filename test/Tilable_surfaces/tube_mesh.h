// Test helper: open tubes swept along a line or a circle, whose rings and
// sections are known by construction.
#ifndef TILABLE_SURFACES_TEST_TUBE_MESH_H
#define TILABLE_SURFACES_TEST_TUBE_MESH_H

#include <cmath>
#include <vector>

// `rings` rings of `around` quads between rings + 1 closed vertex loops;
// vertex j of loop i is at loop_point(i, j). Face (i, j) has vertices
// (i, j), (i, j + 1), (i + 1, j + 1), (i + 1, j) and index i * around + j;
// vertex (i, j) has index i * around + j.
template <typename Mesh, typename LoopPoint>
Mesh swept_tube(int rings, int around, LoopPoint loop_point)
{
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  for(int i = 0; i <= rings; ++i)
    for(int j = 0; j < around; ++j)
      v.push_back(m.add_vertex(loop_point(i, j)));
  auto id = [&](int i, int j) { return v[i * around + (j % around)]; };
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

#endif
