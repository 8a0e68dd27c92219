// The tile catalog: every derived number checked against a hand-made tile.
#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>

#include "csv_cells.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_tile_catalog_unit {

namespace TS = CGAL::Tilable_surfaces;
using Eigen::Vector3d;

namespace {

// Unit square with t3 lifted by h: edges 1, 1, sqrt(1+h^2), sqrt(1+h^2),
// diagonals sqrt(2), sqrt(2+h^2), signed volume h/6, planarity h.
TS::Tile lifted_square(double h)
{
  TS::Tile t;
  t.id = 3;
  t.instance_count = 17;
  t.corners = TS::Panel{{Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(1, 1, 0), Vector3d(0, 1, h)}};
  t.worst_deviation = 2.5e-7;
  t.mirrored_count = 5;
  t.mold = 2;
  return t;
}


} // namespace

TEST(TileCatalog, CsvHasTheHandComputedValues)
{
  const double h = 0.5;
  std::ostringstream out;
  ASSERT_TRUE(TS::IO::write_tile_catalog_CSV(out, {lifted_square(h), lifted_square(0.0)}));
  std::istringstream in(out.str());
  std::string header, row, flat;
  std::getline(in, header);
  std::getline(in, row);
  std::getline(in, flat);
  const std::vector<std::string> names = csv_cells(header), cells = csv_cells(row);
  ASSERT_EQ(names.size(), 27u);
  ASSERT_EQ(cells.size(), names.size());
  auto value = [&](const std::string& name) {
    for(std::size_t i = 0; i < names.size(); ++i)
      if(names[i] == name) return std::stod(cells[i]);
    ADD_FAILURE() << "no column " << name;
    return 0.0;
  };
  EXPECT_EQ(value("id"), 3);
  EXPECT_EQ(value("instances"), 17);
  EXPECT_EQ(value("mirrored"), 5);
  EXPECT_EQ(value("t3z"), h);
  EXPECT_EQ(value("e01"), 1.0);
  EXPECT_EQ(value("e12"), 1.0);
  EXPECT_DOUBLE_EQ(value("e23"), std::sqrt(1 + h * h));
  EXPECT_DOUBLE_EQ(value("e30"), std::sqrt(1 + h * h));
  EXPECT_DOUBLE_EQ(value("d02"), std::sqrt(2.0));
  EXPECT_DOUBLE_EQ(value("d13"), std::sqrt(2 + h * h));
  EXPECT_DOUBLE_EQ(value("signed_volume"), h / 6);
  EXPECT_DOUBLE_EQ(value("planarity"), h);
  EXPECT_EQ(value("worst_deviation"), 2.5e-7);
  // The diagonals (0,0,0)-(1,1,0) and (1,0,0)-(0,1,h) are h / sqrt(2 h^2 + 4) apart.
  EXPECT_EQ(value("planar"), 0) << "diagonals 0.24 apart";
  EXPECT_EQ(std::stod(csv_cells(flat)[names.size() - 5]), 0.0) << "a flat tile has planarity 0";
  EXPECT_EQ(csv_cells(flat)[names.size() - 4], "1") << "and is planar";
  EXPECT_EQ(cells[names.size() - 2], "quad");
  EXPECT_EQ(value("mold"), 2);
}

TEST(TileCatalog, AnSTriangleRowHasItsThreeEdgesAndLeavesTheQuadColumnsEmpty)
{
  TS::Tile t;
  t.id = 1;
  t.instance_count = 2;
  t.corners = TS::Panel(Vector3d(0, 0, 0), Vector3d(3, 0, 0), Vector3d(0, 4, 0));
  std::ostringstream out;
  ASSERT_TRUE(TS::IO::write_tile_catalog_CSV(out, {t}));
  std::istringstream in(out.str());
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  const std::vector<std::string> names = csv_cells(header), cells = csv_cells(row);
  ASSERT_EQ(cells.size(), names.size());
  auto cell = [&](const std::string& name) {
    for(std::size_t i = 0; i < names.size(); ++i)
      if(names[i] == name) return cells[i];
    ADD_FAILURE() << "no column " << name;
    return std::string();
  };
  // The 3-4-5 right triangle: edges t0t1 = 3, t1t2 = 5, t2t0 = 4.
  EXPECT_EQ(std::stod(cell("e01")), 3.0);
  EXPECT_EQ(std::stod(cell("e12")), 5.0);
  EXPECT_EQ(std::stod(cell("e23")), 4.0);
  for(const char* empty : {"t3x", "t3y", "t3z", "e30", "d02", "d13"})
    EXPECT_EQ(cell(empty), "") << empty;
  EXPECT_EQ(cell("planar"), "1");
  EXPECT_EQ(cell("kind"), "triangle");

  const nlohmann::json j = TS::IO::tile_catalog_json({t})[0];
  EXPECT_EQ(j["kind"], "triangle");
  EXPECT_EQ(j["mold"], 0u);
  EXPECT_EQ(j["corners"].size(), 3u);
  EXPECT_EQ(j["edges"].size(), 3u);
  EXPECT_EQ(j["diagonals"].size(), 0u);
}

TEST(TileCatalog, JsonParsesBackWithTheSameNumbers)
{
  const double h = 0.25;
  std::ostringstream out;
  ASSERT_TRUE(TS::IO::write_tile_catalog_JSON(out, {lifted_square(h)}));
  const nlohmann::json catalog = nlohmann::json::parse(out.str());
  ASSERT_TRUE(catalog.is_array());
  ASSERT_EQ(catalog.size(), 1u);
  const nlohmann::json& t = catalog[0];
  EXPECT_EQ(t["id"], 3);
  EXPECT_EQ(t["instances"], 17);
  EXPECT_EQ(t["corners"][3][2].get<double>(), h);
  EXPECT_DOUBLE_EQ(t["edges"][2].get<double>(), std::sqrt(1 + h * h));
  EXPECT_DOUBLE_EQ(t["diagonals"][1].get<double>(), std::sqrt(2 + h * h));
  EXPECT_DOUBLE_EQ(t["signed_volume"].get<double>(), h / 6);
  EXPECT_DOUBLE_EQ(t["planarity"].get<double>(), h);
  EXPECT_FALSE(t["planar"].get<bool>());
  EXPECT_EQ(t["mirrored"].get<std::size_t>(), 5u);
  EXPECT_EQ(t["worst_deviation"].get<double>(), 2.5e-7);
}

// With a panel tolerance T, `planar` says that a flat mold holds every
// instance within T: the worst deviation plus half the distance between the
// diagonals at most T. The lifted square's diagonals are d = h / sqrt(2 h^2 + 4)
// apart along n = (h, -h, 2) / sqrt(2 h^2 + 4); moving t0, t2 by d / 2 along n
// and t1, t3 by d / 2 against it flattens it, which is checked here too.
TEST(TileCatalog, WithAPanelTolerancePlanarMeansAFlatMoldHoldsEveryInstanceWithinIt)
{
  const double h = 0.01, root = std::sqrt(2 * h * h + 4), d = h / root;
  TS::Tile t = lifted_square(h);
  const Vector3d n(h / root, -h / root, 2 / root);
  std::array<Vector3d, 4> flat;
  for(int i = 0; i < 4; ++i) flat[std::size_t(i)] = t.corners[i] + (i % 2 == 0 ? 0.5 : -0.5) * d * n;
  EXPECT_NEAR((flat[1] - flat[0]).cross(flat[2] - flat[0]).dot(flat[3] - flat[0]), 0.0, 1e-15) << "flattened";

  auto planar = [&](double tolerance) {
    t.panel_tolerance = tolerance;
    return TS::IO::tile_catalog_json({t})[0]["planar"].get<bool>();
  };
  const double needed = t.worst_deviation + d / 2;
  EXPECT_FALSE(planar(0.0)) << "exact mode: diagonals " << d << " apart, above 1e-6 of the edge";
  EXPECT_TRUE(planar(needed * (1 + 1e-9)));
  EXPECT_FALSE(planar(needed * (1 - 1e-9)));
  EXPECT_FALSE(planar(d / 2)) << "the instances' own deviation counts";

  std::ostringstream out;
  t.panel_tolerance = 2 * needed;
  ASSERT_TRUE(TS::IO::write_tile_catalog_CSV(out, {t}));
  EXPECT_EQ(csv_cells(out.str().substr(out.str().find('\n') + 1)).at(23), "1") << "the CSV agrees";
}

} // namespace test_tile_catalog_unit
