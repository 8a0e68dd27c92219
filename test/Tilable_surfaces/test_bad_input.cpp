// Every public entry point refuses bad input the same way: Invalid_input
// naming the culprit, and the mesh, the maps and the output stream untouched
// byte for byte. One table: bad inputs x entry points.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/IO/write_edge_components_PLY.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_bad_input_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Property_map<Mesh::Face_index, int> Face_map;

namespace {

// A mesh with a cluster and an orientation per face (all 0 unless the case
// says otherwise).
struct Case_input
{
  Mesh mesh;
  Face_map cluster, orientation;
};

// Two unit squares side by side: vertices (0,0) (1,0) (2,0) (0,1) (1,1) (2,1),
// faces [0 1 4 3] and [1 2 5 4]; `move` changes the points first.
Case_input two_squares(const std::function<void(std::vector<Point>&)>& move = nullptr)
{
  std::vector<Point> p{Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0),
                       Point(0, 1, 0), Point(1, 1, 0), Point(2, 1, 0)};
  if(move) move(p);
  Case_input in;
  std::vector<Mesh::Vertex_index> v;
  for(const Point& q : p) v.push_back(in.mesh.add_vertex(q));
  in.mesh.add_face(v[0], v[1], v[4], v[3]);
  in.mesh.add_face(v[1], v[2], v[5], v[4]);
  return in;
}

struct Bad_input
{
  const char* name;
  std::function<Case_input()> make;
  TS::Invalid_input::Element element;  // what the error must be about
  std::size_t index;                   // which one (max for the mesh)
  const char* says;                    // a part of the message
  bool about_labels;                   // an error in the cluster / orientation maps
};

const std::size_t none = (std::numeric_limits<std::size_t>::max)();
const double not_a_number = std::numeric_limits<double>::quiet_NaN();
const double inf = std::numeric_limits<double>::infinity();

std::vector<Bad_input> bad_inputs()
{
  return {
    {"NaN coordinate", [] { return two_squares([](std::vector<Point>& p) { p[5] = Point(2, not_a_number, 0); }); },
     TS::Invalid_input::VERTEX, 5, "non-finite coordinate", false},
    {"infinite coordinate", [] { return two_squares([](std::vector<Point>& p) { p[4] = Point(1, 1, -inf); }); },
     TS::Invalid_input::VERTEX, 4, "non-finite coordinate", false},
    {"degenerate face", [] { return two_squares([](std::vector<Point>& p) { p[5] = Point(2, -1, 0); }); },
     TS::Invalid_input::FACE, 1, "is collapsed", false},
    {"zero-length edge", [] { return two_squares([](std::vector<Point>& p) { p[5] = p[2]; }); },
     TS::Invalid_input::FACE, 1, "zero-length edge between vertices 2 and 5", false},
    {"empty mesh", [] { return Case_input(); }, TS::Invalid_input::MESH, none, "no face", false},
    {"broken halfedge structure", [] {
       Case_input in = two_squares();
       // Vertex 4's halfedge points to vertex 0 instead.
       in.mesh.set_halfedge(Mesh::Vertex_index(4), in.mesh.halfedge(Mesh::Vertex_index(0)));
       return in; },
     TS::Invalid_input::MESH, none, "broken halfedge structure", false},
    {"broken face cycle", [] {
       Case_input in = two_squares();
       // Face 0's cycle skips a halfedge: next and previous disagree.
       const Mesh::Halfedge_index h = in.mesh.halfedge(Mesh::Face_index(0));
       in.mesh.set_next(h, in.mesh.next(in.mesh.next(h)));
       return in; },
     TS::Invalid_input::MESH, none, "not reciprocal", false},
    {"pentagon face", [] {
       Case_input in = two_squares();
       const Mesh::Vertex_index a = in.mesh.add_vertex(Point(3, 0, 0)), b = in.mesh.add_vertex(Point(3.5, 0.5, 0)),
                                c = in.mesh.add_vertex(Point(3, 1, 0));
       const std::vector<Mesh::Vertex_index> pentagon{Mesh::Vertex_index(2), a, b, c, Mesh::Vertex_index(5)};
       in.mesh.add_face(pentagon);
       return in; },
     TS::Invalid_input::FACE, 2, "has 5 vertices; only quads and triangles", false},
    {"overflowing coordinates", [] {
       return two_squares([](std::vector<Point>& p) { for(Point& q : p) q = Point(1e200 * q.x(), 1e200 * q.y(), 0); }); },
     TS::Invalid_input::VERTEX, 1, "overflows", false},
    {"underflowing coordinates", [] {
       return two_squares([](std::vector<Point>& p) { for(Point& q : p) q = Point(1e-200 * q.x(), 1e-200 * q.y(), 0); }); },
     TS::Invalid_input::MESH, none, "underflow", false},
    {"cluster id out of range", [] {
       Case_input in = two_squares();
       in.cluster = in.mesh.add_property_map<Mesh::Face_index, int>("f:cluster", 0).first;
       in.cluster[Mesh::Face_index(1)] = -1;
       return in; },
     TS::Invalid_input::FACE, 1, "has cluster -1", true},
    {"orientation out of range", [] {
       Case_input in = two_squares();
       in.orientation = in.mesh.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
       in.orientation[Mesh::Face_index(1)] = 8;
       return in; },
     TS::Invalid_input::FACE, 1, "has orientation 8", true},
  };
}

struct Entry_point
{
  const char* name;
  bool reads_labels;  // false: the maps are outputs, or not used
  std::function<void(Case_input&, std::ostream&)> call;
};

std::vector<Entry_point> entry_points()
{
  auto maps = [](Case_input& in) {
    return TSP::face_cluster_map(in.cluster).face_orientation_map(in.orientation);
  };
  return {
    {"cluster_panels", false,
     [=](Case_input& in, std::ostream&) { TS::cluster_panels(in.mesh, maps(in).number_of_tiles(1)); }},
    {"Edge_sharing_graph", true,
     [](Case_input& in, std::ostream&) { TS::Edge_sharing_graph<Mesh>(in.mesh, 2, in.cluster, in.orientation); }},
    {"optimize_tilable_surface", true,
     [=](Case_input& in, std::ostream&) { TS::optimize_tilable_surface(in.mesh, maps(in).number_of_iterations(3)); }},
    {"measure_tilability", true,
     [=](Case_input& in, std::ostream&) { const Mesh input = in.mesh; TS::measure_tilability(in.mesh, input, maps(in)); }},
    {"make_k_set_tilable", false,
     [=](Case_input& in, std::ostream&) { TS::make_k_set_tilable(in.mesh, maps(in).number_of_tiles(1)); }},
    {"K_set_tilable_surface", true,
     [](Case_input& in, std::ostream&) {
       TS::K_set_tilable_surface surface(in.mesh);
       surface.set_clustering(in.cluster, in.orientation); }},
    {"IO::write_tiled_PLY", true,
     [=](Case_input& in, std::ostream& os) { TS::IO::write_tiled_PLY(os, in.mesh, maps(in)); }},
    {"IO::write_edge_components_PLY", false,
     [](Case_input& in, std::ostream& os) {
       TS::IO::write_edge_components_PLY(
         os, in.mesh, CGAL::Constant_property_map<Mesh::Edge_index, std::size_t>(0)); }},
  };
}

// Everything of the mesh and the maps, as bytes: points, connectivity, labels.
std::string snapshot(const Case_input& in)
{
  std::string bytes;
  auto append = [&](const void* p, std::size_t n) { bytes.append(static_cast<const char*>(p), n); };
  for(std::size_t i = 0; i < in.mesh.num_vertices(); ++i)
  {
    const Mesh::Vertex_index v(static_cast<Mesh::size_type>(i));
    const double xyz[3] = {in.mesh.point(v).x(), in.mesh.point(v).y(), in.mesh.point(v).z()};
    const std::size_t h = in.mesh.halfedge(v);
    append(xyz, sizeof xyz);
    append(&h, sizeof h);
  }
  for(std::size_t i = 0; i < in.mesh.num_halfedges(); ++i)
  {
    const Mesh::Halfedge_index h(static_cast<Mesh::size_type>(i));
    const std::size_t links[3] = {in.mesh.next(h), in.mesh.target(h), in.mesh.face(h)};
    append(links, sizeof links);
  }
  for(std::size_t i = 0; i < in.mesh.num_faces(); ++i)
  {
    const Mesh::Face_index f(static_cast<Mesh::size_type>(i));
    const int labels[2] = {in.cluster[f], in.orientation[f]};
    const std::size_t h = in.mesh.halfedge(f);
    append(labels, sizeof labels);
    append(&h, sizeof h);
  }
  return bytes;
}

} // namespace

TEST(BadInput, EveryEntryPointThrowsNamingTheCulpritAndTouchesNothing)
{
  std::size_t checked = 0;
  for(const Bad_input& bad : bad_inputs())
    for(const Entry_point& entry : entry_points())
    {
      if(bad.about_labels && !entry.reads_labels)
        continue;  // the maps are outputs there: no label is read
      SCOPED_TRACE(std::string(bad.name) + " x " + entry.name);
      Case_input in = bad.make();
      // Existing maps (with the bad labels) are returned as they are.
      in.cluster = in.mesh.add_property_map<Mesh::Face_index, int>("f:cluster", 0).first;
      in.orientation = in.mesh.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
      const std::string before = snapshot(in);
      std::ostringstream os;
      try
      {
        entry.call(in, os);
        ADD_FAILURE() << "no exception";
      }
      catch(const TS::Invalid_input& e)
      {
        EXPECT_NE(std::string(e.what()).find(bad.says), std::string::npos) << e.what();
        EXPECT_EQ(e.element(), bad.element) << e.what();
        EXPECT_EQ(e.index(), bad.index) << e.what();
      }
      EXPECT_TRUE(snapshot(in) == before) << "the mesh or the maps changed";
      EXPECT_TRUE(os.str().empty()) << "the writer wrote " << os.str().size() << " bytes";
      ++checked;
    }
  EXPECT_EQ(checked, 10u * 8u + 2u * 5u);
}

TEST(BadInput, TileCatalogWritersRefuseNonFiniteTilesBeforeWriting)
{
  std::vector<TS::Tile> tiles(3);
  for(auto& t : tiles)
    for(int i = 0; i < 4; ++i) t.corners[i] = Eigen::Vector3d(i & 1, i >> 1, 0);
  tiles[2].corners[3].y() = not_a_number;
  for(bool csv : {true, false})
  {
    std::ostringstream os;
    try
    {
      csv ? TS::IO::write_tile_catalog_CSV(os, tiles) : TS::IO::write_tile_catalog_JSON(os, tiles);
      ADD_FAILURE() << "no exception";
    }
    catch(const TS::Invalid_input& e)
    {
      EXPECT_EQ(e.index(), 2u);
      EXPECT_NE(std::string(e.what()).find("tile 2"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(os.str().empty());
  }
}

} // namespace test_bad_input_unit
