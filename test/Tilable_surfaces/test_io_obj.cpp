// The OBJ output keeps the tiles: read back by the test's own reader
// (obj_file.h), every face is in the group and material of its cluster, the
// material library has one material per cluster with the PLY's colour, and
// the positions are bit-exact.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Tilable_surfaces/IO/write_OBJ.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "obj_file.h"

#include <gtest/gtest.h>

#include <boost/property_map/property_map.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_io_obj_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
namespace fs = std::filesystem;
typedef CGAL::Simple_cartesian<double> K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

namespace {

const std::string data_dir = CGAL_TILABLE_SURFACES_TEST_DATA;

// Faces as 0-based vertex positions in `vertices(pm)` order, in `faces(pm)`
// order, with the cluster of each.
template <typename PolygonMesh, typename ClusterMap>
std::map<std::vector<std::size_t>, int> face_clusters(const PolygonMesh& pm, ClusterMap cluster)
{
  std::map<typename boost::graph_traits<PolygonMesh>::vertex_descriptor, std::size_t> index;
  for(auto v : vertices(pm)) index.emplace(v, index.size());
  std::map<std::vector<std::size_t>, int> result;
  for(auto f : faces(pm))
  {
    std::vector<std::size_t> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm)) corners.push_back(index.at(v));
    EXPECT_TRUE(result.emplace(corners, int(get(cluster, f))).second);
  }
  return result;
}

// Every face of `pm` is in the OBJ once, with its vertex cycle, in group and
// material tile_<its cluster>; each non-empty cluster is one `g` statement.
template <typename PolygonMesh, typename ClusterMap>
void expect_groups_are_clusters(const Obj_file& obj, const PolygonMesh& pm, ClusterMap cluster)
{
  const std::map<std::vector<std::size_t>, int> expected = face_clusters(pm, cluster);
  ASSERT_EQ(obj.faces.size(), expected.size());
  std::set<std::vector<std::size_t> > seen;
  for(std::size_t i = 0; i < obj.faces.size(); ++i)
  {
    const auto it = expected.find(obj.faces[i]);
    ASSERT_NE(it, expected.end()) << "OBJ face " << i << " is not a face of the mesh";
    EXPECT_TRUE(seen.insert(obj.faces[i]).second) << "OBJ face " << i << " written twice";
    EXPECT_EQ(obj.face_group[i], "tile_" + std::to_string(it->second)) << i;
    EXPECT_EQ(obj.face_material[i], "tile_" + std::to_string(it->second)) << i;
  }
  std::set<int> clusters;
  for(const auto& fc : expected) clusters.insert(fc.second);
  EXPECT_EQ(obj.group_statements.size(), clusters.size()) << "one g statement per cluster";
  EXPECT_EQ(std::set<std::string>(obj.group_statements.begin(), obj.group_statements.end()).size(),
            clusters.size());
}

// The materials are tile_0..tile_{n-1}, each with the diffuse colour `colors[c]`.
void expect_materials(const std::vector<Mtl_material>& materials,
                      const std::map<int, CGAL::IO::Color>& colors, std::size_t n)
{
  ASSERT_EQ(materials.size(), n);
  for(std::size_t c = 0; c < n; ++c)
  {
    EXPECT_EQ(materials[c].name, "tile_" + std::to_string(c));
    const auto it = colors.find(int(c));
    if(it == colors.end())
      continue;
    const int rgb[3] = {it->second.red(), it->second.green(), it->second.blue()};
    for(int j = 0; j < 3; ++j)
    {
      EXPECT_GE(materials[c].diffuse[j], 0.0);
      EXPECT_LE(materials[c].diffuse[j], 1.0);
      EXPECT_EQ(std::lround(255 * materials[c].diffuse[j]), rgb[j]) << materials[c].name << " channel " << j;
    }
  }
}

// The colour of each cluster in the PLY output, read back with CGAL's reader.
std::map<int, CGAL::IO::Color> ply_colors(const Mesh& mesh, Mesh::Property_map<Mesh::Face_index, int> cluster,
                                          Mesh::Property_map<Mesh::Face_index, int> orientation)
{
  std::ostringstream out(std::ios::binary);
  EXPECT_TRUE(TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster).face_orientation_map(orientation)));
  std::istringstream in(out.str(), std::ios::binary);
  Mesh back;
  EXPECT_TRUE(CGAL::IO::read_PLY(in, back));
  auto read_cluster = back.property_map<Mesh::Face_index, int>("f:cluster");
  auto read_color = back.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color");
  EXPECT_TRUE(read_cluster.second && read_color.second);
  std::map<int, CGAL::IO::Color> colors;
  for(auto f : faces(back)) colors.emplace(read_cluster.first[f], read_color.first[f]);
  return colors;
}

fs::path scratch(const std::string& name)
{
  const fs::path dir = fs::temp_directory_path() / ("tilable_surfaces_test_io_obj_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

} // namespace

TEST(WriteTiledOBJ, GroupsMaterialsAndPositionsOfATiledSurface)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data_dir + "/monkey_saddle.off", mesh));
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const int k = 7;
  TS::make_k_set_tilable(mesh, TSP::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation));

  const fs::path dir = scratch("saddle");
  ASSERT_TRUE(TS::IO::write_tiled_OBJ((dir / "saddle.obj").string(), mesh, TSP::face_cluster_map(cluster)));
  ASSERT_TRUE(fs::exists(dir / "saddle.mtl")) << "the material library beside the OBJ";

  std::ifstream obj_in(dir / "saddle.obj");
  const Obj_file obj = read_obj(obj_in);
  EXPECT_EQ(obj.material_library, "saddle.mtl");
  ASSERT_EQ(obj.vertices.size(), mesh.number_of_vertices());
  std::size_t i = 0;
  for(auto v : vertices(mesh))
  {
    const K::Point_3& p = mesh.point(v);
    EXPECT_EQ(obj.vertices[i][0], p.x()) << std::setprecision(17) << "vertex " << i;  // bit-exact
    EXPECT_EQ(obj.vertices[i][1], p.y()) << std::setprecision(17) << "vertex " << i;
    EXPECT_EQ(obj.vertices[i][2], p.z()) << std::setprecision(17) << "vertex " << i;
    ++i;
  }
  expect_groups_are_clusters(obj, mesh, cluster);

  std::ifstream mtl_in(dir / "saddle.mtl");
  const std::map<int, CGAL::IO::Color> colors = ply_colors(mesh, cluster, orientation);
  ASSERT_EQ(colors.size(), std::size_t(k)) << "every cluster has faces";
  expect_materials(read_mtl(mtl_in), colors, std::size_t(k));
}

TEST(WriteTiledOBJ, WorksForAnotherMeshTypeAndEmptyClusters)
{
  typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron;
  Polyhedron poly;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data_dir + "/de_beers_ginza.off", poly));
  CGAL::set_halfedgeds_items_id(poly);
  // Clusters 0, 2, 4, ..., 10 only: 11 materials, 6 groups.
  std::map<Polyhedron::Face_handle, int> cluster;
  int i = 0;
  for(auto f : faces(poly)) cluster[f] = 2 * ((i++ * 5) % 6);
  const auto cluster_map = boost::make_assoc_property_map(cluster);

  std::ostringstream obj_out, mtl_out;
  obj_out << std::setprecision(3) << std::fixed;
  ASSERT_TRUE(TS::IO::write_tiled_OBJ(obj_out, poly, "tiles.mtl", TSP::face_cluster_map(cluster_map)));
  ASSERT_TRUE(TS::IO::write_tiled_MTL(mtl_out, poly, TSP::face_cluster_map(cluster_map)));
  EXPECT_EQ(obj_out.precision(), 3) << "the caller's stream format is restored";
  EXPECT_TRUE(obj_out.flags() & std::ios::fixed);

  std::istringstream obj_in(obj_out.str()), mtl_in(mtl_out.str());
  const Obj_file obj = read_obj(obj_in);
  EXPECT_EQ(obj.material_library, "tiles.mtl");
  ASSERT_EQ(obj.vertices.size(), poly.size_of_vertices());
  i = 0;
  for(auto v : vertices(poly))
  {
    EXPECT_EQ(obj.vertices[std::size_t(i)][0], v->point().x()) << i;
    EXPECT_EQ(obj.vertices[std::size_t(i)][2], v->point().z()) << i;
    ++i;
  }
  expect_groups_are_clusters(obj, poly, cluster_map);
  std::map<int, CGAL::IO::Color> colors;
  const auto palette = TS::IO::cluster_colors(11);
  for(int c = 0; c < 11; ++c) colors.emplace(c, palette[std::size_t(c)]);
  expect_materials(read_mtl(mtl_in), colors, 11);
}

TEST(WriteTiledOBJ, RefusesANegativeClusterIdAndCreatesNoFile)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data_dir + "/monkey_saddle.off", mesh));
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  cluster[Mesh::Face_index(17)] = -2;
  const fs::path dir = scratch("negative");
  EXPECT_THROW(TS::IO::write_tiled_OBJ((dir / "bad.obj").string(), mesh, TSP::face_cluster_map(cluster)),
               TS::Invalid_input);
  EXPECT_TRUE(fs::is_empty(dir));
  std::ostringstream obj_out, mtl_out;
  EXPECT_THROW(TS::IO::write_tiled_OBJ(obj_out, mesh, "bad.mtl", TSP::face_cluster_map(cluster)),
               TS::Invalid_input);
  EXPECT_TRUE(obj_out.str().empty());
  EXPECT_THROW(TS::IO::write_tiled_MTL(mtl_out, mesh, TSP::face_cluster_map(cluster)), TS::Invalid_input);
}

} // namespace test_io_obj_unit
