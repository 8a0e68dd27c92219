// Tests of measure_tilability(): exact values on tiny meshes, and agreement
// with an independent rigid-fit check on an optimized surface.

#include "optimization_test_helpers.h"

#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_measure_unit {

using namespace test_helpers;

namespace {

// Two unit squares side by side in the plane z = 0, sharing the edge x = 1.
Mesh two_squares()
{
  Mesh m;
  const Vertex a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(1, 0, 0)),
               c = m.add_vertex(Point(1, 1, 0)), d = m.add_vertex(Point(0, 1, 0)),
               e = m.add_vertex(Point(2, 0, 0)), f = m.add_vertex(Point(2, 1, 0));
  m.add_face(a, b, c, d);
  m.add_face(b, e, f, c);
  return m;
}

Mesh unit_square()
{
  Mesh m;
  m.add_face(m.add_vertex(Point(0, 0, 0)), m.add_vertex(Point(1, 0, 0)),
             m.add_vertex(Point(1, 1, 0)), m.add_vertex(Point(0, 1, 0)));
  return m;
}

} // namespace

TEST(Measure, TwoUnitSquaresAreExactlyTilable)
{
  Mesh mesh = two_squares();
  const Clustering c = single_cluster(mesh);
  const TS::Tilability_measure m = TS::measure_tilability(mesh, mesh, clustering_parameters(c));
  EXPECT_EQ(m.number_of_clusters, 1u);
  EXPECT_EQ(m.degree_of_flexibility, 3u); // template edges 1 and 3 are shared
  EXPECT_EQ(m.cluster_sizes, std::vector<std::size_t>{2});
  EXPECT_EQ(m.congruence_error, 0.0);
  EXPECT_EQ(m.max_approximation_error, 0.0);
  EXPECT_EQ(m.mean_approximation_error, 0.0);
  EXPECT_EQ(m.max_displacement, 0.0);
  EXPECT_DOUBLE_EQ(m.mean_edge_length, 1.0);
  EXPECT_DOUBLE_EQ(m.input_bbox_diagonal, std::sqrt(5.0));
  for(double t : {m.normalized_terms.distance, m.normalized_terms.fairness,
                  m.normalized_terms.edge_length, m.normalized_terms.diagonal,
                  m.normalized_terms.volume})
    EXPECT_EQ(t, 0.0);
  // The S-quad is the unit square, t0 at the origin and t1 on +x.
  const TS::Panel& s = m.s_quads[0];
  const Eigen::Vector3d expected[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for(int i = 0; i < 4; ++i)
    EXPECT_LE((s[i] - expected[i]).norm(), 1e-15) << "corner " << i;
}

TEST(Measure, MovedVertexGivesItsDisplacement)
{
  Mesh input = two_squares();
  Mesh result = input;
  const Clustering c = every_face_alone(result);
  result.point(Vertex(0)) = Point(0, 0, 0.1); // corner of the first square only
  const TS::Tilability_measure m = TS::measure_tilability(result, input, clustering_parameters(c));
  EXPECT_DOUBLE_EQ(m.max_displacement, 0.1);
  EXPECT_DOUBLE_EQ(m.mean_displacement, 0.1 / 6);
  EXPECT_DOUBLE_EQ(m.max_approximation_error, 0.1 / std::sqrt(5.0));
  EXPECT_LE(m.congruence_error, 1e-15); // every face alone: rounding only
  // Scaled into the unit cube by 1/2: F_d = (0.05)^2 over 6 vertices.
  EXPECT_DOUBLE_EQ(m.normalized_terms.distance, 0.0025 / 6);
}

// The four-argument form reads the input through its own maps. The input
// positions kept as a property of the result mesh give the displacements by
// hand of the test above; an input vertex index map that pairs vertex i of
// the result with vertex 5 - i of the input gives the distances to those,
// computed here.
TEST(Measure, TheInputsOwnMapsPairTheVertices)
{
  Mesh result = two_squares();
  const Clustering c = every_face_alone(result);
  auto kept = result.add_property_map<Vertex, Point>("v:input").first;
  for(Vertex v : vertices(result)) kept[v] = result.point(v);
  result.point(Vertex(0)) = Point(0, 0, 0.1);
  const TS::Tilability_measure own =
    TS::measure_tilability(result, result, clustering_parameters(c), TS::parameters::vertex_point_map(kept));
  EXPECT_DOUBLE_EQ(own.max_displacement, 0.1);
  EXPECT_DOUBLE_EQ(own.mean_displacement, 0.1 / 6);
  EXPECT_DOUBLE_EQ(own.max_approximation_error, 0.1 / std::sqrt(5.0));

  Mesh input = two_squares();
  const std::size_t n = input.number_of_vertices();
  auto reversed = input.add_property_map<Vertex, std::size_t>("v:reversed").first;
  for(Vertex v : vertices(input)) reversed[v] = n - 1 - std::size_t(v);
  const TS::Tilability_measure paired =
    TS::measure_tilability(result, input, clustering_parameters(c), TS::parameters::vertex_index_map(reversed));
  double largest = 0, sum = 0;
  for(Vertex v : vertices(result))
  {
    const double d = std::sqrt(CGAL::squared_distance(result.point(v), input.point(Vertex(n - 1 - std::size_t(v)))));
    largest = (std::max)(largest, d);
    sum += d;
  }
  EXPECT_DOUBLE_EQ(paired.max_displacement, largest);
  EXPECT_DOUBLE_EQ(paired.mean_displacement, sum / double(n));
  EXPECT_GT(largest, 1.0) << "the pairing is not the identity";
}

TEST(Measure, QuadTranslatedOffThePlane)
{
  Mesh input = unit_square();
  Mesh result = input;
  const Clustering c = every_face_alone(result);
  const double d = 0.25;
  for(Vertex v : vertices(result))
    result.point(v) = result.point(v) + Kernel::Vector_3(0, 0, d);
  const TS::Tilability_measure m = TS::measure_tilability(result, input, clustering_parameters(c));
  EXPECT_DOUBLE_EQ(m.max_approximation_error, d / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.mean_approximation_error, d / std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(m.max_displacement, d);
  EXPECT_LE(m.congruence_error, 1e-15);
}

TEST(Measure, DistancesAreToTheNearestPointNotTheCorrespondingOne)
{
  // The result slid by half a square along the strip and lifted by 0.1: a
  // sample's corresponding point of the input is at distance sqrt(0.26),
  // the input itself at 0.1 below it, except past the input's end x = 2.
  Mesh input = two_squares();
  Mesh result = input;
  const Clustering c = every_face_alone(result);
  for(Vertex v : vertices(result))
    result.point(v) = result.point(v) + Kernel::Vector_3(0.5, 0, 0.1);
  const TS::Tilability_measure m = TS::measure_tilability(result, input, clustering_parameters(c));
  // The 24 samples of the result (6 vertices; per square its centre, 4 edge
  // midpoints, 4 fan-triangle centroids): past x = 2 lie the 2 vertices and
  // the edge midpoint at x = 2.5, and one fan centroid at x = 7/3; the
  // other 20 are above the input. By symmetry the input's samples are as
  // far from the result.
  const double far = std::sqrt(0.26), centroid = std::sqrt(1.0 / 9 + 0.01);
  const double diagonal = std::sqrt(5.0), mean = (3 * far + centroid + 20 * 0.1) / 24;
  EXPECT_DOUBLE_EQ(m.max_approximation_error, far / diagonal);
  EXPECT_DOUBLE_EQ(m.mean_approximation_error, mean / diagonal);
  EXPECT_DOUBLE_EQ(m.max_coverage_error, far / diagonal);
  EXPECT_DOUBLE_EQ(m.mean_coverage_error, mean / diagonal);
}

TEST(Measure, CongruenceErrorAgreesWithPairwiseFits)
{
  // Non-congruent instances: the monkey saddle in one cluster. The package's
  // error (against the Procrustes mean) is between half the pairwise error
  // and the pairwise error (triangle inequality).
  Mesh mesh = load("monkey_saddle.off");
  const Clustering c = single_cluster(mesh);
  const TS::Tilability_measure m = TS::measure_tilability(mesh, mesh, clustering_parameters(c));
  const double pairwise = pairwise_congruence_error(mesh, c);
  EXPECT_GT(m.congruence_error, 0.0);
  EXPECT_LE(m.congruence_error, pairwise * (1 + 1e-12));
  EXPECT_GE(m.congruence_error, 0.5 * pairwise / 2); // vs the first instance, not the worst pair
  EXPECT_EQ(m.cluster_congruence_errors.size(), 1u);
  EXPECT_EQ(m.max_displacement, 0.0);
  EXPECT_LE(m.max_approximation_error, 1e-15); // a surface against itself
}

TEST(Measure, OptimizedSurfaceMeasuredTwiceAgrees)
{
  Mesh input = load("monkey_saddle.off");
  Mesh result = input;
  const Clustering c = single_cluster(result);
  const TS::Optimization_result r = TS::optimize_tilable_surface(result, clustering_parameters(c));
  const TS::Tilability_measure m = TS::measure_tilability(result, input, clustering_parameters(c));
  EXPECT_NEAR(m.congruence_error, r.measure.congruence_error, 1e-12);
  EXPECT_NEAR(m.max_approximation_error, r.measure.max_approximation_error, 1e-12);
  EXPECT_NEAR(m.max_displacement, r.measure.max_displacement, 1e-12);
  EXPECT_LE(pairwise_congruence_error(result, c), 2 * m.congruence_error + 1e-12);
  // Canonical frame of the S-quad.
  const TS::Panel& s = m.s_quads[0];
  EXPECT_LE(s[0].norm(), 1e-12);
  EXPECT_GT(s[1].x(), 0.0);
  EXPECT_LE(std::abs(s[1].y()) + std::abs(s[1].z()) + std::abs(s[2].z()), 1e-12);
  EXPECT_GE(s[2].y(), 0.0);
  EXPECT_EQ(m.degree_of_flexibility, 1u);
}

// A strip of three unit squares along x; the result stands the middle one up
// (x = 2 lifted to (1, y, 1)) and swings the last one back to x = 0.5, at
// height `end_height`. At -1 the last square crosses the plane z = 0 at
// x = 0.75, inside the first square: exactly one pair of panels crosses. At
// 0.5 it stays above that plane: none, although it folds back as far.
std::size_t crossing_pairs_of_folded_strip(double end_height)
{
  Mesh input;
  std::vector<Vertex> v;
  for(int x = 0; x <= 3; ++x)
    for(int y = 0; y <= 1; ++y)
      v.push_back(input.add_vertex(Point(x, y, 0)));
  for(int x = 0; x < 3; ++x)
    input.add_face(v[2 * x], v[2 * x + 2], v[2 * x + 3], v[2 * x + 1]);
  Mesh result = input;
  for(int y = 0; y <= 1; ++y)
  {
    result.point(v[4 + y]) = Point(1, y, 1);
    result.point(v[6 + y]) = Point(0.5, y, end_height);
  }
  const Clustering c = every_face_alone(result);
  EXPECT_EQ(TS::measure_tilability(input, input, clustering_parameters(c)).self_intersecting_face_pairs, 0u);
  return TS::measure_tilability(result, input, clustering_parameters(c)).self_intersecting_face_pairs;
}

TEST(Measure, PanelsCrossingEachOtherAreCounted)
{
  EXPECT_EQ(crossing_pairs_of_folded_strip(-1.0), 1u);
  EXPECT_EQ(crossing_pairs_of_folded_strip(0.5), 0u);
}

TEST(Measure, MismatchedMeshesThrow)
{
  Mesh a = two_squares();
  Mesh b = unit_square();
  const Clustering c = every_face_alone(a);
  EXPECT_THROW(TS::measure_tilability(a, b, clustering_parameters(c)), TS::Invalid_input);
}

namespace {

// Two separate quads: `q` and `r`, each its own cluster.
Mesh two_quads(const std::array<Point, 4>& q, const std::array<Point, 4>& r)
{
  Mesh m;
  for(const auto* corners : {&q, &r})
    m.add_face(m.add_vertex((*corners)[0]), m.add_vertex((*corners)[1]), m.add_vertex((*corners)[2]),
               m.add_vertex((*corners)[3]));
  return m;
}

} // namespace

// Clusters whose S-quads are congruent need one mold between them. By hand:
// two unit squares, each its own cluster, are one mold; a unit square and a
// 1 x 2 rectangle two. A generic non-planar quad and its mirror image (x ->
// 6 - x, same labelling) are two molds under proper motions, one when
// mirrored panels are allowed. A corner moved by 1e-4 of the edge length
// makes a second mold, by 1e-9 not (the tolerance is 1e-6).
TEST(Measure, CongruentSQuadsAreOneMold)
{
  auto molds = [](Mesh mesh, TS::Orientation_policy policy) {
    const Clustering c = every_face_alone(mesh);
    const TS::Tilability_measure m =
      TS::measure_tilability(mesh, mesh, clustering_parameters(c).orientation_policy(policy));
    EXPECT_EQ(m.number_of_clusters, 2u);
    // The first cluster makes mold 0; the second shares it or makes mold 1.
    EXPECT_EQ(m.cluster_molds, (std::vector<std::size_t>{0, m.number_of_distinct_molds - 1}));
    const std::vector<TS::Tile> catalog = TS::tile_catalog(m);
    EXPECT_EQ(catalog[1].mold, m.cluster_molds[1]);
    return m.number_of_distinct_molds;
  };
  const TS::Orientation_policy proper = TS::PROPER_RIGID_MOTIONS;
  EXPECT_EQ(molds(two_squares(), proper), 1u);
  Mesh rectangle = two_squares();
  for(auto v : vertices(rectangle))
    if(rectangle.point(v).x() == 2)
      rectangle.point(v) = Point(3, rectangle.point(v).y(), 0);
  EXPECT_EQ(molds(rectangle, proper), 2u);

  const std::array<Point, 4> q = {Point(0, 0, 0), Point(1.2, 0, 0), Point(1, 1, 0.3), Point(0, 0.8, 0.1)};
  std::array<Point, 4> mirror;
  for(int i = 0; i < 4; ++i) mirror[i] = Point(6 - q[i].x(), q[i].y(), q[i].z());
  EXPECT_EQ(molds(two_quads(q, mirror), proper), 2u);
  EXPECT_EQ(molds(two_quads(q, mirror), TS::ALLOW_MIRRORED_PANELS), 1u);

  for(double shift : {1e-4, 1e-9})
  {
    std::array<Point, 4> moved = q;
    for(Point& p : moved) p = Point(p.x() + 5, p.y() - 2, p.z() + 1); // a translate of q
    moved[2] = Point(moved[2].x() + shift, moved[2].y(), moved[2].z());
    EXPECT_EQ(molds(two_quads(q, moved), proper), shift > 1e-6 ? 2u : 1u) << "corner moved by " << shift;
  }
}

// By hand: the first of two unit squares with its corner (0, 1) lifted by
// 0.2 has det[b - a, c - a, d - a] = 0.2 over a mean edge of
// (3 + sqrt(1.04)) / 4, a relative twist of about 0.197; the same mesh with
// that corner back at z = 0 has both squares planar. Measured against the
// lifted input, the planar result flattened one quad of two (the second
// square is planar in both, so it does not count), which is at least a tenth
// of the faces: the only warning. The lifted mesh measured against itself
// flattened none.
TEST(Measure, FlattenedPanelsAreCountedAndWarnedAbout)
{
  Mesh flat = two_squares();
  // The two squares with the corner (0, 1, 0) lifted by `lift`.
  const auto lifted_by = [&flat](double lift) {
    Mesh m = flat;
    for(auto v : vertices(m))
      if(m.point(v) == Point(0, 1, 0))
        m.point(v) = Point(0, 1, lift);
    return m;
  };
  Mesh lifted = lifted_by(0.2);
  const Clustering c = single_cluster(flat);
  const TS::Tilability_measure m = TS::measure_tilability(flat, lifted, clustering_parameters(c));
  EXPECT_EQ(m.flattened_panels, 1u);
  const std::vector<std::string> warnings = TS::buildability_warnings(m);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("1 of 2 panels were flattened"), std::string::npos) << warnings[0];

  const Clustering own = single_cluster(lifted);
  EXPECT_EQ(TS::measure_tilability(lifted, lifted, clustering_parameters(own)).flattened_panels, 0u);

  // A corner lifted by 0.03 (relative twist about 0.03, the mean edge within
  // 1e-4 of 1) is below the input twist that counts, 0.05; one lifted by 0.06 is not.
  for(const double lift : {0.03, 0.06})
    EXPECT_EQ(TS::measure_tilability(flat, lifted_by(lift), clustering_parameters(c)).flattened_panels,
              lift > 0.05 ? 1u : 0u) << "corner lifted by " << lift;
}

// Three unit squares in a row, each its own cluster: K = 3 and one distinct
// mold, fewer than half of K, which is warned about; two squares in two
// clusters (one mold of K = 2, half of K) are not.
TEST(Measure, FewerMoldsThanHalfOfKAreWarnedAbout)
{
  Mesh three = two_squares();
  const Vertex g = three.add_vertex(Point(3, 0, 0)), h = three.add_vertex(Point(3, 1, 0));
  Vertex e, f;
  for(auto v : vertices(three))
  {
    if(three.point(v) == Point(2, 0, 0)) e = v;
    if(three.point(v) == Point(2, 1, 0)) f = v;
  }
  three.add_face(e, g, h, f);
  const Clustering c = every_face_alone(three);
  const TS::Tilability_measure m = TS::measure_tilability(three, three, clustering_parameters(c));
  ASSERT_EQ(m.number_of_clusters, 3u);
  ASSERT_EQ(m.number_of_distinct_molds, 1u);
  const std::vector<std::string> warnings = TS::buildability_warnings(m);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("only 1 distinct molds for K = 3"), std::string::npos) << warnings[0];

  Mesh two = two_squares();
  const Clustering alone = every_face_alone(two);
  EXPECT_TRUE(TS::buildability_warnings(TS::measure_tilability(two, two, clustering_parameters(alone))).empty());
}

} // namespace test_measure_unit
