// The coarsening of 2 x 2 refinements (internal/Shape_analysis/quad_coarsening.h)
// on meshes whose coarse counts are known by hand, and the prolongation of an
// exact coarse result, checked by an independent Umeyama fit. (A sub-quad
// numbered by the coarse corner instead of the template corner, or
// oriented without the coarse reversal, is 0.74 to 0.77 mean edge lengths
// off on this case.)

#include "congruence_check.h"
#include "grid_mesh.h"
#include "test_mesh.h"

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_coarsening.h>

#include <CGAL/boost/graph/generators.h>
#include <CGAL/subdivision_method_3.h>

#include <gtest/gtest.h>

#include <set>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_quad_coarsening_unit {

namespace TSI = CGAL::Tilable_surfaces::internal;

namespace {

// The box [0, a] x [0, b] x [0, c], 6 quads facing out, Catmull-Clark
// subdivided `steps` times: 6 x 4^steps quads; its 8 corners keep valence 3.
Mesh subdivided_box(int steps, double a = 1, double b = 2, double c = 3)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int k = 0; k < 2; ++k)
    for(int j = 0; j < 2; ++j)
      for(int i = 0; i < 2; ++i)
        v.push_back(m.add_vertex(Point(a * i, b * j, c * k)));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads)
    m.add_face(v[q[0]], v[q[1]], v[q[2]], v[q[3]]);
  if(steps > 0)
    CGAL::Subdivision_method_3::CatmullClark_subdivision(m, CGAL::parameters::number_of_iterations(steps));
  return m;
}

// An nx x ny grid closed both ways (a torus), every vertex of valence 4.
Mesh torus_grid(int nx, int ny)
{
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
    {
      const double u = 2 * CGAL_PI * i / nx, w = 2 * CGAL_PI * j / ny;
      v.push_back(m.add_vertex(Point((3 + std::cos(w)) * std::cos(u), (3 + std::cos(w)) * std::sin(u), std::sin(w))));
    }
  auto id = [&](int i, int j) { return v[std::size_t((i % nx) + nx * (j % ny))]; };
  for(int j = 0; j < ny; ++j)
    for(int i = 0; i < nx; ++i)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

std::optional<TSI::Quad_coarsening> coarsening_of(const Mesh& m)
{
  return TSI::quad_coarsening(m, get(CGAL::face_index, m), get(CGAL::vertex_index, m));
}

// The coarse mesh of `m`, its vertices at their fine points; a test failure if there is none.
Mesh coarse_mesh_of(const Mesh& m, const TSI::Quad_coarsening& coarsening)
{
  Mesh coarse;
  EXPECT_TRUE(TSI::make_coarse_mesh(coarsening, std::vector<Point>(m.points().begin(), m.points().end()), coarse));
  return coarse;
}

} // namespace

TEST(QuadCoarsening, RecoversTheMeshBeforeEachCatmullClarkStep)
{
  // A box subdivided twice: 96 quads and 98 vertices; once: 24 quads and
  // 8 + 12 + 6 = 26 vertices (corners, edges, faces); the box: 6 and 8.
  const Mesh fine = subdivided_box(2);
  ASSERT_EQ(fine.number_of_faces(), 96u);
  const std::optional<TSI::Quad_coarsening> once = coarsening_of(fine);
  ASSERT_TRUE(once);
  EXPECT_EQ(once->number_of_coarse_faces(), 24u);
  EXPECT_EQ(once->number_of_coarse_vertices(), 26u);
  const Mesh coarse = coarse_mesh_of(fine, *once);
  EXPECT_TRUE(CGAL::is_closed(coarse));
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(coarse));
  // Every coarse quad holds 4 fine quads, one at each of its corners.
  std::vector<std::set<int> > corners(24);
  for(std::size_t f = 0; f < 96; ++f)
    corners[once->coarse_face[f]].insert(once->coarse_corner[f]);
  for(const std::set<int>& c : corners)
    EXPECT_EQ(c, (std::set<int>{0, 1, 2, 3}));

  const std::optional<TSI::Quad_coarsening> twice = coarsening_of(coarse);
  ASSERT_TRUE(twice);
  EXPECT_EQ(twice->number_of_coarse_faces(), 6u);
  EXPECT_EQ(twice->number_of_coarse_vertices(), 8u);
  // The box itself has only valence-3 vertices: no refinement.
  EXPECT_FALSE(coarsening_of(subdivided_box(0)));
}

TEST(QuadCoarsening, GridsAndToriOfEvenSizesOnly)
{
  // A 4 x 4 grid is the 2 x 2 grid refined (9 vertices); in a 3 x 3 grid
  // two border corners (valence 2, coarse) are 3 edges apart.
  const std::optional<TSI::Quad_coarsening> even = coarsening_of(grid<Mesh>(4, 4));
  ASSERT_TRUE(even);
  EXPECT_EQ(even->number_of_coarse_faces(), 4u);
  EXPECT_EQ(even->number_of_coarse_vertices(), 9u);
  EXPECT_FALSE(coarsening_of(grid<Mesh>(3, 3)));
  EXPECT_FALSE(coarsening_of(grid<Mesh>(4, 3)));
  // A torus has no vertex that must be coarse: the corners of its first
  // quad are tried in turn. 4 x 6 -> 2 x 3; 3 x 4 has no 2 x 2 structure.
  const std::optional<TSI::Quad_coarsening> torus = coarsening_of(torus_grid(4, 6));
  ASSERT_TRUE(torus);
  EXPECT_EQ(torus->number_of_coarse_faces(), 6u);
  EXPECT_EQ(torus->number_of_coarse_vertices(), 6u);
  EXPECT_FALSE(coarsening_of(torus_grid(3, 4)));
  // Triangles: refused.
  Mesh tetrahedron;
  CGAL::make_tetrahedron(Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), tetrahedron);
  EXPECT_FALSE(coarsening_of(tetrahedron));
}

TEST(QuadCoarsening, AnExactCoarseResultProlongatesToAnExactFineOne)
{
  // The box subdivided twice, coarsened, and the coarse mesh made tilable by
  // the pipeline; prolongated, each coarse cluster gives four fine ones,
  // congruent by an Umeyama fit written in the test.
  Mesh fine = subdivided_box(2);
  const std::optional<TSI::Quad_coarsening> coarsening = coarsening_of(fine);
  ASSERT_TRUE(coarsening);
  Mesh coarse = coarse_mesh_of(fine, *coarsening);
  auto cluster = coarse.add_property_map<Mesh::Face_index, int>("f:cluster", 0).first;
  auto orientation = coarse.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
  const std::size_t k = 6;
  // Mirrored molds: the box's mirror symmetries turn panels over, so both
  // directions of the correspondences are prolongated.
  TS::make_k_set_tilable(coarse, TSP::number_of_tiles(k)
                                   .orientation_policy(TS::ALLOW_MIRRORED_PANELS)
                                   .face_cluster_map(cluster)
                                   .face_orientation_map(orientation));
  // Without an exact coarse result, or without both directions, the test would prove little.
  const double coarse_error = congruence_by_umeyama(coarse, cluster, orientation, true);
  ASSERT_LE(coarse_error, 1e-6);
  std::set<bool> reversed;
  for(auto f : faces(coarse))
    reversed.insert(TS::Panel_orientation(orientation[f]).is_reversed());
  ASSERT_EQ(reversed.size(), 2u);

  TSI::Face_clustering coarse_clustering{std::vector<std::size_t>(coarse.number_of_faces()),
                                         std::vector<TS::Panel_orientation>(coarse.number_of_faces()), k};
  for(auto f : faces(coarse))
  {
    coarse_clustering.label[f.idx()] = std::size_t(cluster[f]);
    coarse_clustering.orientation[f.idx()] = TS::Panel_orientation(orientation[f]);
  }
  const std::vector<Point> points =
    TSI::prolongated_points(*coarsening, std::vector<Point>(coarse.points().begin(), coarse.points().end()));
  const TSI::Face_clustering prolongated = TSI::prolongated_clustering(*coarsening, coarse_clustering);
  EXPECT_EQ(prolongated.number_of_clusters, 4 * k);
  auto fine_cluster = fine.add_property_map<Mesh::Face_index, int>("f:cluster", 0).first;
  auto fine_orientation = fine.add_property_map<Mesh::Face_index, int>("f:orientation", 0).first;
  std::set<int> used;
  for(auto f : faces(fine))
  {
    fine_cluster[f] = int(prolongated.label[f.idx()]);
    fine_orientation[f] = prolongated.orientation[f.idx()].index();
    used.insert(fine_cluster[f]);
  }
  EXPECT_EQ(used.size(), 4 * k);
  for(auto v : vertices(fine))
    fine.point(v) = points[v.idx()];
  // A sub-quad's corners are means of its coarse quad's: each deviates at
  // most as far as they do, measured in the fine mesh's mean edge length.
  EXPECT_LE(congruence_by_umeyama(fine, fine_cluster, fine_orientation, true),
            coarse_error * TS::mean_edge_length(coarse) / TS::mean_edge_length(fine) + 1e-12);
  // Corners of the coarse mesh stay where the coarse result put them.
  for(std::size_t c = 0; c < coarsening->number_of_coarse_vertices(); ++c)
    EXPECT_EQ(points[coarsening->fine_vertex[c]], coarse.point(Mesh::Vertex_index(Mesh::size_type(c))));
}

} // namespace test_quad_coarsening_unit
