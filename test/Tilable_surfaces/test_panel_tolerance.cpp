// Panel tolerance (named parameter panel_tolerance, CLI --panel-tolerance):
// every instance within T of its mold, checked by a rigid fit written here;
// T = 0 is the exact mode; a bad T is refused before anything moves; and the
// tolerance lowers the displacement and K where panels already fit one mold.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "grid_mesh.h"
#include "temp_dir.h"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <Eigen/SVD>

#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_panel_tolerance_unit {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Simple_cartesian<double>::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Eigen::Matrix<double, 3, 4> Corners;

namespace {

// A 4 x 4 grid of unit squares, each vertex moved by at most `jitter` in a
// fixed pattern: no two panels congruent, every panel within about
// 4 `jitter` of the unit square (every corner moved by at most sqrt(3) `jitter`).
Mesh jittered_grid(double jitter)
{
  return grid_of_kept_cells<Mesh>(
    4, 4,
    [jitter](int i, int j) {
      return Point(i + jitter * std::sin(7.0 * i + 3.0 * j), j + jitter * std::cos(5.0 * i + 11.0 * j),
                   jitter * std::sin(3.0 * i * j + 1.0));
    },
    [](int, int) { return true; });
}

// A 5 x 5 grid on a paraboloid: its panels differ by far more than the
// tolerances used here, so the solver has to move it.
Mesh paraboloid_grid()
{
  return grid_of_kept_cells<Mesh>(
    5, 5, [](int i, int j) { return Point(i, j, 0.15 * ((i - 2.5) * (i - 2.5) + (j - 2.5) * (j - 2.5))); },
    [](int, int) { return true; });
}

double mean_edge(const Mesh& m)
{
  double sum = 0;
  for(auto e : edges(m))
    sum += std::sqrt(CGAL::squared_distance(m.point(source(e, m)), m.point(target(e, m))));
  return sum / double(num_edges(m));
}

// The corners of face f in the order of its mold's corners t0..t3: corner i
// is face vertex (i + o) mod 4 for o < 4, (o - 4 - i) mod 4 for o >= 4, the
// face's vertices counted from the target of its halfedge, as the user
// manual defines orientations (section Definitions), written out here.
Corners instance_corners(const Mesh& m, Mesh::Face_index f, int o)
{
  std::vector<Point> v;
  for(auto w : CGAL::vertices_around_face(m.halfedge(f), m)) v.push_back(m.point(w));
  Corners x;
  for(int i = 0; i < 4; ++i)
  {
    const int k = o < 4 ? (i + o) % 4 : ((o - 4 - i) % 4 + 4) % 4;
    x.col(i) = Eigen::Vector3d(v[std::size_t(k)].x(), v[std::size_t(k)].y(), v[std::size_t(k)].z());
  }
  return x;
}

// Kabsch: the proper rigid motion taking `from` closest to `to` in the least
// squares sense, by an SVD of the cross-covariance; the largest corner
// distance after it.
double kabsch_deviation(const Corners& from, const Corners& to)
{
  const Eigen::Vector3d cf = from.rowwise().mean(), ct = to.rowwise().mean();
  const Corners a = from.colwise() - cf, b = to.colwise() - ct;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(b * a.transpose(), Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  s(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  const Eigen::Matrix3d R = svd.matrixU() * s * svd.matrixV().transpose();
  return (R * a - b).colwise().norm().maxCoeff();
}

struct Tolerance_run
{
  Mesh mesh;
  std::vector<int> cluster, orientation;
  TS::K_set_tilable_result result;
};

template <typename NP>
Tolerance_run run_at(const Mesh& input, const NP& np)
{
  Tolerance_run r;
  r.mesh = input;
  r.cluster.assign(num_faces(input), -1);
  r.orientation.assign(num_faces(input), -1);
  auto fim = get(CGAL::face_index, r.mesh);
  auto cluster = boost::make_iterator_property_map(r.cluster.begin(), fim);
  auto orientation = boost::make_iterator_property_map(r.orientation.begin(), fim);
  r.result = TS::make_k_set_tilable(r.mesh, TSP::extend(np).face_cluster_map(cluster).face_orientation_map(orientation));
  return r;
}

// Every instance of the result, fitted here onto its mold as the tile
// catalog gives it: within `tolerance`, and as far as the report says.
void expect_every_instance_within(const Tolerance_run& r, double tolerance)
{
  ASSERT_EQ(r.result.tiles.size(), r.result.optimization.measure.number_of_clusters);
  const std::vector<double>& reported = r.result.optimization.measure.panel_deviations;
  ASSERT_EQ(reported.size(), num_faces(r.mesh));
  double worst = 0;
  for(auto f : faces(r.mesh))
  {
    const TS::Tile& tile = r.result.tiles[std::size_t(r.cluster[f])];
    Corners mold;
    for(int i = 0; i < 4; ++i) mold.col(i) = tile.corners[i];
    const double d = kabsch_deviation(mold, instance_corners(r.mesh, f, r.orientation[f]));
    EXPECT_LE(d, tolerance * (1 + 1e-9)) << "face " << std::size_t(f);
    EXPECT_NEAR(d, reported[std::size_t(f)], 1e-9 * mean_edge(r.mesh)) << "face " << std::size_t(f);
    worst = (std::max)(worst, d);
  }
  EXPECT_NEAR(worst, r.result.optimization.measure.worst_panel_deviation, 1e-9 * mean_edge(r.mesh));
}

double largest_move(const Mesh& input, const Mesh& result)
{
  double m = 0;
  for(auto v : vertices(input)) m = (std::max)(m, std::sqrt(CGAL::squared_distance(input.point(v), result.point(v))));
  return m;
}

} // namespace

TEST(PanelTolerance, EveryInstanceIsWithinTOfItsMoldByAFitWrittenInTheTest)
{
  const Mesh input = paraboloid_grid();
  const double T = 0.005 * mean_edge(input);
  const Tolerance_run r = run_at(input, TSP::number_of_tiles(4).panel_tolerance(T).number_of_improvement_rounds(0));
  ASSERT_TRUE(r.result.is_tilable()) << r.result.optimization.ending();
  EXPECT_TRUE(r.result.optimization.measure.within_panel_tolerance());
  EXPECT_EQ(r.result.optimization.measure.panel_tolerance, T);
  EXPECT_GT(largest_move(input, r.mesh), 0.0) << "the fixture must make the solver move";
  expect_every_instance_within(r, T);
  for(const TS::Tile& tile : r.result.tiles)
    EXPECT_EQ(tile.instance_faces.size(), tile.instance_count);
}

TEST(PanelTolerance, ZeroIsTheExactMode)
{
  const Mesh input = paraboloid_grid();
  const auto np = TSP::number_of_tiles(4).number_of_improvement_rounds(0);
  const Tolerance_run exact = run_at(input, np);
  const Tolerance_run zero = run_at(input, np.panel_tolerance(0.0));
  ASSERT_TRUE(exact.result.is_tilable());
  EXPECT_EQ(zero.cluster, exact.cluster);
  EXPECT_EQ(zero.orientation, exact.orientation);
  for(auto v : vertices(input)) EXPECT_EQ(zero.mesh.point(v), exact.mesh.point(v));
  EXPECT_EQ(zero.result.optimization.iterations, exact.result.optimization.iterations);
  EXPECT_LE(zero.result.optimization.measure.congruence_error, TS::defaults::congruence_tolerance);
  EXPECT_FALSE(zero.result.optimization.measure.within_panel_tolerance()) << "no tolerance to be within";
}

TEST(PanelTolerance, ABadToleranceIsRefusedByNameAndTheMeshIsUntouched)
{
  const Mesh input = paraboloid_grid();
  for(double bad : {-1e-3, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
  {
    Mesh mesh = input;
    try
    {
      TS::make_k_set_tilable(mesh, TSP::number_of_tiles(4).panel_tolerance(bad));
      ADD_FAILURE() << "panel_tolerance " << bad << " was accepted";
    }
    catch(const TS::Invalid_input& e)
    {
      EXPECT_NE(std::string(e.what()).find("panel_tolerance"), std::string::npos) << e.what();
    }
    for(auto v : vertices(input)) EXPECT_EQ(mesh.point(v), input.point(v));
  }
}

TEST(PanelTolerance, PanelsThatFitOneMoldShareItUnmovedWhereExactnessMovesThem)
{
  const Mesh input = jittered_grid(1e-3);
  const double T = 0.05;
  const auto np = TSP::number_of_tiles(1).number_of_improvement_rounds(0);
  const Tolerance_run exact = run_at(input, np);
  const Tolerance_run within = run_at(input, np.panel_tolerance(T));
  ASSERT_TRUE(within.result.is_tilable());
  EXPECT_EQ(largest_move(input, within.mesh), 0.0) << "every panel already fits one mold within T";
  EXPECT_GT(largest_move(input, exact.mesh), 1e-4) << "exactness has to move the jittered grid";
  expect_every_instance_within(within, T);
}

TEST(PanelTolerance, ADeviationBudgetNeedsFewerMoldsWithinATolerance)
{
  const Mesh input = jittered_grid(1e-3);
  const auto np = TSP::max_deviation(1e-6).number_of_improvement_rounds(0);
  const Tolerance_run exact = run_at(input, np);
  const Tolerance_run within = run_at(input, np.panel_tolerance(0.05));
  ASSERT_TRUE(within.result.is_tilable());
  EXPECT_LE(within.result.optimization.measure.number_of_clusters, 2u);
  EXPECT_GT(exact.result.optimization.measure.number_of_clusters,
            4 * within.result.optimization.measure.number_of_clusters);
}

TEST(PanelTolerance, TheCommandLineCertifiesItAndRefusesABadOne)
{
  Temp_dir dir("panel_tolerance");
  const std::string mesh_file = (dir / "grid.off").string();
  {
    std::ofstream out(mesh_file);
    out.precision(17);
    ASSERT_TRUE(CGAL::IO::write_OFF(out, paraboloid_grid()));
  }
  auto run = [&](const std::string& arguments) {
    const std::string command = std::string(K_SET_TILABLE_BINARY) + " " + mesh_file + " " + arguments + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string output;
    std::array<char, 4096> buffer;
    while(pipe != nullptr && std::fgets(buffer.data(), int(buffer.size()), pipe)) output += buffer.data();
    const int status = pipe != nullptr ? pclose(pipe) : -1;
    return std::make_pair(WIFEXITED(status) ? WEXITSTATUS(status) : -1, output);
  };
  const std::string out = (dir / "out.ply").string();
  const auto good = run("-k 4 --improvement-rounds 0 --panel-tolerance-relative 0.02 -q -o " + out);
  EXPECT_EQ(good.first, 0) << good.second;
  EXPECT_NE(good.second.find("] every panel within"), std::string::npos) << good.second;
  for(const std::string bad : {"--panel-tolerance=-1", "--panel-tolerance-relative nan",
                               "--panel-tolerance 1 --panel-tolerance-relative 0.001"})
  {
    const std::string refused = (dir / "refused.ply").string();
    const auto r = run("-k 4 " + bad + " -o " + refused);
    EXPECT_EQ(r.first, 2) << bad << ": " << r.second;
    EXPECT_NE(r.second.find("--panel-tolerance"), std::string::npos) << bad << ": " << r.second;
    EXPECT_FALSE(std::ifstream(refused).good()) << bad;
  }
}

} // namespace test_panel_tolerance_unit
