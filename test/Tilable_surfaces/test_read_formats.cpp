// The readers held to the formats: one small mesh written the many ways OFF,
// OBJ and PLY allow (records across lines, comments anywhere, header
// variants, colours, byte-order mark, line continuations, relative indices,
// three PLY encodings and list types). Each file must give the mesh written
// by hand below, and the same mesh as CGAL's own reader where CGAL reads it.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_mesh_to_polygon_soup.h>

#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>

#include "temp_dir.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_read_formats_unit {

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef std::vector<std::vector<std::size_t> > Polygons;

namespace {

// The mesh every file below describes: two quads side by side, coordinates
// exact in float and after a division by 2.
const std::vector<Point> reference_points = {Point(0, 0, 0), Point(1, 0, 0.25), Point(2, 0, 0),
                                             Point(0, 1, 0.5), Point(1, 1, 0), Point(2, 1, 0.5)};
const Polygons reference_faces = {{0, 1, 4, 3}, {1, 2, 5, 4}};

// Each polygon rotated to start at its smallest index: a mesh gives its faces
// from any of their corners.
Polygons canonical(Polygons polygons)
{
  for(std::vector<std::size_t>& p : polygons)
    std::rotate(p.begin(), std::min_element(p.begin(), p.end()), p.end());
  return polygons;
}

struct Soup
{
  std::vector<Point> points;
  Polygons faces;
};

// What the package's reader makes of the file at `path`.
Soup ours(const std::string& path)
{
  Mesh mesh;
  TS::IO::read_panel_mesh(path, mesh);
  Soup soup;
  CGAL::Polygon_mesh_processing::polygon_mesh_to_polygon_soup(mesh, soup.points, soup.faces);
  soup.faces = canonical(soup.faces);
  return soup;
}

void expect_reference(const Soup& soup, const std::string& what)
{
  EXPECT_EQ(soup.points, reference_points) << what;
  EXPECT_EQ(soup.faces, reference_faces) << what;
}

struct Format_case
{
  std::string name;  // with the extension that selects the reader
  std::string content;
  bool cgal_reads;   // CGAL's reader accepts it (and must then agree)
};

std::string write(const Temp_dir& dir, const std::string& name, const std::string& content)
{
  const std::string path = (dir / name).string();
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

// Every case gives the reference mesh; the cases CGAL reads give its soup.
void check_cases(const std::vector<Format_case>& cases, const std::string& dir_name)
{
  const Temp_dir dir(dir_name);
  for(const Format_case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const std::string path = write(dir, c.name, c.content);
    Soup mine;
    ASSERT_NO_THROW(mine = ours(path));
    expect_reference(mine, "against the hand-written mesh");
    if(!c.cgal_reads)
      continue;
    Soup cgal;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, cgal.points, cgal.faces, CGAL::parameters::verbose(false)));
    EXPECT_EQ(mine.points, cgal.points) << "against CGAL's reader";
    EXPECT_EQ(mine.faces, canonical(cgal.faces)) << "against CGAL's reader";
  }
}

// The message of the Invalid_input that reading `content` as `name` throws.
std::string refusal(const std::string& name, const std::string& content)
{
  const Temp_dir dir("read_formats_refused");
  Mesh mesh;
  try { TS::IO::read_panel_mesh(write(dir, name, content), mesh); }
  catch(const TS::Invalid_input& e) { return e.what(); }
  return "accepted";
}

const std::string off_vertices = "0 0 0\n1 0 0.25\n2 0 0\n0 1 0.5\n1 1 0\n2 1 0.5\n";

} // namespace

TEST(ReadFormats, OffIsATokenStream)
{
  check_cases({
    {"plain.off", "OFF\n6 2 0\n" + off_vertices + "4 0 1 4 3\n4 1 2 5 4\n", true},
    {"crlf.off", "OFF\r\n6 2 0\r\n0 0 0\r\n1 0 0.25\r\n2 0 0\r\n0 1 0.5\r\n1 1 0\r\n2 1 0.5\r\n"
                 "4 0 1 4 3\r\n4 1 2 5 4\r\n", true},
    {"counts_on_keyword_line.off", "OFF 6 2 0\n" + off_vertices + "4 0 1 4 3\n4 1 2 5 4\n", true},
    // A record across lines, as some datasets of quad meshes are written.
    {"faces_across_lines.off", "OFF\n6 2 0\n" + off_vertices + "4\n0 1\n4 3\n4 1 2 5\n4\n", false},
    {"vertices_across_lines.off", "OFF\n6 2 0\n0 0\n0\n1 0 0.25\n2\n0\n0\n0 1 0.5\n1 1 0\n2 1 0.5\n"
                                  "4 0 1 4 3\n4 1 2 5 4\n", false},
    {"comments.off", "# made by hand\nOFF # the keyword\n# the counts:\n6 2 0\n0 0 0 # v0\n1 0 0.25\n"
                     "# between vertices\n2 0 0\n0 1 0.5\n1 1 0\n2 1 0.5\n4 0 1 4 3 # f0\n4 1 2 5 4\n", true},
    {"comment_inside_a_face.off", "OFF\n6 2 0\n" + off_vertices + "4 0 1 # half\n4 3\n4 1 2 5 4\n", false},
  }, "read_formats_off");
}

TEST(ReadFormats, OffHeaderVariantsAndColours)
{
  check_cases({
    // Vertex colours (RGB integers, RGBA floats) and face colours after the indices.
    {"coff.off", "COFF\n6 2 0\n0 0 0 255 0 0\n1 0 0.25 0 255 0\n2 0 0 0 0 255\n0 1 0.5 1 1 1\n"
                 "1 1 0 0.5 0.5 0.5 1\n2 1 0.5 9 9 9 255\n4 0 1 4 3 255 0 0\n4 1 2 5 4 0.1 0.2 0.3 0.4\n", true},
    {"face_colour_after_a_record_across_lines.off",
     "OFF\n6 2 0\n" + off_vertices + "4 0 1\n4 3 255 0 0\n4 1 2 5 4 7\n", false},
    {"noff.off", "NOFF\n6 2 0\n0 0 0 0 0 1\n1 0 0.25 0 0 1\n2 0 0 0 0 1\n0 1 0.5 0 0 1\n1 1 0 0 0 1\n"
                 "2 1 0.5 0 0 1\n4 0 1 4 3\n4 1 2 5 4\n", true},
    {"stcnoff.off", "STCNOFF\n6 2 0\n0 0 0 0 0 1 9 9 9 0 0\n1 0 0.25 0 0 1 9 9 9 0.5 0\n"
                    "2 0 0 0 0 1 9 9 9 1 0\n0 1 0.5 0 0 1 9 9 9 0 1\n1 1 0 0 0 1 9 9 9 0.5 1\n"
                    "2 1 0.5 0 0 1 9 9 9 1 1\n4 0 1 4 3\n4 1 2 5 4\n", true},
    // Homogeneous coordinates: (x, y, z, w) is the point (x/w, y/w, z/w).
    {"4off.off", "4OFF\n6 2 0\n0 0 0 2\n2 0 0.5 2\n4 0 0 2\n0 2 1 2\n1 1 0 1\n4 2 1 2\n"
                 "4 0 1 4 3\n4 1 2 5 4\n", true},
    {"noff_dimension_3.off", "nOFF\n3\n6 2 0\n" + off_vertices + "4 0 1 4 3\n4 1 2 5 4\n", false},
  }, "read_formats_off_variants");
}

TEST(ReadFormats, OffRefusalsNameTheCulprit)
{
  const std::string faces = "4 0 1 4 3\n4 1 2 5 4\n";
  EXPECT_NE(refusal("a.off", "nOFF\n4\n6 2 0\n" + off_vertices + faces).find(
              "the OFF dimension is 4; only 3 is supported"), std::string::npos);
  EXPECT_NE(refusal("a.off", "4OFF\n6 2 0\n0 0 0 1\n1 0 0 0\n2 0 0 1\n0 1 0 1\n1 1 0 1\n2 1 0 1\n" + faces)
              .find("OFF vertex 1 has w = 0"), std::string::npos);
  const std::string cut = refusal("a.off", "OFF\n6 2 0\n" + off_vertices + "4 0 1 4 3\n4 1\n2\n");
  EXPECT_NE(cut.find("OFF face 1 (line 10) claims 4 vertices but lists 2 before the end of the file"),
            std::string::npos) << cut;
  const std::string letter = "OFF\n6 2 0\n0 0 0\n1 x 0.25\n" + off_vertices.substr(15) + faces;
  EXPECT_NE(refusal("a.off", letter).find("OFF vertex 1 has 'x', not a number"), std::string::npos);
  EXPECT_NE(refusal("a.off", "OFF\n").find("the OFF header ends before the OFF vertex count"),
            std::string::npos);
}

TEST(ReadFormats, ObjAsToolsWriteIt)
{
  const std::string v_rest = "v 2 0 0\nv 0 1 0.5\nv 1 1 0\nv 2 1 0.5\n";
  const std::string v = "v 0 0 0\nv 1 0 0.25\n" + v_rest;
  check_cases({
    {"plain.obj", v + "f 1 2 5 4\nf 2 3 6 5\n", true},
    {"byte_order_mark.obj", "\xEF\xBB\xBF" + v + "f 1 2 5 4\nf 2 3 6 5\n", false},
    {"continued_lines.obj", "v 0 0 0\nv 1 \\\n0 0.25\n" + v_rest + "f 1 2 \\\n 5 4\nf 2 3 6 5\n", false},
    {"groups_and_materials.obj", "mtllib tiles.mtl\no panel\n" + v + "g left\nusemtl red\ns 1\nf 1 2 5 4\n"
                                 "g right\nusemtl blue\ns off\nf 2 3 6 5\n", true},
    {"negative_indices.obj", "v 0 0 0\nv 1 0 0.25\nv 2 0 0\nv 0 1 0.5\nv 1 1 0\nf -5 -4 -1 -2\n"
                             "v 2 1 0.5\nf -5 -4 -1 -2\n", true},
    {"texture_and_normal_indices.obj", v + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/1 5/1/1 4/1/1\n"
                                       "f 2//1 3//1 6//1 5//1\n", true},
    {"weights_and_colours.obj", "v 0 0 0 1\nv 1 0 0.25 0.5 0.5 0.5\n" + v_rest +
                                "f 1 2 5 4\nf 2 3 6 5\n", true},
    {"tabs.obj", "v\t0\t0\t0\nv 1 0 0.25\n" + v_rest + "f\t1\t2\t5\t4\nf 2 3 6 5\n", false},
    {"polyline.obj", v + "l 1 2 3\nf 1 2 5 4\nf 2 3 6 5\n", false},
  }, "read_formats_obj");
}

TEST(ReadFormats, ObjRefusalsNameTheCulprit)
{
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  EXPECT_NE(refusal("a.obj", v + "f 1 2 0\n").find("face 0 (line 4) has '0', not a vertex reference"),
            std::string::npos);
  EXPECT_NE(refusal("a.obj", v + "f -1 -2 -4\n").find("face 0 (line 4) has '-4', before the first vertex"),
            std::string::npos);
  EXPECT_NE(refusal("a.obj", v + "f 1 2 x/1\n").find("has 'x/1', not a vertex reference"), std::string::npos);
  EXPECT_NE(refusal("a.obj", v + "vertex 1 2 3\nf 1 2 3\n").find("line 4 starts with 'vertex', not an OBJ"),
            std::string::npos);
  EXPECT_NE(refusal("a.obj", v + "f 1 2 9\n").find("face 0 uses vertex 8 but there are 3 vertices"),
            std::string::npos);
}

namespace {

// `value` as the `bytes` bytes of a PLY binary body, in either byte order.
template <typename T>
void put(std::string& body, T value, bool big_endian)
{
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if(big_endian)
    std::reverse(bytes, bytes + sizeof(T));
  body.append(bytes, sizeof(T));
}

// The reference mesh as a PLY file in `format`, coordinates as `coordinate`
// (float or double), faces as a list of `count_type` lengths and
// `index_type` indices named `list_name`.
std::string reference_ply(const std::string& format, const std::string& coordinate,
                          const std::string& count_type, const std::string& index_type,
                          const std::string& list_name = "vertex_indices")
{
  std::string s = "ply\nformat " + format + " 1.0\ncomment two quads\nelement vertex 6\n";
  for(const char* axis : {"x", "y", "z"})
    s += "property " + coordinate + " " + axis + "\n";
  s += "element face 2\nproperty list " + count_type + " " + index_type + " " + list_name + "\nend_header\n";
  const bool big = format == "binary_big_endian";
  for(const Point& p : reference_points)
    for(int i = 0; i < 3; ++i)
    {
      if(format == "ascii") s += std::to_string(p[i]) + (i < 2 ? " " : "\n");
      else if(coordinate == "float") put(s, float(p[i]), big);
      else put(s, p[i], big);
    }
  for(const std::vector<std::size_t>& f : reference_faces)
  {
    if(format == "ascii") s += "4";
    else if(count_type == "uchar") put(s, std::uint8_t(4), big);
    else put(s, std::uint32_t(4), big);  // int and uint alike for a small count
    for(std::size_t v : f)
    {
      if(format == "ascii") s += " " + std::to_string(v);
      else put(s, std::uint32_t(v), big);
    }
    if(format == "ascii") s += "\n";
  }
  return s;
}

} // namespace

TEST(ReadFormats, PlyInEveryEncodingAndListType)
{
  std::vector<Format_case> cases;
  for(const char* format : {"ascii", "binary_little_endian", "binary_big_endian"})
    for(const char* count_type : {"uchar", "int", "uint"})
      for(const char* index_type : {"int", "uint"})
        for(const char* coordinate : {"float", "double"})
          cases.push_back({std::string(format) + "_" + count_type + "_" + index_type + "_" + coordinate + ".ply",
                           reference_ply(format, coordinate, count_type, index_type), true});
  cases.push_back({"vertex_index.ply",
                   reference_ply("binary_little_endian", "float", "uchar", "int", "vertex_index"), true});
  check_cases(cases, "read_formats_ply");
}

TEST(ReadFormats, PlyListsCgalCannotReadAreRefusedByName)
{
  const std::string message = refusal("a.ply", reference_ply("ascii", "float", "uchar", "uchar"));
  EXPECT_NE(message.find("the PLY face list vertex_indices holds 'uchar' values"), std::string::npos)
    << message;
}

} // namespace test_read_formats_unit
