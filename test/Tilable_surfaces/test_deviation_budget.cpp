// A deviation budget instead of K (make_k_set_tilable() with max_deviation),
// the K / deviation curve (k_set_tilable_curve()) and its CSV.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/IO/report.h>
#include <CGAL/Tilable_surfaces/IO/write_tile_count_curve.h>
#include <CGAL/Tilable_surfaces/internal/Search/smallest_passing_tile_count.h>
#include <CGAL/Tilable_surfaces/k_set_tilable_curve.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>
#include <CGAL/Tilable_surfaces/measure.h>

#include "congruence_check.h"
#include "csv_cells.h"
#include "grid_mesh.h"
#include "hausdorff_oracle.h"

#include "test_mesh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_deviation_budget_unit {

namespace {

// A 3 x 3 grid on the monkey saddle z = x^3 - 3 x y^2 over [-1, 1]^2: nine
// faces, all different, so every K from 1 to 9 can be run in a test.
Mesh small_saddle()
{
  Mesh m = grid<Mesh>(3, 3, 2.0 / 3, 2.0 / 3);
  for(auto v : vertices(m))
  {
    const double x = m.point(v).x() - 1, y = m.point(v).y() - 1;
    m.point(v) = Point(x, y, 0.5 * (x * x * x - 3 * x * y * y));
  }
  return m;
}

// Records the K asked, and passes from `threshold` on, or as `table` says.
struct Recorder
{
  std::vector<std::size_t> asked;
  std::map<std::size_t, bool> table;
  std::size_t threshold = 0;
  bool operator()(std::size_t k)
  {
    asked.push_back(k);
    return table.empty() ? k >= threshold : table.at(k);
  }
};

} // namespace

TEST(TileCountSearch, FindsTheThresholdOfAMonotoneTestTryingEachKOnce)
{
  // k_min = 2: a mesh of quads and triangles, where K = 1 cannot be asked.
  for(std::size_t k_min : {1, 2})
  for(std::size_t k_max : {1, 2, 7, 100})
    for(std::size_t first : {1, 2, 5, 60, 200})
      for(std::size_t threshold = k_min; threshold <= k_max + 1; ++threshold)
      {
        Recorder passes;
        passes.threshold = threshold;
        const std::size_t k = TS::internal::smallest_passing_tile_count(first, k_min, k_max, std::ref(passes));
        EXPECT_EQ(k, threshold) << "k_max " << k_max << " first " << first;
        std::vector<std::size_t> sorted = passes.asked;
        std::sort(sorted.begin(), sorted.end());
        EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) << "a K asked twice";
        EXPECT_LE(passes.asked.size(), std::size_t(2 * 8 + 2)) << "logarithmic in k_max";
        for(std::size_t a : passes.asked) EXPECT_TRUE(a >= k_min && a <= k_max);
        if(k > k_min && k <= k_max)
          EXPECT_NE(std::find(passes.asked.begin(), passes.asked.end(), k - 1), passes.asked.end())
            << "K - 1 was tried";
      }
}

TEST(TileCountSearch, WhateverTheTestTheResultPassedAndKMinusOneFailed)
{
  // Not monotone: 3 passes, 4 to 6 fail, 7 on pass.
  Recorder passes;
  for(std::size_t k = 1; k <= 12; ++k) passes.table[k] = (k == 3 || k >= 7);
  const std::size_t k = TS::internal::smallest_passing_tile_count(6, 1, 12, std::ref(passes));
  EXPECT_TRUE(passes.table.at(k));
  EXPECT_FALSE(passes.table.at(k - 1));
  EXPECT_NE(std::find(passes.asked.begin(), passes.asked.end(), k - 1), passes.asked.end());
}

// What the deviation search promises of the K it tried (`trials`, in the
// order tried): each is its own search's result (`own`, by K) unless a
// result of fewer clusters tried before was better, which is then refined
// to it (refined_from); so no K ends worse than a buildable result of fewer
// clusters tried before it (tilable, not crossing, no farther).
static void expect_no_k_worse_than_fewer_tried_before(const std::vector<TS::Tile_count_trial>& trials,
                                              const std::map<std::size_t, TS::Tile_count_trial>& own)
{
  auto buildable = [](const TS::Tile_count_trial& t) { return t.is_tilable && t.self_intersecting_face_pairs == 0; };
  for(std::size_t i = 0; i < trials.size(); ++i)
  {
    const TS::Tile_count_trial& t = trials[i];
    if(own.count(t.number_of_tiles) > 0 && t.refined_from == 0)
      EXPECT_EQ(t.hausdorff_distance, own.at(t.number_of_tiles).hausdorff_distance) << "K = " << t.number_of_tiles;
    if(t.refined_from > 0)
    {
      EXPECT_LT(t.refined_from, t.number_of_tiles);
      EXPECT_TRUE(std::any_of(trials.begin(), trials.begin() + std::ptrdiff_t(i), [&](const TS::Tile_count_trial& s) {
        return s.number_of_tiles == t.refined_from;
      })) << "refined from a K tried before";
    }
    for(std::size_t j = 0; j < i; ++j)
      if(trials[j].number_of_tiles < t.number_of_tiles && buildable(trials[j]))
      {
        EXPECT_TRUE(buildable(t)) << "K = " << t.number_of_tiles;
        EXPECT_LE(t.hausdorff_distance, trials[j].hausdorff_distance + 1e-12)
          << "K = " << t.number_of_tiles << " against K = " << trials[j].number_of_tiles;
      }
  }
}

// On a mesh where every K is run: the curve over every K never rises, the
// search returns a K that meets the budget while K - 1 was tried and misses
// it, no K tried ends worse than one of fewer clusters tried before it, and
// the mesh it returns is within the budget by the oracle.
TEST(TileCountSearch, SmallestKWithinTheBudgetOnAMeshWhereEveryKIsChecked)
{
  Mesh mesh = small_saddle();
  const Mesh input = mesh;
  std::vector<std::size_t> all(num_faces(mesh));
  std::iota(all.begin(), all.end(), std::size_t(1));
  const std::vector<TS::Tile_count_trial> refined_curve = TS::k_set_tilable_curve(mesh, all);
  ASSERT_EQ(refined_curve.size(), all.size());
  for(auto v : vertices(mesh)) EXPECT_EQ(mesh.point(v), input.point(v)) << "the curve leaves the mesh as it was";
  EXPECT_TRUE(refined_curve.back().is_tilable);
  EXPECT_LT(refined_curve.back().hausdorff_distance, 1e-12) << "one tile per face: nothing moves";
  // Each K's own search, as a curve of that K alone gives it (it has
  // nothing to refine).
  std::map<std::size_t, TS::Tile_count_trial> own;
  for(std::size_t k : all) own[k] = TS::k_set_tilable_curve(mesh, std::vector<std::size_t>{k}).front();
  for(const auto& [k, t] : own) EXPECT_EQ(t.refined_from, 0u);
  // The whole curve, every K in increasing order, never rises.
  expect_no_k_worse_than_fewer_tried_before(refined_curve, own);

  // A budget between the deviations of the last K that misses and the next.
  double budget = -1;
  for(std::size_t k = all.size(); k > 1; --k)
    if(own[k].is_tilable && own[k - 1].is_tilable && own[k - 1].hausdorff_distance > own[k].hausdorff_distance)
    {
      budget = 0.5 * (own[k].hausdorff_distance + own[k - 1].hausdorff_distance);
      break;
    }
  ASSERT_GT(budget, 0) << "the deviation decreases somewhere";

  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::max_deviation(budget).face_cluster_map(cluster).face_orientation_map(orientation));
  const std::size_t k = r.optimization.measure.number_of_clusters;
  auto tried = [&](std::size_t kk) {
    return std::find_if(r.trials.begin(), r.trials.end(),
                        [&](const TS::Tile_count_trial& t) { return t.number_of_tiles == kk; });
  };
  ASSERT_NE(tried(k), r.trials.end());
  EXPECT_TRUE(tried(k)->meets(budget)) << "K = " << k;
  EXPECT_EQ(tried(k)->hausdorff_distance, r.optimization.measure.hausdorff_distance);
  ASSERT_GT(k, 1u) << "the budget is below what one mold reaches";
  ASSERT_NE(tried(k - 1), r.trials.end()) << "K - 1 was tried";
  EXPECT_FALSE(tried(k - 1)->meets(budget)) << "K - 1 = " << k - 1 << " misses the budget";
  expect_no_k_worse_than_fewer_tried_before(r.trials, own);

  // The maps and the mesh returned are what the search reported.
  const TS::Tilability_measure m = TS::measure_tilability(
    mesh, input, TSP::face_cluster_map(cluster).face_orientation_map(orientation));
  EXPECT_EQ(m.number_of_clusters, k);
  EXPECT_LE(m.congruence_error, 1e-6);
  EXPECT_LE(m.hausdorff_distance, budget);
  // Within the budget by the oracle, up to what sampling can tell.
  EXPECT_LE(hausdorff_oracle::distances(mesh, input).hausdorff(),
            budget + hausdorff_oracle::sampling_tolerance(input));
}

// A 4 x 3 grid on the saddle z = 0.4 x y: every K from 1 to 12 in one curve,
// which never rises once a K is buildable.
TEST(TileCountCurve, NeverRisesOverEveryKOfASecondSmallGrid)
{
  Mesh mesh = grid<Mesh>(4, 3, 0.5, 0.5);
  for(auto v : vertices(mesh))
  {
    const double x = mesh.point(v).x() - 1, y = mesh.point(v).y() - 0.75;
    mesh.point(v) = Point(x, y, 0.4 * x * y + 0.1 * x * x * x);
  }
  std::vector<std::size_t> all(num_faces(mesh));
  std::iota(all.begin(), all.end(), std::size_t(1));
  const std::vector<TS::Tile_count_trial> curve = TS::k_set_tilable_curve(mesh, all);
  ASSERT_EQ(curve.size(), all.size());
  ASSERT_TRUE(curve.back().is_tilable);
  expect_no_k_worse_than_fewer_tried_before(curve, {});
}

// The monkey saddle's own searches are far from monotone in K (measured:
// K = 8 30%, K = 16 31.6%), so the search refines: with at most 16 molds and
// a budget no K up to 16 meets, some K is a result of fewer molds refined,
// and no K ends worse than one of fewer tried before it.
TEST(TileCountSearch, RefinesAKFromABetterResultOfFewerMoldsTriedBefore)
{
  Mesh mesh = read("monkey_saddle.off");
  const TS::K_set_tilable_result r = TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(
    mesh, TSP::max_deviation(0.04).number_of_tiles(16));
  for(const TS::Tile_count_trial& t : r.trials) EXPECT_FALSE(t.meets(0.04)) << "K = " << t.number_of_tiles;
  EXPECT_EQ(r.optimization.measure.number_of_clusters, 16u) << "no K meets: the largest allowed";
  EXPECT_TRUE(std::any_of(r.trials.begin(), r.trials.end(),
                          [](const TS::Tile_count_trial& t) { return t.refined_from > 0; }))
    << "the case the rule is for: a K refined from fewer molds";
  expect_no_k_worse_than_fewer_tried_before(r.trials, {});
}

TEST(TileCountSearch, ABudgetNoKMeetsGivesTheLargestKTried)
{
  Mesh mesh = small_saddle();
  const TS::K_set_tilable_result r =
    TS::make_k_set_tilable(mesh, TSP::max_deviation(0.0).number_of_tiles(4));
  EXPECT_EQ(r.optimization.measure.number_of_clusters, 4u) << "the largest K allowed";
  for(const TS::Tile_count_trial& t : r.trials) EXPECT_LE(t.number_of_tiles, 4u);
  EXPECT_THROW(TS::make_k_set_tilable(mesh, TSP::max_deviation(-1.0)), TS::Invalid_input);
}

TEST(TileCountCurve, TheCsvHasOneRowPerKWithItsValues)
{
  Mesh mesh = small_saddle();
  const std::vector<std::size_t> ks{1, 3, 9};
  const std::vector<TS::Tile_count_trial> curve = TS::k_set_tilable_curve(mesh, ks);
  std::stringstream out;
  ASSERT_TRUE(TS::IO::write_tile_count_curve_CSV(out, curve));
  std::string line;
  std::getline(out, line);
  const std::vector<std::string> header = csv_cells(line);
  ASSERT_EQ(header.size(), 9u);
  EXPECT_EQ(header[0], "K");
  EXPECT_EQ(header[3], "hausdorff_distance");
  EXPECT_EQ(header[8], "refined_from");
  std::size_t row = 0;
  while(std::getline(out, line))
  {
    const std::vector<std::string> cells = csv_cells(line);
    ASSERT_EQ(cells.size(), header.size());
    ASSERT_LT(row, ks.size());
    EXPECT_EQ(std::stoul(cells[0]), ks[row]);
    EXPECT_EQ(std::stod(cells[3]), curve[row].hausdorff_distance) << "full precision";
    EXPECT_EQ(cells[6], curve[row].is_tilable ? "1" : "0");
    EXPECT_EQ(std::stoul(cells[7]), curve[row].self_intersecting_face_pairs);
    EXPECT_EQ(std::stoul(cells[8]), curve[row].refined_from);
    ++row;
  }
  EXPECT_EQ(row, ks.size());
  EXPECT_THROW(TS::k_set_tilable_curve(mesh, std::vector<std::size_t>{10}), TS::Invalid_input);
  EXPECT_THROW(TS::k_set_tilable_curve(mesh, std::vector<std::size_t>{0}), TS::Invalid_input);
}

// The monkey saddle's own search ends at 5.1% of the diagonal at K = 13 and
// at 31.6% at K = 14. With 14 molds the K = 13 result
// is still a 14-set tiling (a split cluster's parts are instances of its
// S-quad), so the curve's K = 14 is that one refined: tilable, not crossing,
// no farther than K = 13.
TEST(TileCountCurve, MoreMoldsNeverEndFartherThanFewer)
{
  Mesh mesh = read("monkey_saddle.off");
  const std::vector<TS::Tile_count_trial> curve =
    TS::k_set_tilable_curve<CGAL::Parallel_if_available_tag>(mesh, std::vector<std::size_t>{13, 14});
  ASSERT_EQ(curve.size(), 2u);
  ASSERT_TRUE(curve[0].is_tilable);
  EXPECT_EQ(curve[0].self_intersecting_face_pairs, 0u);
  EXPECT_EQ(curve[0].refined_from, 0u);
  EXPECT_EQ(curve[1].number_of_tiles, 14u);
  EXPECT_TRUE(curve[1].is_tilable);
  EXPECT_LE(curve[1].congruence_error, 1e-6);
  EXPECT_EQ(curve[1].self_intersecting_face_pairs, 0u);
  EXPECT_LE(curve[1].hausdorff_distance, curve[0].hausdorff_distance + 1e-12);
  expect_no_k_worse_than_fewer_tried_before(curve, {});
}

namespace {

// The paper's normalized F_d (its Table 1), computed here: both surfaces
// scaled so that the input's largest bounding-box side is 1, the sum of the
// squared displacements over the number of vertices.
double normalized_distance_term(const Mesh& result, const Mesh& input)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(input.points().begin(), input.points().end());
  const double side = (std::max)({box.xmax() - box.xmin(), box.ymax() - box.ymin(), box.zmax() - box.zmin()});
  double sum = 0;
  for(auto v : vertices(input)) sum += CGAL::squared_distance(result.point(v), input.point(v));
  return sum / (side * side) / double(input.number_of_vertices());
}

} // namespace

// The JSON report (IO/report.h) of a deviation search, against what the test
// measures itself: K and the cluster sizes counted from the maps, the
// largest displacement and the normalized F_d from the points, the Hausdorff
// distance by the oracle, the congruence by its own fit, one row per K tried
// with the kept K within the budget. A tolerance below the result's
// congruence error makes the report say it is not tilable.
TEST(Report, JsonOfADeviationSearchStatesWhatTheTestMeasures)
{
  Mesh mesh = small_saddle();
  const Mesh input = mesh;
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
  const double budget = 0.05;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::max_deviation(budget).face_cluster_map(cluster).face_orientation_map(orientation));
  ASSERT_TRUE(r.is_tilable());
  const nlohmann::json report = TS::IO::tilability_report_json(r);

  std::map<int, std::size_t> sizes;
  for(auto f : faces(mesh)) ++sizes[cluster[f]];
  std::vector<std::size_t> by_id;
  for(const auto& [id, n] : sizes) { EXPECT_EQ(id, int(by_id.size())); by_id.push_back(n); }
  ASSERT_LT(by_id.size(), num_faces(mesh)) << "a K that moves the mesh";
  EXPECT_EQ(report["K"].get<std::size_t>(), by_id.size());
  EXPECT_EQ(report["cluster_sizes"].get<std::vector<std::size_t> >(), by_id);
  double largest = 0;
  for(auto v : vertices(mesh)) largest = (std::max)(largest, std::sqrt(CGAL::squared_distance(mesh.point(v), input.point(v))));
  ASSERT_GT(largest, 0.0);
  EXPECT_NEAR(report["displacement"]["max"].get<double>(), largest, 1e-12);
  const double f_d = normalized_distance_term(mesh, input);
  EXPECT_NEAR(report["normalized_terms"]["distance"].get<double>(), f_d, 1e-9 * f_d);
  EXPECT_NEAR(report["fidelity"]["hausdorff"]["max"].get<double>(), hausdorff_oracle::distances(mesh, input).hausdorff(),
              hausdorff_oracle::sampling_tolerance(input));
  const double congruence = report["congruence_error"]["worst"].get<double>();
  EXPECT_LE(congruence, 1e-6);
  EXPECT_LE(congruence_by_umeyama(mesh, cluster, orientation), 2 * congruence + 1e-12)
    << "each panel against its cluster's first: at most twice the error against the S-quad";

  ASSERT_EQ(report["tried_K"].size(), r.trials.size());
  bool kept_row = false;
  for(const nlohmann::json& row : report["tried_K"])
    if(row["K"].get<std::size_t>() == by_id.size())
    {
      kept_row = true;
      EXPECT_TRUE(row["tilable"].get<bool>());
      EXPECT_LE(row["hausdorff_distance"].get<double>(), budget);
    }
  EXPECT_TRUE(kept_row) << "the K kept is a K tried";

  ASSERT_GT(congruence, 0.0);
  const auto says_not_tilable = [](const nlohmann::json& j) {
    for(const nlohmann::json& w : j["buildability"]["warnings"])
      if(w.get<std::string>().rfind("not tilable", 0) == 0) return true;
    return false;
  };
  EXPECT_FALSE(says_not_tilable(report));
  const nlohmann::json strict = TS::IO::tilability_report_json(r, congruence / 2);
  EXPECT_TRUE(says_not_tilable(strict));
  EXPECT_EQ(strict["congruence_error"]["tolerance"].get<double>(), congruence / 2);
}

} // namespace test_deviation_budget_unit
