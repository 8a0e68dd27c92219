// The package's sampled distances (measure_tilability()) against the oracle
// of hausdorff_oracle.h (CGAL's approximate_Hausdorff_distance on dense
// grids), on the six paper surfaces and two real quad meshes, each moved by a
// smooth field and one spike.
#include "hausdorff_oracle.h"
#include "optimization_test_helpers.h"

#include <CGAL/Tilable_surfaces/measure.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_hausdorff_oracle_unit {

using namespace test_helpers;

namespace {

// `input` with every vertex moved by a smooth field of about 1% of the
// diagonal, and one vertex 4% more along z: the input's points farthest from
// the result then lie inside faces, between the package's samples.
Mesh moved(const Mesh& input)
{
  Mesh result = input;
  const double d = hausdorff_oracle::diagonal(hausdorff_oracle::centroid_fans(input));
  for(Vertex v : vertices(result))
  {
    const Point& p = result.point(v);
    result.point(v) = Point(p.x() + 0.01 * d * std::sin(5 * p.y() / d + 1),
                            p.y() + 0.01 * d * std::sin(7 * p.z() / d + 2),
                            p.z() + 0.01 * d * std::sin(3 * p.x() / d + 3));
  }
  const Vertex spike(static_cast<Mesh::size_type>(result.number_of_vertices() / 3));
  result.point(spike) = result.point(spike) + Kernel::Vector_3(0, 0, 0.04 * d);
  return result;
}

} // namespace

// Both are maxima over samples, so both are below the exact distances. The
// oracle's grid comes within its spacing of each of the package's samples:
// the package is at most the spacing above it. The package samples each fan
// triangle at its corners, an edge midpoint and its centroid, so the exact
// distance, 1-Lipschitz along the surface, is above the package's by less
// than a quarter of an edge; measured, the oracle is at most 0.05 of a mean
// edge above (quad_dome.obj, the input's points near the spike): 0.1 holds
// that with margin and sees a sample lost from a face.
TEST(HausdorffOracle, MeasureAgreesWithPmpOnPaperSurfacesAndRealMeshes)
{
  const double spacing = 1.0 / 400;
  for(const char* name : {"monkey_saddle.off", "seashell.off", "swiss_re.off", "tunnel.off", "decocube.off",
                          "de_beers_ginza.off", "quad_dome.obj", "6-sub-lifted.obj"})
  {
    SCOPED_TRACE(name);
    Mesh input = load(name);
    Mesh result = moved(input);
    const Clustering c = every_face_alone(result);
    const TS::Tilability_measure m = TS::measure_tilability(result, input, clustering_parameters(c));
    const hausdorff_oracle::Distances oracle = hausdorff_oracle::distances(result, input, spacing);
    const double edge = m.input_mean_edge_length / m.input_bbox_diagonal;
    std::cout << "[ numbers  ] " << name << ": result to input " << m.max_approximation_error << " (oracle "
              << oracle.result_to_input << "), input to result " << m.max_coverage_error << " (oracle "
              << oracle.input_to_result << "), Hausdorff " << m.hausdorff_distance << " (oracle "
              << oracle.hausdorff() << "), mean edge " << edge << "\n";
    EXPECT_LE(m.max_approximation_error, oracle.result_to_input + spacing);
    EXPECT_LE(m.max_coverage_error, oracle.input_to_result + spacing);
    EXPECT_LE(oracle.result_to_input, m.max_approximation_error + 0.1 * edge);
    EXPECT_LE(oracle.input_to_result, m.max_coverage_error + 0.1 * edge);
    EXPECT_GT(oracle.hausdorff(), 0.01) << "the surfaces are apart: the comparison says something";
  }
}

} // namespace test_hausdorff_oracle_unit
