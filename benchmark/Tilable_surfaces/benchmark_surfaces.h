// The surfaces and the memory probe the benchmark programs share.
#ifndef CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H
#define CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H

#include "../../test/Tilable_surfaces/grid_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace benchmark_surfaces {

// An n x n grid of quads between loops of n vertices, vertex j of loop i at
// point(t, s) with s = 2 pi j / n and t = t_end * i / n: n + 1 loops, or n
// when `welded` (the last row of quads joins loop n - 1 to loop 0).
template <typename Mesh, typename PointAt>
Mesh tube_grid(int n, double t_end, bool welded, PointAt point)
{
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  const int loops = welded ? n : n + 1;
  for(int i = 0; i < loops; ++i)
    for(int j = 0; j < n; ++j)
      v.push_back(m.add_vertex(point(t_end * i / n, 2 * M_PI * j / n)));
  auto id = [&](int i, int j) { return v[std::size_t((i % loops) * n + (j % n))]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

// The SEASHELL parametrization of the test data on an n x n grid (n^2 quads):
// the planispiral tube P(t, s) = (R + r cos s)(cos t, sin t, 0) + r sin s (0, 0, 1),
// R = e^{0.25 t}, r = 0.55 e^{0.25 t}, t in [0, 1.5 pi], closed around s.
template <typename Mesh>
Mesh seashell(int n)
{
  typedef typename Mesh::Point Point;
  return tube_grid<Mesh>(n, 1.5 * M_PI, false, [](double t, double s) {
    const double big_r = std::exp(0.25 * t), r = 0.55 * big_r;
    return Point((big_r + r * std::cos(s)) * std::cos(t), (big_r + r * std::cos(s)) * std::sin(t), r * std::sin(s));
  });
}

// A saddle roof z = 0.35 (x^2 - y^2) + 0.08 sin(2.5 x + 1.3 y) on an n x n grid
// over [-1, 1]^2, trimmed by its outline: only the cells whose centre lies in
// the ellipse x^2 + (y / 0.8)^2 <= 0.95 are kept (about 0.6 n^2 quads), so its
// rows have different lengths, as a facade's or a roof's do.
template <typename Mesh>
Mesh trimmed_roof(int n)
{
  typedef typename Mesh::Point Point;
  return grid_of_kept_cells<Mesh>(
    n, n,
    [n](int i, int j) {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      return Point(x, y, 0.35 * (x * x - y * y) + 0.08 * std::sin(2.5 * x + 1.3 * y));
    },
    [n](int i, int j) {
      const double x = -1 + 2 * (i + 0.5) / n, y = -1 + 2 * (j + 0.5) / n;
      return x * x + (y / 0.8) * (y / 0.8) <= 0.95;
    });
}

// A torus closed both ways on an n x n grid (n^2 quads): its tube, a circle
// of radius 1, runs at the distance 3 + 0.5 cos 2t from the z axis, an oval,
// so that no two of its loops are congruent.
template <typename Mesh>
Mesh oval_torus(int n)
{
  typedef typename Mesh::Point Point;
  return tube_grid<Mesh>(n, 2 * M_PI, true, [](double t, double s) {
    const double out = 3 + 0.5 * std::cos(2 * t) + std::cos(s);
    return Point(out * std::cos(t), out * std::sin(t), std::sin(s));
  });
}

// A dome meshed with a pole, as domes are: the cap of the ellipsoid
// x^2 + (y / 0.7)^2 + (z / 0.8)^2 = 1 above its equator, a fan of n triangles
// around the pole, then n rings of n quads down to the equator (n^2 quads).
// Its section is an ellipse, so no two of its meridians are congruent.
template <typename Mesh>
Mesh polar_dome(int n)
{
  typedef typename Mesh::Point Point;
  // The vertex rings, numbered 1 .. n + 1 from the pole (ring 0, t = 0) to the equator (t = pi / 2).
  Mesh m = tube_grid<Mesh>(n, 1.0, false, [n](double u, double s) {
    const double t = 0.5 * M_PI * (u * n + 1) / (n + 1);
    return Point(std::sin(t) * std::cos(s), 0.7 * std::sin(t) * std::sin(s), 0.8 * std::cos(t));
  });
  // tube_grid() adds the first ring's vertices first, so they are 0 .. n - 1.
  const typename Mesh::Vertex_index pole = m.add_vertex(Point(0, 0, 0.8));
  auto first_ring = [n](int j) { return typename Mesh::Vertex_index(typename Mesh::size_type(j % n)); };
  for(int j = 0; j < n; ++j)
    m.add_face(pole, first_ring(j), first_ring(j + 1));
  return m;
}

// A curved facade on an n x n grid over [0, 1]^2, z = 0.15 sin(3 x) + 0.1 x y,
// with window openings: a 4 x 4 array of holes of about n / 10 x n / 8 cells
// (about 0.8 n^2 quads). A trimmed grid whose boundary has inner loops.
template <typename Mesh>
Mesh facade_with_openings(int n)
{
  typedef typename Mesh::Point Point;
  const int bay = (std::max)(n / 4, 3);
  return grid_of_kept_cells<Mesh>(
    n, n,
    [n](int i, int j) {
      const double x = double(i) / n, y = double(j) / n;
      return Point(x, y, 0.15 * std::sin(3 * x) + 0.1 * x * y);
    },
    [n, bay](int i, int j) {
      const int u = i % bay - bay / 3, w = j % bay - bay / 4;
      return !(u >= 0 && u < (std::max)(n / 10, 1) && w >= 0 && w < (std::max)(n / 8, 1));
    });
}

// An ellipsoid x^2 + (y / 0.8)^2 + (z / 0.7)^2 = 1 meshed as a quad ball: the
// six faces of a cube, each an n x n grid, pushed out to it (6 n^2 quads).
// Not a grid: its eight corners are vertices of valence 3, so it has no
// sweep, as most remeshed freeform surfaces have none.
template <typename Mesh>
Mesh quad_ball(int n)
{
  typedef typename Mesh::Point Point;
  typedef typename Mesh::Vertex_index Vertex;
  Mesh m;
  // The vertex at lattice point p of the cube's surface, p in [-n, n]^3.
  std::map<std::array<int, 3>, Vertex> v;
  auto id = [&](const std::array<int, 3>& p) {
    auto it = v.find(p);
    if(it == v.end())
    {
      const double r = std::sqrt(double(p[0]) * p[0] + double(p[1]) * p[1] + double(p[2]) * p[2]);
      it = v.emplace(p, m.add_vertex(Point(p[0] / r, 0.8 * p[1] / r, 0.7 * p[2] / r))).first;
    }
    return it->second;
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side : {-1, 1})
      for(int i = 0; i < n; ++i)
        for(int j = 0; j < n; ++j)
        {
          std::vector<Vertex> corners;
          for(const auto& uv : {std::make_pair(i, j), std::make_pair(i + 1, j), std::make_pair(i + 1, j + 1),
                                std::make_pair(i, j + 1)})
          {
            std::array<int, 3> p;
            p[std::size_t(axis)] = side * n;
            p[std::size_t(axis + 1) % 3] = 2 * uv.first - n;
            p[std::size_t(axis + 2) % 3] = 2 * uv.second - n;
            corners.push_back(id(p));
          }
          if(side < 0)
            std::reverse(corners.begin(), corners.end());
          m.add_face(corners);
        }
  return m;
}

// The process's high-water mark of resident memory (VmHWM) in MB since the
// last reset_peak_memory(), -1 where /proc is not available.
inline double peak_memory_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024.0; // kB
  return -1;
}

// Sets the high-water mark to the current resident memory (Linux 4.0 and
// later), so that each run's peak is its own; false where that is not
// possible (the mark then only grows: measure sizes in increasing order).
inline bool reset_peak_memory()
{
  std::ofstream clear_refs("/proc/self/clear_refs");
  clear_refs << "5";
  return bool(clear_refs.flush());
}

} // namespace benchmark_surfaces

#endif // CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H
