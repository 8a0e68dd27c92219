// End to end on every kind of mesh: a closed surface, CGAL::Polyhedron_3 and a
// Surface_mesh with removed elements not yet collected (other kernels:
// test_kernels.cpp). Each result is checked for congruence independently.
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "any_mesh_check.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <map>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_mesh_kinds_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
using any_mesh_check::read;
using any_mesh_check::tile_and_check;

namespace {

template <typename Mesh>
double max_coordinate_change(const Mesh& before, const Mesh& after)
{
  double change = 0;
  auto b = vertices(before).begin();
  for(auto v : vertices(after))
  {
    change = (std::max)(change, std::sqrt(CGAL::to_double(CGAL::squared_distance(
                                  get(CGAL::vertex_point, before, *b), get(CGAL::vertex_point, after, v)))));
    ++b;
  }
  return change;
}

} // namespace

TEST(MeshKinds, ClosedTorusHasNoBoundaryAndBecomesTilable)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  Mesh torus = read<Mesh>("torus_quad.off");
  ASSERT_TRUE(CGAL::is_closed(torus));
  ASSERT_EQ(torus.number_of_faces(), 25u);
  const Mesh input = torus;
  const TS::K_set_tilable_result r = tile_and_check(torus, 2);
  EXPECT_TRUE(CGAL::is_closed(torus));
  EXPECT_GT(max_coordinate_change(input, torus), 1e-3) << "the 5 rings of quads into 2 tiles";
  // Closer to the input than the tube's radius (about the y axis, 0.12 of
  // the diagonal; measured 0.074): the tube is not collapsed onto its core.
  double inner = std::numeric_limits<double>::max(), outer = 0;
  for(auto v : vertices(input))
  {
    const double rho = std::hypot(input.point(v).x(), input.point(v).z());
    inner = (std::min)(inner, rho);
    outer = (std::max)(outer, rho);
  }
  const TS::Tilability_measure& m = r.optimization.measure;
  EXPECT_LT(m.hausdorff_distance * m.input_bbox_diagonal, 0.5 * (outer - inner));
}

// With items with ids: the package indexes edges by halfedge id (without, a
// static_assert says so).
TEST(MeshKinds, Polyhedron3WithIds)
{
  typedef CGAL::Polyhedron_3<CGAL::Simple_cartesian<double>, CGAL::Polyhedron_items_with_id_3> Polyhedron;
  Polyhedron mesh = read<Polyhedron>("monkey_saddle.off");
  ASSERT_EQ(num_faces(mesh), 100u);
  const Polyhedron input = mesh;
  tile_and_check(mesh, 30);
  EXPECT_GT(max_coordinate_change(input, mesh), 1e-6);
}

TEST(MeshKinds, SurfaceMeshWithRemovedElementsIsRefusedUntilCollected)
{
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
  Mesh mesh = read<Mesh>("monkey_saddle.off");
  // A quad added and removed again, its vertices with it: 4 vertices, 4
  // edges and a face removed but not collected.
  std::vector<Mesh::Vertex_index> extra;
  for(int i = 0; i < 4; ++i) extra.push_back(mesh.add_vertex(Mesh::Point(5 + (i & 1), 5 + (i >> 1), 0)));
  CGAL::Euler::remove_face(mesh.halfedge(mesh.add_face(extra[0], extra[1], extra[3], extra[2])), mesh);
  // remove_face() removed the isolated vertices too.
  ASSERT_TRUE(mesh.has_garbage());
  ASSERT_EQ(mesh.number_of_faces(), 100u);
  ASSERT_GT(num_faces(mesh), 100u) << "BGL counts the removed face";

  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const Mesh before = mesh;
  try
  {
    TS::make_k_set_tilable(mesh, TSP::number_of_tiles(30).face_cluster_map(cluster).face_orientation_map(orientation));
    ADD_FAILURE() << "accepted";
  }
  catch(const TS::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("collect_garbage()"), std::string::npos) << e.what();
  }
  EXPECT_EQ(max_coordinate_change(before, mesh), 0.0);
  for(auto f : faces(mesh)) EXPECT_EQ(cluster[f], -1);

  mesh.collect_garbage();
  tile_and_check(mesh, 30);
}

} // namespace test_mesh_kinds_unit
