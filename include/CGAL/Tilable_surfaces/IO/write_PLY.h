// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_PLY_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_PLY_H

/// \file write_PLY.h
/// Writes a tiled mesh as PLY with, per face, its cluster, its S-quad
/// orientation and a colour per cluster.

#include <CGAL/Tilable_surfaces/IO/cluster_colors.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh/IO/PLY.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstdint>
#include <ostream>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

namespace internal {

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Output_mesh;

// A copy of `pm` as a Surface_mesh, so that CGAL's writer emits the
// properties, and the pairs (face of `pm`, its copy). It is built face by
// face (not with copy_face_graph(), which may start a face's vertex cycle
// elsewhere) because orientations refer to v0 of each face.
template <typename PolygonMesh, typename VertexPointMap>
Output_mesh output_mesh(const PolygonMesh& pm, const VertexPointMap& vpm,
                        std::vector<std::pair<typename boost::graph_traits<PolygonMesh>::face_descriptor,
                                              Output_mesh::Face_index> >& face_pairs)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  Output_mesh out;
  std::unordered_map<vertex_descriptor, Output_mesh::Vertex_index> vertex_image;
  for(vertex_descriptor v : vertices(pm))
  {
    const Eigen::Vector3d p = Tilable_surfaces::internal::to_eigen(get(vpm, v));
    vertex_image.emplace(v, out.add_vertex(Output_mesh::Point(p.x(), p.y(), p.z())));
  }
  std::vector<Output_mesh::Vertex_index> corners;
  for(auto f : faces(pm))
  {
    corners.clear();
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      corners.push_back(vertex_image.at(v));
    face_pairs.emplace_back(f, out.add_face(corners));
  }
  return out;
}

// Adds to `out` the face properties of write_tiled_PLY(): cluster,
// orientation, corners and colour.
template <typename FacePairs, typename ClusterMap, typename OrientationMap>
void add_face_properties(Output_mesh& out, const FacePairs& face_pairs, ClusterMap clusters,
                         OrientationMap orientations, const std::vector<CGAL::IO::Color>& colors)
{
  auto cluster_property = out.add_property_map<Output_mesh::Face_index, int>("f:cluster", 0).first;
  auto orientation_property =
    out.add_property_map<Output_mesh::Face_index, std::uint8_t>("f:orientation", 0).first;
  auto corners_property = out.add_property_map<Output_mesh::Face_index, std::uint8_t>("f:corners", 4).first;
  auto color_property = out.add_property_map<Output_mesh::Face_index, CGAL::IO::Color>("f:color").first;
  for(const auto& fp : face_pairs)
  {
    const std::size_t c = std::size_t(get(clusters, fp.first));
    cluster_property[fp.second] = int(c);
    orientation_property[fp.second] = std::uint8_t(int(get(orientations, fp.first)));
    corners_property[fp.second] = std::uint8_t(out.degree(fp.second));
    color_property[fp.second] = colors[c];
  }
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Writes `pm` to `os` in PLY, vertices and faces in the order of
/// `vertices(pm)` and `faces(pm)`, with the face properties `cluster` (int),
/// `orientation` (uchar, 0..7), `corners` (uchar: 4 for a quad, 3 for a
/// triangle, so that a reader that drops the face lists still tells the kinds
/// apart) and `red`, `green`, `blue`, `alpha` (uchar, one distinct colour per
/// cluster, see `cluster_colors()`).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} cluster ids 0..K-1 (required) \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} orientations 0..7 (required) \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm` \cgalParamNEnd
///   \cgalParamNBegin{use_binary_mode} binary little-endian if `true` (default) \cgalParamNEnd
///   \cgalParamNBegin{stream_precision} digits of ASCII coordinates (default 17) \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether the stream is good after writing.
/// \throws Invalid_input if `pm` fails `validate_panel_mesh()` or a face has
/// a negative cluster or an orientation that is not one of its own; nothing
/// is written then.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_tiled_PLY(std::ostream& os, const PolygonMesh& pm,
                     const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;

  const auto clusters = get_parameter(np, internal_np::face_cluster);
  const auto orientations = get_parameter(np, internal_np::face_orientation);
  const bool binary =
    choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), defaults::use_binary_mode);
  const int precision =
    choose_parameter(get_parameter(np, CGAL::internal_np::stream_precision), defaults::stream_precision);
  const auto vpm = Tilable_surfaces::internal::const_vertex_point_map(pm, np);

  validate_panel_mesh(pm, np);
  Tilable_surfaces::internal::check_face_labels(pm, CGAL::get_initialized_face_index_map(pm, np),
                                                clusters, orientations);

  std::vector<std::pair<face_descriptor, internal::Output_mesh::Face_index> > face_pairs;
  internal::Output_mesh out = internal::output_mesh(pm, vpm, face_pairs);
  const std::vector<CGAL::IO::Color> colors =
    cluster_colors(internal::number_of_face_clusters(pm, clusters));
  internal::add_face_properties(out, face_pairs, clusters, orientations, colors);

  if(binary)
    CGAL::IO::set_binary_mode(os);
  else
    CGAL::IO::set_ascii_mode(os);
  return CGAL::IO::write_PLY(os, out, CGAL::parameters::stream_precision(precision));
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_PLY_H
