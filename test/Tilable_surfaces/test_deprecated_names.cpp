// The names of 1.0.0 that the panel vocabulary replaced still compile, as
// deprecated aliases, and do what the new names do.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_deprecated_names_unit {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"

namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Mesh;
const std::string data = CGAL_TILABLE_SURFACES_TEST_DATA;

static_assert(std::is_same<TS::Quad_orientation, TS::Panel_orientation>::value,
              "Quad_orientation names Panel_orientation");

TEST(DeprecatedNames, ReadQuadMeshReadsWhatReadPanelMeshReads)
{
  Mesh old_name, new_name;
  TS::IO::read_quad_mesh(data + "/monkey_saddle.off", old_name);
  TS::IO::read_panel_mesh(data + "/monkey_saddle.off", new_name);
  ASSERT_GT(num_faces(new_name), 0u);
  EXPECT_EQ(num_faces(old_name), num_faces(new_name));
  EXPECT_TRUE(std::equal(old_name.points().begin(), old_name.points().end(), new_name.points().begin()));
}

TEST(DeprecatedNames, ValidateQuadMeshRefusesWhatValidatePanelMeshRefuses)
{
  Mesh empty;
  EXPECT_THROW(TS::validate_quad_mesh(empty), TS::Invalid_input);
  EXPECT_THROW(TS::validate_panel_mesh(empty), TS::Invalid_input);
  Mesh mesh;
  TS::IO::read_panel_mesh(data + "/monkey_saddle.off", mesh);
  EXPECT_NO_THROW(TS::validate_quad_mesh(mesh));
}

TEST(DeprecatedNames, ClusterQuadsClustersAsClusterPanels)
{
  Mesh mesh;
  TS::IO::read_panel_mesh(data + "/monkey_saddle.off", mesh);
  std::vector<std::vector<int> > labels;
  for(int run = 0; run < 2; ++run)
  {
    auto cluster = mesh.add_property_map<Mesh::Face_index, int>("f:c" + std::to_string(run), -1).first;
    auto orientation = mesh.add_property_map<Mesh::Face_index, int>("f:o" + std::to_string(run), -1).first;
    const auto np = TS::parameters::number_of_tiles(5).face_cluster_map(cluster).face_orientation_map(orientation);
    const TS::Clustering_result r = run == 0 ? TS::cluster_quads(mesh, np) : TS::cluster_panels(mesh, np);
    EXPECT_EQ(r.s_quads.size(), 5u);
    labels.emplace_back();
    for(Mesh::Face_index f : faces(mesh))
      labels.back().push_back(cluster[f]);
  }
  EXPECT_EQ(labels[0], labels[1]);
  EXPECT_NE(*std::max_element(labels[0].begin(), labels[0].end()), 0) << "more than one cluster used";
}

#pragma GCC diagnostic pop

} // namespace test_deprecated_names_unit
