// The coloured PLY output reads back with the same geometry, order and properties.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Tilable_surfaces/IO/cluster_colors.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/IO/write_edge_components_PLY.h>

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <set>
#include <sstream>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_io_ply_unit {

namespace {

Mesh read_back(const std::string& text)
{
  std::istringstream in(text, std::ios::binary);
  Mesh mesh;
  EXPECT_TRUE(CGAL::IO::read_PLY(in, mesh));
  return mesh;
}

void expect_same_mesh_and_properties(const Mesh& input, const Mesh& output,
                                     const Mesh::Property_map<Mesh::Face_index, int>& cluster,
                                     const Mesh::Property_map<Mesh::Face_index, int>& orientation)
{
  ASSERT_EQ(output.number_of_vertices(), input.number_of_vertices());
  ASSERT_EQ(output.number_of_faces(), input.number_of_faces());
  for(auto v : vertices(input))
    EXPECT_EQ(output.point(v), input.point(v)) << v;  // bit-exact with 17 digits or binary
  for(auto f : faces(input))
  {
    std::vector<Mesh::Vertex_index> a, b;
    for(auto v : CGAL::vertices_around_face(input.halfedge(f), input)) a.push_back(v);
    for(auto v : CGAL::vertices_around_face(output.halfedge(f), output)) b.push_back(v);
    EXPECT_EQ(a, b) << f;
  }
  auto read_cluster = output.property_map<Mesh::Face_index, int>("f:cluster");
  auto read_orientation = output.property_map<Mesh::Face_index, std::uint8_t>("f:orientation");
  auto read_color = output.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color");
  ASSERT_TRUE(read_cluster.second);
  ASSERT_TRUE(read_orientation.second);
  ASSERT_TRUE(read_color.second);
  std::map<int, CGAL::IO::Color> color_of_cluster;
  std::set<std::array<int, 3> > distinct;
  for(auto f : faces(input))
  {
    EXPECT_EQ(read_cluster.first[f], cluster[f]);
    EXPECT_EQ(int(read_orientation.first[f]), orientation[f]);
    const CGAL::IO::Color c = read_color.first[f];
    auto it = color_of_cluster.emplace(cluster[f], c).first;
    EXPECT_EQ(it->second, c) << "one colour per cluster";
  }
  for(const auto& cc : color_of_cluster)
    distinct.insert({{cc.second.red(), cc.second.green(), cc.second.blue()}});
  EXPECT_EQ(distinct.size(), color_of_cluster.size()) << "distinct colours per cluster";
}

} // namespace

TEST(ClusterColors, AreDistinctAndDeterministic)
{
  for(std::size_t n : {1u, 2u, 7u, 60u, 1000u, 20000u})
  {
    const auto colors = TS::IO::cluster_colors(n);
    ASSERT_EQ(colors.size(), n);
    std::set<std::array<int, 3> > distinct;
    for(const auto& c : colors) distinct.insert({{c.red(), c.green(), c.blue()}});
    EXPECT_EQ(distinct.size(), n);
    EXPECT_EQ(TS::IO::cluster_colors(n), colors);
  }
}

TEST(WriteTiledPLY, BinaryAndAsciiReadBackIdentically)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) +
                                          "/de_beers_ginza.off", mesh));
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
  for(auto f : faces(mesh))
  {
    cluster[f] = int(f) % 13;
    orientation[f] = (int(f) * 5) % 8;
  }
  for(bool binary : {true, false})
  {
    std::ostringstream out(std::ios::binary);
    ASSERT_TRUE(TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster)
                                                     .face_orientation_map(orientation)
                                                     .use_binary_mode(binary)));
    EXPECT_EQ(out.str().find("format binary_little_endian") != std::string::npos, binary);
    EXPECT_NE(out.str().find("property int cluster"), std::string::npos);
    EXPECT_NE(out.str().find("property uchar orientation"), std::string::npos);
    expect_same_mesh_and_properties(mesh, read_back(out.str()), cluster, orientation);
  }
}

// stream_precision: the ASCII coordinates are written with that many
// significant digits, so that they read back rounded to them.
TEST(WriteTiledPLY, StreamPrecisionRoundsTheAsciiCoordinates)
{
  Mesh mesh;
  const Point p(1.0 / 3, 2.0 / 3, 1.23456789);
  std::vector<Mesh::Vertex_index> v;
  for(const Point& corner : {Point(0, 0, 0), Point(1, 0, 0), p, Point(0, 1, 0)}) v.push_back(mesh.add_vertex(corner));
  mesh.add_face(v[0], v[1], v[2], v[3]);
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
  for(int digits : {4, 17})
  {
    std::ostringstream out(std::ios::binary);
    ASSERT_TRUE(TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster).face_orientation_map(orientation)
                                                     .use_binary_mode(false).stream_precision(digits)));
    const Mesh back = read_back(out.str());
    ASSERT_EQ(back.number_of_vertices(), 4u);
    const Point q = back.point(Mesh::Vertex_index(2));
    if(digits == 17)
      EXPECT_EQ(q, p);
    else
    {
      EXPECT_DOUBLE_EQ(q.x(), 0.3333);
      EXPECT_DOUBLE_EQ(q.y(), 0.6667);
      EXPECT_DOUBLE_EQ(q.z(), 1.235);
    }
  }
}

TEST(WriteTiledPLY, WorksForAnotherMeshType)
{
  typedef CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3> Polyhedron;
  Polyhedron poly;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) +
                                          "/monkey_saddle.off", poly));
  CGAL::set_halfedgeds_items_id(poly);
  std::map<Polyhedron::Face_handle, int> cluster, orientation;
  int i = 0;
  for(auto f : faces(poly)) { cluster[f] = i % 3; orientation[f] = i % 8; ++i; }
  std::ostringstream out(std::ios::binary);
  ASSERT_TRUE(TS::IO::write_tiled_PLY(out, poly,
      TSP::face_cluster_map(boost::make_assoc_property_map(cluster))
         .face_orientation_map(boost::make_assoc_property_map(orientation))));
  const Mesh back = read_back(out.str());
  EXPECT_EQ(back.number_of_faces(), 100u);
  EXPECT_EQ(back.number_of_vertices(), 121u);
  auto read_cluster = back.property_map<Mesh::Face_index, int>("f:cluster").first;
  int j = 0;
  for(auto f : faces(back)) EXPECT_EQ(read_cluster[f], j++ % 3);
}

TEST(WriteEdgeComponentsPLY, EachFanTriangleHasItsEdgesComponentColour)
{
  Mesh mesh;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) +
                                          "/monkey_saddle.off", mesh));
  // Components by direction in the grid: edges along x are 0, along y are 1.
  std::map<Mesh::Edge_index, int> component;
  for(auto e : edges(mesh))
  {
    const auto d = mesh.point(target(e, mesh)) - mesh.point(source(e, mesh));
    component[e] = std::abs(d.x()) > std::abs(d.y()) ? 0 : 1;
  }
  std::ostringstream out(std::ios::binary);
  ASSERT_TRUE(TS::IO::write_edge_components_PLY(out, mesh, boost::make_assoc_property_map(component)));
  const Mesh back = read_back(out.str());
  ASSERT_EQ(back.number_of_faces(), 4 * mesh.number_of_faces());
  auto color = back.property_map<Mesh::Face_index, CGAL::IO::Color>("f:color");
  ASSERT_TRUE(color.second);
  const auto palette = TS::IO::cluster_colors(2);
  for(auto t : faces(back))
  {
    // The triangle's first two vertices are the ends of its mesh edge.
    auto h = back.halfedge(t);
    const auto a = back.point(target(h, back));
    const auto b = back.point(target(next(h, back), back));
    const int expected = std::abs(b.x() - a.x()) > std::abs(b.y() - a.y()) ? 0 : 1;
    EXPECT_EQ(color.first[t], palette[expected]) << t;
  }
}

} // namespace test_io_ply_unit
