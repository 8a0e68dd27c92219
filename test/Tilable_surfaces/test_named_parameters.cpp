// Package named parameters chain with CGAL's and are read by CGAL's helpers.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>

#include <gtest/gtest.h>

#include <type_traits>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_named_parameters_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
namespace TNP = CGAL::Tilable_surfaces::internal_np;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

namespace {

// What a package function sees: CGAL's own pack type (CGAL 5.5 signature).
template <typename CGAL_NP_TEMPLATE_PARAMETERS>
int tiles_as_seen_by_a_function(const CGAL_NP_CLASS& np = CGAL::parameters::default_values())
{
  return choose_parameter(get_parameter(np, TNP::number_of_tiles), -1);
}

template <typename NP, typename Tag>
bool is_default(const NP&, Tag)
{
  return bool(CGAL::parameters::is_default_parameter<NP, Tag>::value);
}

} // namespace

TEST(NamedParameters, PackageAndCgalParametersChainInAnyOrder)
{
  const auto np = TSP::number_of_tiles(60).random_seed(7u).distance_weight(1e-3).verbose(true);
  EXPECT_EQ(choose_parameter(get_parameter(np, TNP::number_of_tiles), 0), 60);
  EXPECT_EQ(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u), 7u);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, TNP::distance_weight), 0.0), 1e-3);
  EXPECT_TRUE(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false));

  const auto np2 = TSP::number_of_iterations(5).flexibility_penalty(2.5);
  EXPECT_EQ(choose_parameter(get_parameter(np2, CGAL::internal_np::number_of_iterations), 0), 5);
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np2, TNP::flexibility_penalty), 0.0), 2.5);
}

TEST(NamedParameters, MissingParametersFallBackToTheDefault)
{
  const auto np = TSP::number_of_tiles(3);
  EXPECT_TRUE(is_default(np, TNP::solver));
  EXPECT_TRUE(is_default(np, CGAL::internal_np::random_seed));
  EXPECT_FALSE(is_default(np, TNP::number_of_tiles));
  EXPECT_DOUBLE_EQ(choose_parameter(get_parameter(np, TNP::volume_weight), 1.0), 1.0);
  EXPECT_TRUE(is_default(TSP::default_values(), TNP::number_of_tiles));
}

TEST(NamedParameters, APackageChainIsACgalChain)
{
  // Functions written for CGAL's pack type accept the package's packs.
  EXPECT_EQ(tiles_as_seen_by_a_function(TSP::number_of_tiles(12)), 12);
  EXPECT_EQ(tiles_as_seen_by_a_function(TSP::random_seed(1u).number_of_tiles(9)), 9);
  EXPECT_EQ(tiles_as_seen_by_a_function(), -1);

  // CGAL's helpers find CGAL's parameters in it.
  Mesh mesh;
  auto vpm = mesh.points();
  const auto np = TSP::number_of_tiles(2).vertex_point_map(vpm);
  typedef CGAL::GetVertexPointMap<Mesh, decltype(np)>::const_type Vpm;
  static_assert(std::is_same<Vpm, decltype(vpm)>::value, "the vertex point map is found");
  SUCCEED();
}

TEST(NamedParameters, ExtendContinuesAChainStartedInCgalParameters)
{
  const auto np = TSP::extend(CGAL::parameters::random_seed(9u).verbose(true)).number_of_tiles(4);
  EXPECT_EQ(choose_parameter(get_parameter(np, TNP::number_of_tiles), 0), 4);
  EXPECT_EQ(choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u), 9u);
  EXPECT_TRUE(choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false));

  const auto single = TSP::extend(CGAL::parameters::random_seed(4u)).solver(1);
  EXPECT_EQ(choose_parameter(get_parameter(single, CGAL::internal_np::random_seed), 0u), 4u);
  EXPECT_EQ(choose_parameter(get_parameter(single, TNP::solver), 0), 1);
}

TEST(NamedParameters, PropertyMapsAreStoredByValueAndShareTheirData)
{
  Mesh mesh;
  mesh.add_vertex(Point(0, 0, 0));
  auto cluster = mesh.add_property_map<Mesh::Vertex_index, int>("v:c", 0).first;
  const auto np = TSP::face_cluster_map(cluster).number_of_tiles(1);
  auto stored = get_parameter(np, TNP::face_cluster);
  put(stored, Mesh::Vertex_index(0), 42);
  EXPECT_EQ(get(cluster, Mesh::Vertex_index(0)), 42);
}

// The pipeline below a public function sees the caller's parameters in one
// type whatever values were chained, and in whatever order: it is compiled
// once for all of them. The values and the absent ones are kept.
TEST(NamedParameters, CanonicalFormHasOneTypeAndKeepsTheValues)
{
  using TS::internal::canonical_parameters;
  using TS::internal::parameter_or;
  const auto a = canonical_parameters(TSP::number_of_tiles(5).solver(TS::PAPER_CONJUGATE_GRADIENT));
  const auto b = canonical_parameters(TSP::random_seed(3u).distance_weight(0.5f).number_of_tiles(std::size_t(8)));
  const auto none = canonical_parameters(TSP::default_values());
  static_assert(std::is_same<decltype(a), decltype(b)>::value, "value parameters do not change the type");
  static_assert(std::is_same<decltype(a), decltype(none)>::value, "absent parameters do not change the type");
  static_assert(std::is_same<std::remove_const_t<decltype(a)>, decltype(canonical_parameters(a))>::value,
                "canonical twice is canonical");

  EXPECT_EQ(parameter_or(a, TNP::number_of_tiles, 0), 5);
  EXPECT_EQ(parameter_or(a, TNP::solver, TS::CONSTRAINED_GAUSS_NEWTON), TS::PAPER_CONJUGATE_GRADIENT);
  EXPECT_EQ(parameter_or(b, TNP::solver, TS::CONSTRAINED_GAUSS_NEWTON), TS::CONSTRAINED_GAUSS_NEWTON);
  EXPECT_EQ(parameter_or(b, TNP::number_of_tiles, 0), 8);
  EXPECT_EQ(parameter_or(b, CGAL::internal_np::random_seed, 0u), 3u);
  EXPECT_DOUBLE_EQ(parameter_or(b, TNP::distance_weight, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(parameter_or(none, TNP::distance_weight, 1.0), 1.0);
  EXPECT_EQ(parameter_or(canonical_parameters(a), TNP::number_of_tiles, 0), 5);
  // A value chained in front of a canonical list is found first.
  EXPECT_EQ(parameter_or(TSP::extend(a).number_of_tiles(11), TNP::number_of_tiles, 0), 11);

  // Maps are passed on as given, and absent maps stay absent.
  Mesh mesh;
  const auto with_map = canonical_parameters(TSP::number_of_tiles(2).vertex_point_map(mesh.points()));
  typedef CGAL::GetVertexPointMap<Mesh, std::remove_const_t<decltype(with_map)> >::const_type Vpm;
  static_assert(std::is_same<Vpm, std::decay_t<decltype(mesh.points())> >::value, "the vertex point map is passed on");
  EXPECT_TRUE(is_default(a, TNP::face_cluster));
  EXPECT_TRUE(is_default(a, CGAL::internal_np::vertex_point));
  // The pipeline's inputs leave out the output maps, which only the end writes.
  auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c", 0).first;
  const auto outputs = TSP::number_of_tiles(2).face_cluster_map(cluster);
  EXPECT_FALSE(is_default(canonical_parameters(outputs), TNP::face_cluster));
  EXPECT_TRUE(is_default(TS::internal::canonical_inputs(outputs), TNP::face_cluster));
  static_assert(std::is_same<decltype(TS::internal::canonical_inputs(outputs)),
                             decltype(TS::internal::canonical_inputs(TSP::default_values()))>::value,
                "output maps do not change the pipeline's type");
}

} // namespace test_named_parameters_unit
