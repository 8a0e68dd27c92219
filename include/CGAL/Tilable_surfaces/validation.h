// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_VALIDATION_H
#define CGAL_TILABLE_SURFACES_VALIDATION_H

/// \file validation.h
/// Input checks shared by every entry point of the package.

#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Checks that `pm` can be processed by the package and throws otherwise.
///
/// The mesh must have at least one face, a valid halfedge structure
/// (`CGAL::is_valid_polygon_mesh()`), finite coordinates at every vertex, and
/// every face must be a quad with 4 distinct vertices, no edge shorter than
/// 1e-12 times the bounding-box diagonal and a vector area
/// |(v2 - v0) x (v3 - v1)| / 2 larger than 1e-12 times the squared diagonal
/// (a face collapsed to a point or a segment has vector area 0).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map} the points of the vertices \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} indices used in the messages \cgalParamNEnd
///   \cgalParamNBegin{face_index_map} indices used in the messages \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input naming the first offending vertex or face (in the
/// order of `vertices(pm)` and `faces(pm)`). Never modifies `pm`.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void validate_quad_mesh(const PolygonMesh& pm,
                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, pm));
  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  const auto fim = CGAL::get_initialized_face_index_map(pm, np);

  if(faces(pm).empty())
    throw Invalid_input("the mesh has no face");
  if(!CGAL::is_valid_polygon_mesh(pm))
    throw Invalid_input("the mesh is not a valid polygon mesh (broken halfedge structure)");

  Eigen::Vector3d lo = Eigen::Vector3d::Constant((std::numeric_limits<double>::max)());
  Eigen::Vector3d hi = -lo;
  for(auto v : vertices(pm))
  {
    const Eigen::Vector3d x = internal::to_eigen(get(vpm, v));
    if(!x.allFinite())
    {
      std::ostringstream out;
      out << "vertex " << get(vim, v) << " has a non-finite coordinate ("
          << x.x() << ", " << x.y() << ", " << x.z() << ")";
      throw Invalid_input(out.str(), Invalid_input::VERTEX, get(vim, v));
    }
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double diagonal = (hi - lo).norm();
  const double min_length = 1e-12 * diagonal;
  const double min_area = 1e-12 * diagonal * diagonal;

  for(auto f : faces(pm))
  {
    const std::size_t fi = get(fim, f);
    auto fail = [&](const std::string& what) {
      throw Invalid_input("face " + std::to_string(fi) + " " + what, Invalid_input::FACE, fi);
    };
    std::vector<std::size_t> ids;
    for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      ids.push_back(get(vim, v));
    if(ids.size() != 4)
      fail("has " + std::to_string(ids.size()) +
           " vertices; only quad meshes are supported");
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j)
        if(ids[i] == ids[j])
          fail("uses vertex " + std::to_string(ids[i]) + " twice");

    const Quad q = face_quad(f, pm, Quad_orientation(), np);
    for(int k = 0; k < 4; ++k)
      if(!((q[(k + 1) & 3] - q[k]).norm() > min_length))
        fail("has a zero-length edge between vertices " + std::to_string(ids[k]) +
             " and " + std::to_string(ids[(k + 1) & 3]));
    if(!(0.5 * (q[2] - q[0]).cross(q[3] - q[1]).norm() > min_area))
      fail("is collapsed: its area is zero");
  }
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_VALIDATION_H
