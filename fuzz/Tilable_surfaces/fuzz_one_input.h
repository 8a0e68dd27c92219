// The body of the fuzz target, shared with the regression test that replays
// the inputs it once crashed on (test_fuzz_regressions): reading (OFF, OBJ
// or PLY, told apart by the first bytes as a user's file would be by its
// extension), validation, and a small run of the whole pipeline (K <= 3, 4
// solver iterations) on the small meshes that are accepted. Refusals
// (Invalid_input) are the expected outcome of bad data; anything else
// escaping, a crash or a sanitizer report is a finding.
#ifndef TILABLE_SURFACES_FUZZ_ONE_INPUT_H
#define TILABLE_SURFACES_FUZZ_ONE_INPUT_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>
#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <cstddef>
#include <sstream>
#include <string>

namespace fuzz_one_input_detail {

inline std::string format_of(const std::string& data)
{
  if(data.compare(0, 3, "ply") == 0) return "ply";
  const std::size_t off = data.find("OFF");
  if(off != std::string::npos && off < 8) return "off";
  return "obj";
}

} // namespace fuzz_one_input_detail

// Returns whether the input was accepted (read and valid).
inline bool fuzz_one_input(const std::string& data)
{
  namespace TS = CGAL::Tilable_surfaces;
  namespace TSP = CGAL::Tilable_surfaces::parameters;
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  std::istringstream in(data, std::ios::binary);
  Mesh mesh;
  try
  {
    TS::IO::read_panel_mesh(in, fuzz_one_input_detail::format_of(data), mesh, "fuzz input");
    TS::validate_panel_mesh(mesh);
    if(mesh.number_of_faces() > 40)
      return true;
    auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
    auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
    const std::size_t n = mesh.number_of_faces();
    const int k = 1 + int(data.size() % (n < 3 ? n : 3));
    const TS::K_set_tilable_result r = TS::make_k_set_tilable(
      mesh, TSP::number_of_tiles(k)
              .face_cluster_map(cluster)
              .face_orientation_map(orientation)
              .number_of_iterations(4)
              .number_of_candidates(std::size_t(2)));
    std::ostringstream out;
    TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster).face_orientation_map(orientation));
    TS::IO::write_tile_catalog_CSV(out, r.tiles);
    return true;
  }
  catch(const TS::Invalid_input&)
  {
    return false;  // refused: what bad data should get
  }
}

#endif
