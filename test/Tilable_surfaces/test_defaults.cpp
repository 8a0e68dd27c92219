// The defaults of the named parameters live in one header (defaults.h): the
// user manual's table states the same values, and the pipeline run with
// every default spelled out from that header gives the same result as the
// pipeline run without them.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_defaults_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;

namespace {

// Name -> text of \cgalParamDefault{...} of every parameter in the manual.
std::map<std::string, std::string> documented_defaults()
{
  std::ifstream in(TILABLE_SURFACES_USER_MANUAL);
  EXPECT_TRUE(in.good()) << TILABLE_SURFACES_USER_MANUAL;
  std::stringstream text;
  text << in.rdbuf();
  const std::string manual = text.str();
  const std::regex entry(R"(\\cgalParamNBegin\{(\w+)\}[^]*?\\cgalParamDefault\{([^\n]*)\})");
  std::map<std::string, std::string> defaults;
  for(auto it = std::sregex_iterator(manual.begin(), manual.end(), entry); it != std::sregex_iterator(); ++it)
    defaults[(*it)[1]] = (*it)[2];
  return defaults;
}

// The numbers in `text`, in order ("1e-6 (default solver), 1e-4 ..." gives 1e-6, 1e-4).
std::vector<double> numbers_in(const std::string& text)
{
  const std::regex number(R"((^|[ (])([0-9]+(\.[0-9]+)?(e-?[0-9]+)?)\b)");
  std::vector<double> values;
  for(auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
    values.push_back(std::stod((*it)[2]));
  return values;
}

} // namespace

TEST(Defaults, TheUserManualStatesTheDefaultsOfDefaultsH)
{
  const std::map<std::string, std::string> doc = documented_defaults();
  const std::map<std::string, double> scalars = {
    {"number_of_candidates", double(TS::defaults::number_of_candidates)},
    {"similarity_threshold", TS::defaults::similarity_threshold},
    {"flexibility_penalty", TS::defaults::flexibility_penalty},
    {"structure_penalty", TS::defaults::structure_penalty},
    {"exact_clustering_limit", double(TS::defaults::exact_clustering_limit)},
    {"random_seed", double(TS::defaults::random_seed)},
    {"distance_weight", TS::defaults::distance_weight},
    {"tangential_weight", TS::defaults::tangential_weight},
    {"edge_length_weight", TS::defaults::edge_length_weight},
    {"diagonal_weight", TS::defaults::diagonal_weight},
    {"volume_weight", TS::defaults::volume_weight},
    {"congruence_tolerance", TS::defaults::congruence_tolerance},
    {"panel_tolerance", TS::defaults::panel_tolerance},
    {"number_of_improvement_rounds", double(TS::defaults::number_of_improvement_rounds)},
    {"feature_angle", TS::defaults::feature_angle},
    {"stream_precision", double(TS::defaults::stream_precision)}};
  for(const auto& [name, value] : scalars)
  {
    ASSERT_EQ(doc.count(name), 1u) << name << " is not in the manual's table";
    EXPECT_EQ(numbers_in(doc.at(name)), std::vector<double>{value}) << name << ": " << doc.at(name);
  }
  const std::map<std::string, bool> switches = {
    {"use_kmeans_candidate", TS::defaults::use_kmeans_candidate},
    {"use_auto_merge", TS::defaults::use_auto_merge},
    {"use_strip_candidates", TS::defaults::use_strip_candidates},
    {"use_segment_candidates", TS::defaults::use_segment_candidates},
    {"planar_tiles", TS::defaults::planar_tiles},
    {"use_binary_mode", TS::defaults::use_binary_mode}};
  for(const auto& [name, value] : switches)
  {
    ASSERT_EQ(doc.count(name), 1u) << name << " is not in the manual's table";
    EXPECT_EQ(doc.at(name), value ? "`true`" : "`false`") << name;
  }
  const std::map<std::string, std::string> enumerations = {
    {"clustering_path", "`AUTOMATIC_PATH`"},
    {"orientation_policy", "`PROPER_RIGID_MOTIONS`"},
    {"solver", "`CONSTRAINED_GAUSS_NEWTON`"}};
  EXPECT_EQ(TS::defaults::clustering_path, TS::AUTOMATIC_PATH);
  EXPECT_EQ(TS::defaults::orientation_policy, TS::PROPER_RIGID_MOTIONS);
  EXPECT_EQ(TS::defaults::solver, TS::CONSTRAINED_GAUSS_NEWTON);
  for(const auto& [name, text] : enumerations)
    EXPECT_EQ(doc.at(name), text) << name;

  // The solver-dependent defaults: the default solver's first, then the
  // conjugate gradient's.
  const auto both = [](auto f) {
    return std::vector<double>{double(f(TS::CONSTRAINED_GAUSS_NEWTON)), double(f(TS::PAPER_CONJUGATE_GRADIENT))};
  };
  EXPECT_EQ(numbers_in(doc.at("fairness_weight")), both(TS::default_fairness_weight));
  EXPECT_EQ(numbers_in(doc.at("convergence_tolerance")), both(TS::default_convergence_tolerance));
  EXPECT_EQ(numbers_in(doc.at("number_of_iterations")), both(TS::default_number_of_iterations));
  // "2 + 10000 / number of faces, at most 12; 0 above 5000 faces".
  const std::vector<double> candidates = numbers_in(doc.at("number_of_optimized_candidates"));
  ASSERT_EQ(candidates.size(), 5u);
  for(std::size_t faces : {1u, 96u, 1000u, 5000u, 5001u, 10000u, 100000u})
    EXPECT_EQ(double(TS::default_number_of_optimized_candidates(faces)),
              double(faces) > candidates[4]
                ? candidates[3]
                : (std::min)(candidates[2], candidates[0] + std::floor(candidates[1] / double(faces))))
      << faces << " faces";
}

TEST(Defaults, ThePipelineUsesThem)
{
  Mesh input;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/monkey_saddle.off", input));
  struct Run
  {
    std::vector<int> cluster, orientation;
    std::vector<Mesh::Point> points;
  };
  auto run = [&](const auto& np) {
    Mesh m = input;
    auto c = m.add_property_map<Mesh::Face_index, int>("f:c", -1).first;
    auto o = m.add_property_map<Mesh::Face_index, int>("f:o", -1).first;
    TS::make_k_set_tilable(m, np.face_cluster_map(c).face_orientation_map(o));
    Run r;
    for(auto f : faces(m)) { r.cluster.push_back(c[f]); r.orientation.push_back(o[f]); }
    r.points.assign(m.points().begin(), m.points().end());
    return r;
  };
  const std::size_t k = 7;
  const Run implicit = run(TSP::number_of_tiles(k));
  const TS::Solver_type solver = TS::defaults::solver;
  const Run spelled_out = run(TSP::number_of_tiles(k)
                                .number_of_candidates(TS::defaults::number_of_candidates)
                                .use_kmeans_candidate(TS::defaults::use_kmeans_candidate)
                                .use_auto_merge(TS::defaults::use_auto_merge)
                                .use_strip_candidates(TS::defaults::use_strip_candidates)
                                .use_segment_candidates(TS::defaults::use_segment_candidates)
                                .planar_tiles(TS::defaults::planar_tiles)
                                .similarity_threshold(TS::defaults::similarity_threshold)
                                .flexibility_penalty(TS::defaults::flexibility_penalty)
                                .structure_penalty(TS::defaults::structure_penalty)
                                .clustering_path(TS::defaults::clustering_path)
                                .exact_clustering_limit(TS::defaults::exact_clustering_limit)
                                .orientation_policy(TS::defaults::orientation_policy)
                                .random_seed(TS::defaults::random_seed)
                                .solver(solver)
                                .distance_weight(TS::defaults::distance_weight)
                                .fairness_weight(TS::default_fairness_weight(solver))
                                .tangential_weight(TS::defaults::tangential_weight)
                                .edge_length_weight(TS::defaults::edge_length_weight)
                                .diagonal_weight(TS::defaults::diagonal_weight)
                                .volume_weight(TS::defaults::volume_weight)
                                .congruence_tolerance(TS::defaults::congruence_tolerance)
                                .convergence_tolerance(TS::default_convergence_tolerance(solver))
                                .number_of_iterations(TS::default_number_of_iterations(solver))
                                .number_of_improvement_rounds(TS::defaults::number_of_improvement_rounds)
                                .number_of_optimized_candidates(
                                  TS::default_number_of_optimized_candidates(num_faces(input)))
                                .feature_angle(TS::defaults::feature_angle));
  EXPECT_EQ(implicit.cluster, spelled_out.cluster);
  EXPECT_EQ(implicit.orientation, spelled_out.orientation);
  EXPECT_EQ(implicit.points, spelled_out.points);
}

} // namespace test_defaults_unit
