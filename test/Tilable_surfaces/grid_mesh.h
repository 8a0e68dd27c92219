// Test helper: flat grids of equal rectangles, whose edge-sharing graphs can
// be counted by hand, and grids with cells left out (trimmed outlines,
// openings), which the benchmarks generate too.
#ifndef TILABLE_SURFACES_TEST_GRID_MESH_H
#define TILABLE_SURFACES_TEST_GRID_MESH_H

#include <cstddef>
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

// An nx x ny grid of quads over the lattice points (i, j), vertex (i, j) at
// point(i, j), with only the cells (i, j) where keep(i, j) (and only their
// vertices, numbered as first used). Cell (i, j) has the corners (i, j),
// (i+1, j), (i+1, j+1), (i, j+1); the cells are added row j by row j.
template <typename Mesh, typename PointAt, typename Keep>
Mesh grid_of_kept_cells(int nx, int ny, PointAt point, Keep keep)
{
  typedef typename Mesh::Vertex_index Vertex;
  Mesh m;
  std::vector<Vertex> v(std::size_t(nx + 1) * std::size_t(ny + 1), Mesh::null_vertex());
  auto id = [&](int i, int j) {
    Vertex& w = v[std::size_t(j) * std::size_t(nx + 1) + std::size_t(i)];
    if(w == Mesh::null_vertex())
      w = m.add_vertex(point(i, j));
    return w;
  };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      if(keep(i, j))
        m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

#endif
