// Clustering time and memory at ~1k, ~10k and ~100k quads.
//
// Generates the SEASHELL parametrization of the test data (planispiral tube
// P(t, s) = (R + r cos s)(cos t, sin t, 0) + r sin s (0, 0, 1), R = e^{0.25 t},
// r = 0.55 e^{0.25 t}, t in [0, 1.5 pi], s around) on an n x n grid, clusters
// it into K = 100 S-quads and prints a markdown table. Peak memory is the
// process's high-water mark (VmHWM), so sizes are run in increasing order.
//
// Usage: benchmark_clustering [K] [max_quads]
#include "benchmark_surfaces.h"

#include <CGAL/Tilable_surfaces/cluster_panels.h>

#include <CGAL/Real_timer.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <cstdlib>
#include <iostream>
#include <string>

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

using benchmark_surfaces::peak_memory_mb;

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
    Mesh m = benchmark_surfaces::seashell<Mesh>(n);
    auto cluster = m.add_property_map<Mesh::Face_index, std::size_t>("f:cluster", 0).first;
    auto orientation = m.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
    CGAL::Real_timer timer;
    timer.start();
    const TS::Clustering_result r = TS::cluster_panels(
      m, TS::parameters::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation));
    timer.stop();
    std::cout << "| " << m.number_of_faces() << " | " << k << " | "
              << (r.path == TS::EXACT_PATH ? "exact" : "descriptor") << " | "
              << r.number_of_initial_clusters << " | " << timer.time() << " | "
              << peak_memory_mb() << " | " << r.degree_of_flexibility << " |" << std::endl;
  }
  return EXIT_SUCCESS;
}
