// The surfaces and the memory probe the benchmark programs share.
#ifndef CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H
#define CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H

#include <cmath>
#include <fstream>
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
  typedef typename Mesh::Vertex_index Vertex;
  auto inside = [n](int i, int j) {
    const double x = -1 + 2 * (i + 0.5) / n, y = -1 + 2 * (j + 0.5) / n;
    return x * x + (y / 0.8) * (y / 0.8) <= 0.95;
  };
  Mesh m;
  std::vector<Vertex> v(std::size_t(n + 1) * std::size_t(n + 1), Mesh::null_vertex());
  auto id = [&](int i, int j) {
    Vertex& w = v[std::size_t(j) * std::size_t(n + 1) + std::size_t(i)];
    if(w == Mesh::null_vertex())
    {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      w = m.add_vertex(Point(x, y, 0.35 * (x * x - y * y) + 0.08 * std::sin(2.5 * x + 1.3 * y)));
    }
    return w;
  };
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if(inside(i, j))
        m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
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
  Mesh m;
  const typename Mesh::Vertex_index pole = m.add_vertex(Point(0, 0, 0.8));
  std::vector<typename Mesh::Vertex_index> v;
  for(int i = 1; i <= n + 1; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double t = 0.5 * M_PI * i / (n + 1), s = 2 * M_PI * j / n;
      v.push_back(m.add_vertex(Point(std::sin(t) * std::cos(s), 0.7 * std::sin(t) * std::sin(s), 0.8 * std::cos(t))));
    }
  auto id = [&](int i, int j) { return v[std::size_t(i * n + (j % n))]; };
  for(int j = 0; j < n; ++j)
    m.add_face(pole, id(0, j), id(0, j + 1));
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
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
