// Sweep clusterings of quad grids and their exact start
// (internal/Clustering/sweep_candidates.h, internal/Optimization/sweep_start.h):
// every cluster in one column of a run of rows, or in a run of columns of
// one run of rows, exact on a swept surface built directly, which
// make_k_set_tilable() falls back to.

#include "congruence_check.h"
#include "grid_mesh.h"
#include "hausdorff_oracle.h"
#include "optimization_test_helpers.h"
#include "sweep_pipeline_check.h"
#include "tube_mesh.h"

#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/boost/graph/generators.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_sweep_start_unit {

using namespace test_helpers;
namespace TSI = CGAL::Tilable_surfaces::internal;

namespace {

const int rings = 9, around = 8;

// A bent tube whose section grows by 60% and moves off-centre: no two
// rings are congruent, so no column clustering is exact at the input.
Mesh growing_horn()
{
  return horn<Mesh>(rings, around, 3.0, 2.0, [](int i) { return 1.0 + 0.075 * i; });
}

std::vector<std::vector<std::size_t> > sweeps(const Mesh& m, std::size_t k)
{
  return TSI::sweep_clusterings(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m), k,
                                TS::PROPER_RIGID_MOTIONS);
}

// Whether a cluster of `label` (a tube of loops of `around` quads, face
// i * around + j) is one whole loop: a coaxial transition row.
bool has_loop_cluster(const std::vector<std::size_t>& label, int around)
{
  for(std::size_t first = 0; first < label.size(); first += std::size_t(around))
    if(std::count(label.begin(), label.end(), label[first]) == around &&
       std::count(label.begin() + std::ptrdiff_t(first), label.begin() + std::ptrdiff_t(first) + around,
                  label[first]) == around)
      return true;
  return false;
}

// The sweeps of `m`, a tube of loops of `around` quads (face i * around + j),
// whose rows are its loops: not those whose rows run along the tube and
// close up around it (rotation sweeps), each of whose clusters holds whole
// loops or lies within one. With `coaxial`, only the coaxial transition
// sweeps (has_loop_cluster()), else only the others.
std::vector<std::vector<std::size_t> > loop_sweeps(const Mesh& m, std::size_t k, int around, bool coaxial = false)
{
  std::vector<std::vector<std::size_t> > result;
  for(const std::vector<std::size_t>& label : sweeps(m, k))
  {
    if(has_loop_cluster(label, around) != coaxial)
      continue;
    std::map<std::size_t, std::set<std::size_t> > loops;
    std::map<std::size_t, std::size_t> size;
    for(std::size_t f = 0; f < label.size(); ++f)
    {
      loops[label[f]].insert(f / std::size_t(around));
      ++size[label[f]];
    }
    bool around_the_tube = true;
    for(const auto& cluster : loops)
      around_the_tube = around_the_tube && (cluster.second.size() == 1 ||
                                            size[cluster.first] == cluster.second.size() * std::size_t(around));
    if(!around_the_tube)
      result.push_back(label);
  }
  return result;
}

TSI::Point_matrix start_of(const Mesh& m, const std::vector<std::size_t>& label)
{
  return TSI::sweep_start(m, get(CGAL::face_index, m), get(CGAL::vertex_index, m), get(CGAL::vertex_point, m),
                          TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m)), label);
}

// The largest distance between ring i of `points` (vertex index
// i * around + j, tube_mesh.h) fitted rigidly onto ring 0, and ring i.
double ring_spread(const TSI::Point_matrix& points)
{
  auto ring = [&](int i) { return Eigen::Matrix3Xd(points.middleRows(i * around, around).transpose()); };
  double worst = 0;
  for(int i = 1; i <= rings; ++i)
  {
    const Eigen::Matrix4d t = Eigen::umeyama(ring(0), ring(i), false);
    const Eigen::Matrix3Xd fitted = (t.topLeftCorner<3, 3>() * ring(0)).colwise() + t.topRightCorner<3, 1>();
    worst = (std::max)(worst, (fitted - ring(i)).colwise().norm().maxCoeff());
  }
  return worst;
}

} // namespace

// With K = 8 molds on rings of 8 quads, the one sweep along the horn is the
// columns: face (i, j) in cluster j (numbered by first face). The other
// grid direction, rows along the horn closed around it, has one rotation
// sweep whose 9 columns are cut into 8 runs.
TEST(SweepStart, EightMoldsAreTheEightColumns)
{
  const Mesh m = growing_horn();
  EXPECT_EQ(sweeps(m, 8).size(), 2u);
  const std::vector<std::vector<std::size_t> > labels = loop_sweeps(m, 8, around);
  ASSERT_EQ(labels.size(), 1u);
  for(int f = 0; f < rings * around; ++f)
    EXPECT_EQ(labels[0][std::size_t(f)], std::size_t(f % around)) << "face " << f;
}

// With 19 = 2 x 8 + 3 molds: two runs of whole rows, 3 of the 16 column
// pieces split in two; every cluster lies in one column and in consecutive
// rows.
TEST(SweepStart, LeftoverMoldsSplitColumns)
{
  const Mesh m = growing_horn();
  const std::vector<std::vector<std::size_t> > labels = loop_sweeps(m, 19, around);
  ASSERT_EQ(labels.size(), 1u);
  const std::vector<std::size_t>& l = labels[0];
  EXPECT_EQ(std::set<std::size_t>(l.begin(), l.end()).size(), 19u);
  std::vector<std::set<int> > columns(19), rows_of(19);
  for(int f = 0; f < rings * around; ++f)
  {
    columns[l[std::size_t(f)]].insert(f % around);
    rows_of[l[std::size_t(f)]].insert(f / around);
  }
  for(std::size_t c = 0; c < 19; ++c)
  {
    EXPECT_EQ(columns[c].size(), 1u) << "cluster " << c;
    EXPECT_EQ(int(rows_of[c].size()), *rows_of[c].rbegin() - *rows_of[c].begin() + 1) << "cluster " << c;
  }
}

// The start is a sweep of one section: every ring is congruent to the first
// (Umeyama, no scale), the input's are not (the section grows); and every
// cluster's instances are congruent there, checked independently.
TEST(SweepStart, StartIsOneSectionSweptAndExact)
{
  Mesh m = growing_horn();
  EXPECT_GT(ring_spread(TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m))), 0.1);
  for(std::size_t k : {8u, 19u})
  {
    const std::vector<std::size_t> label = loop_sweeps(m, k, around).at(0);
    const TSI::Point_matrix start = start_of(m, label);
    ASSERT_EQ(start.rows(), rings * around + around);
    EXPECT_LE(ring_spread(start), 1e-12);
    Mesh moved = moved_to(m, start);
    const Clustering c = clustered(moved, label);
    EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-12) << "K = " << k;
  }
}

namespace {

// The largest distance between ring a of `points` fitted rigidly onto ring
// b (Umeyama, no scale) and ring b.
double ring_fit(const TSI::Point_matrix& points, int a, int b)
{
  auto ring = [&](int i) { return Eigen::Matrix3Xd(points.middleRows(i * around, around).transpose()); };
  const Eigen::Matrix4d t = Eigen::umeyama(ring(a), ring(b), false);
  return ((t.topLeftCorner<3, 3>() * ring(a)).colwise() + t.topRightCorner<3, 1>() - ring(b)).colwise().norm().maxCoeff();
}

// The horn moved to `start`, the start of `label`, checked: every cluster
// congruent (Umeyama, independently), the rings on each side of
// `transition_row` congruent among themselves, but not all of them (the
// section grows across the transition).
Mesh expect_exact_with_growing_section(const Mesh& m, const TSI::Point_matrix& start,
                                       const std::vector<std::size_t>& label, int transition_row)
{
  Mesh moved = moved_to(m, start);
  const Clustering c = clustered(moved, label);
  EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-12);
  EXPECT_LE(ring_fit(start, 0, transition_row), 1e-12);
  EXPECT_LE(ring_fit(start, transition_row + 1, rings), 1e-12);
  EXPECT_GT(ring_fit(start, 0, rings), 0.1);
  return moved;
}

} // namespace

// With K = 24 = 3 x 8 molds the horn has, besides the sweep of three runs of
// one section, a transition sweep: two groups of rows, each one run, and
// between them one row whose 8 quads are molds of their own. Its start is
// exact (Umeyama, independently); the rings of a group are congruent, but
// the section grows across the transition row, so the start stays closer to
// the growing horn than the one-section sweep's.
TEST(SweepStart, TransitionRowLetsTheSectionGrow)
{
  const Mesh m = growing_horn();
  const TSI::Point_matrix input = TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m));
  std::vector<std::size_t> transition, one_section;
  int transition_row = -1;
  for(const std::vector<std::size_t>& label : loop_sweeps(m, 24, around))
  {
    std::map<std::size_t, int> size;
    for(std::size_t l : label) ++size[l];
    std::vector<int> singles(rings, 0);
    for(int f = 0; f < rings * around; ++f)
      singles[std::size_t(f / around)] += size[label[std::size_t(f)]] == 1 ? 1 : 0;
    const auto row = std::find(singles.begin(), singles.end(), around);
    if(row == singles.end())
      one_section = label;
    else
    {
      transition = label;
      transition_row = int(row - singles.begin());
      EXPECT_EQ(std::count(singles.begin(), singles.end(), 0), rings - 1) << "one transition row";
    }
  }
  ASSERT_FALSE(transition.empty());
  ASSERT_FALSE(one_section.empty());
  ASSERT_GE(transition_row, 2);
  ASSERT_LE(transition_row, rings - 3);
  const TSI::Point_matrix start = start_of(m, transition);
  ASSERT_EQ(start.rows(), input.rows());
  expect_exact_with_growing_section(m, start, transition, transition_row);
  const double transition_distance = (start - input).rowwise().norm().maxCoeff();
  const double one_section_distance = (start_of(m, one_section) - input).rowwise().norm().maxCoeff();
  EXPECT_LT(transition_distance, 0.75 * one_section_distance);
}

// The horn's loops are circles, so with K = 19 (two rows of 8 column molds
// and one more) it also has a coaxial transition sweep: two groups of loops,
// each one run of 8 column molds, and between them one loop that is a
// single mold, the 2 molds left splitting columns. At its start every
// cluster is congruent (Umeyama, independently), the rings of each group
// are congruent while the section grows across the transition loop, and
// the start is closer to the horn (symmetric Hausdorff distance by CGAL's
// sampling) than the one-section sweep with as many molds.
TEST(SweepStart, CoaxialTransitionLoopIsOneMold)
{
  const Mesh m = growing_horn();
  const std::vector<std::vector<std::size_t> > coaxial = loop_sweeps(m, 19, around, true);
  ASSERT_EQ(coaxial.size(), 1u);
  const std::vector<std::size_t>& label = coaxial[0];
  EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), 19u);
  int transition_row = -1;
  for(int i = 0; i < rings; ++i)
    if(std::count(label.begin() + i * around, label.begin() + (i + 1) * around, label[std::size_t(i * around)]) ==
       around)
      transition_row = i;
  ASSERT_GE(transition_row, 2);
  ASSERT_LE(transition_row, rings - 3);
  const TSI::Point_matrix start = start_of(m, label);
  ASSERT_EQ(start.rows(), rings * around + around);
  const Mesh moved = expect_exact_with_growing_section(m, start, label, transition_row);
  const Mesh one_section = moved_to(m, start_of(m, loop_sweeps(m, 19, around).at(0)));
  EXPECT_LT(hausdorff_oracle::distances(moved, m).hausdorff(),
            0.75 * hausdorff_oracle::distances(one_section, m).hausdorff());
}

namespace {

// Whether every cluster of `label` (on a grid of `columns` columns, face
// r * columns + c) is one run of consecutive columns of a closed ring, the
// same in every row, and there are `k` of them.
void expect_column_runs(const std::vector<std::size_t>& label, std::size_t columns, std::size_t k)
{
  EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), k);
  for(std::size_t f = columns; f < label.size(); ++f)
    EXPECT_EQ(label[f], label[f % columns]) << "face " << f;
  // k runs of consecutive columns have k ends.
  std::size_t ends = 0;
  for(std::size_t c = 0; c < columns; ++c)
    ends += label[c] != label[(c + 1) % columns] ? 1 : 0;
  EXPECT_EQ(ends, k);
}

} // namespace

// A straight prism over a square, 6 equal steps per side: ring to ring is a
// translation, and each side is already a line of equal steps, so with
// K = 8 (per side a run of 5 columns and a single one) the section needs
// no move: the start is the input.
TEST(SweepStart, PrismSidesAreColumnRunsAlready)
{
  const int steps = 6, columns = 4 * steps, rows = 5;
  const Mesh m = swept_tube<Mesh>(rows, columns, [&](int i, int j) {
    const double corner[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    const int side = j / steps;
    const double t = double(j % steps) / steps;
    return Point(corner[side][0] + t * (corner[side + 1][0] - corner[side][0]),
                 corner[side][1] + t * (corner[side + 1][1] - corner[side][1]), 0.3 * i);
  });
  const std::vector<std::vector<std::size_t> > labels = loop_sweeps(m, 8, columns);
  ASSERT_EQ(labels.size(), 1u);
  expect_column_runs(labels[0], columns, 8);
  const TSI::Point_matrix start = start_of(m, labels[0]);
  ASSERT_EQ(start.rows(), (rows + 1) * columns);
  EXPECT_LE((start - TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m))).cwiseAbs().maxCoeff(),
            1e-9);
}

// With more columns than molds (24 quads per ring, K = 10), the growing horn
// has one run of rows whose columns are cut into 10 runs of consecutive
// columns; the start is exact, checked independently, where the input is
// far from it (its section grows).
TEST(SweepStart, MoreColumnsThanMoldsAreCutIntoRuns)
{
  const int columns = 24;
  const Mesh m = horn<Mesh>(rings, columns, 3.0, 2.0, [](int i) { return 1.0 + 0.075 * i; });
  const std::vector<std::vector<std::size_t> > labels = loop_sweeps(m, 10, columns);
  ASSERT_EQ(labels.size(), 1u);
  expect_column_runs(labels[0], columns, 10);
  Mesh input = m;
  const Clustering at_input = clustered(input, labels[0]);
  EXPECT_GT(congruence_by_umeyama(input, at_input.cluster, at_input.orientation), 1e-2);
  const TSI::Point_matrix start = start_of(m, labels[0]);
  ASSERT_EQ(start.rows(), (rings + 1) * columns);
  Mesh moved = moved_to(m, start);
  const Clustering c = clustered(moved, labels[0]);
  EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-9);
}

// A flat fan: its rings are radial lines turned about the z axis, so a run
// of columns on a helix about that axis (at one distance from it) would
// collapse onto a point. With K = 5 for 12 quads per ring, no sweep
// clustering's start has an edge shorter than half the input's shortest.
TEST(SweepStart, ColumnRunsNeverCollapse)
{
  const int columns = 12, rows = 8;
  Mesh m;
  std::vector<Vertex> v;
  for(int i = 0; i <= rows; ++i)
    for(int j = 0; j <= columns; ++j)
      v.push_back(m.add_vertex(Point((1 + 0.1 * j) * std::cos(0.2 * i), (1 + 0.1 * j) * std::sin(0.2 * i), 0)));
  for(int i = 0; i < rows; ++i)
    for(int j = 0; j < columns; ++j)
      m.add_face(v[i * (columns + 1) + j], v[i * (columns + 1) + j + 1], v[(i + 1) * (columns + 1) + j + 1],
                 v[(i + 1) * (columns + 1) + j]);
  auto shortest_edge = [&](const TSI::Point_matrix& p) {
    double shortest = std::numeric_limits<double>::max();
    for(auto e : edges(m))
      shortest = (std::min)(shortest, (p.row(int(source(e, m))) - p.row(int(target(e, m)))).norm());
    return shortest;
  };
  const double input = shortest_edge(TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m)));
  const std::vector<std::vector<std::size_t> > labels = sweeps(m, 5);
  ASSERT_FALSE(labels.empty());
  for(const std::vector<std::size_t>& label : labels)
  {
    const TSI::Point_matrix start = start_of(m, label);
    ASSERT_GT(start.rows(), 0) << "every sweep clustering of the fan has its start";
    EXPECT_GE(shortest_edge(start), 0.5 * input);
  }
}

// A cluster across two columns has no sweep.
TEST(SweepStart, NoneWhenAClusterCrossesColumns)
{
  const Mesh m = growing_horn();
  std::vector<std::size_t> label = loop_sweeps(m, 8, around).at(0);
  label[1] = label[0];  // face (0, 1) joins column 0
  EXPECT_EQ(start_of(m, label).rows(), 0);
}

namespace {

const int torus_rows = 12;

// A torus of 12 x `around` quads about the z axis whose tube runs at the
// distance 3 + 0.5 cos 2t from it (an oval): loop i at t = 2 pi i / 12 is
// the circle of radius 1 about that point, in the plane through the z axis.
Mesh oval_torus(int around)
{
  return swept_tube<Mesh>(torus_rows, around, [&](int i, int j) {
    const double t = 2 * CGAL_PI * i / torus_rows, a = 2 * CGAL_PI * j / around;
    const double out = 3 + 0.5 * std::cos(2 * t) + std::cos(a);
    return Point(out * std::cos(t), out * std::sin(t), std::sin(a));
  }, true);
}

// The loops of `points` (vertex index i * around + j) as columns.
Eigen::Matrix3Xd loop(const TSI::Point_matrix& points, int i, int around)
{
  return points.middleRows(i * around, around).transpose();
}

// The largest distance between M^i applied to loop 0 and loop i, where M is
// the rigid motion that best maps loop 0 onto loop 1 (Umeyama, no scale).
double distance_from_rotation_sweep(const TSI::Point_matrix& points, int around)
{
  const Eigen::Matrix4d m = Eigen::umeyama(loop(points, 0, around), loop(points, 1, around), false);
  Eigen::Matrix4d power = Eigen::Matrix4d::Identity();
  double worst = 0;
  for(int i = 0; i <= torus_rows; ++i, power = m * power)
    worst = (std::max)(worst, (TSI::apply_motion(power, loop(points, 0, around)) -
                               loop(points, i % torus_rows, around)).colwise().norm().maxCoeff());
  return worst;
}

} // namespace

// A grid closed across its rows sweeps as a rotation that closes up: on the
// oval torus (no two loops congruent), with K = 8 molds for 8 quads per
// loop, the columns are a sweep clustering, exact at its start (checked
// independently), where each loop is the first turned by i twelfths of a
// turn about one axis. By the torus's symmetries that axis is z and the
// section is the mean loop, the circle at distance 3 (the mean of
// 0.5 cos 2t over the twelve loops is 0): every vertex moves by
// |0.5 cos 2t| at most, 0.5 at t = 0.
TEST(SweepStart, ClosedGridSweepsAsARotation)
{
  const int around = 8;
  const Mesh m = oval_torus(around);
  const TSI::Point_matrix input = TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m));
  EXPECT_GT(distance_from_rotation_sweep(input, around), 0.1);
  std::vector<std::size_t> columns(std::size_t(torus_rows * around));
  for(std::size_t f = 0; f < columns.size(); ++f)
    columns[f] = f % around;
  const std::vector<std::vector<std::size_t> > labels = sweeps(m, around);
  EXPECT_EQ(std::count(labels.begin(), labels.end(), columns), 1);
  const TSI::Point_matrix start = start_of(m, columns);
  ASSERT_EQ(start.rows(), torus_rows * around);
  EXPECT_LE(distance_from_rotation_sweep(start, around), 1e-9);
  EXPECT_NEAR((start - input).rowwise().norm().maxCoeff(), 0.5, 1e-9);
  Mesh moved = moved_to(m, start);
  const Clustering c = clustered(moved, columns);
  EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-9);
}

// With more columns than molds (16 quads per loop, K = 6), the closed sweep
// cuts its columns into 6 runs; its start is exact, checked independently,
// and still a rotation sweep.
TEST(SweepStart, ClosedGridWithMoreColumnsThanMolds)
{
  const int around = 16;
  const Mesh m = oval_torus(around);
  bool found = false;
  for(const std::vector<std::size_t>& label : sweeps(m, 6))
  {
    const TSI::Point_matrix start = start_of(m, label);
    if(start.rows() == 0 || label[1] != label[around + 1])
      continue;  // the other grid direction, or none
    found = true;
    expect_column_runs(label, around, 6);
    EXPECT_LE(distance_from_rotation_sweep(start, around), 1e-9);
    Mesh moved = moved_to(m, start);
    const Clustering c = clustered(moved, label);
    EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-9);
  }
  EXPECT_TRUE(found);
}

// make_k_set_tilable() on the oval torus at K = 8 with no solver iteration
// ends tilable, checked independently: only the closed sweep is exact.
TEST(SweepStart, PipelineMakesAClosedGridTilable)
{
  Mesh m = oval_torus(8);
  Clustering c = add_clustering_maps(m);
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    m, TS::parameters::number_of_tiles(8).number_of_iterations(0).face_cluster_map(c.cluster).face_orientation_map(c.orientation));
  EXPECT_TRUE(r.is_tilable());
  EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::GRID_SWEEPS);
  EXPECT_LE(congruence_by_umeyama(m, c.cluster, c.orientation), 1e-6);
}

// make_k_set_tilable() at K = 8 on the growing horn ends tilable, checked
// independently. With no solver iteration at all, only the sweep is exact
// (the input is not: its rings grow), so the result is the swept surface;
// without the sweeps it is the input, not tilable.
TEST(SweepStart, PipelineEndsTilableEvenWithoutIterations)
{
  for(int iterations : {300, 0})
  {
    Mesh m = growing_horn();
    Clustering c = add_clustering_maps(m);
    const TS::K_set_tilable_result r = TS::make_k_set_tilable(
      m, TS::parameters::number_of_tiles(8).number_of_iterations(iterations)
           .face_cluster_map(c.cluster).face_orientation_map(c.orientation));
    EXPECT_TRUE(r.is_tilable()) << iterations << " iterations";
    EXPECT_LE(congruence_by_umeyama(m, c.cluster, c.orientation), 1e-6) << iterations << " iterations";
    if(iterations > 0)
      continue;
    EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::GRID_SWEEPS);
    EXPECT_LE(ring_spread(TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m))), 1e-9);

    Mesh without = growing_horn();
    EXPECT_FALSE(TS::make_k_set_tilable(without, TS::parameters::number_of_tiles(8).number_of_iterations(0)
                                                   .use_segment_candidates(false)).is_tilable());
  }
}

// A solve from the exact start is kept only if it ends exact and closer to
// the input (symmetric Hausdorff distance) than the start: whatever the
// number of iterations, the result is tilable, checked independently, and no
// farther than the swept surface, by the package's measure and by the oracle.
TEST(SweepStart, SolveFromTheStartNeverEndsFarther)
{
  const Mesh input = growing_horn();
  const double tolerance = hausdorff_oracle::sampling_tolerance(input);
  for(std::size_t k : {8u, 19u})
  {
    const std::vector<std::size_t> label = loop_sweeps(input, k, around).at(0);
    const TSI::Point_matrix start = start_of(input, label);
    Mesh swept = moved_to(input, start);
    const Clustering s = clustered(swept, label);
    const double start_distance =
      TS::measure_tilability(swept, input, TS::parameters::face_cluster_map(s.cluster).face_orientation_map(s.orientation))
        .hausdorff_distance;
    const double start_by_oracle = hausdorff_oracle::distances(swept, input).hausdorff();
    for(int iterations : {1, 3, 10, 30, 60})
    {
      Mesh m = input;
      const Clustering c = clustered(m, label);
      const auto maps = TS::parameters::face_cluster_map(c.cluster).face_orientation_map(c.orientation);
      TSI::optimize_tilable_surface(TSI::Validated_mesh(true), m, maps.number_of_iterations(iterations), &start);
      EXPECT_LE(congruence_by_umeyama(m, c.cluster, c.orientation), 1e-6) << "K = " << k << ", " << iterations;
      EXPECT_LE(TS::measure_tilability(m, input, maps).hausdorff_distance, start_distance)
        << "K = " << k << ", " << iterations << " iterations";
      EXPECT_LE(hausdorff_oracle::distances(m, input).hausdorff(), start_by_oracle + tolerance)
        << "K = " << k << ", " << iterations << " iterations, by the oracle";
    }
  }
}

namespace {

// A grid of quads trimmed by the ellipse inscribed in its rows x columns
// box (a roof cut by its outline): face (i, j) kept when its centre is
// inside.
template <typename PointAt>
Mesh trimmed_grid(int rows, int columns, PointAt point)
{
  return grid_of_kept_cells<Mesh>(rows, columns, point, [rows, columns](int i, int j) {
    const double x = (i + 0.5) / rows - 0.5, y = (j + 0.5) / columns - 0.5;
    return x * x + y * y <= 0.25;
  });
}

// A saddle roof whose quads all differ: no column clustering is exact at
// the input.
Mesh trimmed_roof()
{
  return trimmed_grid(16, 20, [](int i, int j) {
    const double x = 0.1 * i, y = 0.1 * j;
    return Point(x, y, 0.3 * (x - 0.8) * (x - 0.8) - 0.2 * (y - 1.0) * (y - 1.0) + 0.05 * std::sin(2 * x + y));
  });
}

// Positions and orientations of the exact start of `label`.
TSI::Point_matrix start_of(const Mesh& m, const std::vector<std::size_t>& label,
                           std::vector<TS::Panel_orientation>& orientation)
{
  orientation.assign(num_faces(m), TS::Panel_orientation());
  return TSI::sweep_start(m, get(CGAL::face_index, m), get(CGAL::vertex_index, m), get(CGAL::vertex_point, m),
                          TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m)), label,
                          &orientation);
}

// The sweep clustering `label` of `m` is not exact at the input, and exact
// at its start, which places every vertex; checked independently.
void expect_exact_only_at_start(const Mesh& m, const std::vector<std::size_t>& label)
{
  std::vector<TS::Panel_orientation> orientation;
  const TSI::Point_matrix start = start_of(m, label, orientation);
  ASSERT_EQ(std::size_t(start.rows()), num_vertices(m));
  Mesh input = m;
  const Clustering at_input = clustered(input, label, orientation);
  EXPECT_GT(congruence_by_umeyama(input, at_input.cluster, at_input.orientation), 1e-3);
  Mesh moved = moved_to(m, start);
  const Clustering c = clustered(moved, label, orientation);
  EXPECT_LE(congruence_by_umeyama(moved, c.cluster, c.orientation), 1e-9);
}

} // namespace

// A trimmed grid has rows of different lengths; with fewer molds than
// columns each direction gives a sweep of K column runs. At the input no
// such clustering is exact; at its start every one is, checked
// independently, and every vertex is placed.
TEST(SweepStart, TrimmedGridsAreSweptByColumnRuns)
{
  const Mesh m = trimmed_roof();
  ASSERT_LT(num_faces(m), 16u * 20u);
  const std::vector<std::vector<std::size_t> > labels = sweeps(m, 6);
  ASSERT_EQ(labels.size(), 2u);
  for(const std::vector<std::size_t>& label : labels)
  {
    EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), 6u);
    expect_exact_only_at_start(m, label);
  }
}

// With more molds than columns (K = 24 on 16 x 20), a trimmed grid is swept
// as one run of rows, every column of each direction cut into pieces of
// consecutive quads: 24 clusters, each within one grid line (face (i, j)
// has its lowest corner at (0.1 i, 0.1 j)), none at the input exact, every
// one at the start, checked independently.
TEST(SweepStart, TrimmedGridWithFewColumnsIsOneRun)
{
  const Mesh m = trimmed_roof();
  const std::vector<std::vector<std::size_t> > labels = sweeps(m, 24);
  ASSERT_EQ(labels.size(), 2u);
  std::set<int> directions;
  for(const std::vector<std::size_t>& label : labels)
  {
    EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), 24u);
    // Per cluster, the grid lines i and j of its faces.
    std::vector<std::set<long> > lines_i(24), lines_j(24);
    for(Face f : faces(m))
    {
      double x = std::numeric_limits<double>::max(), y = x;
      for(Vertex v : vertices_around_face(halfedge(f, m), m))
      {
        x = (std::min)(x, m.point(v).x());
        y = (std::min)(y, m.point(v).y());
      }
      lines_i[label[std::size_t(f)]].insert(std::lround(10 * x));
      lines_j[label[std::size_t(f)]].insert(std::lround(10 * y));
    }
    const int direction = lines_i[0].size() == 1 ? 0 : 1;
    directions.insert(direction);
    for(std::size_t l = 0; l < 24; ++l)
      EXPECT_EQ((direction == 0 ? lines_i : lines_j)[l].size(), 1u) << "cluster " << l;
    expect_exact_only_at_start(m, label);
  }
  EXPECT_EQ(directions.size(), 2u);
}

// A trimmed piece of a cylinder, axis z, 0.1 radians per column: each
// row's vertex line (constant angle) is the one before turned about the
// axis, and a line along the axis at equal steps is a run of columns on a
// helix of that turn. So the sweep whose rings are those lines starts at
// the input itself.
TEST(SweepStart, TrimmedCylinderIsItsOwnSweep)
{
  const Mesh m = trimmed_grid(14, 18, [](int i, int j) {
    return Point(2 * std::cos(0.1 * i), 2 * std::sin(0.1 * i), 0.25 * j);
  });
  const TSI::Point_matrix input = TSI::read_points(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m));
  double closest = std::numeric_limits<double>::max();
  for(const std::vector<std::size_t>& label : sweeps(m, 4))
  {
    std::vector<TS::Panel_orientation> orientation;
    const TSI::Point_matrix start = start_of(m, label, orientation);
    ASSERT_EQ(start.rows(), input.rows());
    closest = (std::min)(closest, (start - input).rowwise().norm().maxCoeff());
  }
  EXPECT_LE(closest, 1e-9);
}

// Not a trimmed grid: a slit (the vertices along part of a grid line
// doubled, so that the faces on its two sides do not meet there) would put
// two vertices at one lattice point. Without the slit the roof has sweeps.
TEST(SweepStart, NoSweepAcrossASlit)
{
  Mesh slit = trimmed_roof();
  EXPECT_FALSE(sweeps(slit, 6).empty());
  {
    // The faces right of the line x = 0.8 get their own copies of its
    // vertices below y = 0.95.
    Mesh cut;
    std::map<Vertex, Vertex> copy, doubled;
    for(Vertex v : vertices(slit))
      copy[v] = cut.add_vertex(slit.point(v));
    for(Face f : faces(slit))
    {
      std::vector<Vertex> corners;
      double lowest_x = std::numeric_limits<double>::max(), lowest_y = lowest_x;
      for(Vertex v : vertices_around_face(halfedge(f, slit), slit))
      {
        lowest_x = (std::min)(lowest_x, slit.point(v).x());
        lowest_y = (std::min)(lowest_y, slit.point(v).y());
      }
      const bool beyond = lowest_x > 0.75 && lowest_y < 0.95;
      for(Vertex v : vertices_around_face(halfedge(f, slit), slit))
      {
        const bool on_line = std::abs(slit.point(v).x() - 0.8) < 1e-9 && slit.point(v).y() < 0.95;
        if(beyond && on_line)
        {
          if(!doubled.count(v))
            doubled[v] = cut.add_vertex(slit.point(v));
          corners.push_back(doubled[v]);
        }
        else
          corners.push_back(copy[v]);
      }
      ASSERT_NE(cut.add_face(corners), Mesh::null_face());
    }
    ASSERT_FALSE(doubled.empty());
    slit = cut;
  }
  EXPECT_TRUE(sweeps(slit, 6).empty());
}

// A curved facade of 16 x 20 panels with six window openings of 2 x 3
// cells, two rows of three: a grid with holes, whose boundary has inner
// loops. Every vertex inside is still of valence 4, so the holes do not
// break the lattice: both directions give a sweep of K column runs, not
// exact at the input, exact at its start (checked independently), and the
// pipeline makes it tilable through one where nothing else is exact
// without solver iterations.
Mesh facade_with_openings()
{
  return grid_of_kept_cells<Mesh>(
    16, 20,
    [](int i, int j) {
      const double x = 0.1 * i, y = 0.1 * j;
      return Point(x, y, 0.25 * std::sin(1.7 * x) + 0.1 * x * y + 0.03 * y * y);
    },
    [](int i, int j) { return !((i % 5 == 2 || i % 5 == 3) && i < 15 && (j == 4 || j == 5 || j == 6 || (j >= 13 && j <= 15))); });
}

TEST(SweepStart, FacadeWithOpeningsIsSwept)
{
  const Mesh m = facade_with_openings();
  ASSERT_EQ(num_faces(m), 16u * 20u - 6u * 6u);
  std::vector<Mesh::Halfedge_index> border_loops;
  CGAL::Polygon_mesh_processing::extract_boundary_cycles(m, std::back_inserter(border_loops));
  ASSERT_EQ(border_loops.size(), 7u);
  const std::vector<std::vector<std::size_t> > labels = sweeps(m, 6);
  ASSERT_EQ(labels.size(), 2u);
  for(const std::vector<std::size_t>& label : labels)
  {
    EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), 6u);
    expect_exact_only_at_start(m, label);
  }
  expect_tilable_only_through_a_sweep(facade_with_openings, 6);
}

// make_k_set_tilable() on the trimmed roof at K = 6, with no solver
// iteration: the sweep's start is the only exact result, so it is chosen
// and the result is tilable, checked independently; without the sweeps
// (segment candidates off) it is not.
TEST(SweepStart, PipelineMakesATrimmedGridTilable)
{
  expect_tilable_only_through_a_sweep(trimmed_roof, 6);
}

namespace {

// `m` with the corners of face f listed from its corner first_corner(f):
// the same surface, its faces started elsewhere.
template <typename FirstCorner>
Mesh faces_started_at(const Mesh& m, FirstCorner first_corner)
{
  Mesh out;
  for(Vertex v : vertices(m))
    out.add_vertex(m.point(v));
  for(Face f : faces(m))
  {
    std::vector<Vertex> corners;
    for(Vertex v : CGAL::vertices_around_face(halfedge(f, m), m))
      corners.push_back(v);
    std::rotate(corners.begin(), corners.begin() + std::ptrdiff_t(first_corner(std::size_t(f)) % corners.size()),
                corners.end());
    out.add_face(corners);
  }
  return out;
}

// Faces started at corner (3 f + f / 5) mod 4, as some CAD exports write
// them, so that a strip crosses neighbouring faces through face edges of
// different parities.
Mesh faces_started_anywhere(const Mesh& m)
{
  return faces_started_at(m, [](std::size_t f) { return 3 * f + f / 5; });
}

// `strips` (both directions) as the sets of faces they hold.
std::set<std::set<std::size_t> > strip_sets(const std::array<std::vector<std::size_t>, 2>& strips)
{
  std::set<std::set<std::size_t> > result;
  for(int d = 0; d < 2; ++d)
  {
    std::map<std::size_t, std::set<std::size_t> > faces_of;
    for(std::size_t f = 0; f < strips[d].size(); ++f)
      faces_of[strips[d][f]].insert(f);
    for(const auto& strip : faces_of)
      result.insert(strip.second);
  }
  return result;
}

} // namespace

// The growing horn with its faces started anywhere is still the grid of its
// 9 rings by 8 lines, one way and the other, with 9 + 8 strips; it has the
// same sweeps as the horn, and the pipeline makes it tilable through one
// where nothing else is exact without solver iterations.
TEST(SweepStart, GridWhoseFacesStartAtAnyCornerIsSwept)
{
  const Mesh horn = growing_horn(), scrambled = faces_started_anywhere(horn);
  const auto strips = TSI::quad_strips(scrambled, get(CGAL::face_index, scrambled));
  std::vector<std::size_t> counts;
  for(int d = 0; d < 2; ++d)
  {
    counts.push_back(std::set<std::size_t>(strips[d].begin(), strips[d].end()).size());
    const TSI::Quad_grid grid =
      TSI::quad_grid(scrambled, get(CGAL::face_index, scrambled), get(CGAL::vertex_point, scrambled), strips, d);
    EXPECT_EQ(grid.rows * grid.columns, num_faces(scrambled)) << "row direction " << d;
  }
  std::sort(counts.begin(), counts.end());
  EXPECT_EQ(counts, (std::vector<std::size_t>{std::size_t(around), std::size_t(rings)}));
  typedef std::set<std::vector<std::size_t> > Labels;
  const std::vector<std::vector<std::size_t> > swept = sweeps(scrambled, 8), horn_swept = sweeps(horn, 8);
  EXPECT_FALSE(swept.empty());
  EXPECT_EQ(Labels(swept.begin(), swept.end()), Labels(horn_swept.begin(), horn_swept.end()));
  expect_tilable_only_through_a_sweep([] { return faces_started_anywhere(growing_horn()); }, 8);
}

// Only face 0 of the horn started one corner on: all the other faces cross
// the strips the other way round from it. Face 0's direction stays the
// reference, since the grid search walks from face 0 along its own face
// edges: the horn is still its grid of 9 rings by 8 lines, both ways.
TEST(SweepStart, GridWhoseFirstFaceAloneStartsElsewhereIsAGrid)
{
  const Mesh m = faces_started_at(growing_horn(), [](std::size_t f) { return f == 0 ? 1 : 0; });
  const auto fim = get(CGAL::face_index, m);
  std::vector<int> expected(num_faces(m), 1);
  expected[0] = 0;
  EXPECT_EQ(TSI::strip_direction_flips(m, fim), expected);
  const auto strips = TSI::quad_strips(m, fim);
  std::set<std::pair<std::size_t, std::size_t> > shapes;
  for(int d = 0; d < 2; ++d)
  {
    const TSI::Quad_grid grid = TSI::quad_grid(m, fim, get(CGAL::vertex_point, m), strips, d);
    shapes.insert({grid.rows, grid.columns});
  }
  EXPECT_EQ(shapes, (std::set<std::pair<std::size_t, std::size_t> >{{rings, around}, {around, rings}}));
}

// The strips that the strip candidates group are the rings and lines of the
// horn, its faces started anywhere or not (faces keep their indices): on a
// grid the directions are carried across the edges. Each face's own
// parities would mix rings and lines into other strips.
TEST(SweepStart, StripCandidatesOfAGridAreItsRingsAndLines)
{
  const Mesh horn = growing_horn(), scrambled = faces_started_anywhere(horn);
  auto candidate_strips = [](const Mesh& m) {
    return TSI::candidate_strips(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m));
  };
  const std::set<std::set<std::size_t> > rings_and_lines = strip_sets(candidate_strips(horn));
  EXPECT_EQ(rings_and_lines.size(), std::size_t(rings + around));
  EXPECT_EQ(strip_sets(candidate_strips(scrambled)), rings_and_lines);
  EXPECT_NE(strip_sets(TSI::quad_strips(scrambled, get(CGAL::face_index, scrambled), false)), rings_and_lines);
}

// On a cube every vertex has valence 3 and each of its 3 strips crosses the
// other two: no two directions can be carried across all edges, and every
// face keeps the parity of its own face edges (all flips 0), started at any
// corner or not.
TEST(SweepStart, CubeStripsKeepEachFacesParity)
{
  Mesh cube;
  CGAL::make_hexahedron(Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(0, 1, 1),
                        Point(0, 0, 1), Point(1, 0, 1), Point(1, 1, 1), cube);
  ASSERT_EQ(num_faces(cube), 6u);
  for(const Mesh& m : {cube, faces_started_anywhere(cube)})
    EXPECT_EQ(TSI::strip_direction_flips(m, get(CGAL::face_index, m)), std::vector<int>(6, 0));
}

// Above large_mesh_faces with number_of_optimized_candidates 0 (the default
// there), an exact sweep ends the search, so cluster() makes no k-means,
// strip or segment candidate: the pool is the merges' and the sweeps'. With
// a candidate to optimize, those are made again. Either way the result is
// tilable, checked independently (the growing horn's rings all differ, so
// only a sweep is exact without iterations).
TEST(SweepStart, LargeGridPoolEndsAtAnExactSweep)
{
  const int long_rings = 104, long_around = 50;  // 5,200 quads
  ASSERT_GT(std::size_t(long_rings * long_around), TS::large_mesh_faces);
  const auto long_horn = [&] {
    return horn<Mesh>(long_rings, long_around, 3.0, 2.0, [](int i) { return 1.0 + 0.005 * i; });
  };
  auto origins = [](const TS::Clustering_result& r) {
    std::set<TS::Clustering_candidate::Origin> o;
    for(const TS::Clustering_candidate& c : r.candidates)
      o.insert(c.origin);
    return o;
  };
  for(bool by_default : {true, false})
  {
    Mesh m = long_horn();
    TS::K_set_tilable_surface surface(m);
    const auto tiles = TS::parameters::number_of_tiles(60).number_of_iterations(0);
    const std::set<TS::Clustering_candidate::Origin> made =
      origins(by_default ? surface.cluster(tiles) : surface.cluster(tiles.number_of_optimized_candidates(1)));
    EXPECT_EQ(made.count(TS::Clustering_candidate::GRID_SWEEPS), 1u);
    // The beam of merges is not made when an exact sweep ends the search.
    EXPECT_EQ(made.count(TS::Clustering_candidate::HIERARCHICAL), by_default ? 0u : 1u);
    EXPECT_EQ(made.count(TS::Clustering_candidate::QUAD_STRIPS), by_default ? 0u : 1u);
    EXPECT_EQ(made.count(TS::Clustering_candidate::KMEANS), by_default ? 0u : 1u);
    if(!by_default)
      continue;  // solving candidates from the input at 5,200 quads is not what this test is for
    surface.optimize_closest(tiles);
    EXPECT_EQ(surface.clustering().candidates[surface.clustering().chosen_candidate].origin,
              TS::Clustering_candidate::GRID_SWEEPS);
    EXPECT_LE(congruence_by_umeyama(m, surface.face_cluster_map(), surface.face_orientation_map()), 1e-6);
  }
}

} // namespace test_sweep_start_unit
