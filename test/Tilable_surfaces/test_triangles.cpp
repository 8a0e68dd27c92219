// Quad-dominant meshes: triangles are panels of their own kind (3 corners,
// 6 correspondences), never in a cluster with quads. Shape analysis, the
// edge-sharing graph, the clustering, the optimizer and the measure take them.
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

#include "congruence_check.h"
#include "optimization_test_helpers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_triangles_unit {

using namespace test_helpers;

namespace {

using Eigen::Vector3d;

// A "house": two unit squares side by side (faces 0, 1) and two right
// isosceles triangles on top (faces 2, 3) meeting at v6 = (1, 2, 0) (with
// `apex` added to v6, and `corner` added to v5). Triangle 3 = (v4, v5, v6)
// is triangle 2 = (v3, v4, v6) turned over: template corners (t0, t1, t2)
// = (v3, v4, v6) go to (v5, v4, v6), correspondence 5 (reversed, o(i) =
// (1 - i) mod 3).
Mesh house(const Vector3d& apex = Vector3d::Zero(), const Vector3d& corner = Vector3d::Zero())
{
  Mesh m;
  auto v = [&](double x, double y, const Vector3d& d = Vector3d::Zero()) {
    return m.add_vertex(Point(x + d.x(), y + d.y(), d.z()));
  };
  const auto v0 = v(0, 0), v1 = v(1, 0), v2 = v(2, 0), v3 = v(0, 1), v4 = v(1, 1),
             v5 = v(2, 1, corner), v6 = v(1, 2, apex);
  m.add_face(v0, v1, v4, v3);
  m.add_face(v1, v2, v5, v4);
  m.add_face(v3, v4, v6);
  m.add_face(v4, v5, v6);
  return m;
}

// The quads in cluster 0 (orientation 0), the triangles in cluster 1
// (orientations 0 and 5).
Clustering house_clustering(Mesh& m)
{
  Clustering c = add_clustering_maps(m);
  c.K = 2;
  c.cluster[Face(2)] = c.cluster[Face(3)] = 1;
  c.orientation[Face(3)] = 5;
  return c;
}

TS::Panel triangle(const Vector3d& a, const Vector3d& b, const Vector3d& c) { return TS::Panel(a, b, c); }

} // namespace

TEST(Triangles, TheSixCorrespondencesOfATriangleAreItsSymmetries)
{
  for(int index : {0, 1, 2, 4, 5, 6})
  {
    const TS::Panel_orientation o(index);
    ASSERT_TRUE(o.is_valid_for(3));
    std::array<bool, 3> hit{{false, false, false}};
    for(int i = 0; i < 3; ++i)
    {
      hit[std::size_t(o(i, 3))] = true;
      EXPECT_EQ(o.inverse(3)(o(i, 3), 3), i) << index;
      // Template edge k (t_k t_{k+1}) lands on the face edge between the images of its ends.
      const int j = o.face_edge(i, 3), a = o(i, 3), b = o((i + 1) % 3, 3);
      EXPECT_TRUE((a == j && b == (j + 1) % 3) || (b == j && a == (j + 1) % 3)) << index;
      EXPECT_EQ(o.template_edge(j, 3), i) << index;
    }
    EXPECT_TRUE(hit[0] && hit[1] && hit[2]) << index << " is a permutation";
    for(int other : {0, 1, 2, 4, 5, 6})
    {
      const TS::Panel_orientation p(other), composed = TS::compose(o, p, 3);
      ASSERT_TRUE(composed.is_valid_for(3));
      for(int i = 0; i < 3; ++i)
        EXPECT_EQ(composed(i, 3), o(p(i, 3), 3));
    }
  }
  EXPECT_FALSE(TS::Panel_orientation(3).is_valid_for(3));
  EXPECT_FALSE(TS::Panel_orientation(7).is_valid_for(3));
}

TEST(Triangles, BestMatchRecoversTheRelabellingAndNeverMatchesAQuad)
{
  const TS::Panel p = triangle(Vector3d(0, 0, 0), Vector3d(2, 0, 0.3), Vector3d(0.4, 1.1, -0.2));
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  for(int index : {0, 1, 2, 4, 5, 6})
  {
    const TS::Panel_orientation o(index);
    // q lists the moved corners so that q[o(i)] = R p[i] + t.
    TS::Panel q = p;
    for(int i = 0; i < 3; ++i) q[o(i, 3)] = R * p[i] + Vector3d(5, -1, 2);
    const TS::Quad_match m = TS::best_match(p, q);
    EXPECT_LT(m.dissimilarity, 1e-12) << index;
    EXPECT_EQ(m.orientation, o) << index << ": a scalene triangle has one matching correspondence";
    EXPECT_LT(TS::rigid_fit_deviation(p, TS::reoriented(q, m.orientation)), 1e-12);
  }
  const TS::Panel square{{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, 0)}};
  EXPECT_EQ(TS::dissimilarity(p, square), std::numeric_limits<double>::infinity());
  EXPECT_EQ(TS::dissimilarity(square, p), std::numeric_limits<double>::infinity());
}

TEST(Triangles, EdgeSharingGraphOfTheHouseCountedByHand)
{
  Mesh m = house();
  const Clustering c = house_clustering(m);
  const TS::Edge_sharing_graph<Mesh> g(m, 2, c.cluster, c.orientation);
  EXPECT_EQ(g.corner_count(0), 4);
  EXPECT_EQ(g.corner_count(1), 3);
  // 4 + 3 template edges. Links: the shared edge v1v4 joins quad edges 1 and
  // 3; v3v4 and v4v5 both join quad edge 2 to triangle edge 0; v4v6 is
  // triangle edge 1 on both sides (a self-loop). Left: {q0}, {q1, q3},
  // {q2, t0}, {t1}, {t2}.
  EXPECT_EQ(g.degree_of_flexibility(), 5u);
  EXPECT_EQ(g.component(0, 1), g.component(0, 3));
  EXPECT_EQ(g.component(0, 2), g.component(1, 0));
  EXPECT_NE(g.component(1, 1), g.component(1, 2));
  EXPECT_THROW(g.component(1, 3), TS::Invalid_input);
  EXPECT_EQ(g.length_deviation_after_merge(0, 1, TS::Panel_orientation()),
            std::numeric_limits<double>::infinity());
  TS::Edge_sharing_graph<Mesh> copy = g;
  try
  {
    copy.merge_clusters(0, 1, TS::Panel_orientation());
    ADD_FAILURE() << "a quad cluster and a triangle cluster were merged";
  }
  catch(const TS::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("a quad cluster and a triangle cluster"), std::string::npos) << e.what();
  }
}

TEST(Triangles, OptimizationMakesTheHouseTwoMoldsAndStaysClose)
{
  const Vector3d apex(0.15, -0.1, 0.2);
  const Mesh input = house(apex, Vector3d(0.1, 0.05, -0.1));
  Mesh mesh = input;
  const Clustering c = house_clustering(mesh);
  ASSERT_GT(congruence_by_umeyama(mesh, c.cluster, c.orientation), 1e-2) << "the input is not tiled";
  const TS::Optimization_result r = TS::optimize_tilable_surface(mesh, clustering_parameters(c));
  EXPECT_LE(r.measure.congruence_error, 1e-6);
  // Checked independently: every instance fitted rigidly onto its cluster's first.
  EXPECT_LE(congruence_by_umeyama(mesh, c.cluster, c.orientation), 1e-6);
  const TS::Tilability_measure m = TS::measure_tilability(mesh, input, clustering_parameters(c));
  EXPECT_LE(m.congruence_error, 1e-6);
  EXPECT_EQ(m.degree_of_flexibility, 5u);
  ASSERT_EQ(m.s_quads.size(), 2u);
  EXPECT_EQ(m.s_quads[0].size(), 4);
  EXPECT_EQ(m.s_quads[1].size(), 3);
  // Moved, but less than undoing the perturbation that made it untileable
  // would move it (the apex's, 0.27, the larger; measured 0.099).
  EXPECT_GT(m.max_displacement, 1e-3);
  EXPECT_LT(m.max_displacement, apex.norm());
}

TEST(Triangles, OrientationsAndClustersThatDoNotFitATriangleAreRefused)
{
  {
    Mesh mesh = house();
    const Clustering c = house_clustering(mesh);
    c.orientation[Face(2)] = 3;
    const Mesh before = mesh;
    try
    {
      TS::optimize_tilable_surface(mesh, clustering_parameters(c));
      ADD_FAILURE() << "orientation 3 was accepted on a triangle";
    }
    catch(const TS::Invalid_input& e)
    {
      EXPECT_EQ(e.element(), TS::Invalid_input::FACE);
      EXPECT_EQ(e.index(), 2u);
      EXPECT_NE(std::string(e.what()).find("face 2 is a triangle and has orientation 3"), std::string::npos)
        << e.what();
    }
    for(auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v), before.point(v));
  }
  {
    Mesh mesh = house();
    const Clustering c = house_clustering(mesh);
    c.cluster[Face(3)] = 0;
    try
    {
      TS::optimize_tilable_surface(mesh, clustering_parameters(c));
      ADD_FAILURE() << "a cluster of quads and triangles was accepted";
    }
    catch(const TS::Invalid_input& e)
    {
      EXPECT_EQ(e.index(), 3u);
      EXPECT_NE(std::string(e.what()).find("cluster 0 holds both the triangle 3 and the quad 0"),
                std::string::npos) << e.what();
    }
  }
}

// Every cluster holds one kind of face.
bool clusters_are_pure(const Mesh& mesh, const Face_int_map& cluster)
{
  std::map<int, int> kind;
  for(auto f : faces(mesh))
  {
    const int n = int(CGAL::halfedges_around_face(halfedge(f, mesh), mesh).size());
    if(kind.emplace(cluster[f], n).first->second != n) return false;
  }
  return true;
}

TEST(Triangles, TheHouseBecomesOneQuadTileAndOneTriangleTile)
{
  const Vector3d apex(0.15, -0.1, 0.2);
  const Mesh input = house(apex, Vector3d(0.1, 0.05, -0.1));
  Mesh mesh = input;
  Clustering c = add_clustering_maps(mesh);
  const TS::K_set_tilable_result r =
    TS::make_k_set_tilable(mesh, TS::parameters::number_of_tiles(2).face_cluster_map(c.cluster)
                                   .face_orientation_map(c.orientation));
  EXPECT_TRUE(r.is_tilable());
  EXPECT_TRUE(clusters_are_pure(mesh, c.cluster));
  EXPECT_NE(c.cluster[Face(0)], c.cluster[Face(2)]);
  EXPECT_EQ(c.cluster[Face(0)], c.cluster[Face(1)]);
  EXPECT_EQ(c.cluster[Face(2)], c.cluster[Face(3)]);
  EXPECT_LE(congruence_by_umeyama(mesh, c.cluster, c.orientation), 1e-6);
  // Less than undoing the apex's perturbation would move it (measured 0.068).
  EXPECT_LT(r.optimization.measure.max_displacement, apex.norm());
}

TEST(Triangles, OneTileIsRefusedWhenTheMeshHasQuadsAndTriangles)
{
  Mesh mesh = house(Vector3d(0.15, -0.1, 0.2));
  const Mesh before = mesh;
  Clustering c = add_clustering_maps(mesh);
  auto expect_refused = [&](auto run, const char* what) {
    try
    {
      run();
      ADD_FAILURE() << "one tile for quads and triangles, " << what;
    }
    catch(const TS::Invalid_input& e)
    {
      EXPECT_EQ(e.element(), TS::Invalid_input::PARAMETER);
      EXPECT_NE(std::string(e.what()).find("at least 2 tiles"), std::string::npos) << e.what();
    }
    for(auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v), before.point(v));
  };
  const auto maps = TS::parameters::face_cluster_map(c.cluster).face_orientation_map(c.orientation);
  expect_refused([&] { TS::make_k_set_tilable(mesh, maps.number_of_tiles(1)); }, "K = 1");
  // A deviation search whose largest K is 1 has no K to try.
  expect_refused([&] { TS::make_k_set_tilable(mesh, maps.number_of_tiles(1).max_deviation(0.5)); },
                 "the largest K of a deviation search");
}

} // namespace test_triangles_unit
