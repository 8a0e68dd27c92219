// Input validation: refuses what the package cannot tile, names the culprit.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/validation.h>

#include <gtest/gtest.h>

#include <limits>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_validation_unit {

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

Mesh read(const std::string& name)
{
  Mesh mesh;
  const std::string path = std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/" + name;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(path, mesh)) << path;
  EXPECT_GT(num_faces(mesh), 0u) << path;
  return mesh;
}

// An n x n grid of unit squares in the plane z = 0.
Mesh grid(int n)
{
  Mesh mesh;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      v.push_back(mesh.add_vertex(Point(i, j, 0)));
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      mesh.add_face(v[j * (n + 1) + i], v[j * (n + 1) + i + 1],
                    v[(j + 1) * (n + 1) + i + 1], v[(j + 1) * (n + 1) + i]);
  return mesh;
}

// The message and location of the error validate_panel_mesh() throws.
TS::Invalid_input error_of(const Mesh& mesh)
{
  try { TS::validate_panel_mesh(mesh); }
  catch(const TS::Invalid_input& e) { return e; }
  ADD_FAILURE() << "no error thrown";
  return TS::Invalid_input("none");
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

} // namespace

TEST(Validation, AcceptsTheSixPaperSurfacesAndOtherQuadMeshes)
{
  for(const char* name : {"monkey_saddle.off", "seashell.off", "swiss_re.off", "tunnel.off",
                          "decocube.off", "de_beers_ginza.off", "torus_quad.off",
                          "cross_quad.off", "quad_dome.obj", "mushroom.off"})
    EXPECT_NO_THROW(TS::validate_panel_mesh(read(name))) << name;
}

TEST(Validation, RefusesMeshesWithPolygonsOfFiveOrMoreVerticesNamingTheFirstOne)
{
  const Mesh mesh = read("double-torus-example.off");
  const TS::Invalid_input e = error_of(mesh);
  EXPECT_EQ(e.element(), TS::Invalid_input::FACE);
  // The named face really is the first face that is neither a quad nor a triangle.
  std::size_t first = 0;
  for(auto f : faces(mesh))
    if(CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size() > 4) { first = f; break; }
  EXPECT_EQ(e.index(), first);
  EXPECT_TRUE(contains(e.what(), "face " + std::to_string(first) + " has ")) << e.what();
  EXPECT_TRUE(contains(e.what(), "only quads and triangles")) << e.what();
}

TEST(Validation, RefusesANonFiniteCoordinateNamingTheVertex)
{
  Mesh mesh = grid(2);
  const Mesh::Vertex_index bad(4);
  mesh.point(bad) = Point(1, std::numeric_limits<double>::quiet_NaN(), 0);
  const Mesh copy = mesh;
  const TS::Invalid_input e = error_of(mesh);
  EXPECT_EQ(e.element(), TS::Invalid_input::VERTEX);
  EXPECT_EQ(e.index(), 4u);
  EXPECT_TRUE(contains(e.what(), "vertex 4 has a non-finite coordinate")) << e.what();

  mesh.point(bad) = Point(std::numeric_limits<double>::infinity(), 1, 0);
  EXPECT_TRUE(contains(error_of(mesh).what(), "vertex 4")) << error_of(mesh).what();
  // Validation only reads.
  EXPECT_EQ(copy.number_of_vertices(), mesh.number_of_vertices());
}

TEST(Validation, RefusesACollapsedFaceNamingIt)
{
  Mesh mesh = grid(1);
  // A second, separate face whose four distinct vertices lie on one line.
  auto a = mesh.add_vertex(Point(5, 0, 0)), b = mesh.add_vertex(Point(6, 0, 0));
  auto c = mesh.add_vertex(Point(7, 0, 0)), d = mesh.add_vertex(Point(8, 0, 0));
  mesh.add_face(a, b, c, d);
  const TS::Invalid_input e = error_of(mesh);
  EXPECT_EQ(e.element(), TS::Invalid_input::FACE);
  EXPECT_EQ(e.index(), 1u);
  EXPECT_TRUE(contains(e.what(), "face 1 is collapsed")) << e.what();
}

TEST(Validation, RefusesAZeroLengthEdgeNamingItsVertices)
{
  Mesh mesh = grid(2);
  // Move vertex 4 (the centre) onto vertex 1: face 0 = (0, 1, 4, 3) then has
  // a zero-length edge 1-4.
  mesh.point(Mesh::Vertex_index(4)) = mesh.point(Mesh::Vertex_index(1));
  const TS::Invalid_input e = error_of(mesh);
  EXPECT_EQ(e.index(), 0u);
  EXPECT_TRUE(contains(e.what(), "face 0 has a zero-length edge between vertices 1 and 4"))
    << e.what();
}

TEST(Validation, RefusesAnEmptyMesh)
{
  const TS::Invalid_input e = error_of(Mesh());
  EXPECT_EQ(e.element(), TS::Invalid_input::MESH);
  EXPECT_TRUE(contains(e.what(), "no face")) << e.what();
}

} // namespace test_validation_unit
