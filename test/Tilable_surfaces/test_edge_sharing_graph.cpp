// Edge-sharing graph: degrees of flexibility counted by hand on small grids.
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include "grid_mesh.h"

#include <gtest/gtest.h>

#include <array>
#include <functional>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_edge_sharing_graph_unit {

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;
typedef Mesh::Face_index Face;

namespace {


struct Labelling
{
  Mesh::Property_map<Face, int> cluster, orientation;
};

Labelling label(Mesh& m, const std::function<int(int)>& cluster,
                const std::function<int(int)>& orientation = [](int) { return 0; })
{
  Labelling l{m.add_property_map<Face, int>("f:c", 0).first,
              m.add_property_map<Face, int>("f:o", 0).first};
  for(Face f : faces(m))
  {
    l.cluster[f] = cluster(int(f));
    l.orientation[f] = orientation(int(f));
  }
  return l;
}

} // namespace

TEST(EdgeSharingGraph, FlatGridOneClusterHasTwoLengths)
{
  // All faces oriented alike: shared vertical edges link template edges 1 and
  // 3, shared horizontal ones link 0 and 2: components {0, 2} and {1, 3}.
  Mesh m = grid<Mesh>(5, 3);
  Labelling l = label(m, [](int) { return 0; });
  TS::Edge_sharing_graph<Mesh> g(m, 1, l.cluster, l.orientation);
  EXPECT_EQ(g.degree_of_flexibility(), 2u);
  EXPECT_EQ(g.component(0, 0), g.component(0, 2));
  EXPECT_EQ(g.component(0, 1), g.component(0, 3));
  EXPECT_NE(g.component(0, 0), g.component(0, 1));
}

TEST(EdgeSharingGraph, BoundaryEdgesAddNoLink)
{
  // A single face: only boundary edges, so the 4 S-quad edges stay apart.
  Mesh m = grid<Mesh>(1, 1);
  Labelling l = label(m, [](int) { return 0; });
  TS::Edge_sharing_graph<Mesh> g(m, 1, l.cluster, l.orientation);
  EXPECT_EQ(g.degree_of_flexibility(), 4u);
}

TEST(EdgeSharingGraph, SelfLoopsAreIgnored)
{
  // Two faces side by side in one cluster; the right one has orientation 2,
  // so its face edge 3 (the shared edge) is template edge (3 - 2) = 1, the
  // same node as the left face's edge 1: a self-loop, no constraint.
  Mesh m = grid<Mesh>(2, 1);
  Labelling l = label(m, [](int) { return 0; }, [](int f) { return f == 1 ? 2 : 0; });
  TS::Edge_sharing_graph<Mesh> g(m, 1, l.cluster, l.orientation);
  EXPECT_EQ(g.degree_of_flexibility(), 4u);
}

TEST(EdgeSharingGraph, FourByFourPeriodicLabellingCountedByHand)
{
  // Face (i, j) in cluster c = (i mod 2) + 2 (j mod 2), orientation 0.
  // Vertical interior edges between columns i and i+1 link (c(i,j), 1) with
  // (c(i+1,j), 3); both parities of i occur (i = 0, 1, 2), so for each row
  // parity b: (2b,1)~(2b+1,3) and (2b+1,1)~(2b,3): 4 components of vertical
  // edges. Likewise horizontal edges, for each column parity a:
  // (a,2)~(a+2,0) and (a+2,2)~(a,0): 4 components. DOF = 8.
  Mesh m = grid<Mesh>(4, 4);
  Labelling l = label(m, [](int f) { return (f % 4) % 2 + 2 * ((f / 4) % 2); });
  TS::Edge_sharing_graph<Mesh> g(m, 4, l.cluster, l.orientation);
  EXPECT_EQ(g.degree_of_flexibility(), 8u);
  EXPECT_EQ(g.component(0, 1), g.component(1, 3));
  EXPECT_EQ(g.component(1, 1), g.component(0, 3));
  EXPECT_NE(g.component(0, 1), g.component(0, 3));
  EXPECT_EQ(g.component(0, 2), g.component(2, 0));
}

TEST(EdgeSharingGraph, FourByFourQuadrantsCountedByHand)
{
  // Face (i, j) in cluster c = (i / 2) + 2 (j / 2). Inside a quadrant, edges
  // link (c,1)~(c,3) and (c,0)~(c,2); across the middle column (c,1)~(c+1,3)
  // for c = 0, 2; across the middle row (c,2)~(c+2,0) for c = 0, 1. Vertical
  // components: {0,1} and {2,3} clusters; horizontal: {0,2} and {1,3}. DOF 4.
  Mesh m = grid<Mesh>(4, 4);
  Labelling l = label(m, [](int f) { return (f % 4) / 2 + 2 * ((f / 4) / 2); });
  TS::Edge_sharing_graph<Mesh> g(m, 4, l.cluster, l.orientation);
  EXPECT_EQ(g.degree_of_flexibility(), 4u);
  const auto p0 = g.cluster_pattern(0), p3 = g.cluster_pattern(3);
  EXPECT_EQ(p0[1], p0[3]);
  EXPECT_NE(p0[1], p3[1]);

  // Clusters 0 and 3 share no component; merging them with the identity
  // correspondence joins {0,1}-vertical with {2,3}-vertical and {0,2}- with
  // {1,3}-horizontal: DOF 2.
  EXPECT_EQ(g.merge_clusters(0, 3, TS::Panel_orientation(0)), 2u);
  EXPECT_FALSE(g.is_alive(3));
}

// compact_cluster_ids() drops the ids of merged clusters: the clusters
// alive keep their order and their components, numbered 0..K'-1. On the
// quadrants above, merging clusters 0 and 1 (side by side) joins the
// horizontal components {0, 2} and {1, 3}: DOF 3 by hand.
TEST(EdgeSharingGraph, CompactingIdsKeepsTheOrderAndTheComponents)
{
  Mesh m = grid<Mesh>(4, 4);
  Labelling l = label(m, [](int f) { return (f % 4) / 2 + 2 * ((f / 4) / 2); });
  TS::Edge_sharing_graph<Mesh> g(m, 4, l.cluster, l.orientation);
  EXPECT_EQ(g.merge_clusters(0, 1, TS::Panel_orientation(0)), 3u);
  EXPECT_EQ(g.number_of_clusters(), 4u) << "the merged id stays reserved";
  const std::vector<std::size_t> alive{0, 2, 3};
  std::vector<std::array<std::size_t, 4> > before;
  for(std::size_t c : alive) before.push_back(g.cluster_pattern(c));
  g.compact_cluster_ids();
  EXPECT_EQ(g.number_of_clusters(), 3u);
  EXPECT_EQ(g.degree_of_flexibility(), 3u);
  for(std::size_t a = 0; a < 3; ++a)
  {
    EXPECT_TRUE(g.is_alive(a));
    for(std::size_t b = 0; b < 3; ++b)
      for(int i = 0; i < 4; ++i)
        for(int j = 0; j < 4; ++j)
          EXPECT_EQ(g.component(a, i) == g.component(b, j), before[a][i] == before[b][j])
            << "new " << a << "." << i << " and " << b << "." << j;
  }
}

TEST(EdgeSharingGraph, EdgeComponentMapColoursMeshEdges)
{
  Mesh m = grid<Mesh>(3, 2);
  Labelling l = label(m, [](int) { return 0; });
  TS::Edge_sharing_graph<Mesh> g(m, 1, l.cluster, l.orientation);
  const auto colours = g.edge_component_map();
  for(auto e : edges(m))
  {
    const auto a = m.point(source(e, m)), b = m.point(target(e, m));
    const bool horizontal = a.y() == b.y();
    EXPECT_EQ(get(colours, e), horizontal ? g.component(0, 0) : g.component(0, 1));
  }
}

TEST(EdgeSharingGraph, CopiesAreIndependent)
{
  Mesh m = grid<Mesh>(4, 4);
  Labelling l = label(m, [](int f) { return (f % 4) % 2 + 2 * ((f / 4) % 2); });
  TS::Edge_sharing_graph<Mesh> g(m, 4, l.cluster, l.orientation);
  TS::Edge_sharing_graph<Mesh> copy = g;
  copy.merge_clusters(0, 1, TS::Panel_orientation(0));
  EXPECT_EQ(g.degree_of_flexibility(), 8u);
  EXPECT_LT(copy.degree_of_flexibility(), 8u);
  EXPECT_TRUE(g.is_alive(1));
}

TEST(EdgeSharingGraph, RejectsBadLabels)
{
  Mesh m = grid<Mesh>(2, 2);
  Labelling l = label(m, [](int f) { return f; });
  EXPECT_THROW(TS::Edge_sharing_graph<Mesh>(m, 3, l.cluster, l.orientation), TS::Invalid_input);
  Labelling o = label(m, [](int) { return 0; }, [](int) { return 8; });
  EXPECT_THROW(TS::Edge_sharing_graph<Mesh>(m, 1, o.cluster, o.orientation), TS::Invalid_input);
}

// Two faces side by side, 2 x 1 and 3 x 1 (vertices 2 and 5 moved from x = 4
// to x = 5). length_deviation() is the spread that the links of the graph
// add between S-quad edges, not the spread of the edges that one S-quad edge
// already holds (that is the cluster's shape dissimilarity): built as one
// cluster, the two bottom edges (2 and 3) are the same S-quad edge, so 0.
// Built as two clusters nothing is linked but the shared vertical edges
// (all 1): 0; merging the two clusters links the bottom edges (2 x 0.5^2
// about their mean 2.5) and the top edges likewise: 1.
TEST(EdgeSharingGraph, LengthDeviationByHand)
{
  Mesh m = grid<Mesh>(2, 1, 2.0, 1.0);
  m.point(Mesh::Vertex_index(2)) = Kernel::Point_3(5, 0, 0);
  m.point(Mesh::Vertex_index(5)) = Kernel::Point_3(5, 1, 0);
  Labelling one = label(m, [](int) { return 0; });
  const TS::Edge_sharing_graph<Mesh> joined(m, 1, one.cluster, one.orientation);
  EXPECT_EQ(joined.degree_of_flexibility(), 3u);
  EXPECT_NEAR(joined.length_deviation(), 0.0, 1e-12);

  Mesh m2 = m;
  Labelling two = label(m2, [](int f) { return f; });
  TS::Edge_sharing_graph<Mesh> apart(m2, 2, two.cluster, two.orientation);
  EXPECT_NEAR(apart.length_deviation(), 0.0, 1e-12);
  EXPECT_NEAR(apart.length_deviation_after_merge(0, 1, TS::Panel_orientation(0)), 1.0, 1e-12);
  apart.merge_clusters(0, 1, TS::Panel_orientation(0));
  EXPECT_NEAR(apart.length_deviation(), 1.0, 1e-12);
}

} // namespace test_edge_sharing_graph_unit
