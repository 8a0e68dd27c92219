// Panel shape analysis: facts that can be checked by hand or by construction.
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <random>
#include <set>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_quad_shape_unit {

namespace TS = CGAL::Tilable_surfaces;
using Eigen::Vector3d;

namespace {

// A generic non-planar quad with no symmetry (all edges and diagonals distinct).
TS::Panel skew_quad()
{
  return TS::Panel{{Vector3d(0, 0, 0), Vector3d(1.3, 0.1, 0.05), Vector3d(1.5, 0.9, 0.3),
                   Vector3d(-0.1, 1.1, -0.2)}};
}

Eigen::Matrix3d random_rotation(std::mt19937& rng)
{
  std::normal_distribution<double> n(0, 1);
  Eigen::Quaterniond r(n(rng), n(rng), n(rng), n(rng));
  return r.normalized().toRotationMatrix();
}

TS::Panel moved(const TS::Panel& q, const Eigen::Matrix3d& r, const Vector3d& t)
{
  TS::Panel m;
  for(int i = 0; i < 4; ++i) m[i] = r * q[i] + t;
  return m;
}

TS::Panel mirrored_x(const TS::Panel& q)
{
  TS::Panel m = q;
  for(auto& p : m) p.x() = -p.x();
  return m;
}

// The face that carries template q with correspondence o: v[o(i)] = q[i].
TS::Panel face_with_orientation(const TS::Panel& q, TS::Panel_orientation o)
{
  TS::Panel v;
  for(int i = 0; i < 4; ++i) v[o(i)] = q[i];
  return v;
}

// Sign of a permutation of 0..3, by counting inversions.
int permutation_sign(const std::array<int, 4>& p)
{
  int inversions = 0;
  for(int i = 0; i < 4; ++i)
    for(int j = i + 1; j < 4; ++j)
      if(p[i] > p[j]) ++inversions;
  return inversions % 2 == 0 ? 1 : -1;
}

} // namespace

TEST(QuadOrientation, MatchesTheDefinitionOfMethodNotes)
{
  for(int o = 0; o < 8; ++o)
    for(int i = 0; i < 4; ++i)
    {
      const int expected = o < 4 ? (i + o) % 4 : ((o - i) % 4 + 4) % 4;
      EXPECT_EQ(TS::Panel_orientation(o)(i), expected) << "o=" << o << " i=" << i;
    }
  EXPECT_THROW(TS::Panel_orientation(8), TS::Invalid_input);
  EXPECT_THROW(TS::Panel_orientation(-1), TS::Invalid_input);
}

TEST(QuadOrientation, InverseAndCompositionArePermutationAlgebra)
{
  for(int a = 0; a < 8; ++a)
  {
    const TS::Panel_orientation oa(a);
    for(int i = 0; i < 4; ++i)
      EXPECT_EQ(oa.inverse()(oa(i)), i);
    EXPECT_EQ(oa * oa.inverse(), TS::Panel_orientation(0));
    for(int b = 0; b < 8; ++b)
    {
      const TS::Panel_orientation ob(b);
      for(int i = 0; i < 4; ++i)
        EXPECT_EQ((oa * ob)(i), oa(ob(i)));
    }
  }
}

TEST(QuadOrientation, TemplateEdgesGoToTheFaceEdgeWithTheSameEndpoints)
{
  for(int o = 0; o < 8; ++o)
  {
    const TS::Panel_orientation orientation(o);
    for(int k = 0; k < 4; ++k)
    {
      const int j = orientation.face_edge(k);
      const std::set<int> template_ends{orientation(k), orientation((k + 1) % 4)};
      const std::set<int> face_ends{j, (j + 1) % 4};
      EXPECT_EQ(template_ends, face_ends) << "o=" << o << " k=" << k;
      EXPECT_EQ(orientation.template_edge(j), k);
    }
  }
}

TEST(QuadShape, HandComputedLengthsVolumeAndPlanarity)
{
  const double h = 0.25;
  const TS::Panel q{{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, h)}};
  const auto e = TS::edge_lengths(q);
  EXPECT_DOUBLE_EQ(e[0], 1.0);
  EXPECT_DOUBLE_EQ(e[1], 1.0);
  EXPECT_DOUBLE_EQ(e[2], std::sqrt(1 + h * h));
  EXPECT_DOUBLE_EQ(e[3], std::sqrt(1 + h * h));
  const auto d = TS::diagonal_lengths(q);
  EXPECT_DOUBLE_EQ(d[0], std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(d[1], std::sqrt(2 + h * h));
  // det[(1,0,0), (1,1,0), (0,1,h)] = h.
  EXPECT_DOUBLE_EQ(TS::signed_volume(q), h / 6);
  // t3 lies h above the plane z = 0 of t0, t1, t2.
  EXPECT_NEAR(TS::planarity_defect(q), h, 1e-15);
  // The diagonals: t0 + s (1,1,0) and t1 + u (-1,1,h); their common normal
  // (h, -h, 2) and the offset t1 - t0 = (1,0,0) give h / sqrt(2 h^2 + 4).
  EXPECT_DOUBLE_EQ(TS::diagonal_distance(q), h / std::sqrt(2 * h * h + 4));
  TS::Panel flat = q;
  flat[3].z() = 0;
  EXPECT_EQ(TS::planarity_defect(flat), 0.0);
  EXPECT_EQ(TS::diagonal_distance(flat), 0.0);
}

// The relative twist 6 V / mean edge^3 of the quad above, by hand; it keeps
// its value under scaling and a rigid motion, flips under a mirror, and is 0
// for a triangle.
TEST(QuadShape, RelativeTwistIsTheScaleFreeSignedVolume)
{
  const double h = 0.25;
  const TS::Panel q{{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, h)}};
  const double mean = (2 + 2 * std::sqrt(1 + h * h)) / 4;
  EXPECT_DOUBLE_EQ(TS::relative_twist(q), h / (mean * mean * mean));
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd(0.7, Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  TS::Panel moved = q;
  for(int i = 0; i < 4; ++i)
    moved[i] = 3.5 * (rotation * q[i]) + Vector3d(-2, 5, 1);
  EXPECT_NEAR(TS::relative_twist(moved), TS::relative_twist(q), 1e-14);
  EXPECT_NEAR(TS::relative_twist(mirrored_x(q)), -TS::relative_twist(q), 1e-15);
  const TS::Panel triangle(Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, h));
  EXPECT_EQ(TS::relative_twist(triangle), 0.0);
}

TEST(QuadShape, SignedVolumeFollowsTheSignOfTheRelabelling)
{
  const TS::Panel q = skew_quad();
  const double v = TS::signed_volume(q);
  ASSERT_GT(std::abs(v), 1e-3);
  for(int o = 0; o < 8; ++o)
  {
    const TS::Panel_orientation orientation(o);
    const std::array<int, 4> p{{orientation(0), orientation(1), orientation(2), orientation(3)}};
    EXPECT_NEAR(TS::signed_volume(TS::reoriented(q, orientation)), permutation_sign(p) * v, 1e-15)
      << "o=" << o;
  }
  // A cyclic shift by one and the reversal o = 4 are odd: the sign flips.
  EXPECT_LT(TS::signed_volume(TS::reoriented(q, TS::Panel_orientation(1))) * v, 0);
  EXPECT_LT(TS::signed_volume(TS::reoriented(q, TS::Panel_orientation(4))) * v, 0);
  // A mirror flips it too.
  EXPECT_NEAR(TS::signed_volume(mirrored_x(q)), -v, 1e-15);
}

TEST(QuadShape, RigidCopyHasZeroDissimilarityAndTheAppliedOrientation)
{
  std::mt19937 rng(1);
  const TS::Panel q = skew_quad();
  for(int trial = 0; trial < 5; ++trial)
  {
    const Eigen::Matrix3d r = random_rotation(rng);
    const Vector3d t(3.0 * trial, -2.0, 7.5);
    for(int o = 0; o < 8; ++o)
    {
      const TS::Panel face = face_with_orientation(moved(q, r, t), TS::Panel_orientation(o));
      const TS::Quad_match match = TS::best_match(q, face);
      EXPECT_LT(match.dissimilarity, 1e-12) << "o=" << o;
      EXPECT_EQ(match.orientation.index(), o);
      EXPECT_NEAR(match.fit.rotation.determinant(), 1.0, 1e-12);
      EXPECT_LT((match.fit.rotation - r).norm(), 1e-10);
    }
  }
}

TEST(QuadShape, MirrorImageIsNotACopyUnlessPlanar)
{
  const TS::Panel q = skew_quad();
  const TS::Quad_match match = TS::best_match(q, mirrored_x(q));
  EXPECT_GT(match.dissimilarity, 1e-2);
  EXPECT_NEAR(match.fit.rotation.determinant(), 1.0, 1e-12);
  // ... but with mirrored panels allowed it is one.
  EXPECT_LT(TS::dissimilarity(q, mirrored_x(q), TS::ALLOW_MIRRORED_PANELS), 1e-12);

  TS::Panel planar = q;
  for(auto& p : planar) p.z() = 0;
  EXPECT_LT(TS::dissimilarity(planar, mirrored_x(planar)), 1e-12);
}

TEST(QuadShape, TurnedOverCopiesNeedTheReversedOrientations)
{
  const TS::Panel q = skew_quad();
  const TS::Panel face = face_with_orientation(q, TS::Panel_orientation(5));
  EXPECT_LT(TS::dissimilarity(q, face), 1e-12);
  EXPECT_GT(TS::dissimilarity(q, face, TS::NO_TURNED_OVER_PANELS), 1e-2);
  EXPECT_LT(TS::best_match(q, face, TS::NO_TURNED_OVER_PANELS).orientation.index(), 4);
}

TEST(QuadShape, DissimilarityIsSymmetricWithInverseOrientation)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for(int trial = 0; trial < 20; ++trial)
  {
    TS::Panel p, q;
    for(int i = 0; i < 4; ++i)
    {
      p[i] = skew_quad()[i] + 0.3 * Vector3d(u(rng), u(rng), u(rng));
      q[i] = skew_quad()[i] + 0.3 * Vector3d(u(rng), u(rng), u(rng));
    }
    const TS::Quad_match pq = TS::best_match(p, q), qp = TS::best_match(q, p);
    EXPECT_NEAR(pq.dissimilarity, qp.dissimilarity, 1e-12);
    EXPECT_GT(pq.dissimilarity, 0.0);
  }
}

TEST(QuadShape, DissimilarityGrowsWithPerturbation)
{
  const TS::Panel q = skew_quad();
  const std::array<Vector3d, 4> direction{{Vector3d(0.3, -0.2, 0.5), Vector3d(-0.4, 0.1, 0.2),
                                           Vector3d(0.2, 0.6, -0.3), Vector3d(-0.1, -0.5, 0.4)}};
  double previous = TS::dissimilarity(q, q);
  EXPECT_LT(previous, 1e-14);
  for(double eps : {1e-4, 1e-3, 1e-2, 1e-1})
  {
    TS::Panel p = q;
    for(int i = 0; i < 4; ++i) p[i] += eps * direction[i];
    const double s = TS::dissimilarity(q, p);
    EXPECT_GT(s, previous) << "eps=" << eps;
    previous = s;
  }
}

TEST(QuadShape, CongruenceErrorOfExactCopiesIsRoundOff)
{
  std::mt19937 rng(3);
  const TS::Panel q = skew_quad();
  std::vector<TS::Panel> copies;
  for(int i = 0; i < 50; ++i)
    copies.push_back(moved(q, random_rotation(rng), Vector3d(i, 2.0 * i, -3.0)));
  EXPECT_LT(TS::congruence_error(copies, q), 1e-13);

  // One instance off by delta at one corner. Upper bound: the least-squares
  // fit has a sum of squared residuals <= delta^2 (the exact motion achieves
  // it), so no residual exceeds delta. Lower bound: a rigid motion keeps
  // distances, so |d'_ij - d_ij| <= |r_i| + |r_j| <= 2 max |r|.
  const double delta = 0.01;
  const TS::Panel before = copies[17];
  copies[17][2] += Vector3d(0.6, -0.48, 0.64) * delta;
  double distance_change = 0;
  for(int j = 0; j < 4; ++j)
    distance_change = (std::max)(distance_change,
      std::abs((copies[17][2] - copies[17][j]).norm() - (before[2] - before[j]).norm()));
  const double error = TS::congruence_error(copies, q);
  EXPECT_GE(error, distance_change / 2 - 1e-12);
  EXPECT_GT(distance_change, 0.1 * delta);
  EXPECT_LE(error, delta + 1e-12);
  // The length scale divides the error.
  EXPECT_NEAR(TS::congruence_error(copies, q, 2.0), error / 2, 1e-15);
}

TEST(QuadShape, DescriptorIsInvariantUnderMotionAndRelabelling)
{
  std::mt19937 rng(5);
  const TS::Panel q = skew_quad();
  const TS::Quad_descriptor d = TS::shape_descriptor(q);
  for(int o = 0; o < 8; ++o)
  {
    const TS::Panel other = TS::reoriented(moved(q, random_rotation(rng), Vector3d(1, 2, 3)),
                                          TS::Panel_orientation(o));
    const TS::Quad_descriptor e = TS::shape_descriptor(other);
    for(int i = 0; i < 7; ++i)
      EXPECT_NEAR(d[i], e[i], 1e-12);
  }
  EXPECT_TRUE(std::is_sorted(d.begin(), d.begin() + 4));
  EXPECT_LE(d[4], d[5]);
  EXPECT_NEAR(d[6], std::cbrt(6 * std::abs(TS::signed_volume(q))), 1e-15);
}

// The correspondences between two panels of n corners are the symmetries of
// the n-gon, the dihedral group: 2n of them, of which the n rotations keep
// the cyclic order. So: 8 and 4 for quads, 6 and 3 for triangles; and every
// admissible one is a permutation of the corners that maps neighbours to
// neighbours.
TEST(QuadOrientation, AdmissibleCorrespondencesAreTheSymmetriesOfThePolygon)
{
  for(int n : {3, 4})
    for(TS::Orientation_policy policy :
        {TS::PROPER_RIGID_MOTIONS, TS::NO_TURNED_OVER_PANELS, TS::ALLOW_MIRRORED_PANELS})
    {
      int admissible = 0;
      for(int index = 0; index < 8; ++index)
      {
        const TS::Panel_orientation o(index);
        if(!TS::is_admissible(o, n, policy))
          continue;
        ++admissible;
        std::set<int> image;
        for(int i = 0; i < n; ++i)
        {
          image.insert(o(i, n));
          const int step = (o((i + 1) % n, n) - o(i, n) + n) % n;
          EXPECT_EQ(step, o.is_reversed() ? n - 1 : 1) << "n " << n << " orientation " << index;
        }
        EXPECT_EQ(int(image.size()), n);
      }
      EXPECT_EQ(admissible, policy == TS::NO_TURNED_OVER_PANELS ? n : 2 * n) << "n " << n;
    }
}

// The in-place list of face edges keeps what was pushed, in order, up to
// its bound, and is a range.
TEST(BoundedList, KeepsValuesInOrderUpToItsBound)
{
  TS::internal::Bounded_list<int, 4> list;
  EXPECT_EQ(list.size(), 0u);
  EXPECT_EQ(list.begin(), list.end());
  for(int x : {7, 3, 5, 9})
    list.push_back(x);
  EXPECT_EQ(list.size(), 4u);
  EXPECT_EQ(std::vector<int>(list.begin(), list.end()), (std::vector<int>{7, 3, 5, 9}));
  EXPECT_EQ(list[2], 5);
  const TS::internal::Bounded_list<int, 4> copy = list;
  int sum = 0;
  for(int x : copy) sum += x;
  EXPECT_EQ(sum, 24);
}

} // namespace test_quad_shape_unit
