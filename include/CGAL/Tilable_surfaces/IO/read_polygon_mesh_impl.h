// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_IMPL_H

// The bodies of the non-template functions declared in read_polygon_mesh.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> line_tokens(const std::string& line)
{
  std::istringstream in(line.substr(0, line.find('#')));
  std::vector<std::string> tokens;
  for(std::string t; in >> t;) tokens.push_back(t);
  return tokens;
}

CGAL_TILABLE_SURFACES_INLINE
std::size_t parse_count(const std::string& token, std::size_t limit, std::size_t size,
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

CGAL_TILABLE_SURFACES_INLINE
double parse_coordinate(const std::string& token, const std::string& what)
{
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  if(token.empty() || end != token.c_str() + token.size())
    throw File_error(what + " has '" + token + "', not a number");
  return x;
}

CGAL_TILABLE_SURFACES_INLINE
OFF_header read_OFF_header(Token_stream& tokens, std::size_t size)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> read_OFF_face(Token_stream& tokens, const OFF_header& header,
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

CGAL_TILABLE_SURFACES_INLINE
int PLY_type_bytes(const std::string& t)
{
  if(t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
  if(t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
  if(t == "int" || t == "uint" || t == "float" || t == "int32" || t == "uint32" || t == "float32") return 4;
  if(t == "double" || t == "float64") return 8;
  throw File_error("the PLY header has an unknown type '" + t + "'");
}

CGAL_TILABLE_SURFACES_INLINE
void check_PLY_face_lists(const PLY_header& header)
{
  for(const PLY_element& e : header.elements)
    for(const PLY_property& p : e.properties)
      if(e.name == "face" && (p.name == "vertex_indices" || p.name == "vertex_index") &&
         p.value_type != "int" && p.value_type != "uint" && p.value_type != "int32" &&
         p.value_type != "uint32")
        throw File_error("the PLY face list " + p.name + " holds '" + p.value_type +
                         "' values; only int and uint (32 bits) are read");
}

CGAL_TILABLE_SURFACES_INLINE
PLY_header read_PLY_header(std::istream& in, std::size_t size)
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

CGAL_TILABLE_SURFACES_INLINE
long double read_PLY_list_length(std::istream& in, const PLY_header& header, const PLY_property& p)
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

CGAL_TILABLE_SURFACES_INLINE
void check_PLY_counts(std::istream& in, std::size_t size)
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

CGAL_TILABLE_SURFACES_INLINE
std::string coordinate_problem(const std::vector<std::string>& coordinates, std::size_t vertex,
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

CGAL_TILABLE_SURFACES_INLINE
bool next_OBJ_statement(std::istream& in, std::string& statement, std::size_t& line_number,
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

CGAL_TILABLE_SURFACES_INLINE
bool is_ignored_OBJ_statement(const std::string& keyword)
{
  static const char* const ignored[] = {
    "vt", "vn", "vp", "o", "g", "s", "mg", "mtllib", "usemtl", "maplib", "usemap", "l", "p",
    "bevel", "c_interp", "d_interp", "lod", "shadow_obj", "trace_obj", "ctech", "stech", "call", "csh",
    "cstype", "deg", "bmat", "step", "curv", "curv2", "surf", "parm", "trim", "hole", "scrv", "sp",
    "end", "con", "bsp", "bzp", "cdc", "cdp", "res"};
  return std::find(std::begin(ignored), std::end(ignored), keyword) != std::end(ignored);
}

CGAL_TILABLE_SURFACES_INLINE
std::size_t OBJ_vertex_index(const std::string& token, std::size_t number_of_points,
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

CGAL_TILABLE_SURFACES_INLINE
std::string unreadable_PLY_coordinate(std::istream& in, std::size_t size)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<bool> used_points(std::size_t number_of_points,
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

CGAL_TILABLE_SURFACES_INLINE
std::string lower_extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.'), slash = path.find_last_of('/');
  if(dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return std::string();
  std::string e = path.substr(dot + 1);
  for(char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
  return e;
}

} // namespace internal
} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_READ_POLYGON_MESH_IMPL_H
