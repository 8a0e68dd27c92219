// Test helper: the pipeline on a mesh of any type, checked independently
// of the package's measurement.
#ifndef TILABLE_SURFACES_TEST_ANY_MESH_CHECK_H
#define TILABLE_SURFACES_TEST_ANY_MESH_CHECK_H

#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include "congruence_check.h"

#include <gtest/gtest.h>

#include <boost/property_map/property_map.hpp>

#include <map>
#include <string>

namespace any_mesh_check {

namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;

// The test data file `name`, read by CGAL into a `Mesh`.
template <typename Mesh>
Mesh read(const std::string& name)
{
  Mesh mesh;
  EXPECT_TRUE(CGAL::IO::read_polygon_mesh(std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/" + name, mesh));
  return mesh;
}

// Runs make_k_set_tilable() with K = k, maps keyed by face descriptor (so any
// mesh type will do), and checks the result by an independent fit: tilable,
// congruent, K clusters, every face labelled.
template <typename Mesh>
TS::K_set_tilable_result tile_and_check(Mesh& mesh, int k)
{
  typedef typename boost::graph_traits<Mesh>::face_descriptor Face;
  std::map<Face, int> cluster, orientation;
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    mesh, TSP::number_of_tiles(k)
            .face_cluster_map(boost::make_assoc_property_map(cluster))
            .face_orientation_map(boost::make_assoc_property_map(orientation)));
  EXPECT_TRUE(r.is_tilable()) << r.optimization.measure.congruence_error;
  EXPECT_EQ(cluster.size(), num_faces(mesh));
  EXPECT_EQ(r.tiles.size(), std::size_t(k));
  EXPECT_LE(congruence_by_umeyama(mesh, boost::make_assoc_property_map(cluster),
                                  boost::make_assoc_property_map(orientation)), 2e-6);
  return r;
}

} // namespace any_mesh_check

#endif // TILABLE_SURFACES_TEST_ANY_MESH_CHECK_H
