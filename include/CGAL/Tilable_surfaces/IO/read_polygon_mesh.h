// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H
#define CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H

/// \file read_polygon_mesh.h
/// Reads a quad mesh from OFF, OBJ or PLY without trusting the file: every
/// count a file declares is checked against what the file's size can hold
/// before anything is allocated, vertex references are checked, and unused
/// vertices are kept (with a warning) instead of making the mesh invalid.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <istream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// What `read_panel_mesh()` read, and what the caller should know about it.
struct Read_report
{
  /// The number of vertices of the file used by no face. They are kept, at
  /// their place in the vertex order, and the package never moves them.
  std::size_t number_of_isolated_vertices = 0;
  /// Warnings in words (empty when there is nothing to say).
  std::vector<std::string> warnings;
};

namespace internal {

// The tokens of a line, comments (from '#') removed.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> line_tokens(const std::string& line);

// What is wrong with a file, before the path is prefixed.
struct File_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A count written in a file of `size` bytes: a non-negative integer no
// larger than `limit`.
CGAL_TILABLE_SURFACES_INLINE
std::size_t parse_count(const std::string& token, std::size_t limit, std::size_t size,
                        const std::string& what);

// Parses a whole token as a double, or throws saying what it was for.
CGAL_TILABLE_SURFACES_INLINE
double parse_coordinate(const std::string& token, const std::string& what);

// The whitespace-separated tokens of a stream, comments (from '#' to the end
// of the line) removed, with the number of the line each comes from: OFF is
// such a token stream, its records may span lines.
class Token_stream
{
public:
  explicit Token_stream(std::istream& in) : in_(in) {}

  // The next token; false at the end of the stream.
  bool next(std::string& token)
  {
    while(position_ == tokens_.size())
    {
      std::string line;
      if(!std::getline(in_, line))
        return false;
      ++line_number_;
      tokens_ = line_tokens(line);
      position_ = 0;
    }
    token = tokens_[position_++];
    return true;
  }

  // Drops what is left of the line of the last token.
  void skip_rest_of_line() { position_ = tokens_.size(); }

  std::size_t line_number() const { return line_number_; }

private:
  std::istream& in_;
  std::vector<std::string> tokens_;
  std::size_t position_ = 0, line_number_ = 0;
};

// What an OFF header declares: [ST][C][N][4][n]OFF, the dimension after nOFF
// (only 3 is read), BINARY refused, then the vertex, face and edge counts.
struct OFF_header
{
  bool homogeneous = false;  // 4OFF: x y z w per vertex, the point (x/w, y/w, z/w)
  std::size_t vertices = 0, faces = 0;
};

CGAL_TILABLE_SURFACES_INLINE
OFF_header read_OFF_header(Token_stream& tokens, std::size_t size);

// The OFF vertex `i`: its coordinates may span lines; what follows them on
// their line (normal, colour, texture coordinates) is ignored.
template <typename Point>
Point read_OFF_vertex(Token_stream& tokens, const OFF_header& header, std::size_t i)
{
  const std::string what = "OFF vertex " + std::to_string(i);
  double c[4] = {0, 0, 0, 1};
  std::string token;
  for(int d = 0; d < (header.homogeneous ? 4 : 3); ++d)
  {
    if(!tokens.next(token))
      throw File_error("the OFF file is truncated: it ends in vertex " + std::to_string(i) + " of " +
                       std::to_string(header.vertices));
    c[d] = parse_coordinate(token, what);
  }
  tokens.skip_rest_of_line();
  if(c[3] == 0)
    throw File_error(what + " has w = 0, a point at infinity (line " +
                     std::to_string(tokens.line_number()) + ")");
  return c[3] == 1 ? Point(c[0], c[1], c[2]) : Point(c[0] / c[3], c[1] / c[3], c[2] / c[3]);
}

// The vertex indices of OFF face `f`: they may span lines; what follows the
// last one on its line (the face's colour) is ignored.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> read_OFF_face(Token_stream& tokens, const OFF_header& header,
                                       std::size_t f, std::size_t size);

// ASCII OFF, read here rather than by CGAL's reader so that every count is
// checked before it sizes anything, and as the token stream the format is
// (CGAL's reader wants a record per line). Each vertex needs at least 6 bytes
// ("0 0 0\n"), each face 4 ("1 0\n"), each face corner 2.
template <typename Point>
void read_OFF_soup(std::istream& in, std::size_t size, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons)
{
  Token_stream tokens(in);
  const OFF_header header = read_OFF_header(tokens, size);
  points.reserve(header.vertices);
  polygons.reserve(header.faces);
  for(std::size_t i = 0; i < header.vertices; ++i)
    points.push_back(read_OFF_vertex<Point>(tokens, header, i));
  for(std::size_t f = 0; f < header.faces; ++f)
    polygons.push_back(read_OFF_face(tokens, header, f, size));
}

struct PLY_property { int count_bytes = 0; int value_bytes = 0; std::string count_type, value_type, name; };
struct PLY_element { std::string name; std::size_t count = 0; std::vector<PLY_property> properties; };
struct PLY_header { std::string format; std::vector<PLY_element> elements; };

CGAL_TILABLE_SURFACES_INLINE
int PLY_type_bytes(const std::string& t);

// CGAL's reader takes a face's vertex list of 32-bit integers only (and reads
// no face from a list of other values): such a list is refused by its name.
CGAL_TILABLE_SURFACES_INLINE
void check_PLY_face_lists(const PLY_header& header);

// The header up to end_header, each element count at most `size`.
CGAL_TILABLE_SURFACES_INLINE
PLY_header read_PLY_header(std::istream& in, std::size_t size);

// The length of list property `p` read at the current position, -1 if
// negative, NaN if unreadable.
CGAL_TILABLE_SURFACES_INLINE
long double read_PLY_list_length(std::istream& in, const PLY_header& header, const PLY_property& p);

// PLY: each element count times the fewest bytes one element takes, and each
// list's length, against the bytes left in the file (CGAL's reader sizes its
// buffers by them). Binary bodies are walked property by property.
CGAL_TILABLE_SURFACES_INLINE
void check_PLY_counts(std::istream& in, std::size_t size);

// What is wrong with the coordinates of vertex `vertex` (on line
// `line_number`), or an empty string: fewer than 3, or one that is not a
// finite double ("nan", "inf", or one that overflows such as "1e400").
CGAL_TILABLE_SURFACES_INLINE
std::string coordinate_problem(const std::vector<std::string>& coordinates, std::size_t vertex,
                               std::size_t line_number);

// The next statement of an OBJ file and the number of its first line: a
// UTF-8 byte-order mark at the start of the file is dropped, and a line that
// ends in '\' continues on the next one.
CGAL_TILABLE_SURFACES_INLINE
bool next_OBJ_statement(std::istream& in, std::string& statement, std::size_t& line_number,
                        std::size_t& first_line);

// The OBJ statements that describe no polygon: read and ignored.
CGAL_TILABLE_SURFACES_INLINE
bool is_ignored_OBJ_statement(const std::string& keyword);

// The 0-based vertex index of the face corner `token` ("v", "v/vt", "v//vn"
// or "v/vt/vn"): v counts from 1, or back from the last of the
// `number_of_points` vertices read so far when negative.
CGAL_TILABLE_SURFACES_INLINE
std::size_t OBJ_vertex_index(const std::string& token, std::size_t number_of_points,
                             const std::string& what);

// An OBJ file's vertices ("v x y z", anything after z ignored: a weight or a
// colour) and faces ("f" with indices as OBJ_vertex_index() reads them);
// the other statements of the format are ignored, anything else is refused.
template <typename Point>
void read_OBJ_soup(std::istream& in, std::vector<Point>& points,
                   std::vector<std::vector<std::size_t> >& polygons)
{
  std::string statement;
  for(std::size_t line_number = 0, first_line = 0;
      next_OBJ_statement(in, statement, line_number, first_line);)
  {
    std::vector<std::string> tokens = line_tokens(statement);
    const std::string where = " (line " + std::to_string(first_line) + ")";
    if(tokens.empty() || is_ignored_OBJ_statement(tokens[0]))
      continue;
    if(tokens[0] == "v")
    {
      tokens.erase(tokens.begin());
      tokens.resize((std::min)(tokens.size(), std::size_t(3)));
      const std::string problem = coordinate_problem(tokens, points.size(), first_line);
      if(!problem.empty())
        throw File_error(problem);
      points.emplace_back(std::strtod(tokens[0].c_str(), nullptr), std::strtod(tokens[1].c_str(), nullptr),
                          std::strtod(tokens[2].c_str(), nullptr));
    }
    else if(tokens[0] == "f")
    {
      polygons.emplace_back();
      const std::string what = "face " + std::to_string(polygons.size() - 1) + where;
      for(std::size_t j = 1; j < tokens.size(); ++j)
        polygons.back().push_back(OBJ_vertex_index(tokens[j], points.size(), what));
    }
    else
      throw File_error("line " + std::to_string(first_line) + " starts with '" + tokens[0] +
                       "', not an OBJ statement");
  }
}

// The first coordinate_problem() of the vertex lines of an ASCII PLY file of
// `size` bytes, read from its start; empty for a binary one.
CGAL_TILABLE_SURFACES_INLINE
std::string unreadable_PLY_coordinate(std::istream& in, std::size_t size);

// Why CGAL's ASCII PLY reader may have failed on a coordinate, which it does
// not say: the first vertex coordinate that is not a finite double, or a
// vertex with fewer than three coordinates. Empty if every vertex line reads
// (or the PLY is binary): the failure was elsewhere.
inline std::string unreadable_coordinate(std::istream& in, std::size_t size)
{
  in.clear();
  in.seekg(0, std::ios::beg);
  return unreadable_PLY_coordinate(in, size);
}

// Reads the points and polygons of a file in `format` ("off", "obj" or "ply"):
// OFF and OBJ by the package (read_OFF_soup(), read_OBJ_soup()), PLY by
// CGAL once check_PLY_counts() has checked every count; throws Invalid_input
// naming the source `name`.
template <typename Point>
void read_polygon_soup(std::istream& in, const std::string& format, const std::string& name,
                       std::vector<Point>& points, std::vector<std::vector<std::size_t> >& polygons)
{
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  in.seekg(0, std::ios::beg);
  const std::size_t size = end > 0 ? std::size_t(end) : 0;
  try
  {
    if(format == "off") read_OFF_soup(in, size, points, polygons);
    if(format == "ply") check_PLY_counts(in, size);
  }
  catch(const File_error& e)
  {
    throw Invalid_input("'" + name + "': " + e.what());
  }
  std::string problem;
  if(format == "obj")
  {
    try { read_OBJ_soup(in, points, polygons); }
    catch(const File_error& e) { problem = e.what(); }
  }
  else if(format == "ply")
  {
    in.clear();
    in.seekg(0, std::ios::beg);
    if(!CGAL::IO::read_PLY(in, points, polygons, CGAL::parameters::verbose(false)))
    {
      problem = unreadable_coordinate(in, size);
      if(problem.empty()) problem = "corrupt or truncated file";
    }
  }
  if(!problem.empty())
    throw Invalid_input("'" + name + "' is not a readable polygon mesh (" + problem + ")");
}

// Which of the `number_of_points` points the polygons use; throws
// Invalid_input for a reference to no point.
CGAL_TILABLE_SURFACES_INLINE
std::vector<bool> used_points(std::size_t number_of_points,
                              const std::vector<std::vector<std::size_t> >& polygons,
                              const std::string& name);

CGAL_TILABLE_SURFACES_INLINE
std::string lower_extension(const std::string& path);

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Reads a polygon mesh in the format `format` from `in`, which must be
/// seekable (a file opened in binary mode, or a string stream), into `pm`
/// (cleared first). `name` names the source in the messages. The formats:
/// - "off": ASCII OFF, [ST][C][N][4][n]OFF (nOFF of dimension 3), read as the
///   token stream it is: records may span lines, comments ('#' to the end of
///   the line) may stand anywhere; what follows a vertex's coordinates or a
///   face's indices on their line (normals, colours, texture coordinates) is
///   ignored;
/// - "obj": a byte-order mark, '\' line continuations, relative (negative)
///   indices, "v/vt/vn" corners; statements other than "v" and "f" are ignored;
/// - "ply": ASCII, binary little- or big-endian, faces as a list named
///   vertex_indices or vertex_index of int or uint values.
///
/// Unlike `CGAL::IO::read_polygon_mesh()`, it does not trust the data:
/// - every count it declares (OFF header and face sizes, PLY element counts
///   and list lengths) is compared with what the stream's size can hold
///   before anything is allocated, so a 28-byte file claiming 1e9 vertices
///   is refused at once instead of exhausting memory;
/// - every vertex reference of a face must name a vertex of the data;
/// - vertices used by no face are kept in the file's order and counted in the
///   returned report, with a warning: the package accepts them and never
///   moves them (see `number_of_isolated_vertices()`);
/// - a soup that is not a manifold, consistently oriented polygon mesh is
///   refused (nothing is repaired).
///
/// The mesh is not checked further: `validate_panel_mesh()` does that (every
/// entry point of the package calls it).
///
/// \tparam PolygonMesh a model of `MutableFaceGraph` whose points are 3D
///   points constructible from three doubles.
/// \returns what was read that the caller should know.
/// \throws Invalid_input saying what is wrong with the data; `pm` is empty then.
template <typename PolygonMesh>
Read_report read_panel_mesh(std::istream& in, const std::string& format, PolygonMesh& pm,
                           const std::string& name = "the input")
{
  typedef CGAL::Simple_cartesian<double>::Point_3 Point;
  CGAL::clear(pm);
  if(format != "off" && format != "obj" && format != "ply")
    throw Invalid_input("'" + name + "' is not an OFF, OBJ or PLY file (by its extension)");
  std::vector<Point> points;
  std::vector<std::vector<std::size_t> > polygons;
  internal::read_polygon_soup(in, format, name, points, polygons);
  const std::vector<bool> used = internal::used_points(points.size(), polygons, name);
  if(polygons.empty())
    throw Invalid_input("'" + name + "' has no face");
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(polygons))
    throw Invalid_input("'" + name + "' is not a polygon mesh: a face uses a vertex twice or has "
                        "fewer than 3, an edge has more than 2 faces, a vertex is non-manifold, or "
                        "the faces are inconsistently oriented");
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, polygons, pm);

  Read_report report;
  report.number_of_isolated_vertices = std::size_t(std::count(used.begin(), used.end(), false));
  if(report.number_of_isolated_vertices > 0)
  {
    const std::size_t first = std::size_t(std::find(used.begin(), used.end(), false) - used.begin());
    report.warnings.push_back(std::to_string(report.number_of_isolated_vertices) +
                              " vertices are used by no face (the first is vertex " +
                              std::to_string(first) + "); they are kept and never moved");
  }
  return report;
}

/// \ingroup PkgTilableSurfacesRef
/// Reads the file `path` as the function above does, the format given by its
/// extension (.off, .obj or .ply, in any case).
/// \throws Invalid_input if the file cannot be opened, or as the function above.
template <typename PolygonMesh>
Read_report read_panel_mesh(const std::string& path, PolygonMesh& pm)
{
  CGAL::clear(pm);
  std::ifstream in(path, std::ios::binary);
  if(!in)
    throw Invalid_input("cannot open '" + path + "': no such file or not readable");
  return read_panel_mesh(in, internal::lower_extension(path), pm, path);
}

#ifndef CGAL_NO_DEPRECATED_CODE
/// \ingroup PkgTilableSurfacesRef
/// \deprecated The name of `read_panel_mesh()` until 1.0.0.
template <typename PolygonMesh>
CGAL_DEPRECATED_MSG("use read_panel_mesh()")
Read_report read_quad_mesh(const std::string& path, PolygonMesh& pm)
{
  return read_panel_mesh(path, pm);
}

/// \ingroup PkgTilableSurfacesRef
/// \deprecated The name of `read_panel_mesh()` until 1.0.0.
template <typename PolygonMesh>
CGAL_DEPRECATED_MSG("use read_panel_mesh()")
Read_report read_quad_mesh(std::istream& in, const std::string& format, PolygonMesh& pm,
                           const std::string& name = "the input")
{
  return read_panel_mesh(in, format, pm, name);
}
#endif

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H
