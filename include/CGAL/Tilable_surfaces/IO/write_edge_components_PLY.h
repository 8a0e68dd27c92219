// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_EDGE_COMPONENTS_PLY_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_EDGE_COMPONENTS_PLY_H

/// \file write_edge_components_PLY.h
/// A picture of the edge-sharing graph on the surface (the paper's Fig. 6):
/// edges of one component get one colour.

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
#include <ostream>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// Writes a triangle mesh in PLY where each face of `pm` becomes the fan of
/// triangles (v_j, v_{j+1}, centroid), each coloured by the component of its
/// edge v_j v_{j+1} in `edge_component_map` (for example
/// `Edge_sharing_graph::edge_component_map()`). Viewed shaded, every edge of
/// the surface is flanked by its component's colour, as in the paper's Fig. 6.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map} the points of `pm` \cgalParamNEnd
///   \cgalParamNBegin{use_binary_mode} binary if `true` (default) \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether the stream is good after writing.
/// \throws Invalid_input if `pm` fails `validate_panel_mesh()`; nothing is
/// written then.
template <typename PolygonMesh, typename EdgeComponentMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_edge_components_PLY(std::ostream& os, const PolygonMesh& pm,
                               EdgeComponentMap edge_component_map,
                               const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Output_mesh;
  typedef Output_mesh::Point Point;
  const auto vpm = Tilable_surfaces::internal::const_vertex_point_map(pm, np);
  const bool binary =
    choose_parameter(get_parameter(np, CGAL::internal_np::use_binary_mode), defaults::use_binary_mode);
  validate_panel_mesh(pm, np);

  std::size_t number_of_components = 0;
  for(auto e : edges(pm))
    number_of_components = (std::max)(number_of_components, std::size_t(get(edge_component_map, e)) + 1);
  const std::vector<CGAL::IO::Color> colors = cluster_colors(number_of_components);

  Output_mesh out;
  auto color = out.add_property_map<Output_mesh::Face_index, CGAL::IO::Color>("f:color").first;
  auto to_point = [](const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); };
  for(auto f : faces(pm))
  {
    // Each face gets its own vertices: the fans must not be glued, or the
    // shading would blend the colours across edges.
    std::vector<Eigen::Vector3d> corners;
    for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      corners.push_back(Tilable_surfaces::internal::to_eigen(get(vpm, v)));
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
    for(const auto& p : corners) centroid += p / double(corners.size());
    const auto c = out.add_vertex(to_point(centroid));
    std::vector<Output_mesh::Vertex_index> ring;
    for(const auto& p : corners) ring.push_back(out.add_vertex(to_point(p)));
    const auto face_edges = face_edge_halfedges(f, pm);
    const std::size_t n = ring.size();
    for(std::size_t j = 0; j < n; ++j)
    {
      const auto t = out.add_face(ring[j], ring[(j + 1) % n], c);
      color[t] = colors[std::size_t(get(edge_component_map, edge(face_edges[j], pm)))];
    }
  }
  if(binary)
    CGAL::IO::set_binary_mode(os);
  else
    CGAL::IO::set_ascii_mode(os);
  return CGAL::IO::write_PLY(os, out);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_EDGE_COMPONENTS_PLY_H
