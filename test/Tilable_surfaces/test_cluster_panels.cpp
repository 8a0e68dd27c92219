// Clustering into S-quads and interactive editing: facts checked by
// construction, by symmetry and by an independent brute-force count.
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/twist_separation.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include "grid_mesh.h"

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>
#include <random>
#include <set>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_cluster_panels_unit {

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;

namespace {

Mesh read(const std::string& name)
{
  Mesh m;
  const std::string path = std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/" + name + ".off";
  if(!CGAL::IO::read_polygon_mesh(path, m))
    ADD_FAILURE() << "cannot read " << path;
  return m;
}


struct Maps
{
  Mesh::Property_map<Face, std::size_t> cluster;
  Mesh::Property_map<Face, int> orientation;
};

Maps maps(Mesh& m)
{
  return Maps{m.add_property_map<Face, std::size_t>("f:cluster", 0).first,
              m.add_property_map<Face, int>("f:orientation", 0).first};
}

TS::Clustering_result cluster(Mesh& m, const Maps& mp, std::size_t k,
                              TS::Clustering_path path = TS::AUTOMATIC_PATH)
{
  return TS::cluster_panels(m, TS::parameters::number_of_tiles(k)
                                .face_cluster_map(mp.cluster)
                                .face_orientation_map(mp.orientation)
                                .clustering_path(path));
}

// Degree of flexibility from scratch: nodes (c, k); for every interior mesh
// edge, the template edge of each side (found by walking the face from
// halfedge(f)), joined unless equal; connected components by BFS.
std::size_t brute_force_dof(const Mesh& m, const Maps& mp, std::size_t k)
{
  auto node = [&](Mesh::Halfedge_index h) {
    const Face f = m.face(h);
    Mesh::Halfedge_index g = m.halfedge(f);
    int j = 0;
    for(g = m.next(g); g != h; g = m.next(g)) ++j;  // h is face edge j
    const TS::Panel_orientation o(mp.orientation[f]);
    return 4 * mp.cluster[f] + std::size_t(o.template_edge(j));
  };
  std::vector<std::vector<std::size_t> > adjacent(4 * k);
  for(auto e : m.edges())
  {
    if(m.is_border(e)) continue;
    const std::size_t a = node(m.halfedge(e, 0)), b = node(m.halfedge(e, 1));
    if(a == b) continue;
    adjacent[a].push_back(b);
    adjacent[b].push_back(a);
  }
  std::vector<bool> seen(4 * k, false);
  std::size_t components = 0;
  for(std::size_t s = 0; s < 4 * k; ++s)
  {
    if(seen[s]) continue;
    ++components;
    std::queue<std::size_t> todo;
    todo.push(s);
    seen[s] = true;
    while(!todo.empty())
    {
      const std::size_t x = todo.front();
      todo.pop();
      for(std::size_t y : adjacent[x])
        if(!seen[y]) { seen[y] = true; todo.push(y); }
    }
  }
  return components;
}

std::size_t number_of_clusters(const Mesh& m, const Maps& mp)
{
  std::set<std::size_t> ids;
  for(Face f : faces(m)) ids.insert(mp.cluster[f]);
  EXPECT_EQ(*ids.rbegin() + 1, ids.size()) << "ids are not contiguous";
  return ids.size();
}

// sum_i |q_o(i) - T(p_i)|, T the best rigid fit of p onto q relabelled by o.
double sum_of_distances(const TS::Panel& p, const TS::Panel& q, TS::Panel_orientation o,
                        bool allow_mirror = false)
{
  const TS::Panel t = TS::reoriented(q, o);
  const TS::Rigid_fit fit = TS::best_rigid_fit(p, t, allow_mirror);
  double sum = 0;
  for(int i = 0; i < 4; ++i) sum += (t[i] - fit(p[i])).norm();
  return sum;
}

// Every face's orientation minimises its dissimilarity to its S-quad, ties
// allowed: ties within tau = 0.01 x mean edge length, the similarity
// threshold (see cluster_panels()).
void expect_admissible_orientations(const Mesh& m, const Maps& mp, const TS::Clustering_result& r)
{
  const double scale = TS::mean_edge_length(m);
  for(Face f : faces(m))
  {
    const TS::Panel& s = r.s_quads[mp.cluster[f]];
    const TS::Panel q = TS::face_panel(f, m);
    // Best over the 8 correspondences (quad_shape.h's reference implementation)
    // against the sum of corner distances under the tagged correspondence.
    const double best = TS::best_match(s, q).dissimilarity;
    const double tagged = sum_of_distances(s, q, TS::Panel_orientation(mp.orientation[f]));
    EXPECT_LE(tagged, best + 0.01 * scale + 1e-9 * scale) << "face " << int(f);
  }
}

} // namespace

TEST(FastMatch, SameAsBestMatch)
{
  // Random quads, and the cases where the rotation is least well determined:
  // near-planar quads (rank-2 cross-covariance) and near-symmetric ones
  // (rectangles, squares, kites: correspondences nearly tie), each against a
  // randomly moved, slightly perturbed copy or an unrelated quad.
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  auto random_quad = [&] {
    TS::Panel q;
    for(auto& p : q) p = Eigen::Vector3d(u(rng), u(rng), u(rng));
    return q;
  };
  auto perturbed = [&](TS::Panel q, double eps) {
    for(auto& p : q) p += eps * Eigen::Vector3d(u(rng), u(rng), u(rng));
    return q;
  };
  auto moved = [&](const TS::Panel& q) {
    const Eigen::Matrix3d r =
      Eigen::Quaterniond(Eigen::Vector4d(u(rng), u(rng), u(rng), u(rng)).normalized())
        .toRotationMatrix();
    const Eigen::Vector3d t(u(rng), u(rng), u(rng));
    TS::Panel m;
    for(int i = 0; i < 4; ++i) m[i] = r * q[i] + t;
    return m;
  };
  auto special_quad = [&](int kind) {
    const double a = 1 + u(rng), b = 1 + u(rng), c = 0.5 * (1 + u(rng));
    switch(kind)
    {
      case 0: return TS::Panel{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(a, 0, 0), Eigen::Vector3d(a, b, 0), Eigen::Vector3d(0, b, 0)}};   // rectangle
      case 1: return TS::Panel{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(a, 0, 0), Eigen::Vector3d(a, a, 0), Eigen::Vector3d(0, a, 0)}};   // square
      case 2: return TS::Panel{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(a, c, 0), Eigen::Vector3d(0, b, 0), Eigen::Vector3d(-a, c, 0)}};  // kite
      default: return TS::Panel{{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(a, 0, c), Eigen::Vector3d(a, b, 0), Eigen::Vector3d(0, b, c)}};  // skew, symmetric
    }
  };
  std::vector<std::pair<TS::Panel, TS::Panel> > cases;
  for(int i = 0; i < 300; ++i)
    cases.push_back({random_quad(), random_quad()});
  for(double eps : {0.0, 1e-12, 1e-8, 1e-4, 1e-2})
    for(int i = 0; i < 200; ++i)
    {
      const TS::Panel p = i % 2 ? special_quad(i % 8 / 2) : perturbed(random_quad(), 0);
      TS::Panel flat = p;
      for(auto& x : flat) x.z() *= eps;  // near-planar version of a random quad
      const TS::Panel base = i % 2 ? p : flat;
      cases.push_back({perturbed(base, eps), moved(perturbed(base, eps))});
      cases.push_back({perturbed(base, eps), random_quad()});
    }
  for(TS::Orientation_policy policy :
      {TS::PROPER_RIGID_MOTIONS, TS::NO_TURNED_OVER_PANELS, TS::ALLOW_MIRRORED_PANELS})
    for(const auto& c : cases)
    {
      const TS::Quad_match a = TS::best_match(c.first, c.second, policy);
      const TS::Quad_match b = TS::internal::fast_best_match(c.first, c.second, policy);
      ASSERT_NEAR(a.dissimilarity, b.dissimilarity, 1e-9);
      // The fit found must achieve the dissimilarity found.
      const TS::Panel t = TS::reoriented(c.second, b.orientation);
      double sum = 0;
      for(int i = 0; i < 4; ++i) sum += (t[i] - b.fit(c.first[i])).norm();
      ASSERT_NEAR(sum, b.dissimilarity, 1e-9);
      EXPECT_NEAR(b.fit.rotation.determinant(), b.fit.is_mirrored ? -1.0 : 1.0, 1e-12);
      // Same correspondence and motion unless two correspondences tie.
      double second_best = std::numeric_limits<double>::max();
      for(int o = 0; o < (policy == TS::NO_TURNED_OVER_PANELS ? 4 : 8); ++o)
        if(o != a.orientation.index())
          second_best = (std::min)(second_best,
            sum_of_distances(c.first, c.second, TS::Panel_orientation(o),
                             policy == TS::ALLOW_MIRRORED_PANELS));
      if(second_best > a.dissimilarity + 1e-6)
      {
        EXPECT_EQ(a.orientation, b.orientation);
        if(a.dissimilarity > 1e-6)
          EXPECT_TRUE(a.fit.rotation.isApprox(b.fit.rotation, 1e-6));
      }
    }
}

// The canonical face order by hand on a 3 x 2 grid of 2 x 1 rectangles whose
// top right corner is pulled to (7, 3). Face centroids: (1, .5), (3, .5),
// (5, .5), (1, 1.5), (3, 1.5) and (5.25, 1.75) for face 5; their mean is
// (3.042, 1.042), farthest from face 5 (squared distance 5.38 against 4.46
// for face 0). Each face's edges run bottom, right, top, left (grid_mesh.h),
// so the breadth-first search from 5 reaches 2 (below), 4 (left), then from
// 2 face 1, from 4 face 3, from 1 face 0.
TEST(CanonicalFaceOrder, BreadthFirstFromTheFaceFarthestFromTheCentroid)
{
  Mesh mesh = grid<Mesh>(3, 2);
  mesh.point(Mesh::Vertex_index(11)) = Point(7, 3, 0);
  const auto fim = CGAL::get_initialized_face_index_map(mesh);
  const std::vector<TS::Panel> quads = TS::internal::face_quads(mesh, fim, CGAL::parameters::default_values());
  const std::vector<std::size_t> rank = TS::internal::canonical_face_ranks(mesh, fim, quads);
  EXPECT_EQ(rank, (std::vector<std::size_t>{5, 3, 1, 4, 2, 0}));
}

TEST(ClusterQuads, FlatGridOfEqualRectanglesIsOneCluster)
{
  Mesh m = grid<Mesh>(6, 4);
  Maps mp = maps(m);
  const TS::Clustering_result r = cluster(m, mp, 1);
  EXPECT_EQ(number_of_clusters(m, mp), 1u);
  ASSERT_EQ(r.cluster_sizes.size(), 1u);
  EXPECT_EQ(r.cluster_sizes[0], 24u);
  // The threshold clustering already finds a single shape.
  EXPECT_EQ(r.number_of_initial_clusters, 1u);
  // Every orientation that maps the long edges to the long edges fits exactly;
  // tagged in a checkerboard of 180-degree turns, every interior edge puts the
  // same S-quad edge on both sides (a self-loop), so the 4 S-quad edges stay
  // apart: DOF 4 = 4K, the maximum (tagging all faces alike gives only 2).
  EXPECT_EQ(r.degree_of_flexibility, 4u);
  EXPECT_EQ(brute_force_dof(m, mp, 1), 4u);
  EXPECT_NEAR(r.total_weight, 0.0, 1e-9);
  // The S-quad is the 2 x 1 rectangle.
  const auto e = TS::edge_lengths(r.s_quads[0]);
  std::vector<double> sorted(e.begin(), e.end());
  std::sort(sorted.begin(), sorted.end());
  EXPECT_NEAR(sorted[0], 1.0, 1e-9);
  EXPECT_NEAR(sorted[3], 2.0, 1e-9);
}

TEST(ClusterQuads, OrientationsChosenForFlexibilityOnSymmetricTiles)
{
  // Squares at K = 1, and rectangles without turned-over panels: as above,
  // a checkerboard of 180-degree turns makes every interior edge a self-loop,
  // DOF 4 = 4K, while each face's first best orientation alone (ties broken
  // by index) gives 2.
  for(double h : {2.0, 1.0})
    for(TS::Orientation_policy policy : {TS::PROPER_RIGID_MOTIONS, TS::NO_TURNED_OVER_PANELS})
    {
      Mesh m = grid<Mesh>(5, 4, 2, h);
      Maps mp = maps(m);
      const TS::Clustering_result r = TS::cluster_panels(
        m, TS::parameters::number_of_tiles(1).face_cluster_map(mp.cluster)
             .face_orientation_map(mp.orientation).orientation_policy(policy));
      EXPECT_EQ(r.degree_of_flexibility, 4u) << "h " << h << ", policy " << int(policy);
      EXPECT_EQ(brute_force_dof(m, mp, 1), 4u);
      if(policy == TS::NO_TURNED_OVER_PANELS)
        for(Face f : faces(m)) EXPECT_LT(mp.orientation[f], 4);
    }
}

TEST(ClusterQuads, CongruentQuadsAreSplitWhenKExceedsTheShapes)
{
  Mesh m = grid<Mesh>(4, 3);
  Maps mp = maps(m);
  const TS::Clustering_result r = cluster(m, mp, 5);
  EXPECT_EQ(number_of_clusters(m, mp), 5u);
  EXPECT_EQ(r.degree_of_flexibility, brute_force_dof(m, mp, 5));
}

TEST(ClusterQuads, ErrorsLeaveTheMapsUntouched)
{
  Mesh m = read("de_beers_ginza");
  Maps mp = maps(m);
  for(Face f : faces(m)) { mp.cluster[f] = 77; mp.orientation[f] = 5; }
  EXPECT_THROW(cluster(m, mp, 0), TS::Invalid_input);
  EXPECT_THROW(cluster(m, mp, m.number_of_faces() + 1), TS::Invalid_input);
  Mesh mixed = read("double-torus-example");  // pentagons and larger faces
  Maps mixed_maps = maps(mixed);
  for(Face f : faces(mixed)) mixed_maps.cluster[f] = 77;
  EXPECT_THROW(cluster(mixed, mixed_maps, 3), TS::Invalid_input);
  for(Face f : faces(m)) { EXPECT_EQ(mp.cluster[f], 77u); EXPECT_EQ(mp.orientation[f], 5); }
  for(Face f : faces(mixed)) EXPECT_EQ(mixed_maps.cluster[f], 77u);
}

TEST(ClusterQuads, KEqualsNumberOfFaces)
{
  Mesh m = read("de_beers_ginza");
  Maps mp = maps(m);
  cluster(m, mp, m.number_of_faces());
  EXPECT_EQ(number_of_clusters(m, mp), m.number_of_faces());
}

// The paper's surfaces and K values (Table 1); DOFs are printed next to the
// paper's for the record, not asserted (the meshes are stand-ins).
struct Paper_case { const char* surface; std::vector<std::size_t> ks; };

// The names of the cases, so that a test keeps its name from one run to the next.
void PrintTo(const Paper_case& p, std::ostream* os) { *os << p.surface; }

class PaperSurfaces : public ::testing::TestWithParam<Paper_case> {};

TEST_P(PaperSurfaces, ExactlyKClustersWithAdmissibleOrientations)
{
  Mesh m = read(GetParam().surface);
  Maps mp = maps(m);
  for(std::size_t k : GetParam().ks)
  {
    const TS::Clustering_result r = cluster(m, mp, k);
    EXPECT_EQ(number_of_clusters(m, mp), k);
    ASSERT_EQ(r.cluster_sizes.size(), k);
    for(std::size_t s : r.cluster_sizes) EXPECT_GT(s, 0u);
    EXPECT_EQ(r.degree_of_flexibility, brute_force_dof(m, mp, k));
    expect_admissible_orientations(m, mp, r);
    std::cout << "[ DOF      ] " << GetParam().surface << " K=" << k << " DOF="
              << r.degree_of_flexibility << " (N=" << r.number_of_initial_clusters << ", "
              << r.choice_reason << ")" << std::endl;
  }
}

INSTANTIATE_TEST_SUITE_P(
  Table1, PaperSurfaces,
  ::testing::Values(Paper_case{"swiss_re", {24, 18, 9}}, Paper_case{"tunnel", {12, 8}},
                    Paper_case{"seashell", {96, 60, 44, 21}},
                    Paper_case{"decocube", {21, 15, 9}}, Paper_case{"monkey_saddle", {24, 3, 1}},
                    Paper_case{"de_beers_ginza", {48, 44, 39, 34, 30, 27, 28, 22, 16}}),
  [](const ::testing::TestParamInfo<Paper_case>& i) { return std::string(i.param.surface); });

// The face whose centroid is nearest to `p`.
Face nearest_face(const Mesh& m, const Eigen::Vector3d& p)
{
  Face best;
  double best_d = std::numeric_limits<double>::max();
  for(Face f : faces(m))
  {
    const TS::Panel q = TS::face_panel(f, m);
    const double d = (0.25 * (q[0] + q[1] + q[2] + q[3]) - p).norm();
    if(d < best_d) { best_d = d; best = f; }
  }
  return best;
}

void expect_rotation_invariant(const char* surface, std::size_t k, const Eigen::Matrix3d& rotation)
{
  Mesh m = read(surface);
  Maps mp = maps(m);
  cluster(m, mp, k);
  for(Face f : faces(m))
  {
    const TS::Panel q = TS::face_panel(f, m);
    const Face g = nearest_face(m, rotation * (0.25 * (q[0] + q[1] + q[2] + q[3])));
    EXPECT_EQ(mp.cluster[f], mp.cluster[g]) << surface << ": faces " << int(f) << ", " << int(g);
  }
}

TEST(ClusterQuads, TunnelSymmetricQuadsShareClusters)
{
  // P = (s, r cos t, r sin t) with r periodic of period 60 degrees in t:
  // rotation by 60 degrees about x maps the mesh onto itself.
  expect_rotation_invariant("tunnel", 10,
    Eigen::AngleAxisd(M_PI / 3, Eigen::Vector3d::UnitX()).toRotationMatrix());
}

TEST(ClusterQuads, TowerSymmetricQuadsShareClusters)
{
  // 24 vertices per level, levels alternately shifted by half a step: the
  // rotation by 2 pi / 24 about the axis z maps the mesh onto itself.
  expect_rotation_invariant("swiss_re", 18,
    Eigen::AngleAxisd(2 * M_PI / 24, Eigen::Vector3d::UnitZ()).toRotationMatrix());
}

// The exact weight of a labelling (by face index): sum of pairwise dissimilarities.
double labelling_weight(const Mesh& m, const std::vector<std::size_t>& label)
{
  std::vector<Face> f(faces(m).begin(), faces(m).end());
  double w = 0;
  for(std::size_t i = 0; i < f.size(); ++i)
    for(std::size_t j = i + 1; j < f.size(); ++j)
      if(label[std::size_t(f[i])] == label[std::size_t(f[j])])
        w += TS::internal::fast_best_match(TS::face_panel(f[i], m), TS::face_panel(f[j], m)).dissimilarity;
  return w;
}

// The same, of the labelling in the maps.
double exact_weight(const Mesh& m, const Maps& mp)
{
  std::vector<std::size_t> label(m.number_of_faces());
  for(Face f : faces(m)) label[std::size_t(f)] = mp.cluster[f];
  return labelling_weight(m, label);
}

TEST(ClusterQuads, DescriptorPathAgreesWithExactPath)
{
  for(const char* surface : {"seashell", "decocube", "de_beers_ginza"})
  {
    Mesh m = read(surface);
    Maps exact_maps = maps(m);
    const TS::Clustering_result exact = cluster(m, exact_maps, 20, TS::EXACT_PATH);
    const double exact_w = exact_weight(m, exact_maps);
    EXPECT_TRUE(exact.weights_are_exact);
    EXPECT_NEAR(exact.total_weight, exact_w, 1e-9 * exact_w);

    Mesh m2 = read(surface);
    Maps descriptor_maps = maps(m2);
    const TS::Clustering_result descriptor = cluster(m2, descriptor_maps, 20, TS::DESCRIPTOR_PATH);
    EXPECT_EQ(descriptor.path, TS::DESCRIPTOR_PATH);
    EXPECT_FALSE(descriptor.weights_are_exact);
    EXPECT_EQ(number_of_clusters(m2, descriptor_maps), 20u);
    // The kd-tree prefilter is exact: same threshold clustering.
    EXPECT_EQ(descriptor.number_of_initial_clusters, exact.number_of_initial_clusters);
    // The estimate bounds the true weight from above, within a factor 2.
    const double descriptor_w = exact_weight(m2, descriptor_maps);
    EXPECT_GE(descriptor.total_weight, descriptor_w * (1 - 1e-9)) << surface;
    EXPECT_LE(descriptor.total_weight, 2 * descriptor_w) << surface;
    // Both clusterings are of comparable quality.
    EXPECT_LT(descriptor_w, 3 * exact_w) << surface;
    EXPECT_LT(exact_w, 3 * descriptor_w) << surface;
    std::cout << "[ WEIGHT   ] " << surface << " K=20 exact path " << exact_w << " (DOF "
              << exact.degree_of_flexibility << "), descriptor path " << descriptor_w
              << " (estimate " << descriptor.total_weight << ", DOF "
              << descriptor.degree_of_flexibility << ")" << std::endl;
  }
}

TEST(ClusterQuads, DeterministicWhateverTheThreads)
{
#ifndef CGAL_LINKED_WITH_TBB
  GTEST_SKIP() << "without TBB every run has one thread";
#else
  Mesh m = read("seashell");
  std::vector<std::vector<std::size_t> > results;
  for(int threads : {1, 2})
  {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    for(TS::Clustering_path path : {TS::EXACT_PATH, TS::DESCRIPTOR_PATH})
    {
      Maps mp = maps(m);
      cluster(m, mp, 30, path);
      std::vector<std::size_t> labels;
      for(Face f : faces(m)) labels.push_back(mp.cluster[f] * 8 + std::size_t(mp.orientation[f]));
      results.push_back(labels);
    }
  }
  EXPECT_EQ(results[0], results[2]);
  EXPECT_EQ(results[1], results[3]);
#endif
}

TEST(ClusterEditing, MergesAndSplitsAgreeWithBruteForce)
{
  Mesh m = read("de_beers_ginza");
  Maps mp = maps(m);
  cluster(m, mp, 16);
  auto np = TS::parameters::face_cluster_map(mp.cluster).face_orientation_map(mp.orientation);
  std::size_t k = 16;

  std::size_t dof = TS::merge_clusters(m, 3, 1, np);
  --k;
  EXPECT_EQ(number_of_clusters(m, mp), k);
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));

  dof = TS::merge_clusters(m, 0, k - 1, np);
  --k;
  EXPECT_EQ(number_of_clusters(m, mp), k);
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));

  std::size_t first_of_zero = m.number_of_faces();
  for(Face f : faces(m)) if(mp.cluster[f] == 0) { first_of_zero = std::size_t(f); break; }
  dof = TS::split_cluster(m, 0, np);
  ++k;
  EXPECT_EQ(number_of_clusters(m, mp), k);
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));
  EXPECT_EQ(mp.cluster[Face(Mesh::size_type(first_of_zero))], 0u);

  dof = TS::split_cluster(m, 2, np);
  ++k;
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));
  dof = TS::merge_clusters(m, 2, 5, np);
  --k;
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));
  dof = TS::retag_orientations(m, np);
  EXPECT_EQ(number_of_clusters(m, mp), k);
  EXPECT_EQ(dof, brute_force_dof(m, mp, k));
}

TEST(ClusterEditing, MergeKeepsInstancesAndLowersNoDofAfterSameShapeMerge)
{
  // Quadrants of a flat grid of equal rectangles, orientation 0 everywhere:
  // merging two quadrant clusters of the same shape keeps template edges 0/2
  // and 1/3 apart; DOF can only decrease on a merge.
  Mesh m = grid<Mesh>(4, 4);
  Maps mp = maps(m);
  for(Face f : faces(m)) mp.cluster[f] = (int(f) % 4) / 2 + 2 * ((int(f) / 4) / 2);
  auto np = TS::parameters::face_cluster_map(mp.cluster).face_orientation_map(mp.orientation);
  EXPECT_EQ(brute_force_dof(m, mp, 4), 4u);
  const std::size_t dof = TS::merge_clusters(m, 0, 3, np);
  EXPECT_LE(dof, 4u);
  EXPECT_GE(dof, 2u);
  EXPECT_EQ(dof, brute_force_dof(m, mp, 3));
}

TEST(ClusterEditing, Errors)
{
  Mesh m = grid<Mesh>(2, 2);
  Maps mp = maps(m);
  for(Face f : faces(m)) mp.cluster[f] = std::size_t(f);
  auto np = TS::parameters::face_cluster_map(mp.cluster).face_orientation_map(mp.orientation);
  EXPECT_THROW(TS::merge_clusters(m, 1, 1, np), TS::Invalid_input);
  EXPECT_THROW(TS::merge_clusters(m, 0, 4, np), TS::Invalid_input);
  EXPECT_THROW(TS::split_cluster(m, 0, np), TS::Invalid_input);  // a single face
  for(Face f : faces(m)) EXPECT_EQ(mp.cluster[f], std::size_t(f));
}

TEST(ClusterQuads, DescriptorPathOnALargerGrid)
{
  // A monkey saddle z = x^3 - 3 x y^2 on a 100 x 100 grid: 10,000 quads.
  const int n = 100;
  Mesh m;
  std::vector<Mesh::Vertex_index> v;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
    {
      const double x = -1 + 2.0 * i / n, y = -1 + 2.0 * j / n;
      v.push_back(m.add_vertex(Point(x, y, x * x * x - 3 * x * y * y)));
    }
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      m.add_face(v[i + (n + 1) * j], v[i + 1 + (n + 1) * j], v[i + 1 + (n + 1) * (j + 1)],
                 v[i + (n + 1) * (j + 1)]);
  Maps mp = maps(m);
  const TS::Clustering_result r = cluster(m, mp, 50);
  EXPECT_EQ(r.path, TS::DESCRIPTOR_PATH);
  EXPECT_EQ(number_of_clusters(m, mp), 50u);
  EXPECT_EQ(r.degree_of_flexibility, brute_force_dof(m, mp, 50));
}

// The sheet z = a (y - 1) (4 - |x - 4|) over [0, 8] x [0, 4], cut into 1 x 2
// rectangles (8 columns, 2 rows), every face labelled from its corner of
// least x and y, counterclockwise: z_xy is +a left of x = 4 and -a right of
// it, so det[v1 - v0, v2 - v0, v3 - v0] = -4 z_xy is -0.2 on the left and
// +0.2 on the right, in every face's own labelling. A 1 x 2 rectangle matches
// another only by correspondences that keep the sign of the signed volume
// (shifts by 0 or 2, the reversals i -> 1 - i and i -> 3 - i), so the left
// and right faces cannot share a mold without flattening. Clustered by rows,
// both clusters mix twists; the twist separation must end with K = 2
// clusters, each of one sign: the left half and the right half (a left face
// of one row is nearer the left faces of the other row than any right face
// it may join).
TEST(TwistSeparation, ClustersByRowsBecomeTheTwoHalves)
{
  const double a = 0.05;
  auto height = [&](double x, double y) { return a * (y - 1) * (4 - std::abs(x - 4)); };
  std::vector<TS::Panel> quads;
  for(int row = 0; row < 2; ++row)
    for(int column = 0; column < 8; ++column)
    {
      TS::Panel q;
      const double x[4] = {double(column), column + 1.0, column + 1.0, double(column)};
      const double y[4] = {2.0 * row, 2.0 * row, 2.0 * row + 2, 2.0 * row + 2};
      for(int i = 0; i < 4; ++i) q[i] = Eigen::Vector3d(x[i], y[i], height(x[i], y[i]));
      quads.push_back(q);
    }
  auto twist = [&](std::size_t f) {
    const TS::Panel& q = quads[f];
    Eigen::Matrix3d m;
    m << q[1] - q[0], q[2] - q[0], q[3] - q[0];
    return m.determinant();
  };
  std::vector<std::size_t> by_rows(16);
  for(std::size_t f = 0; f < 16; ++f)
  {
    by_rows[f] = f / 8;
    ASSERT_GT(std::abs(twist(f)), 0.01) << "face " << f;
  }
  const std::vector<std::size_t> separated =
    TS::internal::Twist_separation(quads, TS::PROPER_RIGID_MOTIONS)(by_rows, 2);
  ASSERT_EQ(separated.size(), 16u);
  for(std::size_t f = 0; f < 16; ++f)
  {
    const bool left = f % 8 < 4;
    EXPECT_NEAR(twist(f), left ? -4 * a : 4 * a, 1e-12) << "face " << f;
    EXPECT_EQ(separated[f] == separated[0], left) << "face " << f;
  }
  // A clustering that keeps the signs apart is left as it is (no candidate).
  std::vector<std::size_t> halves(16);
  for(std::size_t f = 0; f < 16; ++f) halves[f] = f % 8 < 4 ? 0 : 1;
  EXPECT_TRUE(TS::internal::Twist_separation(quads, TS::PROPER_RIGID_MOTIONS)(halves, 2).empty());
}

namespace {

// cluster_panels() of the monkey saddle (100 quads) at K = 6, with the
// parameters `np` besides the maps.
template <typename NP>
TS::Clustering_result saddle_clustering(Mesh& m, const NP& np)
{
  Maps mp = maps(m);
  return TS::cluster_panels(m, np.face_cluster_map(mp.cluster).face_orientation_map(mp.orientation));
}

auto at_six() { return TS::parameters::number_of_tiles(6); }

// The number of candidates of the pool from `origin`.
std::size_t from_origin(const TS::Clustering_result& r, TS::Clustering_candidate::Origin origin)
{
  return std::size_t(std::count_if(r.candidates.begin(), r.candidates.end(),
                                   [&](const TS::Clustering_candidate& c) { return c.origin == origin; }));
}

} // namespace

// number_of_candidates is the width of the beam, whose last configurations
// are the hierarchical candidates; the switches leave out the k-means and
// the quad-strip candidates.
TEST(ClusterQuads, BeamWidthAndSwitchesShapeTheCandidatePool)
{
  typedef TS::Clustering_candidate C;
  Mesh m = read("monkey_saddle");
  const TS::Clustering_result full = saddle_clustering(m, at_six());
  ASSERT_GT(from_origin(full, C::HIERARCHICAL), 1u) << "the fixture must have a beam wider than 1";
  ASSERT_EQ(from_origin(full, C::KMEANS), 1u);
  ASSERT_GE(from_origin(full, C::QUAD_STRIPS), 1u);

  const TS::Clustering_result narrow = saddle_clustering(m, at_six().number_of_candidates(1));
  EXPECT_EQ(from_origin(narrow, C::HIERARCHICAL), 1u);
  const TS::Clustering_result no_kmeans = saddle_clustering(m, at_six().use_kmeans_candidate(false));
  EXPECT_EQ(from_origin(no_kmeans, C::KMEANS), 0u);
  EXPECT_EQ(from_origin(no_kmeans, C::HIERARCHICAL), from_origin(full, C::HIERARCHICAL));
  const TS::Clustering_result no_strips = saddle_clustering(m, at_six().use_strip_candidates(false));
  EXPECT_EQ(from_origin(no_strips, C::QUAD_STRIPS), 0u);
  EXPECT_EQ(from_origin(no_strips, C::KMEANS), 1u);
}

// use_auto_merge: while more than tuning::beam_exhaustive_groups clusters
// remain, the beam also proposes every pair of clusters whose S-quad edges
// lie in the same 4 components of the edge-sharing graph, which keeps the
// degree of flexibility. On planarizednormalized_six_quad (656 quads, more
// initial clusters than that) at K = 26 these proposals enter the beam: its
// configurations change, and its most flexible one has a larger DOF than
// any without them (9 against 6 measured).
TEST(ClusterQuads, AutoMergeProposalsKeepFlexibilityInTheBeam)
{
  Mesh m;
  const std::string path = std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/planarizednormalized_six_quad.obj";
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(path, m)) << path;
  std::set<std::vector<std::size_t> > beam[2];
  std::size_t most_flexible[2] = {0, 0};
  for(bool auto_merge : {false, true})
  {
    const TS::Clustering_result r =
      saddle_clustering(m, TS::parameters::number_of_tiles(26).use_auto_merge(auto_merge));
    ASSERT_GT(r.number_of_initial_clusters, std::size_t(TS::internal::tuning::beam_exhaustive_groups));
    for(const TS::Clustering_candidate& c : r.candidates)
      if(c.origin == TS::Clustering_candidate::HIERARCHICAL)
      {
        beam[auto_merge].insert(c.face_cluster);
        most_flexible[auto_merge] = (std::max)(most_flexible[auto_merge], c.degree_of_flexibility);
      }
    ASSERT_GT(beam[auto_merge].size(), 1u);
  }
  EXPECT_NE(beam[true], beam[false]);
  EXPECT_GT(most_flexible[true], most_flexible[false]);
}

// exact_clustering_limit decides the path of AUTOMATIC_PATH: at or above
// the number of faces the weights are the pairwise sums computed here; below
// it they are the descriptor path's estimates, an upper bound of those sums.
TEST(ClusterQuads, ExactClusteringLimitDecidesThePath)
{
  Mesh m = read("monkey_saddle");
  ASSERT_EQ(m.number_of_faces(), 100u);
  for(std::size_t limit : {std::size_t(100), std::size_t(99)})
  {
    Maps mp = maps(m);
    const TS::Clustering_result r = TS::cluster_panels(
      m, TS::parameters::number_of_tiles(6).exact_clustering_limit(limit).face_cluster_map(mp.cluster)
           .face_orientation_map(mp.orientation));
    const double w = exact_weight(m, mp);
    const bool exact = limit >= 100;
    EXPECT_EQ(r.path, exact ? TS::EXACT_PATH : TS::DESCRIPTOR_PATH) << limit;
    EXPECT_EQ(r.weights_are_exact, exact) << limit;
    if(exact)
      EXPECT_NEAR(r.total_weight, w, 1e-9 * w);
    else
      EXPECT_GT(r.total_weight, w * (1 + 1e-6)) << "an estimate from above, not the pairwise sum";
  }
}

// The score is W / W1 + flexibility_penalty x (D0 - D) / D0 +
// structure_penalty x V / V1 (cluster_panels()): without both penalties the
// chosen candidate has the least weight, computed here from its labelling;
// with an overwhelming flexibility penalty the largest DOF, with an
// overwhelming structure penalty the least length deviation.
TEST(ClusterQuads, PenaltiesOfTheScoreDecideTheChoice)
{
  Mesh m = read("monkey_saddle");
  const auto selectable = [](const TS::Clustering_candidate& c) {
    return c.origin != TS::Clustering_candidate::GRID_SWEEPS;
  };
  const TS::Clustering_result by_weight =
    saddle_clustering(m, at_six().flexibility_penalty(0.0).structure_penalty(0.0));
  std::vector<double> weight;
  for(const TS::Clustering_candidate& c : by_weight.candidates)
    weight.push_back(selectable(c) ? labelling_weight(m, c.face_cluster) : HUGE_VAL);
  const double least = *std::min_element(weight.begin(), weight.end());
  EXPECT_LE(weight[by_weight.chosen_candidate], least * (1 + 1e-9));

  const TS::Clustering_result by_dof =
    saddle_clustering(m, at_six().flexibility_penalty(1e9).structure_penalty(0.0));
  std::size_t most = 0;
  for(const TS::Clustering_candidate& c : by_dof.candidates)
    if(selectable(c)) most = (std::max)(most, c.degree_of_flexibility);
  EXPECT_EQ(by_dof.candidates[by_dof.chosen_candidate].degree_of_flexibility, most);

  const TS::Clustering_result by_length =
    saddle_clustering(m, at_six().flexibility_penalty(0.0).structure_penalty(1e9));
  double smallest = HUGE_VAL;
  for(const TS::Clustering_candidate& c : by_length.candidates)
    if(selectable(c)) smallest = (std::min)(smallest, c.length_deviation);
  EXPECT_EQ(by_length.candidates[by_length.chosen_candidate].length_deviation, smallest);

  // The penalties changed the choice on this fixture: not all three agree.
  const std::vector<std::size_t>& a = by_weight.candidates[by_weight.chosen_candidate].face_cluster;
  EXPECT_TRUE(a != by_dof.candidates[by_dof.chosen_candidate].face_cluster ||
              a != by_length.candidates[by_length.chosen_candidate].face_cluster);
}

// random_seed draws the k-means start: the same seed gives the same k-means
// candidate, and some seeds give another one on this fixture.
TEST(ClusterQuads, RandomSeedDrawsTheKMeansStart)
{
  Mesh m = read("monkey_saddle");
  const auto kmeans = [&](unsigned int seed) {
    const TS::Clustering_result r = saddle_clustering(m, at_six().random_seed(seed));
    for(const TS::Clustering_candidate& c : r.candidates)
      if(c.origin == TS::Clustering_candidate::KMEANS)
        return c.face_cluster;
    ADD_FAILURE() << "no k-means candidate with seed " << seed;
    return std::vector<std::size_t>();
  };
  const std::vector<std::size_t> first = kmeans(1);
  EXPECT_EQ(kmeans(1), first);
  std::set<std::vector<std::size_t> > distinct{kmeans(TS::defaults::random_seed), first};
  for(unsigned int seed = 2; seed < 6; ++seed) distinct.insert(kmeans(seed));
  EXPECT_GT(distinct.size(), 1u);
}


// face_index_map numbers the faces for the package: the clustering does not
// depend on the numbering (faces are put in a canonical order first), so a
// reversed numbering gives the same partition of the faces; a map that gives
// two faces one index is refused before it is used, the mesh untouched.
TEST(ClusterQuads, TheUsersFaceIndexMapNumbersTheFaces)
{
  Mesh m = read("monkey_saddle");
  const std::size_t n = m.number_of_faces();
  auto reversed = m.add_property_map<Face, std::size_t>("f:reversed_index").first;
  auto repeated = m.add_property_map<Face, std::size_t>("f:repeated_index").first;
  for(Face f : faces(m))
  {
    put(reversed, f, n - 1 - std::size_t(f));
    put(repeated, f, std::size_t(f) == 1 ? 0 : std::size_t(f));
  }
  Maps mp = maps(m);
  const auto labels = [&](const auto& np) {
    TS::cluster_panels(m, np.face_cluster_map(mp.cluster).face_orientation_map(mp.orientation));
    std::vector<std::size_t> l;
    for(Face f : faces(m)) l.push_back(get(mp.cluster, f));
    return l;
  };
  const std::vector<std::size_t> own = labels(at_six()), by_reversed = labels(at_six().face_index_map(reversed));
  ASSERT_EQ(std::set<std::size_t>(own.begin(), own.end()).size(), 6u);
  for(std::size_t a = 0; a < n; ++a)
    for(std::size_t b = a + 1; b < n; ++b)
      ASSERT_EQ(own[a] == own[b], by_reversed[a] == by_reversed[b]) << "faces " << a << " and " << b;

  const std::vector<std::size_t> before = labels(at_six());
  const Mesh input = m;
  try
  {
    labels(at_six().face_index_map(repeated));
    ADD_FAILURE() << "a face index map that repeats an index was accepted";
  }
  catch(const TS::Invalid_input& e)
  {
    EXPECT_NE(std::string(e.what()).find("face indices are not 0..n-1"), std::string::npos) << e.what();
  }
  std::vector<std::size_t> after;
  for(Face f : faces(m)) after.push_back(get(mp.cluster, f));
  EXPECT_EQ(after, before);
  for(auto v : vertices(m)) EXPECT_EQ(m.point(v), input.point(v));
}

} // namespace test_cluster_panels_unit
