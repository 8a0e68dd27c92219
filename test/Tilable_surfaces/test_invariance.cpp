// Invariance of the whole pipeline (make_k_set_tilable): a similarity of the
// input (rotation, translation, uniform scale) gives the same clustering and
// the same result up to that similarity; renumbering the vertices gives the
// same result up to the renumbering.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_invariance_unit {

namespace {

struct Tiling
{
  Mesh mesh;                          // the result
  std::vector<int> cluster, orientation;  // per face index
  TS::K_set_tilable_result result;
};

Tiling tile(Mesh mesh, int k)
{
  auto c = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto o = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  Tiling run;
  run.result = TS::make_k_set_tilable(mesh, TSP::number_of_tiles(k).face_cluster_map(c).face_orientation_map(o));
  for(auto f : faces(mesh))
  {
    run.cluster.push_back(c[f]);
    run.orientation.push_back(o[f]);
  }
  run.mesh = mesh;
  return run;
}

double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(m.points().begin(), m.points().end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

Eigen::Vector3d eigen(const Point& p) { return Eigen::Vector3d(p.x(), p.y(), p.z()); }

} // namespace

// Outside the anonymous namespace: the test classes derive from it.
class Invariance : public ::testing::TestWithParam<const char*> {};

TEST_P(Invariance, SimilarityOfTheInputGivesTheSameClusteringAndTheSimilarResult)
{
  const Mesh input = read(GetParam());
  const int k = int(input.number_of_faces()) / 10;
  // A rotation about a skew axis, a scale by 37.5 and a translation.
  const Eigen::Matrix3d rotation =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const double scale = 37.5;
  const Eigen::Vector3d shift(120.25, -3.5, 1e3);
  auto similarity = [&](const Point& p) { return Eigen::Vector3d(scale * (rotation * eigen(p)) + shift); };

  Mesh moved = input;
  for(auto v : vertices(moved))
  {
    const Eigen::Vector3d q = similarity(input.point(v));
    moved.point(v) = Point(q.x(), q.y(), q.z());
  }
  const Tiling a = tile(input, k), b = tile(moved, k);
  EXPECT_EQ(a.cluster, b.cluster);
  EXPECT_EQ(a.orientation, b.orientation);
  EXPECT_EQ(a.result.clustering.degree_of_flexibility, b.result.clustering.degree_of_flexibility);
  EXPECT_EQ(a.result.optimization.iterations, b.result.optimization.iterations);
  const double tolerance = 1e-9 * bbox_diagonal(b.mesh);
  double worst = 0;
  for(auto v : vertices(a.mesh))
    worst = (std::max)(worst, (similarity(a.mesh.point(v)) - eigen(b.mesh.point(v))).norm());
  EXPECT_LE(worst, tolerance) << "relative " << worst / bbox_diagonal(b.mesh);
  // The approximation error is relative to the axis-aligned bounding box
  // (the paper's convention), which a rotation changes; the distances are
  // the same up to the scale.
  const auto& ma = a.result.optimization.measure;
  const auto& mb = b.result.optimization.measure;
  EXPECT_NEAR(scale * ma.max_approximation_error * ma.input_bbox_diagonal,
              mb.max_approximation_error * mb.input_bbox_diagonal, tolerance);
  EXPECT_NEAR(scale * ma.max_displacement, mb.max_displacement, tolerance);
}

// The vertices and the faces renumbered at random, each face starting at the
// same corner (the canonical face order of cluster_panels() starts each face's
// neighbours at halfedge(f)).
TEST_P(Invariance, RenumberingTheVerticesAndFacesGivesTheSameResultRenumbered)
{
  const Mesh input = read(GetParam());
  const int k = int(input.number_of_faces()) / 10;
  std::mt19937 random(11);
  auto shuffled = [&](std::size_t n) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), random);
    return order;
  };
  // New vertex i is old vertex vertex_order[i], new face j is old face face_order[j].
  const std::vector<std::size_t> vertex_order = shuffled(input.number_of_vertices());
  const std::vector<std::size_t> face_order = shuffled(input.number_of_faces());
  Mesh renumbered;
  std::vector<Mesh::Vertex_index> image(input.number_of_vertices());
  for(std::size_t old : vertex_order)
    image[old] = renumbered.add_vertex(input.point(Mesh::Vertex_index(Mesh::size_type(old))));
  for(std::size_t old : face_order)
  {
    std::vector<Mesh::Vertex_index> corners;
    const Mesh::Face_index f{Mesh::size_type(old)};
    for(auto v : CGAL::vertices_around_face(input.halfedge(f), input)) corners.push_back(image[v]);
    ASSERT_NE(renumbered.add_face(corners), Mesh::null_face());
  }
  ASSERT_NE(image[0], Mesh::Vertex_index(0)) << "really renumbered";
  ASSERT_NE(face_order[0], 0u) << "really renumbered";

  const Tiling a = tile(input, k), b = tile(renumbered, k);
  std::vector<int> cluster(face_order.size()), orientation(face_order.size());
  for(std::size_t j = 0; j < face_order.size(); ++j)
  {
    cluster[j] = a.cluster[face_order[j]];
    orientation[j] = a.orientation[face_order[j]];
  }
  EXPECT_EQ(cluster, b.cluster);
  EXPECT_EQ(orientation, b.orientation);
  EXPECT_EQ(a.result.clustering.degree_of_flexibility, b.result.clustering.degree_of_flexibility);
  const double tolerance = 1e-9 * bbox_diagonal(a.mesh);
  double worst = 0;
  for(std::size_t old = 0; old < image.size(); ++old)
    worst = (std::max)(worst, (eigen(a.mesh.point(Mesh::Vertex_index(Mesh::size_type(old)))) -
                               eigen(b.mesh.point(image[old]))).norm());
  EXPECT_LE(worst, tolerance) << "relative " << worst / bbox_diagonal(a.mesh);
}

INSTANTIATE_TEST_SUITE_P(PaperSurfaces, Invariance, ::testing::Values("de_beers_ginza.off"));
// Disabled: on the 3-fold symmetric monkey saddle the start faces of the
// canonical face order tie exactly (the lower index wins), and candidate
// clusterings tie exactly in length spread and predicted displacement, so
// round-off, which a similarity changes, and the face indices decide between
// results of the same quality (user manual, section Invariance). Run with
// --gtest_also_run_disabled_tests.
INSTANTIATE_TEST_SUITE_P(DISABLED_SymmetricSurfaces, Invariance, ::testing::Values("monkey_saddle.off"));

} // namespace test_invariance_unit
