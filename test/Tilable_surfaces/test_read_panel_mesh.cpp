// The safe reader: declared counts checked against the file size before any
// allocation, unused vertices kept, references checked; and what the
// package then does with an isolated vertex or overflowing coordinates.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>
#include <CGAL/Tilable_surfaces/IO/write_PLY.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "congruence_check.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_read_panel_mesh_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;

namespace {

const std::string data_dir = CGAL_TILABLE_SURFACES_TEST_DATA;

std::string write(const Temp_dir& dir, const std::string& name, const std::string& content)
{
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// The message of the Invalid_input that reading `path` throws ("" if none).
std::string refusal(const std::string& path)
{
  Mesh mesh;
  try { TS::IO::read_panel_mesh(path, mesh); }
  catch(const TS::Invalid_input& e)
  {
    EXPECT_TRUE(mesh.is_empty()) << "the mesh is left empty";
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// A 3 x 2 grid of quads in OBJ, with a bump, and `extra` vertices after the
// grid's 12 that no face uses.
std::string grid_obj(const std::string& extra)
{
  std::string s;
  for(int j = 0; j <= 2; ++j)
    for(int i = 0; i <= 3; ++i)
      s += "v " + std::to_string(i) + " " + std::to_string(j) + " " + std::to_string(0.1 * i * j) + "\n";
  s += extra;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 3; ++i)
    {
      const int a = 1 + i + 4 * j;
      s += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " + std::to_string(a + 5) +
           " " + std::to_string(a + 4) + "\n";
    }
  return s;
}

std::string binary_ply_header(const std::string& count_type, std::size_t faces)
{
  return "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
         "property float y\nproperty float z\nelement face " + std::to_string(faces) +
         "\nproperty list " + count_type + " int vertex_indices\nend_header\n";
}

} // namespace

TEST(ReadQuadMesh, ReadsTheTestDataLikeCgal)
{
  for(const char* name : {"monkey_saddle.off", "seashell.off", "torus_quad.off", "cross_quad.off",
                          "quad_dome.obj", "mushroom.off"})
  {
    Mesh ours, cgal;
    const TS::IO::Read_report report = TS::IO::read_panel_mesh(data_dir + "/" + name, ours);
    ASSERT_TRUE(CGAL::IO::read_polygon_mesh(data_dir + "/" + name, cgal)) << name;
    EXPECT_EQ(report.number_of_isolated_vertices, 0u) << name;
    EXPECT_TRUE(report.warnings.empty()) << name;
    ASSERT_EQ(ours.number_of_vertices(), cgal.number_of_vertices()) << name;
    ASSERT_EQ(ours.number_of_faces(), cgal.number_of_faces()) << name;
    EXPECT_TRUE(std::equal(ours.points().begin(), ours.points().end(), cgal.points().begin())) << name;
  }
}

TEST(ReadQuadMesh, RefusesCountsTheFileCannotHoldWithoutAllocating)
{
  const Temp_dir dir("read_counts");
  const auto start = std::chrono::steady_clock::now();
  // The file: 28 bytes claiming 1e9 vertices and 1e9 faces.
  EXPECT_TRUE(contains(refusal(write(dir, "bomb.off", "OFF\n1000000000 1000000000 0\n")),
                       "more than the file")) << "OFF header";
  EXPECT_TRUE(contains(refusal(write(dir, "bomb2.off", "OFF 10 1000000000 0\n")),
                       "more than the file")) << "OFF counts on the keyword's line";
  EXPECT_TRUE(contains(refusal(write(dir, "neg.off", "OFF\n-4 1 0\n")), "not a non-negative integer"));
  // A face line claiming 1e9 corners (CGAL's reader would allocate them).
  EXPECT_TRUE(contains(refusal(write(dir, "face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n1000000000 0 1 2\n")),
                       "vertex count of OFF face 0"));
  EXPECT_TRUE(contains(refusal(write(dir, "short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n")),
                       "claims 4 vertices but lists 3"));
  EXPECT_TRUE(contains(refusal(write(dir, "binary.off", "OFF BINARY\n")), "binary OFF"));
  // PLY: element counts (ascii and binary) and a binary list length.
  EXPECT_TRUE(contains(refusal(write(dir, "bomb.ply",
                                     "ply\nformat ascii 1.0\nelement vertex 1000000000\nproperty float x\n"
                                     "property float y\nproperty float z\nend_header\n0 0 0\n")),
                       "more than the file"));
  EXPECT_TRUE(contains(refusal(write(dir, "bomb_binary.ply", binary_ply_header("uchar", 100000000))),
                       "more than the file"));
  std::string list = binary_ply_header("int", 1) + std::string(36, '\0');
  const std::int32_t huge = 1 << 30;
  list.append(reinterpret_cast<const char*>(&huge), 4);
  list += std::string(12, '\0');
  EXPECT_TRUE(contains(refusal(write(dir, "list.ply", list)), "claims a list of 1073741824"));
  std::string negative = binary_ply_header("int", 1) + std::string(36, '\0');
  const std::int32_t minus_one = -1;
  negative.append(reinterpret_cast<const char*>(&minus_one), 4);
  EXPECT_TRUE(contains(refusal(write(dir, "negative.ply", negative)), "list of negative length"));
  // The fuzzer's first find: a keyword glued to the counts by a control
  // character, which CGAL's reader took for 2e8 vertices.
  EXPECT_TRUE(contains(refusal(write(dir, "glued.off", "OFF\x11" "200000000 0 0\n")), "not an ASCII OFF"));
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 5.0) << "refused at once";
}

TEST(ReadQuadMesh, RefusesWhatIsNotAPolygonMesh)
{
  const Temp_dir dir("read_bad");
  EXPECT_TRUE(contains(refusal((dir / "missing.off").string()), "cannot open"));
  EXPECT_TRUE(contains(refusal(write(dir, "mesh.stl", "solid\n")), "not an OFF, OBJ or PLY"));
  EXPECT_TRUE(contains(refusal(write(dir, "ref.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3 99\n")),
                       "face 0 uses vertex 98 but there are 3 vertices"));
  EXPECT_TRUE(contains(refusal(write(dir, "none.obj", "v 0 0 0\n")), "has no face"));
  EXPECT_TRUE(contains(refusal(write(dir, "none.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n")), "has no face"));
  // Three quads on one edge.
  EXPECT_TRUE(contains(refusal(write(dir, "fan.obj",
                                     "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 -1 0\nv 1 -1 0\n"
                                     "v 0 0 1\nv 1 0 1\nf 1 2 4 3\nf 2 1 5 6\nf 1 2 8 7\n")),
                       "not a polygon mesh"));
}

TEST(ReadQuadMesh, ReadsBackTheTiledPlyBinaryAndAscii)
{
  const Temp_dir dir("read_ply");
  Mesh mesh;
  TS::IO::read_panel_mesh(data_dir + "/monkey_saddle.off", mesh);
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
  for(bool binary : {true, false})
  {
    const std::string path = (dir / (binary ? "b.ply" : "a.ply")).string();
    {
      std::ofstream out(path, std::ios::binary);
      ASSERT_TRUE(TS::IO::write_tiled_PLY(out, mesh, TSP::face_cluster_map(cluster)
                                                      .face_orientation_map(orientation)
                                                      .use_binary_mode(binary)));
    }
    Mesh back;
    TS::IO::read_panel_mesh(path, back);
    ASSERT_EQ(back.number_of_faces(), mesh.number_of_faces());
    EXPECT_TRUE(std::equal(back.points().begin(), back.points().end(), mesh.points().begin())) << binary;
  }
}

TEST(ReadQuadMesh, KeepsUnusedVerticesWhichThePackageNeverMoves)
{
  const Temp_dir dir("read_isolated");
  Mesh plain, cad;
  TS::IO::read_panel_mesh(write(dir, "plain.obj", grid_obj("")), plain);
  // Inside the bounding box, so that nothing scaled by it changes.
  const TS::IO::Read_report report =
    TS::IO::read_panel_mesh(write(dir, "cad.obj", grid_obj("v 1.5 0.5 0.25\n")), cad);
  ASSERT_EQ(report.number_of_isolated_vertices, 1u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_TRUE(contains(report.warnings[0], "the first is vertex 12")) << report.warnings[0];
  ASSERT_EQ(cad.number_of_vertices(), 13u);
  const Mesh::Vertex_index isolated(12);
  EXPECT_TRUE(cad.is_isolated(isolated));
  EXPECT_EQ(TS::number_of_isolated_vertices(cad), 1u);
  EXPECT_NO_THROW(TS::validate_panel_mesh(cad));

  auto run = [](Mesh& m) {
    auto c = m.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
    auto o = m.add_property_map<Mesh::Face_index, int>("f:o", 0).first;
    const TS::K_set_tilable_result r =
      TS::make_k_set_tilable(m, TSP::number_of_tiles(2).face_cluster_map(c).face_orientation_map(o));
    EXPECT_LE(congruence_by_umeyama(m, c, o), 2e-6);
    return r;
  };
  const TS::K_set_tilable_result with = run(cad), without = run(plain);
  EXPECT_EQ(cad.point(isolated), Mesh::Point(1.5, 0.5, 0.25)) << "bit-identical: not moved";
  ASSERT_TRUE(with.is_tilable());
  // The other vertices end where they end without it, and the measurements
  // do not see it (it is 0.25 off the surface).
  for(std::size_t i = 0; i < 12; ++i)
  {
    const Mesh::Vertex_index v(static_cast<Mesh::size_type>(i));
    EXPECT_LT(std::sqrt(CGAL::squared_distance(cad.point(v), plain.point(v))), 1e-9) << i;
  }
  EXPECT_NEAR(with.optimization.measure.max_approximation_error,
              without.optimization.measure.max_approximation_error, 1e-9);
  EXPECT_NEAR(with.optimization.measure.max_displacement,
              without.optimization.measure.max_displacement, 1e-9);
  EXPECT_EQ(with.clustering.degree_of_flexibility, without.clustering.degree_of_flexibility);
}

// The message of validate_panel_mesh() on `mesh` ("" if it accepts it).
std::string validation_error(const Mesh& mesh)
{
  try { TS::validate_panel_mesh(mesh); }
  catch(const TS::Invalid_input& e) { return e.what(); }
  return "";
}

TEST(ReadQuadMesh, OverflowingCoordinatesAreReadThenRefusedAsSuch)
{
  const Temp_dir dir("read_huge");
  Mesh mesh;
  TS::IO::read_panel_mesh(write(dir, "huge.off", "OFF\n4 1 0\n0 0 0\n1e300 0 0\n1e300 1e300 0\n0 1e300 0\n"
                                                "4 0 1 2 3\n"), mesh);
  const std::string huge = validation_error(mesh);
  EXPECT_TRUE(contains(huge, "vertex 1 has a coordinate beyond 1e150")) << huge;
  EXPECT_TRUE(contains(huge, "overflows")) << huge;
  // Far from the origin relative to its size: doubles cannot resolve it.
  Mesh far;
  TS::IO::read_panel_mesh(write(dir, "far.off", "OFF\n4 1 0\n1e9 0 0\n1e9 1e-3 0\n1e9 1e-3 1e-3\n"
                                               "1e9 0 1e-3\n4 0 1 2 3\n"), far);
  EXPECT_TRUE(contains(validation_error(far), "move the mesh near the origin")) << validation_error(far);
  // The same square near the origin is fine.
  Mesh near;
  TS::IO::read_panel_mesh(write(dir, "near.off", "OFF\n4 1 0\n1 0 0\n1 1e-3 0\n1 1e-3 1e-3\n"
                                                "1 0 1e-3\n4 0 1 2 3\n"), near);
  EXPECT_EQ(validation_error(near), "");
}

// A coordinate that is not a finite double: the OBJ reader names the vertex,
// its line and the token; so does the refusal of an ASCII PLY file, which
// CGAL's reader fails on without saying why.
TEST(ReadQuadMesh, UnreadableCoordinatesAreNamed)
{
  const Temp_dir dir("read_coordinates");
  const std::string square = "v 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  const std::string nan = refusal(write(dir, "nan.obj", "# a comment\nvn 0 0 1\nv 0 0 nan\n" + square));
  EXPECT_TRUE(contains(nan, "vertex 0 (line 3) has 'nan', not a finite number")) << nan;
  const std::string huge = refusal(write(dir, "huge.obj", "v 0 0 0\nv 1 0 0\nv 1 1e400 0\nv 0 1 0\nf 1 2 3 4\n"));
  EXPECT_TRUE(contains(huge, "vertex 2 (line 3) has '1e400', too large for a double")) << huge;
  const std::string short_vertex = refusal(write(dir, "short.obj", "v 0 0\n" + square));
  EXPECT_TRUE(contains(short_vertex, "vertex 0 (line 1) has fewer than 3 coordinates")) << short_vertex;
  // An ASCII PLY square whose header ends on line 9.
  auto square_ply = [](const std::string& body) {
    return "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
           "property double z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n" + body;
  };
  const std::string ply = refusal(write(dir, "inf.ply", square_ply("0 0 0\n1 0 0\n1 1 inf\n0 1 0\n4 0 1 2 3\n")));
  EXPECT_TRUE(contains(ply, "vertex 2 (line 12) has 'inf', not a finite number")) << ply;
  // A failure elsewhere (a face index that is not a number) keeps the general message.
  const std::string letter = refusal(write(dir, "letter.ply", square_ply("0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 x\n")));
  EXPECT_TRUE(contains(letter, "(corrupt or truncated file)")) << letter;
}

} // namespace test_read_panel_mesh_unit
