// Test helper: a minimal Wavefront OBJ and MTL reader, written independently
// of the package's writer, for the statements the tiled OBJ uses (mtllib, v,
// g, usemtl, f; newmtl, Kd). Anything it does not understand fails the test.
#ifndef TILABLE_SURFACES_TEST_OBJ_FILE_H
#define TILABLE_SURFACES_TEST_OBJ_FILE_H

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <istream>
#include <sstream>
#include <string>
#include <vector>

struct Obj_file
{
  std::string material_library;
  std::vector<std::array<double, 3> > vertices;
  std::vector<std::vector<std::size_t> > faces;  // 0-based vertex indices
  std::vector<std::string> face_group, face_material;
  std::vector<std::string> group_statements;     // the names of the `g` lines, in order
};

struct Mtl_material
{
  std::string name;
  std::array<double, 3> diffuse{{-1, -1, -1}};  // Kd
};

// A decimal number, the whole token: strtod rounds correctly, so a number
// written with max_digits10 digits reads back bit-exactly.
inline double obj_number(const std::string& token)
{
  char* end = nullptr;
  const double x = std::strtod(token.c_str(), &end);
  EXPECT_TRUE(!token.empty() && *end == '\0') << "not a number: '" << token << "'";
  return x;
}

// Splits a statement into its keyword and arguments; false for a blank or
// comment line.
inline bool obj_statement(const std::string& line, std::string& keyword, std::vector<std::string>& args)
{
  std::istringstream words(line);
  args.clear();
  if(!(words >> keyword) || keyword[0] == '#')
    return false;
  for(std::string w; words >> w;) args.push_back(w);
  return true;
}

inline Obj_file read_obj(std::istream& in)
{
  Obj_file obj;
  std::string line, keyword, group, material;
  std::vector<std::string> args;
  while(std::getline(in, line))
  {
    if(!obj_statement(line, keyword, args))
      continue;
    if(keyword == "mtllib" && args.size() == 1)
      obj.material_library = args[0];
    else if(keyword == "v" && args.size() == 3)
      obj.vertices.push_back({{obj_number(args[0]), obj_number(args[1]), obj_number(args[2])}});
    else if(keyword == "g" && args.size() == 1)
      obj.group_statements.push_back(group = args[0]);
    else if(keyword == "usemtl" && args.size() == 1)
      material = args[0];
    else if(keyword == "f" && args.size() >= 3)
    {
      obj.faces.emplace_back();
      for(const std::string& a : args)
      {
        const long i = std::stol(a.substr(0, a.find('/')));  // v, v/vt, v/vt/vn or v//vn
        EXPECT_TRUE(i >= 1 && std::size_t(i) <= obj.vertices.size()) << line;
        obj.faces.back().push_back(std::size_t(i - 1));
      }
      obj.face_group.push_back(group);
      obj.face_material.push_back(material);
    }
    else
      ADD_FAILURE() << "unexpected OBJ line: " << line;
  }
  return obj;
}

inline std::vector<Mtl_material> read_mtl(std::istream& in)
{
  std::vector<Mtl_material> materials;
  std::string line, keyword;
  std::vector<std::string> args;
  while(std::getline(in, line))
  {
    if(!obj_statement(line, keyword, args))
      continue;
    if(keyword == "newmtl" && args.size() == 1)
      materials.push_back(Mtl_material{args[0]});
    else if(materials.empty())
      ADD_FAILURE() << "MTL statement before any newmtl: " << line;
    else if(keyword == "Kd" && args.size() == 3)
      materials.back().diffuse = {{obj_number(args[0]), obj_number(args[1]), obj_number(args[2])}};
  }
  return materials;
}

#endif
