// The paper's six surfaces made K-set tilable by make_k_set_tilable() (the
// fidelity search over clusterings with the default solver) at one of the
// paper's K values each: the result must be congruent to 1e-6, checked here
// by rigid fits (Eigen::umeyama, independent of the package's measure), with
// finite positions and a finite Hausdorff distance, at least the one-sided one.

#include "hausdorff_oracle.h"
#include "optimization_test_helpers.h"

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_paper_surfaces_unit {

using namespace test_helpers;

namespace {

struct Paper_case
{
  std::string surface;
  int K;
};

class PaperSurface : public ::testing::TestWithParam<Paper_case>
{};

TEST_P(PaperSurface, DefaultSolverReachesCongruence)
{
  const Paper_case& p = GetParam();
  Mesh mesh = load(p.surface + ".off");
  const Mesh input = mesh;
  Clustering c = add_clustering_maps(mesh);
  c.K = p.K;
  const TS::Optimization_result r =
    TS::make_k_set_tilable(mesh, TS::parameters::number_of_tiles(p.K).random_seed(0)
                                   .face_cluster_map(c.cluster).face_orientation_map(c.orientation))
      .optimization;

  for(Vertex v : vertices(mesh))
    ASSERT_TRUE(std::isfinite(mesh.point(v).x()) && std::isfinite(mesh.point(v).y()) &&
                std::isfinite(mesh.point(v).z()));
  // The fit onto each cluster's first instance is at most twice the error
  // against the S-quad, hence 2e-6 for the 1e-6 target.
  const double congruence = pairwise_congruence_error(mesh, c);
  EXPECT_LE(congruence, 2e-6);
  EXPECT_TRUE(r.converged);
  // The measured distance against the oracle's (hausdorff_oracle.h), both
  // sampled: the package's is at most the oracle's grid spacing above it, and
  // below it by at most the package's sampling tolerance.
  const double oracle = hausdorff_oracle::distances(mesh, input).hausdorff();
  EXPECT_LE(r.measure.hausdorff_distance, oracle + 1.0 / 400);
  EXPECT_LE(oracle, r.measure.hausdorff_distance + hausdorff_oracle::sampling_tolerance(input));
  RecordProperty("congruence", std::to_string(congruence));
  RecordProperty("hausdorff_distance", std::to_string(r.measure.hausdorff_distance));
  std::cout << p.surface << " K=" << p.K << ": congruence " << congruence << ", Hausdorff max "
            << r.measure.hausdorff_distance << " (oracle " << oracle << ") mean " << r.measure.mean_symmetric_distance
            << ", " << r.iterations << " iterations\n";
}

INSTANTIATE_TEST_SUITE_P(Paper, PaperSurface,
                         ::testing::Values(Paper_case{"swiss_re", 24}, Paper_case{"tunnel", 8},
                                           Paper_case{"seashell", 96}, Paper_case{"decocube", 21},
                                           Paper_case{"monkey_saddle", 3},
                                           Paper_case{"de_beers_ginza", 48}),
                         [](const ::testing::TestParamInfo<Paper_case>& info) {
                           return info.param.surface + "_K" + std::to_string(info.param.K);
                         });

} // namespace

} // namespace test_paper_surfaces_unit
