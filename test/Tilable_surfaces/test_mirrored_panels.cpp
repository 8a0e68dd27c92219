// orientation_policy(ALLOW_MIRRORED_PANELS): panels cut from the mirror image
// of a mold count as its instances in the clustering, the optimizer, the
// measure and the catalog.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/measure.h>

#include "congruence_check.h"
#include "hausdorff_oracle.h"

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <numeric>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_mirrored_panels_unit {

namespace {

// Two quads that share the edge x = 0, z = 0, each the mirror image of the
// other in the plane x = 0. The quad is not planar and has no symmetry, so
// it is not congruent to its mirror image by a proper motion.
Mesh mirror_pair()
{
  Mesh m;
  const auto a = m.add_vertex(Point(0, 0, 0)), b = m.add_vertex(Point(0, 1, 0)),
             c = m.add_vertex(Point(1.0, 0.1, 0.3)), d = m.add_vertex(Point(1.2, 1.1, -0.2)),
             e = m.add_vertex(Point(-1.0, 0.1, 0.3)), f = m.add_vertex(Point(-1.2, 1.1, -0.2));
  m.add_face(a, c, d, b);
  m.add_face(a, b, f, e);
  return m;
}

} // namespace

TEST(MirroredPanels, AMirrorPairIsOneMoldAndDoesNotMove)
{
  Mesh mesh = mirror_pair();
  const Mesh input = mesh;
  const TS::Panel q0 = TS::face_panel(*faces(mesh).begin(), mesh), q1 = TS::face_panel(*std::next(faces(mesh).begin()), mesh);
  ASSERT_GT(TS::dissimilarity(q0, q1, TS::PROPER_RIGID_MOTIONS), 1e-2) << "not congruent by a proper motion";
  ASSERT_LT(TS::dissimilarity(q0, q1, TS::ALLOW_MIRRORED_PANELS), 1e-12) << "a mirror image";

  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(1).orientation_policy(TS::ALLOW_MIRRORED_PANELS)
            .face_cluster_map(cluster).face_orientation_map(orientation));
  EXPECT_TRUE(r.is_tilable());
  EXPECT_LT(r.optimization.measure.max_displacement, 1e-9) << "already tilable: nothing moves";
  EXPECT_TRUE(r.optimization.measure.allows_mirrored_panels);
  ASSERT_EQ(r.tiles.size(), 1u);
  EXPECT_EQ(r.tiles[0].instance_count, 2u);
  EXPECT_EQ(r.tiles[0].mirrored_count, 1u) << "one of the two is cut from the mirrored mold";
  EXPECT_LT(congruence_by_umeyama(mesh, cluster, orientation, true), 1e-9);

  // The measure honours the policy it is given.
  const auto maps = TSP::face_cluster_map(cluster).face_orientation_map(orientation);
  EXPECT_LT(TS::measure_tilability(mesh, input, maps.orientation_policy(TS::ALLOW_MIRRORED_PANELS))
              .congruence_error, 1e-12);
  EXPECT_GT(TS::measure_tilability(mesh, input, maps).congruence_error, 1e-2)
    << "not one mold for proper motions";

  // Without the policy, one mold means moving the quads.
  Mesh proper = mirror_pair();
  const TS::K_set_tilable_result rp = TS::make_k_set_tilable(proper, TSP::number_of_tiles(1));
  EXPECT_TRUE(rp.is_tilable());
  EXPECT_GT(rp.optimization.measure.max_displacement, 1e-3);
  EXPECT_EQ(rp.tiles[0].mirrored_count, 0u);
}

// The monkey saddle is symmetric in the plane y = 0: with mirrored molds the
// result at the same K is exactly tilable (up to mirrors, checked by an
// independent fit) and at least as close to the input as with proper motions
// (by the package's measure and by the oracle).
TEST(MirroredPanels, OnAMirrorSymmetricSurfaceAtLeastAsCloseAsProperMotions)
{
  Mesh input;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/monkey_saddle.off", input));
  for(int k : {3, 8})
  {
    Mesh proper = input, mirrored = input;
    auto cluster = mirrored.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
    auto orientation = mirrored.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
    const TS::K_set_tilable_result rp = TS::make_k_set_tilable(proper, TSP::number_of_tiles(k));
    const TS::K_set_tilable_result rm = TS::make_k_set_tilable(
      mirrored, TSP::number_of_tiles(k).orientation_policy(TS::ALLOW_MIRRORED_PANELS)
                  .face_cluster_map(cluster).face_orientation_map(orientation));
    EXPECT_TRUE(rm.is_tilable()) << "K = " << k;
    EXPECT_LE(congruence_by_umeyama(mirrored, cluster, orientation, true), 1e-6) << "K = " << k;
    EXPECT_LE(rm.optimization.measure.hausdorff_distance, rp.optimization.measure.hausdorff_distance)
      << "K = " << k;
    EXPECT_TRUE(hausdorff_oracle::no_farther(mirrored, proper, input)) << "K = " << k;
    std::size_t total = 0;
    for(const TS::Tile& t : rm.tiles)
    {
      EXPECT_LE(t.mirrored_count, t.instance_count);
      total += t.instance_count;
    }
    EXPECT_EQ(total, num_faces(mirrored));
  }
}

} // namespace test_mirrored_panels_unit
