// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H
#define CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H

/// \file read_polygon_mesh.h
/// Reads a quad mesh from OFF, OBJ or PLY without trusting the file: every
/// count a file declares is checked against what the file's size can hold
/// before anything is allocated, vertex references are checked, and unused
/// vertices are kept (with a warning) instead of making the mesh invalid.

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
inline std::vector<std::string> line_tokens(const std::string& line)
{
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> tokens;
  for(std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

// What is wrong with a file, before the path is prefixed.
struct File_error : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

// A count written in a file of `size` bytes: a non-negative integer no
// larger than `limit`.
inline std::size_t parse_count(const std::string& token, std::size_t limit, std::size_t size,
                               const std::string& what)
{
  std::size_t end = 0;
  long double value = -1;
  try { value = std::stold(token, &end); } catch(const std::exception&) { end = 0; }
  if(end == 0 || end != token.size() || !(value >= 0) || std::floor(value) != value)
    throw File_error(what + " is '" + token + "', not a non-negative integer");
  if(value > static_cast<long double>(limit))
    throw File_error(what + " is " + token + ", more than the file of " + std::to_string(size) +
                     " bytes can hold");
  return std::size_t(value);
}

// Parses a whole token as a double, or throws saying what it was for.
inline double parse_coordinate(const std::string& token, const std::string& what)
{
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if(token.empty() || end != token.c_str() + token.size())
    throw File_error(what + " has '" + token + "', not a number");
  return x;
}

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

inline OFF_header read_OFF_header(Token_stream& tokens, std::size_t size)
{
  std::string keyword, token;
  tokens.next(keyword);
  std::size_t j = keyword.compare(0, 2, "ST") == 0 ? 2 : 0;
  for(char prefix : {'C', 'N', '4', 'n'})
    if(j < keyword.size() && keyword[j] == prefix) ++j;
  if(keyword.size() < 3 || keyword.compare(j, std::string::npos, "OFF") != 0)
    throw File_error("not an ASCII OFF file: it does not start with [ST][C][N][4][n]OFF");
  OFF_header header;
  header.homogeneous = keyword.find('4') < j;
  auto count = [&](const std::string& what, std::size_t limit) {
    if(!tokens.next(token))
      throw File_error("the OFF header ends before " + what);
    return parse_count(token, limit, size, what);
  };
  if(keyword.find('n') < j && count("the OFF dimension", size) != 3)
    throw File_error("the OFF dimension is " + token + "; only 3 is supported");
  if(!tokens.next(token))
    throw File_error("the OFF header ends before the OFF vertex count");
  if(token == "BINARY")
    throw File_error("binary OFF is not supported; use PLY or ASCII OFF");
  header.vertices = parse_count(token, size / 6, size, "the OFF vertex count");
  header.faces = count("the OFF face count", size / 4);
  count("the OFF edge count", (std::numeric_limits<std::size_t>::max)());
  if(header.vertices * 6 + header.faces * 4 > size)
    throw File_error("the OFF header claims " + std::to_string(header.vertices) + " vertices and " +
                     std::to_string(header.faces) + " faces, more than the file of " +
                     std::to_string(size) + " bytes can hold");
  return header;
}

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
inline std::vector<std::size_t> read_OFF_face(Token_stream& tokens, const OFF_header& header,
                                              std::size_t f, std::size_t size)
{
  std::string token;
  if(!tokens.next(token))
    throw File_error("the OFF file is truncated: it declares " + std::to_string(header.vertices) +
                     " vertices and " + std::to_string(header.faces) + " faces but holds " +
                     std::to_string(header.vertices) + " and " + std::to_string(f));
  const std::string what = "OFF face " + std::to_string(f) + " (line " +
                           std::to_string(tokens.line_number()) + ")";
  const std::size_t corners = parse_count(token, size / 2, size, "the vertex count of " + what);
  std::vector<std::size_t> face;
  while(face.size() < corners)
  {
    if(!tokens.next(token))
      throw File_error(what + " claims " + std::to_string(corners) + " vertices but lists " +
                       std::to_string(face.size()) + " before the end of the file");
    face.push_back(
      parse_count(token, (std::numeric_limits<std::size_t>::max)(), size, "a vertex of " + what));
  }
  tokens.skip_rest_of_line();
  return face;
}

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

inline int PLY_type_bytes(const std::string& t)
{
  if(t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if(t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if(t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if(t == "double" || t == "float64") return 8;
  throw File_error("the PLY header has an unknown type '" + t + "'");
}

// CGAL's reader takes a face's vertex list of 32-bit integers only (and reads
// no face from a list of other values): such a list is refused by its name.
inline void check_PLY_face_lists(const PLY_header& header)
{
  for(const PLY_element& e : header.elements)
    for(const PLY_property& p : e.properties)
      if(e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index") &&
         p.value_type != "int" && p.value_type != "uint" && p.value_type != "int32" &&
         p.value_type != "uint32")
        throw File_error("the PLY face list " + p.name + " holds '" + p.value_type +
                         "' values; only int and uint (32 bits) are read");
}

// The header up to end_header, each element count at most `size`.
inline PLY_header read_PLY_header(std::istream& in, std::size_t size)
{
  PLY_header header;
  std::string line;
  std::getline(in, line);
  if(line.compare(0, 3, "ply") != 0)
    throw File_error("not a PLY file: it does not start with ply");
  while(std::getline(in, line))
  {
    const std::vector<std::string> t = line_tokens(line);
    if(t.empty() || t[0] == "comment" || t[0] == "obj_info")
      continue;
    if(t[0] == "end_header")
      break;
    if(t[0] == "format" && t.size() >= 2)
      header.format = t[1];
    else if(t[0] == "element" && t.size() >= 3)
      header.elements.push_back(
        PLY_element{t[1], parse_count(t[2], size, size, "the PLY " + t[1] + " count"), {}});
    else if(t[0] == "property" && !header.elements.empty() && t.size() >= 3)
    {
      PLY_property p;
      if(t[1] == "list" && t.size() >= 5)
      {
        p.count_type = t[2];
        p.count_bytes = PLY_type_bytes(t[2]);
        p.value_type = t[3];
        p.value_bytes = PLY_type_bytes(t[3]);
        p.name = t[4];
      }
      else
        p.value_bytes = PLY_type_bytes(t[1]);
      header.elements.back().properties.push_back(p);
    }
    else
      throw File_error("the PLY header has an unexpected line '" + line + "'");
  }
  if(header.format != "ascii" && header.format != "binary_little_endian" &&
     header.format != "binary_big_endian")
    throw File_error("the PLY format is '" + header.format + "', not ascii or binary");
  check_PLY_face_lists(header);
  return header;
}

// The length of list property `p` read at the current position, -1 if
// negative, NaN if unreadable.
inline long double read_PLY_list_length(std::istream& in, const PLY_header& header, const PLY_property& p)
{
  const long double unreadable = std::numeric_limits<long double>::quiet_NaN();
  if(header.format == "ascii")
  {
    std::string token;
    if(!(in >> token)) return unreadable;
    try { return std::stold(token); } catch(const std::exception&) { return unreadable; }
  }
  const bool little = (header.format == "binary_little_endian");
  unsigned char b[8] = {0};
  if(!in.read(reinterpret_cast<char*>(b), p.count_bytes)) return unreadable;
  std::uint64_t u = 0;
  for(int i = 0; i < p.count_bytes; ++i)
    u |= std::uint64_t(b[little ? i : p.count_bytes - 1 - i]) << (8 * i);
  const bool is_signed = p.count_type[0] != 'u';
  if(is_signed && (u >> (8 * p.count_bytes - 1)) & 1u) return -1;
  return static_cast<long double>(u);
}

// PLY: each element count times the fewest bytes one element takes, and each
// list's length, against the bytes left in the file (CGAL's reader sizes its
// buffers by them). Binary bodies are walked property by property.
inline void check_PLY_counts(std::istream& in, std::size_t size)
{
  const PLY_header header = read_PLY_header(in, size);
  const bool ascii = (header.format == "ascii");
  const std::size_t body = size - (std::min)(size, std::size_t(in.tellg()));
  // Fewest bytes per element: ascii, 2 per property ("0 "); binary, the sizes.
  long double needed = 0;
  for(const PLY_element& e : header.elements)
  {
    std::size_t bytes = 0;
    for(const PLY_property& p : e.properties)
      bytes += ascii ? 2 : std::size_t(p.count_bytes > 0 ? p.count_bytes : p.value_bytes);
    needed += static_cast<long double>(e.count) * static_cast<long double>((std::max)(bytes, std::size_t(1)));
  }
  if(needed > static_cast<long double>(body))
    throw File_error("the PLY header declares more elements than the " + std::to_string(body) +
                        " bytes of data can hold");

  // Lists: the length read before the values must fit in what is left.
  for(const PLY_element& e : header.elements)
    for(std::size_t i = 0; i < e.count; ++i)
      for(const PLY_property& p : e.properties)
      {
        if(p.count_bytes == 0)
        {
          std::string token;
          if(ascii ? !(in >> token) : !in.ignore(p.value_bytes))
            return;  // truncated: CGAL's reader reports it
          continue;
        }
        const long double n = read_PLY_list_length(in, header, p);
        const std::streamoff here = in.tellg();
        if(std::isnan(n) || here < 0)
          return;  // unreadable or truncated: CGAL's reader fails on it too
        if(n < 0)  // CGAL's reader would take it for a huge unsigned length
          throw File_error("a PLY " + e.name + " (number " + std::to_string(i) +
                           ") has a list of negative length");
        const std::size_t left = size - (std::min)(size, std::size_t(here));
        if(n * (ascii ? 2 : p.value_bytes) > static_cast<long double>(left))
          throw File_error("a PLY " + e.name + " (number " + std::to_string(i) + ") claims a list of " +
                              std::to_string(static_cast<unsigned long long>((std::min)(n, 1e19L))) +
                              " values, more than the file holds");
        if(ascii)
          for(std::size_t j = 0; j < std::size_t(n); ++j) { std::string token; in >> token; }
        else
          in.ignore(std::streamsize(n) * p.value_bytes);
      }
}

// What is wrong with the coordinates of vertex `vertex` (on line
// `line_number`), or an empty string: fewer than 3, or one that is not a
// finite double ("nan", "inf", or one that overflows such as "1e400").
inline std::string coordinate_problem(const std::vector<std::string>& coordinates, std::size_t vertex,
                                      std::size_t line_number)
{
  const std::string where = "vertex " + std::to_string(vertex) + " (line " + std::to_string(line_number) + ")";
  if(coordinates.size() < 3)
    return where + " has fewer than 3 coordinates";
  for(const std::string& token : coordinates)
  {
    char* end = nullptr;
    const double x = std::strtod(token.c_str(), &end);
    if(end != token.c_str() + token.size())
      return where + " has '" + token + "', not a number";
    if(!std::isfinite(x))
      return where + " has '" + token + "', " +
             (std::isnan(x) || token.find_first_of("iInN") != std::string::npos
                ? std::string("not a finite number")
                : std::string("too large for a double"));
  }
  return std::string();
}

// The next statement of an OBJ file and the number of its first line: a
// UTF-8 byte-order mark at the start of the file is dropped, and a line that
// ends in '\' continues on the next one.
inline bool next_OBJ_statement(std::istream& in, std::string& statement, std::size_t& line_number,
                               std::size_t& first_line)
{
  statement.clear();
  first_line = line_number + 1;
  for(std::string line; std::getline(in, line);)
  {
    if(++line_number == 1 && line.compare(0, 3, "\xEF\xBB\xBF") == 0)
      line.erase(0, 3);
    if(!line.empty() && line.back() == '\r')
      line.pop_back();
    const bool continued = !line.empty() && line.back() == '\\';
    statement += continued ? line.substr(0, line.size() - 1) + " " : line;
    if(!continued)
      return true;
  }
  return !statement.empty();
}

// The OBJ statements that describe no polygon: read and ignored.
inline bool is_ignored_OBJ_statement(const std::string& keyword)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "o", "g", "s", "mg", "mtllib", "usemtl", "maplib", "usemap", "l", "p",
    "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh",
    "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "con", "bsp", "bzp", "cdc", "cdp", "res"};
  return std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored);
}

// The 0-based vertex index of the face corner `token` ("v", "v/vt", "v//vn"
// or "v/vt/vn"): v counts from 1, or back from the last of the
// `number_of_points` vertices read so far when negative.
inline std::size_t OBJ_vertex_index(const std::string& token, std::size_t number_of_points,
                                    const std::string& what)
{
  const std::string v = token.substr(0, token.find('/'));
  char* end = nullptr;
  errno = 0;
  const long long i = std::strtoll(v.c_str(), &end, 10);
  if(v.empty() || end != v.c_str() + v.size() || errno == ERANGE || i == 0)
    throw File_error(what + " has '" + token + "', not a vertex reference");
  if(i > 0)
    return std::size_t(i - 1);  // a vertex beyond the file's is refused by used_points()
  if(std::size_t(-(i + 1)) >= number_of_points)
    throw File_error(what + " has '" + token + "', before the first vertex");
  return number_of_points - std::size_t(-i);
}

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
inline std::string unreadable_PLY_coordinate(std::istream& in, std::size_t size)
{
  PLY_header header;
  try { header = read_PLY_header(in, size); } catch(const File_error&) { return std::string(); }
  if(header.format != "ascii")
    return std::string();
  std::size_t line_number = 0, vertex = 0;
  std::string line;
  std::streamoff body = in.tellg();
  in.seekg(0, std::ios::beg);
  for(std::streamoff read = 0; read < body && std::getline(in, line); read = in.tellg())
    ++line_number;
  in.seekg(body, std::ios::beg);
  for(const PLY_element& e : header.elements)
    for(std::size_t i = 0; i < e.count && std::getline(in, line); ++i)
    {
      ++line_number;
      if(e.name != "vertex")
        continue;
      const std::string problem = coordinate_problem(line_tokens(line), vertex, line_number);
      if(!problem.empty())
        return problem;
      ++vertex;
    }
  return std::string();
}

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
inline std::vector<bool> used_points(std::size_t number_of_points,
                                     const std::vector<std::vector<std::size_t> >& polygons,
                                     const std::string& name)
{
  std::vector<bool> used(number_of_points, false);
  for(std::size_t f = 0; f < polygons.size(); ++f)
    for(std::size_t v : polygons[f])
    {
      if(v >= number_of_points)
        throw Invalid_input("'" + name + "': face " + std::to_string(f) + " uses vertex " +
                            std::to_string(v) + " but there are " + std::to_string(number_of_points) +
                            " vertices", Invalid_input::FACE, f);
      used[v] = true;
    }
  return used;
}

inline std::string lower_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string e = path.substr(dot + 1);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

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

#endif // CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_H
