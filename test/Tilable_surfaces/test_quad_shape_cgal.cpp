// CGAL-style test (a main() that asserts): quad extraction from meshes of two
// different CGAL types, hand-checked values, and the paper surfaces.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/boost/graph/helpers.h>

#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <array>
#include <cassert>
#include <cmath>
#include <iostream>
#include <string>

namespace TS = CGAL::Tilable_surfaces;

template <typename Mesh>
void check_unit_grid()
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor vertex_descriptor;
  typedef typename CGAL::Kernel_traits<
    typename boost::property_traits<typename boost::property_map<Mesh, CGAL::vertex_point_t>::type>::value_type
  >::Kernel::Point_3 Point;
  Mesh mesh;
  // 2 x 1 grid of unit squares: vertices 0..5, faces (0,1,4,3) and (1,2,5,4).
  std::vector<vertex_descriptor> v;
  for(int j = 0; j < 2; ++j)
    for(int i = 0; i < 3; ++i)
      v.push_back(add_vertex(Point(i, j, 0), mesh));
  const auto f0 = CGAL::Euler::add_face(std::vector<vertex_descriptor>{v[0], v[1], v[4], v[3]}, mesh);
  CGAL::Euler::add_face(std::vector<vertex_descriptor>{v[1], v[2], v[5], v[4]}, mesh);

  TS::validate_panel_mesh(mesh);
  // 7 edges of length 1.
  assert(std::abs(TS::mean_edge_length(mesh) - 1.0) < 1e-15);

  // Orientation 1: corner i is face vertex i + 1, so corner 0 is (1,0,0).
  const TS::Panel q = TS::face_panel(f0, mesh, TS::Panel_orientation(1));
  assert(q[0] == Eigen::Vector3d(1, 0, 0));
  assert(q[1] == Eigen::Vector3d(1, 1, 0));
  assert(q[2] == Eigen::Vector3d(0, 1, 0));
  assert(q[3] == Eigen::Vector3d(0, 0, 0));
  // Orientation 4 reverses: corners are face vertices 0, 3, 2, 1.
  const TS::Panel r = TS::face_panel(f0, mesh, TS::Panel_orientation(4));
  assert(r[1] == Eigen::Vector3d(0, 1, 0));
  assert(r[3] == Eigen::Vector3d(1, 0, 0));
  // Face edge j goes from face vertex j to j + 1: (v0,v1), (v1,v4), (v4,v3),
  // (v3,v0); only edge 1 is shared, with the second face.
  const std::array<std::size_t, 5> corner{{0, 1, 4, 3, 0}};
  const auto face_edges = TS::face_edge_halfedges(f0, mesh);
  for(std::size_t j = 0; j < 4; ++j)
  {
    assert(source(face_edges[j], mesh) == v[corner[j]]);
    assert(target(face_edges[j], mesh) == v[corner[j + 1]]);
    assert(is_border(opposite(face_edges[j], mesh), mesh) == (j != 1));
  }
  // Both faces are unit squares: congruent.
  for(auto f : faces(mesh))
    assert(TS::dissimilarity(TS::face_panel(f0, mesh), TS::face_panel(f, mesh)) < 1e-14);
}

int main()
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
  check_unit_grid<CGAL::Surface_mesh<K::Point_3> >();
  check_unit_grid<CGAL::Polyhedron_3<Epick, CGAL::Polyhedron_items_with_id_3> >();
  check_unit_grid<CGAL::Polyhedron_3<K> >();

  // Monkey saddle z = x^3 - 3xy^2 on a 10 x 10 grid of [-1,1]^2: mean edge
  // length is at least the grid spacing 0.2, and the rotation by 120 degrees
  // about z maps the surface to itself only approximately (square grid), so
  // just check the values are sane and every face is a proper quad.
  CGAL::Surface_mesh<K::Point_3> saddle;
  const bool ok = CGAL::IO::read_polygon_mesh(
    std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/monkey_saddle.off", saddle);
  assert(ok);
  assert(num_faces(saddle) == 100);
  TS::validate_panel_mesh(saddle);
  assert(TS::mean_edge_length(saddle) >= 0.2);
  for(auto f : faces(saddle))
  {
    const TS::Panel q = TS::face_panel(f, saddle);
    // Grid faces project to 0.2 x 0.2 squares in xy.
    for(int k = 0; k < 4; ++k)
    {
      const Eigen::Vector3d d = q[(k + 1) % 4] - q[k];
      assert(std::abs(std::hypot(d.x(), d.y()) - 0.2) < 1e-6);
    }
  }
  std::cout << "test_quad_shape_cgal: done" << std::endl;
  return 0;
}
