// planar_tiles(true): every panel planar (glass) as well as congruent to its
// S-quad, checked here by an independent computation of the distance
// between the diagonals of every face.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "congruence_check.h"

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_planar_panels_unit {

namespace {

// The largest distance between the diagonals of a face, over the mean edge
// length, with CGAL's kernel: the distance between the lines v0v2 and v1v3.
double worst_diagonal_distance(const Mesh& m)
{
  double worst = 0, edges = 0;
  for(auto e : m.edges())
    edges += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  for(auto f : m.faces())
  {
    std::vector<Kernel::Point_3> p;
    for(auto v : vertices_around_face(m.halfedge(f), m)) p.push_back(m.point(v));
    const Kernel::Vector_3 n = CGAL::cross_product(p[2] - p[0], p[3] - p[1]);
    worst = (std::max)(worst, std::abs((p[1] - p[0]) * n) / std::sqrt(n.squared_length()));
  }
  return worst / (edges / double(m.number_of_edges()));
}

} // namespace

TEST(PlanarPanels, EveryPanelIsPlanarAndCongruentByIndependentChecks)
{
  for(const auto& [name, k] : std::vector<std::pair<std::string, int> >{{"monkey_saddle.off", 8},
                                                                        {"de_beers_ginza.off", 27}})
  {
    const Mesh input = read(name);
    ASSERT_GT(worst_diagonal_distance(input), 1e-3) << name << ": the input is not planar";
    Mesh free_form = input;
    const TS::K_set_tilable_result rf = TS::make_k_set_tilable(free_form, TSP::number_of_tiles(k));
    EXPECT_TRUE(rf.is_tilable());
    // Not planar without the option: 100 times the tolerance below.
    EXPECT_GT(worst_diagonal_distance(free_form), 1e-4) << name << ": congruent is not planar";

    Mesh mesh = input;
    auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
    auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
    const TS::K_set_tilable_result r = TS::make_k_set_tilable(
      mesh, TSP::number_of_tiles(k).planar_tiles(true).face_cluster_map(cluster).face_orientation_map(orientation));
    EXPECT_TRUE(r.is_tilable()) << name;
    EXPECT_TRUE(r.optimization.measure.requires_planar_tiles);
    EXPECT_LE(worst_diagonal_distance(mesh), 1e-6) << name;
    EXPECT_LE(r.optimization.measure.planarity_error, 1e-6) << name;
    EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 1e-6) << name;
    for(const TS::Tile& t : r.tiles)
    {
      const std::array<double, 4> e = TS::edge_lengths(t.corners);
      EXPECT_LE(TS::planarity_defect(t.corners), 1e-5 * (e[0] + e[1] + e[2] + e[3]) / 4)
        << name << ": the mold of tile " << t.id << " is flat";
    }
  }
}

TEST(PlanarPanels, OnlyTheDefaultSolverTakesThem)
{
  Mesh mesh = read("monkey_saddle.off");
  const Mesh before = mesh;
  EXPECT_THROW(TS::make_k_set_tilable(mesh, TSP::number_of_tiles(4).planar_tiles(true).solver(
                                              TS::PAPER_CONJUGATE_GRADIENT)),
               TS::Invalid_input);
  for(auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v), before.point(v)) << "untouched";
}

} // namespace test_planar_panels_unit
