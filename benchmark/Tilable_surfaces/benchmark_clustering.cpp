// Clustering time and memory at ~1k, ~10k and ~100k quads.
//
// Generates the SEASHELL parametrization of the test data (planispiral tube
// P(t, s) = (R + r cos s)(cos t, sin t, 0) + r sin s (0, 0, 1), R = e^{0.25 t},
// r = 0.55 e^{0.25 t}, t in [0, 1.5 pi], s around) on an n x n grid, clusters
// it into K = 100 S-quads and prints a markdown table. Peak memory is the
// process's high-water mark (VmHWM), so sizes are run in increasing order.
//
// Usage: benchmark_clustering [K] [max_quads]
#include <CGAL/Tilable_surfaces/cluster_quads.h>

#include <CGAL/Real_timer.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

namespace {

Mesh seashell(int n)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int i = 0; i <= n; ++i)
    for(int j = 0; j < n; ++j)  // closed around s
    {
      const double t = 1.5 * M_PI * i / n, s = 2 * M_PI * j / n;
      const double big_r = std::exp(0.25 * t), r = 0.55 * big_r;
      v.push_back(m.add_vertex(Kernel::Point_3((big_r + r * std::cos(s)) * std::cos(t),
                                               (big_r + r * std::cos(s)) * std::sin(t),
                                               r * std::sin(s))));
    }
  auto id = [&](int i, int j) { return v[i * n + (j % n)]; };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

double peak_memory_mb()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while(std::getline(status, line))
    if(line.rfind("VmHWM:", 0) == 0)
      return std::stod(line.substr(6)) / 1024.0;  // kB
  return -1;
}

} // namespace

int main(int argc, char** argv)
{
  const std::size_t k = argc > 1 ? std::stoul(argv[1]) : 100;
  const std::size_t max_quads = argc > 2 ? std::stoul(argv[2]) : 100000;
  std::cout << "| quads | K | path | initial clusters | time (s) | peak memory (MB) | DOF |\n"
            << "|---:|---:|---|---:|---:|---:|---:|\n";
  for(int n : {32, 100, 316})
  {
    if(std::size_t(n) * n > max_quads)
      break;
    Mesh m = seashell(n);
    auto cluster = m.add_property_map<Mesh::Face_index, std::size_t>("f:cluster", 0).first;
    auto orientation = m.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
    CGAL::Real_timer timer;
    timer.start();
    const TS::Clustering_result r = TS::cluster_quads(
      m, TS::parameters::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation));
    timer.stop();
    std::cout << "| " << m.number_of_faces() << " | " << k << " | "
              << (r.path == TS::EXACT_PATH ? "exact" : "descriptor") << " | "
              << r.number_of_initial_clusters << " | " << timer.time() << " | "
              << peak_memory_mb() << " | " << r.degree_of_flexibility << " |" << std::endl;
  }
  return EXIT_SUCCESS;
}
