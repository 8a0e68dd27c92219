// The one-call function and the step-by-step class.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>
#include <CGAL/subdivision_method_3.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "congruence_check.h"
#include "hausdorff_oracle.h"

#include "grid_mesh.h"
#include "test_mesh.h"
#include "tube_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/task_arena.h>
#endif

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_make_k_set_tilable_unit {

namespace {

std::vector<Mesh::Point> points(const Mesh& m)
{
  return std::vector<Mesh::Point>(m.points().begin(), m.points().end());
}

} // namespace

TEST(MakeKSetTilable, OneTilePerFaceDoesNotMoveTheMesh)
{
  Mesh mesh = read("de_beers_ginza.off");
  const auto before = points(mesh);
  const TS::K_set_tilable_result r =
    TS::make_k_set_tilable(mesh, TSP::number_of_tiles(int(mesh.number_of_faces())));
  EXPECT_EQ(points(mesh), before) << "bit-identical";
  EXPECT_TRUE(r.is_tilable());
  EXPECT_LT(r.optimization.measure.congruence_error, 1e-13) << "round-off of the rigid fits only";
  EXPECT_EQ(r.tiles.size(), mesh.number_of_faces());
}

TEST(MakeKSetTilable, FillsTheMapsAndTheResultIsCongruentByAnIndependentFit)
{
  Mesh mesh = read("de_beers_ginza.off");
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, unsigned char>("f:o", 99).first;
  const int k = 48;
  const auto start = std::chrono::steady_clock::now();
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::set<int> ids;
  std::size_t instances = 0;
  for(auto f : faces(mesh))
  {
    ids.insert(cluster[f]);
    EXPECT_LE(int(orientation[f]), 7);
  }
  EXPECT_EQ(ids.size(), std::size_t(k));
  EXPECT_EQ(*ids.begin(), 0);
  EXPECT_EQ(*ids.rbegin(), k - 1);
  ASSERT_EQ(r.tiles.size(), std::size_t(k));
  for(const auto& t : r.tiles) instances += t.instance_count;
  EXPECT_EQ(instances, mesh.number_of_faces());

  ASSERT_TRUE(r.is_tilable()) << r.optimization.measure.congruence_error;
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 2e-6);
  // The times are parts of the call's duration, measured here around it.
  EXPECT_GT(r.clustering_time, 0.0);
  EXPECT_GE(r.total_time, r.clustering_time);
  EXPECT_LE(r.total_time, wall);
}

// congruence_tolerance defines "tilable": 6-sub-lifted at K = 7 ends near
// 6.7e-6 of the mean edge at the default 1e-6, not tilable (test_cli); at
// the fabrication grade 1e-4 it is tilable with an error above 1e-6, its
// panels fitting their molds within the tolerance by an independent fit.
TEST(MakeKSetTilable, CongruenceToleranceDefinesTilable)
{
  Mesh mesh = read("6-sub-lifted.obj");
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(7).congruence_tolerance(1e-4).face_cluster_map(cluster)
            .face_orientation_map(orientation));
  EXPECT_TRUE(r.is_tilable());
  EXPECT_LE(r.optimization.measure.congruence_error, 1e-4);
  EXPECT_GT(r.optimization.measure.congruence_error, 1e-6) << "tilable by the looser tolerance only";
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 2e-4)
    << "twice the tolerance: each panel against its cluster's first";
}

// vertex_point_map: the pipeline reads and writes the points of the map
// given and leaves the mesh's own points (here an affine image of the
// input, moved far away) alone; its result is the one of a plain copy of the input, bit for bit,
// congruent by the test's own fit.
TEST(MakeKSetTilable, ReadsAndWritesThePointsOfTheVertexPointMapGiven)
{
  Mesh plain = grid<Mesh>(4, 3, 0.5, 0.5);
  for(auto v : vertices(plain))
  {
    const double x = plain.point(v).x() - 1, y = plain.point(v).y() - 0.75;
    plain.point(v) = Point(x, y, 0.4 * x * y + 0.1 * x * x * x);
  }
  Mesh mesh = plain;
  auto design = mesh.add_property_map<Mesh::Vertex_index, Point>("v:design").first;
  for(auto v : vertices(mesh))
  {
    design[v] = mesh.point(v);
    const Point& p = mesh.point(v);
    mesh.point(v) = Point(100 - 3 * p.x(), 2 * p.y(), -p.z());  // not similar to the design
  }
  const auto own = points(mesh);
  auto cluster = plain.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = plain.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  ASSERT_TRUE(TS::make_k_set_tilable(plain, TSP::number_of_tiles(4).face_cluster_map(cluster)
                                              .face_orientation_map(orientation)).is_tilable());
  ASSERT_TRUE(TS::make_k_set_tilable(mesh, TSP::number_of_tiles(4).vertex_point_map(design)).is_tilable());
  EXPECT_EQ(points(mesh), own);
  for(auto v : vertices(mesh)) EXPECT_EQ(design[v], plain.point(v)) << v;
  EXPECT_LE(congruence_by_umeyama(plain, cluster, orientation), 2e-6);
}

TEST(MakeKSetTilable, ErrorsLeaveTheMeshAndTheMapsUntouched)
{
  Mesh mesh = read("monkey_saddle.off");
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -7).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -7).first;
  const auto before = points(mesh);
  for(int k : {0, 101})
    EXPECT_THROW(TS::make_k_set_tilable(mesh, TSP::number_of_tiles(k)
                                                .face_cluster_map(cluster)
                                                .face_orientation_map(orientation)),
                 TS::Invalid_input) << k;
  EXPECT_THROW(TS::make_k_set_tilable(mesh, TSP::number_of_tiles(3)
                                              .face_cluster_map(cluster)
                                              .distance_weight(-1.0)),
               TS::Invalid_input);
  EXPECT_EQ(points(mesh), before);
  for(auto f : faces(mesh))
  {
    EXPECT_EQ(cluster[f], -7);
    EXPECT_EQ(orientation[f], -7);
  }
}

TEST(KSetTilableSurface, EditingReportsTheDegreeOfFlexibilityOfTheEditedClustering)
{
  Mesh mesh = read("de_beers_ginza.off");
  TS::K_set_tilable_surface surface(mesh);
  EXPECT_THROW(surface.optimize(), TS::Invalid_input) << "no clustering yet";
  const TS::Clustering_result& c = surface.cluster(TSP::number_of_tiles(30));
  EXPECT_EQ(surface.number_of_clusters(), 30u);
  EXPECT_EQ(surface.degree_of_flexibility(), c.degree_of_flexibility);

  const std::size_t merged = surface.merge_clusters(0, 1);
  EXPECT_EQ(surface.number_of_clusters(), 29u);
  EXPECT_EQ(merged, surface.degree_of_flexibility());
  const std::size_t split = surface.split_cluster(0);
  EXPECT_EQ(surface.number_of_clusters(), 30u);
  EXPECT_EQ(split, surface.degree_of_flexibility());
  EXPECT_EQ(surface.retag_orientations(), surface.degree_of_flexibility());
  std::set<int> ids;
  for(auto f : faces(mesh)) ids.insert(get(surface.face_cluster_map(), f));
  EXPECT_EQ(ids.size(), 30u);

  const TS::Optimization_result& o = surface.optimize();
  // optimize() measures against the positions it started from, which are the
  // input here: a fresh measurement against the kept input agrees.
  const TS::Tilability_measure m = surface.measure();
  EXPECT_NEAR(m.congruence_error, o.measure.congruence_error, 1e-12);
  EXPECT_NEAR(m.max_displacement, o.measure.max_displacement, 1e-12);
  EXPECT_NEAR(m.max_approximation_error, o.measure.max_approximation_error, 1e-12);
  EXPECT_LE(congruence_by_umeyama(mesh, surface.face_cluster_map(), surface.face_orientation_map()),
            2 * m.congruence_error + 1e-12);
}

// refine_to() splits an exact result's clusters and solves from there, every
// face keeping its orientation: the split clustering is exact where the
// result is, so the refined result is exact by an independent fit and no
// farther from the input (the split clustering solved from the input alone
// ends at 34% of the diagonal here). Bad K leave the object as it was.
TEST(KSetTilableSurface, RefiningAnExactResultKeepsItExactAndNoFarther)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> surface(mesh);
  EXPECT_THROW(surface.refine_to(14), TS::Invalid_input) << "no clustering yet";
  const Mesh input = mesh;
  surface.cluster(TSP::number_of_tiles(13));
  ASSERT_TRUE(surface.optimize_closest().converged);
  const double closest = surface.measure().hausdorff_distance;
  const Mesh at_13 = mesh;

  const TS::Optimization_result& refined = surface.refine_to(14);
  EXPECT_EQ(surface.number_of_clusters(), 14u);
  EXPECT_TRUE(refined.converged);
  const TS::Tilability_measure m = surface.measure();
  EXPECT_LE(m.hausdorff_distance, closest + 1e-12);
  EXPECT_TRUE(hausdorff_oracle::no_farther(mesh, at_13, input));
  EXPECT_EQ(m.self_intersecting_face_pairs, 0u);
  EXPECT_LE(congruence_by_umeyama(mesh, surface.face_cluster_map(), surface.face_orientation_map()), 1e-6);
  std::set<int> ids;
  for(auto f : faces(mesh)) ids.insert(int(get(surface.face_cluster_map(), f)));
  EXPECT_EQ(ids.size(), 14u);

  const auto before = points(mesh);
  EXPECT_THROW(surface.refine_to(13), TS::Invalid_input) << "fewer clusters than now";
  EXPECT_THROW(surface.refine_to(mesh.number_of_faces() + 1), TS::Invalid_input);
  EXPECT_EQ(surface.number_of_clusters(), 14u);
  EXPECT_EQ(points(mesh), before);
}

// refine_to() also solves the split clustering from the input with the
// orientations the splits chose, and keeps the better: the result is no
// farther than that solve, made here on a second object by the public
// split_cluster() (the largest cluster, the first such, default seed) and
// optimize(). On De Beers 28 -> 30 that solve ends closer than the one from
// the refined result with the orientations kept.
TEST(KSetTilableSurface, RefiningIsNoFartherThanTheSplitClusteringSolvedFromTheInput)
{
  Mesh mesh = read("de_beers_ginza.off");
  const Mesh original = mesh;
  Mesh input = mesh;  // solved by the second object
  TS::K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> surface(mesh);
  surface.cluster(TSP::number_of_tiles(28));
  ASSERT_TRUE(surface.optimize_closest().converged);
  const double refined_from = surface.measure().hausdorff_distance;
  const Mesh at_28 = mesh;

  std::map<Mesh::Face_index, int> cluster, orientation;
  for(auto f : faces(mesh))
  {
    cluster[f] = int(get(surface.face_cluster_map(), f));
    orientation[f] = int(get(surface.face_orientation_map(), f));
  }
  TS::K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> split(input);
  split.set_clustering(boost::make_assoc_property_map(cluster), boost::make_assoc_property_map(orientation),
                       surface.orientation_policy());
  while(split.number_of_clusters() < 30)
  {
    std::vector<int> size(split.number_of_clusters(), 0);
    for(auto f : faces(input)) ++size[std::size_t(get(split.face_cluster_map(), f))];
    split.split_cluster(std::size_t(std::max_element(size.begin(), size.end()) - size.begin()));
  }
  ASSERT_TRUE(split.optimize().converged);
  const TS::Tilability_measure from_input = split.measure();
  ASSERT_EQ(from_input.self_intersecting_face_pairs, 0u);

  ASSERT_TRUE(surface.refine_to(30).converged);
  const TS::Tilability_measure m = surface.measure();
  EXPECT_EQ(m.self_intersecting_face_pairs, 0u);
  EXPECT_LE(m.hausdorff_distance, refined_from + 1e-12);
  EXPECT_LE(m.hausdorff_distance, from_input.hausdorff_distance + 1e-12);
  EXPECT_TRUE(hausdorff_oracle::no_farther(mesh, at_28, original));
  EXPECT_TRUE(hausdorff_oracle::no_farther(mesh, input, original));
  EXPECT_LE(congruence_by_umeyama(mesh, surface.face_cluster_map(), surface.face_orientation_map()), 1e-6);
}

// use_candidate(i) makes candidate i of the pool of the last cluster() the
// clustering in the maps: the same partition of the faces, K clusters, the
// pool kept, the DOF returned the object's; its orientations are those of
// its S-quads, so that a solve ends congruent by the test's own fit.
TEST(KSetTilableSurface, UseCandidateMakesThatCandidateTheClustering)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  const TS::Clustering_result& c = surface.cluster(TSP::number_of_tiles(6));
  const std::vector<TS::Clustering_candidate> pool = c.candidates;
  const std::vector<std::size_t>& chosen = pool[c.chosen_candidate].face_cluster;
  const auto other = std::find_if(pool.begin(), pool.end(),
                                  [&](const TS::Clustering_candidate& p) { return p.face_cluster != chosen; });
  ASSERT_NE(other, pool.end()) << "the fixture's pool holds another labelling than the chosen one";
  const std::size_t dof = surface.use_candidate(std::size_t(other - pool.begin()));
  EXPECT_EQ(dof, surface.degree_of_flexibility());
  EXPECT_EQ(surface.number_of_clusters(), 6u);
  EXPECT_EQ(surface.clustering().candidates.size(), pool.size());
  std::map<std::size_t, int> id_of;  // the candidate's label -> the map's id, one to one
  std::set<int> ids;
  for(auto f : faces(mesh))
  {
    const int id = int(get(surface.face_cluster_map(), f));
    EXPECT_EQ(id_of.emplace(other->face_cluster[std::size_t(f)], id).first->second, id) << f;
    ids.insert(id);
  }
  EXPECT_EQ(ids.size(), id_of.size());
  EXPECT_EQ(ids.size(), 6u);
  ASSERT_TRUE(surface.optimize().converged);
  EXPECT_LE(congruence_by_umeyama(mesh, surface.face_cluster_map(), surface.face_orientation_map()), 2e-6);
}

// predict_displacement() predicts the first step of the object's solve
// from the input (as the free function does for its solve: two squares in
// one cluster, one corner off): the largest move of one iteration of
// optimize(). After a full solve moved the mesh it predicts the same,
// and restore_input() gives back the input points bit for bit.
TEST(KSetTilableSurface, PredictionAndRestoreStartFromTheInput)
{
  Mesh mesh = grid<Mesh>(2, 1, 1.0, 1.0);
  mesh.point(Mesh::Vertex_index(5)) = Point(2.0, 1.03, 0.01);
  const Mesh input = mesh;
  TS::K_set_tilable_surface surface(mesh);
  std::map<Mesh::Face_index, int> one, orientation;
  for(auto f : faces(mesh)) { one[f] = 0; orientation[f] = 0; }
  surface.set_clustering(boost::make_assoc_property_map(one), boost::make_assoc_property_map(orientation));
  const TS::Displacement_prediction predicted = surface.predict_displacement();
  ASSERT_GT(predicted.max_euclidean, 1e-4);
  const CGAL::Bbox_3 box = CGAL::bbox_3(input.points().begin(), input.points().end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));
  double moved = 0;
  ASSERT_EQ(surface.optimize(TSP::number_of_iterations(1)).iterations, 1);
  for(auto v : vertices(mesh)) moved = (std::max)(moved, std::sqrt(CGAL::squared_distance(mesh.point(v), input.point(v))));
  EXPECT_NEAR(moved / diagonal, predicted.max_euclidean, 1e-9 * predicted.max_euclidean);

  ASSERT_TRUE(surface.optimize().converged);
  ASSERT_NE(points(mesh), points(input)) << "the solve moved the mesh";
  EXPECT_EQ(surface.predict_displacement().max_euclidean, predicted.max_euclidean);
  ASSERT_TRUE(surface.optimize().converged);
  surface.restore_input();
  EXPECT_EQ(points(mesh), points(input));
  EXPECT_EQ(surface.measure().max_displacement, 0.0);
}

// tile_catalog(): one tile per cluster, with the instance count counted
// here, and every instance within the tile's worst deviation (at most the
// tolerance) of its corners after a rigid fit computed here (Eigen::umeyama).
TEST(KSetTilableSurface, TileCatalogFitsEveryInstance)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  surface.cluster(TSP::number_of_tiles(6));
  ASSERT_TRUE(surface.optimize().converged);
  const std::vector<TS::Tile> tiles = surface.tile_catalog();
  ASSERT_EQ(tiles.size(), 6u);
  const double length = TS::mean_edge_length(mesh);
  std::vector<std::size_t> instances(tiles.size(), 0);
  for(auto f : faces(mesh))
  {
    const std::size_t c = std::size_t(get(surface.face_cluster_map(), f));
    ++instances[c];
    const TS::Panel q = TS::face_panel(f, mesh, TS::Panel_orientation(int(get(surface.face_orientation_map(), f))));
    Eigen::Matrix<double, 3, 4> mold, panel;
    for(int i = 0; i < 4; ++i) { mold.col(i) = tiles[c].corners[i]; panel.col(i) = q[i]; }
    const Eigen::Matrix4d T = Eigen::umeyama(mold, panel, false);
    const Eigen::Matrix<double, 3, 4> fitted = (T.topLeftCorner<3, 3>() * mold).colwise() + T.topRightCorner<3, 1>();
    EXPECT_LE((fitted - panel).colwise().norm().maxCoeff(), tiles[c].worst_deviation + 1e-9 * length) << f;
  }
  for(std::size_t c = 0; c < tiles.size(); ++c)
  {
    EXPECT_EQ(tiles[c].id, c);
    EXPECT_EQ(tiles[c].instance_count, instances[c]);
    EXPECT_LE(tiles[c].worst_deviation, 1e-6 * length);
  }
}

// orientation_policy() is the policy of the clustering now: cluster()'s
// named parameter, then set_clustering()'s argument.
TEST(KSetTilableSurface, OrientationPolicyIsTheCurrentClusterings)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  surface.cluster(TSP::number_of_tiles(4).orientation_policy(TS::NO_TURNED_OVER_PANELS));
  EXPECT_EQ(surface.orientation_policy(), TS::NO_TURNED_OVER_PANELS);
  std::map<Mesh::Face_index, int> cluster, orientation;
  for(auto f : faces(mesh)) { cluster[f] = 0; orientation[f] = 0; }
  surface.set_clustering(boost::make_assoc_property_map(cluster), boost::make_assoc_property_map(orientation),
                         TS::ALLOW_MIRRORED_PANELS);
  EXPECT_EQ(surface.orientation_policy(), TS::ALLOW_MIRRORED_PANELS);
}

TEST(KSetTilableSurface, SetClusteringChecksTheMaps)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  std::map<Mesh::Face_index, int> cluster, orientation;
  for(auto f : faces(mesh)) { cluster[f] = 0; orientation[f] = 0; }
  cluster[Mesh::Face_index(5)] = 2;  // id 1 unused
  EXPECT_THROW(surface.set_clustering(boost::make_assoc_property_map(cluster),
                                      boost::make_assoc_property_map(orientation)),
               TS::Invalid_input);
  EXPECT_FALSE(surface.is_clustered());
  cluster[Mesh::Face_index(5)] = 1;
  orientation[Mesh::Face_index(7)] = 8;
  EXPECT_THROW(surface.set_clustering(boost::make_assoc_property_map(cluster),
                                      boost::make_assoc_property_map(orientation)),
               TS::Invalid_input);
  orientation[Mesh::Face_index(7)] = 4;
  surface.set_clustering(boost::make_assoc_property_map(cluster),
                         boost::make_assoc_property_map(orientation));
  EXPECT_EQ(surface.number_of_clusters(), 2u);
  EXPECT_EQ(get(surface.face_orientation_map(), Mesh::Face_index(7)), 4);
}

// The maps the object hands out read its current clustering, also after
// set_clustering() and after the fidelity search restored its best state.
TEST(KSetTilableSurface, MapsHandedOutStayValid)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  const auto cluster = surface.face_cluster_map();
  const auto orientation = surface.face_orientation_map();
  std::map<Mesh::Face_index, int> parity, zero;
  for(auto f : faces(mesh)) { parity[f] = int(f.idx() % 2); zero[f] = 0; }
  surface.set_clustering(boost::make_assoc_property_map(parity), boost::make_assoc_property_map(zero));
  for(auto f : faces(mesh))
  {
    EXPECT_EQ(get(cluster, f), int(f.idx() % 2));
    EXPECT_EQ(get(orientation, f), 0);
  }
  const Mesh input = mesh;
  surface.cluster(TSP::number_of_tiles(5));
  surface.optimize_closest(TSP::number_of_optimized_candidates(2).number_of_improvement_rounds(1));
  const auto fresh = surface.face_cluster_map();
  for(auto f : faces(mesh))
    EXPECT_EQ(get(cluster, f), get(fresh, f));
  // The mesh moved; the input positions did not.
  EXPECT_GT(surface.optimization().measure.max_displacement, 0.0);
  for(auto v : vertices(mesh))
    EXPECT_EQ(get(surface.input_point_map(), v), input.point(v));
}

// The edits use the similarity threshold and orientation policy that
// cluster() was given, not the defaults: re-tagging through the object gives
// what the free function gives with those parameters.
TEST(KSetTilableSurface, EditsKeepTheCallersParameters)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  const double threshold = 2.0; // every orientation within 2 mean edges is admissible
  surface.cluster(TSP::number_of_tiles(6).similarity_threshold(threshold).orientation_policy(TS::NO_TURNED_OVER_PANELS));
  std::map<Mesh::Face_index, int> cluster, orientation;
  auto retag_copy = [&](const auto& np) {
    for(auto f : faces(mesh))
    {
      cluster[f] = get(surface.face_cluster_map(), f);
      orientation[f] = get(surface.face_orientation_map(), f);
    }
    const std::size_t dof = TS::retag_orientations(
      mesh, np.face_cluster_map(boost::make_assoc_property_map(cluster))
              .face_orientation_map(boost::make_assoc_property_map(orientation)));
    return std::make_pair(dof, orientation);
  };
  const auto with_callers = retag_copy(TSP::similarity_threshold(threshold).orientation_policy(TS::NO_TURNED_OVER_PANELS));
  const auto with_defaults = retag_copy(TSP::default_values());
  const std::size_t dof = surface.retag_orientations();
  std::map<Mesh::Face_index, int> retagged;
  for(auto f : faces(mesh))
  {
    retagged[f] = get(surface.face_orientation_map(), f);
    EXPECT_LT(retagged[f], 4) << "a turned-over panel under NO_TURNED_OVER_PANELS";
  }
  EXPECT_EQ(dof, with_callers.first);
  EXPECT_EQ(retagged, with_callers.second);
  EXPECT_NE(retagged, with_defaults.second) << "the parameters make no difference on this mesh";
}

namespace {

// The mesh's points, counting every read: what a step reads of the mesh.
struct Counting_point_map
{
  typedef Mesh::Vertex_index key_type;
  typedef Mesh::Point value_type;
  typedef const Mesh::Point& reference;
  typedef boost::read_write_property_map_tag category;

  Mesh* mesh;
  std::size_t* reads;

  friend reference get(const Counting_point_map& m, key_type v)
  {
    ++*m.reads;
    return m.mesh->point(v);
  }
  friend void put(const Counting_point_map& m, key_type v, const value_type& p) { m.mesh->point(v) = p; }
};

// The components of the graph, as a partition of the mesh edges.
std::map<Mesh::Edge_index, std::size_t> edge_components(const Mesh& mesh, const TS::Edge_sharing_graph<Mesh>& g)
{
  std::map<Mesh::Edge_index, std::size_t> component;
  for(auto e : edges(mesh)) component[e] = g.component(e);
  return component;
}

} // namespace

// The object checks the mesh once: its edits work on the state it keeps and
// read no point of the mesh, where the free functions check the mesh first.
TEST(KSetTilableSurface, EditsReuseTheStateInsteadOfRereadingTheMesh)
{
  Mesh mesh = read("monkey_saddle.off");
  std::size_t reads = 0;
  const Counting_point_map vpm{&mesh, &reads};
  TS::K_set_tilable_surface surface(mesh, vpm);
  EXPECT_GE(reads, num_vertices(mesh)) << "the constructor reads the input";
  surface.cluster(TSP::number_of_tiles(6));

  reads = 0;
  surface.merge_clusters(0, 1);
  surface.split_cluster(0);
  surface.retag_orientations();
  surface.degree_of_flexibility();
  surface.clustering();
  EXPECT_EQ(reads, 0u);

  std::map<Mesh::Face_index, int> cluster, orientation;
  for(auto f : faces(mesh))
  {
    cluster[f] = get(surface.face_cluster_map(), f);
    orientation[f] = get(surface.face_orientation_map(), f);
  }
  TS::merge_clusters(mesh, 0, 1, TSP::vertex_point_map(vpm)
                                   .face_cluster_map(boost::make_assoc_property_map(cluster))
                                   .face_orientation_map(boost::make_assoc_property_map(orientation)));
  EXPECT_GE(reads, num_vertices(mesh)) << "the free function checks the mesh";
}

// cluster() is its four stages in turn: run one by one, they build the same
// pool and select the same clustering; out of order, they refuse. (The
// whole run on one thread, the stages with the concurrency tag given first.)
TEST(KSetTilableSurface, StagesOneByOneGiveWhatClusterGives)
{
  Mesh mesh = read("monkey_saddle.off");
  const auto np = TSP::number_of_tiles(6).use_kmeans_candidate(true);
  TS::K_set_tilable_surface whole(mesh);
  static_assert(std::is_same<decltype(whole), TS::K_set_tilable_surface<CGAL::Sequential_tag, Mesh> >::value,
                "deduced: one thread, the mesh's points");
  TS::K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> staged(mesh);
  const TS::Clustering_result& expected = whole.cluster(np);

  EXPECT_THROW(staged.merge_to_tile_count(), TS::Invalid_input);
  const std::size_t initial = staged.initialize_clusters(np);
  EXPECT_EQ(initial, expected.number_of_initial_clusters);
  EXPECT_GE(initial, 6u);
  EXPECT_TRUE(staged.clustering().candidates.empty());
  const std::size_t merged = staged.merge_to_tile_count();
  ASSERT_GT(merged, 0u);
  for(const TS::Clustering_candidate& c : staged.clustering().candidates)
    EXPECT_TRUE(c.origin == TS::Clustering_candidate::HIERARCHICAL ||
                c.origin == TS::Clustering_candidate::TWIST_SEPARATED) << "origin " << int(c.origin);
  EXPECT_GT(staged.add_other_candidates(), merged) << "the k-means candidate was asked for";
  const TS::Clustering_result& selected = staged.select_candidate();
  EXPECT_THROW(staged.select_candidate(), TS::Invalid_input) << "the stages were used up";

  ASSERT_EQ(selected.candidates.size(), expected.candidates.size());
  for(std::size_t i = 0; i < expected.candidates.size(); ++i)
    EXPECT_EQ(selected.candidates[i].face_cluster, expected.candidates[i].face_cluster);
  EXPECT_EQ(selected.chosen_candidate, expected.chosen_candidate);
  EXPECT_EQ(selected.degree_of_flexibility, expected.degree_of_flexibility);
  for(auto f : faces(mesh))
  {
    EXPECT_EQ(get(staged.face_cluster_map(), f), get(whole.face_cluster_map(), f));
    EXPECT_EQ(get(staged.face_orientation_map(), f), get(whole.face_orientation_map(), f));
  }
}

// A merge amends the object's graph in place; it must be the graph of the
// merged clustering all the same: the one built from scratch from the maps,
// edge for edge, id for id, and clustering() must describe that clustering.
TEST(KSetTilableSurface, MergedGraphAndDescriptionAreThoseOfTheMergedClustering)
{
  Mesh mesh = read("monkey_saddle.off");
  TS::K_set_tilable_surface surface(mesh);
  surface.cluster(TSP::number_of_tiles(8));
  for(auto pair : {std::make_pair(std::size_t(2), std::size_t(5)), std::make_pair(std::size_t(6), std::size_t(0))})
  {
    const std::size_t dof = surface.merge_clusters(pair.first, pair.second);
    const std::size_t k = surface.number_of_clusters();
    const TS::Edge_sharing_graph<Mesh> rebuilt(mesh, k, surface.face_cluster_map(), surface.face_orientation_map());
    const TS::Edge_sharing_graph<Mesh>& amended = surface.edge_sharing_graph();
    EXPECT_EQ(dof, rebuilt.degree_of_flexibility());
    EXPECT_EQ(amended.degree_of_flexibility(), rebuilt.degree_of_flexibility());
    ASSERT_EQ(amended.number_of_clusters(), k);
    for(std::size_t c = 0; c < k; ++c)
      EXPECT_EQ(amended.cluster_pattern(c), rebuilt.cluster_pattern(c)) << "cluster " << c;
    EXPECT_EQ(edge_components(mesh, amended), edge_components(mesh, rebuilt));

    std::vector<std::size_t> sizes(k, 0);
    for(auto f : faces(mesh)) ++sizes[std::size_t(get(surface.face_cluster_map(), f))];
    EXPECT_EQ(surface.clustering().cluster_sizes, sizes);
    EXPECT_EQ(surface.clustering().s_quads.size(), k);
    EXPECT_EQ(surface.clustering().degree_of_flexibility, rebuilt.degree_of_flexibility());
  }
  EXPECT_EQ(surface.number_of_clusters(), 6u);
}

namespace {

// Keeps what it saw in itself: only the object given reaches these members.
struct Recording_visitor : TS::Default_visitor
{
  int iterations = 0;
  std::vector<std::string> phases;
  bool iteration(int, double, double)
  {
    ++iterations;
    return true;
  }
  void phase(const char* name, double seconds)
  {
    EXPECT_GE(seconds, 0.0);
    phases.push_back(name);
  }
};

bool has_phase(const Recording_visitor& visitor, const std::string& name)
{
  return std::find(visitor.phases.begin(), visitor.phases.end(), name) != visitor.phases.end();
}

} // namespace

// Given as std::ref, the user's visitor itself is called by every stage:
// validation, the clustering's phases, the fidelity search and each solver;
// the monkey saddle is an open grid, with a sweep clustering per direction.
TEST(MakeKSetTilable, OneVisitorFollowsEveryStage)
{
  Mesh mesh = read("monkey_saddle.off");
  Recording_visitor visitor;
  const TS::K_set_tilable_result r =
    TS::make_k_set_tilable(mesh, TSP::number_of_tiles(5).visitor(std::ref(visitor)));
  // Every candidate's solve counts here, the kept one's in the result.
  EXPECT_GT(r.optimization.iterations, 0);
  EXPECT_GE(visitor.iterations, r.optimization.iterations);
  // Each stage reported, validation before anything and the clustering
  // before the candidates are solved; the kept solve last.
  auto first = [&](const std::string& name) {
    return std::find(visitor.phases.begin(), visitor.phases.end(), name) - visitor.phases.begin();
  };
  for(const char* stage : {"validation", "threshold clustering", "exact starts", "merges", "other candidates",
                           "orientations", "clustering", "sweep candidate", "displacement prediction",
                           "candidate optimization"})
    EXPECT_TRUE(has_phase(visitor, stage)) << stage;
  EXPECT_EQ(first("validation"), 0);
  EXPECT_LT(first("clustering"), first("candidate optimization"));
  EXPECT_EQ(std::count(visitor.phases.begin(), visitor.phases.begin() + first("candidate optimization"),
                       "sweep candidate"), 2) << "one per direction of the grid";
  EXPECT_EQ(visitor.phases.back(), "optimization");
}

// With the parallel tag (the default tag runs on one thread whatever the
// limit): the candidates' displacement predictions, made in parallel, and
// the result are bit-identical on one thread and on two.
TEST(MakeKSetTilable, SameResultWhateverTheThreadCount)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "without TBB every run has one thread";
#else
  std::vector<std::vector<Mesh::Point> > results;
  std::vector<std::vector<double> > predictions;
  for(int threads : {1, 2})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    Mesh mesh = read("de_beers_ginza.off");
    const TS::K_set_tilable_result r =
      TS::make_k_set_tilable<CGAL::Parallel_tag>(mesh, TSP::number_of_tiles(20));
    results.push_back(points(mesh));
    predictions.emplace_back();
    for(const TS::Clustering_candidate& c : r.clustering.candidates)
      if(TS::internal::origin_traits(c.origin).ranked)  // the sweeps and twist separations are not
        predictions.back().push_back(c.predicted_displacement);
  }
  EXPECT_TRUE(results[0] == results[1]) << "bit-identical positions";
  ASSERT_GT(predictions[0].size(), 2u);
  EXPECT_GT(*std::min_element(predictions[0].begin(), predictions[0].end()), 0.0) << "every candidate predicted";
  EXPECT_TRUE(predictions[0] == predictions[1]) << "bit-identical predictions";
#endif
}

namespace {

// Stops the solver at its start (iteration 0); the copies the pipeline
// makes share the count.
struct Stop_at_once_visitor : TS::Default_visitor
{
  int* iterations;
  bool iteration(int, double, double)
  {
    ++*iterations;
    return false;
  }
};

} // namespace

// A visitor that stops the solver stops the whole search: no further
// candidate clustering or improvement round is optimized (without this, each
// of the candidates and rounds would call it again). The De Beers stand-in
// is a grid with a sweep at K = 30, solved first: stopped before any step,
// the result is the swept surface, exact, checked independently.
TEST(MakeKSetTilable, VisitorThatStopsEndsTheSearch)
{
  Mesh mesh = read("de_beers_ginza.off");
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  int iterations = 0;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(30).face_cluster_map(cluster).face_orientation_map(orientation)
            .visitor(Stop_at_once_visitor{{}, &iterations}));
  EXPECT_EQ(iterations, 1);
  EXPECT_TRUE(r.optimization.stopped_by_visitor);
  EXPECT_EQ(r.optimization.iterations, 0);
  // Kept: a candidate the search solves first, from its exact start.
  EXPECT_TRUE(TS::internal::origin_traits(r.clustering.candidates[r.clustering.chosen_candidate].origin)
                .solved_first_from_start);
  EXPECT_TRUE(r.is_tilable());
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 1e-6);
}

// With number_of_optimized_candidates 0, an exact sweep ends the search: the
// De Beers stand-in (a grid with sweeps at K = 30) ends on a sweep, tilable
// by an independent check, and nothing else is predicted or optimized.
// Where no sweep exists (monkey saddle, K = 5, without the grid candidates,
// which include the sweeps), 0 counts as 1.
TEST(MakeKSetTilable, ZeroCandidatesEndAtAnExactSweep)
{
  Mesh mesh = read("de_beers_ginza.off");
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  Recording_visitor visitor;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(30).number_of_optimized_candidates(0).face_cluster_map(cluster)
            .face_orientation_map(orientation).visitor(std::ref(visitor)));
  EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::GRID_SWEEPS);
  EXPECT_TRUE(r.is_tilable());
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 1e-6);
  EXPECT_TRUE(has_phase(visitor, "sweep candidate"));
  for(const char* skipped : {"displacement prediction", "candidate optimization", "improvement round"})
    EXPECT_FALSE(has_phase(visitor, skipped)) << skipped;

  const Mesh saddle = read("monkey_saddle.off");
  auto solved_with = [&](std::size_t optimized) {
    Mesh m = saddle;
    const TS::K_set_tilable_result s =
      TS::make_k_set_tilable(m, TSP::number_of_tiles(5).number_of_optimized_candidates(optimized)
                                  .use_segment_candidates(false));
    for(const TS::Clustering_candidate& c : s.clustering.candidates)
      EXPECT_NE(c.origin, TS::Clustering_candidate::GRID_SWEEPS);
    return points(m);
  };
  EXPECT_TRUE(solved_with(0) == solved_with(1));
}

// Above 5,000 faces the default is 0 candidates: on a 5,050-quad horn whose
// rings grow (so the input itself is not tilable), at K = 100 and at K = 40
// (fewer molds than the 50 quads of a ring), the result is a sweep, exact
// by an independent check, and no solve from the input runs.
TEST(MakeKSetTilable, AboveFiveThousandFacesAnExactSweepIsTheResult)
{
  for(std::size_t k : {100u, 40u})
  {
    Mesh mesh = horn<Mesh>(101, 50, 4.0, 2.0, [](int i) { return 1.0 + 0.005 * i; });
    ASSERT_GT(num_faces(mesh), 5000u);
    auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
    auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
    Recording_visitor visitor;
    const TS::K_set_tilable_result r = TS::make_k_set_tilable(
      mesh, TSP::number_of_tiles(k).face_cluster_map(cluster).face_orientation_map(orientation)
              .visitor(std::ref(visitor)));
    EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::GRID_SWEEPS)
      << "K = " << k;
    EXPECT_LE(r.clustering.cluster_sizes.size(), k);
    EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 1e-6) << "K = " << k;
    EXPECT_FALSE(has_phase(visitor, "candidate optimization")) << "K = " << k;
  }
}

namespace {

// Records the phases and stops every solve at its start.
struct Recording_stopper : Recording_visitor
{
  bool iteration(int, double, double) { return false; }
};

} // namespace

// Above 5,000 faces no displacement prediction is made (each factorizes the
// solver's whole matrix: 8 GB at 187k quads): the candidates are ranked by
// their length spread alone. cross_quad (valences 3 and 5, so no sweep)
// subdivided 3 times (2,432 quads) predicts every candidate; 4 times
// (9,728 quads) none, and its first solve is still made.
TEST(MakeKSetTilable, AboveFiveThousandFacesNoPredictionIsMade)
{
  for(int levels : {3, 4})
  {
    Mesh mesh = read("cross_quad.off");
    CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, CGAL::parameters::number_of_iterations(levels));
    const bool large = num_faces(mesh) > 5000;
    Recording_stopper visitor;
    const TS::K_set_tilable_result r =
      TS::make_k_set_tilable(mesh, TSP::number_of_tiles(num_faces(mesh) / 25).visitor(std::ref(visitor)));
    EXPECT_EQ(has_phase(visitor, "displacement prediction"), !large) << num_faces(mesh) << " quads";
    EXPECT_TRUE(has_phase(visitor, "candidate optimization")) << num_faces(mesh) << " quads";
    std::size_t predicted = 0, ranked = 0;
    for(const TS::Clustering_candidate& c : r.clustering.candidates)
    {
      EXPECT_NE(c.origin, TS::Clustering_candidate::GRID_SWEEPS);
      if(!TS::internal::origin_traits(c.origin).ranked)  // twist separations are not predicted
        continue;
      ++ranked;
      predicted += c.predicted_displacement > 0 ? 1 : 0;
    }
    ASSERT_GT(ranked, 1u);
    EXPECT_EQ(predicted, large ? 0u : ranked) << num_faces(mesh) << " quads";
  }
}

// Above 5,000 faces a mesh that is no grid but a 2 x 2 refinement starts from
// its coarse mesh (user manual, "Multilevel start"): cross_quad (valences 3
// and 5, so no sweep) subdivided 4 times, 9,728 quads at K = faces / 25, is
// coarsened twice to 608 quads, whose result at K / 16 is prolongated. The
// result comes from that start, is exact by an independent Umeyama fit and
// stays within 1% of the diagonal by the PMP oracle (0.36% measured). As an
// exact sweep does, the start ends the clustering: no beam of merges, no
// other candidate, and the coarse solve's iterations reach the visitor.
TEST(MakeKSetTilable, AboveFiveThousandFacesARefinementStartsFromItsCoarseMesh)
{
  Recording_visitor visitor;
  Mesh mesh = read("cross_quad.off");
  CGAL::Subdivision_method_3::CatmullClark_subdivision(mesh, CGAL::parameters::number_of_iterations(4));
  ASSERT_EQ(num_faces(mesh), 9728u);
  const Mesh input = mesh;
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(num_faces(mesh) / 25).face_cluster_map(cluster).face_orientation_map(orientation)
            .visitor(std::ref(visitor)));
  ASSERT_TRUE(r.is_tilable());
  EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::MULTILEVEL);
  EXPECT_TRUE(has_phase(visitor, "exact starts"));
  EXPECT_TRUE(has_phase(visitor, "multilevel start"));
  EXPECT_FALSE(has_phase(visitor, "merges"));
  EXPECT_FALSE(has_phase(visitor, "other candidates"));
  for(const TS::Clustering_candidate& candidate : r.clustering.candidates)
    EXPECT_NE(candidate.origin, TS::Clustering_candidate::HIERARCHICAL);
  // The coarse solve's iterations, beyond the kept solve's (the start is not polished).
  EXPECT_GT(visitor.iterations, r.optimization.iterations + 1);
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 2e-6);
  EXPECT_LT(hausdorff_oracle::distances(mesh, input).hausdorff(), 0.01);
}

#ifdef CGAL_LINKED_WITH_TBB

namespace {

// Records how many threads the arena it is called in may use.
struct Concurrency_probe : TS::Default_visitor
{
  std::set<int>* seen;
  bool iteration(int, double, double)
  {
    seen->insert(tbb::this_task_arena::max_concurrency());
    return true;
  }
};

} // namespace
#endif

// Sequential_tag runs every step on one thread, the parallel tag on all of
// them, and both give the same result.
TEST(MakeKSetTilable, ConcurrencyTagChangesTheThreadsNotTheResult)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "without TBB every run has one thread";
#else
  const Mesh input = read("monkey_saddle.off");
  auto run = [&](auto tag, std::set<int>& seen, std::vector<int>& cluster) {
    Mesh mesh = input;
    auto c = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
    TS::make_k_set_tilable<decltype(tag)>(
      mesh, TSP::number_of_tiles(7).face_cluster_map(c).visitor(Concurrency_probe{{}, &seen}));
    for(auto f : faces(mesh)) cluster.push_back(c[f]);
    return points(mesh);
  };
  std::set<int> sequential_threads, parallel_threads;
  std::vector<int> sequential_cluster, parallel_cluster;
  const auto sequential = run(CGAL::Sequential_tag(), sequential_threads, sequential_cluster);
  const auto parallel = run(CGAL::Parallel_tag(), parallel_threads, parallel_cluster);
  EXPECT_EQ(sequential_threads, std::set<int>{1});
  EXPECT_EQ(parallel_threads, std::set<int>{tbb::info::default_concurrency()});
  EXPECT_EQ(sequential_cluster, parallel_cluster);
  EXPECT_EQ(sequential, parallel);
#endif
}

} // namespace test_make_k_set_tilable_unit
