// Segment clusterings of quad grids (internal/Clustering/segment_candidates.h):
// the grid found on tubes, and the runs of rows chosen on tubes whose best
// clustering is known by construction.

#include "optimization_test_helpers.h"
#include "tube_mesh.h"

#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_segment_candidates_unit {

using namespace test_helpers;
namespace TSI = CGAL::Tilable_surfaces::internal;

namespace {

std::vector<std::vector<std::size_t> > segment_clusterings(const Mesh& m, std::size_t k)
{
  return TSI::segment_clusterings(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m), k,
                                  TS::PROPER_RIGID_MOTIONS);
}

} // namespace

// A tube of 5 rings of 8 quads is a 5 x 8 grid one way (rows: the rings) and
// 8 x 5 the other. Rows are the rings in order, and each face's corners
// start at the edge it shares with the next face of its row.
TEST(SegmentCandidates, TubeIsAGridOfRingsAndLines)
{
  const int rings = 5, around = 8;
  const Mesh m = tube<Mesh>(rings, around, [](int i) { return 1.0 + 0.1 * i; });
  const auto strips = TSI::quad_strips(m, get(CGAL::face_index, m));
  std::vector<std::pair<std::size_t, std::size_t> > shapes;
  for(int d = 0; d < 2; ++d)
  {
    const TSI::Quad_grid grid = TSI::quad_grid(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m), strips, d);
    shapes.push_back({grid.rows, grid.columns});
    if(grid.rows != std::size_t(rings))
      continue;
    // Face i * around + j is on ring i: rows in order, one way or the other.
    const bool up = grid.face_at[0] / around == 0;
    for(std::size_t r = 0; r < grid.rows; ++r)
      for(std::size_t c = 0; c < grid.columns; ++c)
      {
        const std::size_t f = grid.face_at[r * grid.columns + c];
        EXPECT_EQ(f / around, up ? r : rings - 1 - r);
        // Corners 3 and 0 are the edge shared with the next face of the row.
        const std::size_t g = grid.face_at[r * grid.columns + (c + 1) % grid.columns];
        const TS::Panel next_face = TS::face_panel(Face(g), m);
        for(int corner : {3, 0})
          EXPECT_TRUE(std::any_of(next_face.begin(), next_face.end(), [&](const Eigen::Vector3d& p) {
            return p == grid.corners[f][corner];
          })) << "face " << f << " corner " << corner;
      }
  }
  std::sort(shapes.begin(), shapes.end());
  EXPECT_EQ(shapes, (std::vector<std::pair<std::size_t, std::size_t> >{{5, 8}, {8, 5}}));
}

// An L-shaped patch is no grid: its strips do not all cross.
TEST(SegmentCandidates, NoGridNoCandidate)
{
  Mesh m;
  std::vector<Vertex> v;
  for(int j = 0; j <= 2; ++j)
    for(int i = 0; i <= 2; ++i)
      v.push_back(m.add_vertex(Point(i, j, 0)));
  auto id = [&](int i, int j) { return v[i + 3 * j]; };
  m.add_face(id(0, 0), id(1, 0), id(1, 1), id(0, 1));
  m.add_face(id(1, 0), id(2, 0), id(2, 1), id(1, 1));
  m.add_face(id(0, 1), id(1, 1), id(1, 2), id(0, 2));
  EXPECT_TRUE(segment_clusterings(m, 2).empty());
}

// Two cylinders (radii 1 and 2, 3 rings each) joined by a frustum ring:
// three bands, the rings of each part together, make all quads of a mold
// congruent (cost 0), the only way with 3 molds. That clustering is already
// tilable: optimizing it moves nothing.
TEST(SegmentCandidates, CylindersJoinedByAFrustumAreThreeBands)
{
  const int rings = 7, around = 8;
  Mesh m = tube<Mesh>(rings, around, [](int i) { return i <= 3 ? 1.0 : 2.0; });
  const std::vector<std::vector<std::size_t> > labels = segment_clusterings(m, 3);
  std::vector<std::size_t> expected(rings * around);
  for(int f = 0; f < rings * around; ++f)
    expected[f] = f / around < 3 ? 0 : f / around == 3 ? 1 : 2;
  ASSERT_NE(std::find(labels.begin(), labels.end(), expected), labels.end());

  const Mesh input = m;
  Clustering c = add_clustering_maps(m);
  for(Face f : faces(m)) c.cluster[f] = int(expected[std::size_t(f)]);
  TS::retag_orientations(m, TS::parameters::face_cluster_map(c.cluster).face_orientation_map(c.orientation));
  const TS::Optimization_result r = TS::optimize_tilable_surface(
    m, TS::parameters::face_cluster_map(c.cluster).face_orientation_map(c.orientation));
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.measure.hausdorff_distance, 1e-9);
}

// A piece of torus (4 rings of 8 quads, the sections symmetric by the plane
// z = 0): quads at the same place around are congruent along the piece, and
// the ones at mirror places (j and 7 - j) are congruent too. With 4 molds,
// one segment of the mirror pairs costs 0.
TEST(SegmentCandidates, TorusPieceIsOneSegmentOfMirrorPairs)
{
  const int rings = 4, around = 8;
  const Mesh m = horn<Mesh>(rings, around, 3.0, 1.0, [](int) { return 1.0; });
  const std::vector<std::vector<std::size_t> > labels = segment_clusterings(m, 4);
  const bool found = std::any_of(labels.begin(), labels.end(), [&](const std::vector<std::size_t>& l) {
    for(int f = 0; f < rings * around; ++f)
      if(l[f] != l[f % around] || l[f] != l[around - 1 - f % around]) return false;
    return std::set<std::size_t>(l.begin(), l.end()).size() == 4;
  });
  EXPECT_TRUE(found) << [&] { std::string s; for(const auto& l : labels) { for(std::size_t x : l) s += std::to_string(x) + " "; s += "\n"; } return s; }();
}

// cluster_panels() puts them in its pool, unless told not to.
TEST(SegmentCandidates, JoinThePoolOfClusterQuadsUnlessTurnedOff)
{
  Mesh m = tube<Mesh>(7, 8, [](int i) { return i <= 3 ? 1.0 : 2.0; });
  Clustering c = add_clustering_maps(m);
  auto count = [&](bool use) {
    const TS::Clustering_result r = TS::cluster_panels(
      m, TS::parameters::number_of_tiles(3).face_cluster_map(c.cluster).face_orientation_map(c.orientation)
           .use_segment_candidates(use));
    return std::count_if(r.candidates.begin(), r.candidates.end(), [](const TS::Clustering_candidate& x) {
      return x.origin == TS::Clustering_candidate::GRID_SEGMENTS;
    });
  };
  EXPECT_GE(count(true), 1);
  EXPECT_EQ(count(false), 0);
}

// The greedy strip merges to several counts in one sequence give, at each
// count, what a sequence to that count alone gives (a merge depends only on
// the clusters before it); the rings of a tube growing unevenly.
TEST(SegmentCandidates, OneMergeSequenceServesEveryCount)
{
  const Mesh m = tube<Mesh>(14, 6, [](int i) { return 1.0 + 0.1 * i + 0.03 * (i % 3); });
  const auto fim = get(CGAL::face_index, m);
  const auto vpm = get(CGAL::vertex_point, m);
  const std::vector<TS::Panel> quads = TSI::face_quads(m, fim, CGAL::parameters::default_values());
  const auto strips = TSI::quad_strips(m, fim);
  const std::vector<std::size_t>& rings = strips[*std::max_element(strips[0].begin(), strips[0].end()) == 13 ? 0 : 1];
  const std::size_t count = 1 + *std::max_element(rings.begin(), rings.end());
  ASSERT_EQ(count, 14u);
  const std::vector<std::size_t> targets{9, 2, 5, 14, 20};
  const std::vector<std::vector<std::size_t> > together =
    TSI::merge_strips_to_each(targets, m, fim, vpm, quads, TS::PROPER_RIGID_MOTIONS, rings, count);
  ASSERT_EQ(together.size(), targets.size());
  for(std::size_t t = 0; t < targets.size(); ++t)
  {
    EXPECT_EQ(std::set<std::size_t>(together[t].begin(), together[t].end()).size(), (std::min)(targets[t], count));
    EXPECT_EQ(together[t], TSI::merge_strips_to_each({targets[t]}, m, fim, vpm, quads, TS::PROPER_RIGID_MOTIONS,
                                                     rings, count)[0])
      << targets[t] << " clusters";
  }
}

namespace {

// Every segment partition, for every count up to k, of every grid and set
// of segment options of `m`, each computed alone.
std::vector<std::vector<std::size_t> > every_segment_partition(const Mesh& m, std::size_t k)
{
  std::vector<std::vector<std::size_t> > result;
  for(const auto& s : TSI::segment_options(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m), k,
                                           TS::PROPER_RIGID_MOTIONS, 400, 400))
    for(const auto& set : s->sets)
      for(std::size_t count = 1; count <= k; ++count)
      {
        std::vector<std::size_t> label = TSI::best_runs(s->grid, set, count);
        if(!label.empty()) result.push_back(label);
      }
  return result;
}

// Whether every cluster of `fine` lies within one cluster of `coarse`.
bool refines(const std::vector<std::size_t>& fine, const std::vector<std::size_t>& coarse)
{
  std::vector<std::size_t> within(fine.size(), TSI::no_index());
  for(std::size_t f = 0; f < fine.size(); ++f)
  {
    if(within[fine[f]] == TSI::no_index()) within[fine[f]] = coarse[f];
    if(within[fine[f]] != coarse[f]) return false;
  }
  return true;
}

} // namespace

// One dynamic program for K molds gives, for every smaller count, the
// partition the dynamic program for that count alone gives: the states of
// fewer molds are reached by the same steps. A horn, so that the runs
// differ from count to count.
TEST(SegmentCandidates, OneDynamicProgramServesEveryCount)
{
  const Mesh m = horn<Mesh>(12, 8, 2.0, 2.6, [](int i) { return 0.4 * std::exp(0.08 * i); });
  const std::size_t k = 30;
  std::size_t compared = 0;
  for(const auto& s : TSI::segment_options(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m), k,
                                           TS::PROPER_RIGID_MOTIONS, 400, 400))
    for(const auto& set : s->sets)
    {
      const TSI::Run_partitions partitions(s->grid, set, k);
      for(std::size_t count = 1; count <= k; ++count)
      {
        const std::vector<std::size_t> label = partitions.label(count);
        EXPECT_EQ(label, TSI::best_runs(s->grid, set, count)) << count << " molds";
        if(label.empty()) continue;
        ++compared;
        EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), count);
      }
    }
  EXPECT_GT(compared, 20u);
}

// The split segment clusterings have K clusters, each within one cluster of
// a segment partition of fewer molds (at least K / 2), and differ from each
// other.
TEST(SegmentCandidates, SplitOnesRefineAPartitionOfFewerMolds)
{
  const Mesh m = horn<Mesh>(12, 8, 2.0, 2.6, [](int i) { return 0.4 * std::exp(0.08 * i); });
  const auto fim = get(CGAL::face_index, m);
  const auto vpm = get(CGAL::vertex_point, m);
  const std::vector<TS::Panel> quads = TSI::face_quads(m, fim, CGAL::parameters::default_values());
  std::vector<TS::Quad_descriptor> descriptors;
  for(const TS::Panel& q : quads) descriptors.push_back(TS::shape_descriptor(q));
  const std::size_t k = 22;
  const std::vector<std::vector<std::size_t> > split =
    TSI::split_segment_clusterings(m, fim, vpm, quads, descriptors, k, TS::PROPER_RIGID_MOTIONS, 0, 4);
  ASSERT_EQ(split.size(), 4u);
  const std::vector<std::vector<std::size_t> > coarse = every_segment_partition(m, k);
  for(const std::vector<std::size_t>& label : split)
  {
    EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), k);
    EXPECT_TRUE(std::any_of(coarse.begin(), coarse.end(), [&](const std::vector<std::size_t>& c) {
      const std::size_t molds = std::set<std::size_t>(c.begin(), c.end()).size();
      return molds < k && molds >= k / 2 && refines(label, c);
    }));
    EXPECT_EQ(std::count(split.begin(), split.end(), label), 1);
  }
}

} // namespace test_segment_candidates_unit
