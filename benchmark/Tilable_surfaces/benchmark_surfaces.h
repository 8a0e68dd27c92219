// The surface and the memory probe the benchmark programs share.
#ifndef CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H
#define CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace benchmark_surfaces {

// The SEASHELL parametrization of the test data on an n x n grid (n^2 quads):
// the planispiral tube P(t, s) = (R + r cos s)(cos t, sin t, 0) + r sin s (0, 0, 1),
// R = e^{0.25 t}, r = 0.55 e^{0.25 t}, t in [0, 1.5 pi], closed around s.
template <typename Mesh>
Mesh seashell(int n)
{
  typedef typename Mesh::Point Point;
  Mesh m;
  std::vector<typename Mesh::Vertex_index> v;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j < n; ++j)
    {
      const double t = 1.5 * M_PI * i / n, s = 2 * M_PI * j / n;
      const double big_r = std::exp(0.25 * t), r = 0.55 * big_r;
      v.push_back(m.add_vertex(Point((big_r + r * std::cos(s)) * std::cos(t),
                                     (big_r + r * std::cos(s)) * std::sin(t), r * std::sin(s))));
    }
  auto id = [&](int i, int j) { return v[std::size_t(i * n + (j % n))]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

// The process's high-water mark of resident memory (VmHWM) in MB, -1 where
// /proc is not available. It only grows: measure sizes in increasing order.
inline double peak_memory_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024.0; // kB
  return -1;
}

} // namespace benchmark_surfaces

#endif // CGAL_TILABLE_SURFACES_BENCHMARK_SURFACES_H
