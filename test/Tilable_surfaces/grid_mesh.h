// Test helper: flat grids of equal rectangles, whose edge-sharing graphs can
// be counted by hand.
#ifndef TILABLE_SURFACES_TEST_GRID_MESH_H
#define TILABLE_SURFACES_TEST_GRID_MESH_H

#include <vector>

// nx x ny grid of w x h rectangles in the plane z = 0. Face (i, j) is added
// with vertices (i,j), (i+1,j), (i+1,j+1), (i,j+1): its edges 0 and 2 are
// horizontal (length w), 1 and 3 vertical (length h). Faces are numbered
// i + nx * j.
template <typename Mesh>
Mesh grid(int nx, int ny, double w = 2, double h = 1)
{
  typedef typename Mesh::Point Point;
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  for(int j = 0; j <= ny; ++j)
    for(int i = 0; i <= nx; ++i)
      v.push_back(m.add_vertex(Point(w * i, h * j, 0)));
  auto id = [&](int i, int j) { return v[i + (nx + 1) * j]; };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

#endif
