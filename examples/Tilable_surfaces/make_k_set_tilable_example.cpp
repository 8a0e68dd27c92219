// The ten-line use of the package: read a quad mesh, make it 20-set tilable,
// read the cluster and orientation of each face, write the moved mesh.
//
// Usage: make_k_set_tilable_example [mesh.off|obj|ply] [K]   (default: bundled De Beers facade, K = 20)

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <iostream>
#include <string>

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
namespace TS = CGAL::Tilable_surfaces;

int main(int argc, char** argv)
{
  const std::string filename =
    argc > 1 ? argv[1] : std::string(CGAL_TILABLE_SURFACES_EXAMPLE_DATA) + "/de_beers_ginza.off";
  const int k = argc > 2 ? std::stoi(argv[2]) : 20;

  Mesh mesh;
  if(!CGAL::IO::read_polygon_mesh(filename, mesh))
  {
    std::cerr << "cannot read " << filename << "\n";
    return 2;
  }
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:cluster", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, unsigned char>("f:orientation", 0).first;

  // Parallel_if_available_tag: with TBB, the steps use every core (same result).
  const TS::K_set_tilable_result result = TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(
    mesh, TS::parameters::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation));

  const TS::Tilability_measure& m = result.optimization.measure;
  std::cout << "K = " << m.number_of_clusters << ", degree of flexibility " << m.degree_of_flexibility
            << "\ncongruence error " << m.congruence_error << " (" << (result.is_tilable() ? "" : "NOT ")
            << "tilable), max distance to the input " << m.max_approximation_error
            << " of the bounding-box diagonal\n"
            << "face 0: cluster " << cluster[Mesh::Face_index(0)] << ", orientation "
            << int(orientation[Mesh::Face_index(0)]) << "\n";
  CGAL::IO::write_polygon_mesh("tilable.off", mesh, CGAL::parameters::stream_precision(17));
  return result.is_tilable() ? 0 : 1;
}
