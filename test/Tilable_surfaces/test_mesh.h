// Test helper: the mesh type most tests use, the package's namespace aliases,
// and the reader of the test surfaces.
#ifndef TILABLE_SURFACES_TEST_TEST_MESH_H
#define TILABLE_SURFACES_TEST_TEST_MESH_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>

#include <gtest/gtest.h>

#include <string>

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

// The test surface `name` (a file of test/Tilable_surfaces/data, with its
// extension); a test failure if it cannot be read.
inline Mesh read(const std::string& name)
{
  Mesh mesh;
  const std::string path = std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/" + name;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(path, mesh)) << path;
  return mesh;
}

#endif // TILABLE_SURFACES_TEST_TEST_MESH_H
