// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_OBJ_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_OBJ_H

/// \file write_OBJ.h
/// Writes a tiled mesh as Wavefront OBJ with one group and one material per
/// cluster (S-quad), and the materials (`.mtl`) with the colours of the PLY
/// output.

#include <CGAL/Tilable_surfaces/IO/cluster_colors.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <ios>
#include <limits>
#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

namespace internal {

// Restores the format flags and the precision of a stream on leaving a scope.
class Stream_format_guard
{
public:
  explicit Stream_format_guard(std::ostream& os)
    : m_os(os), m_flags(os.flags()), m_precision(os.precision())
  {}
  ~Stream_format_guard()
  {
    m_os.flags(m_flags);
    m_os.precision(m_precision);
  }
  Stream_format_guard(const Stream_format_guard&) = delete;
  Stream_format_guard& operator=(const Stream_format_guard&) = delete;

private:
  std::ostream& m_os;
  std::ios::fmtflags m_flags;
  std::streamsize m_precision;
};

// The writers need the clusters.
template <typename NamedParameters>
void require_face_cluster_map()
{
  static_assert(!parameters::is_default_parameter<NamedParameters, internal_np::face_cluster_t>::value,
                "the named parameter face_cluster_map is required");
}

// The name of the group and of the material of cluster `c`.
inline std::string tile_name(std::size_t c) { return "tile_" + std::to_string(c); }

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Writes the material library of a tiled mesh: one material `tile_<c>` per
/// cluster c in 0..K-1, K being 1 + the largest cluster id of the faces of
/// `pm`, whose diffuse colour `Kd` is the colour of cluster c in the PLY
/// output (`cluster_colors()`, each channel divided by 255).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} cluster ids 0..K-1 (required) \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether the stream is good after writing.
/// \throws Invalid_input if a cluster id is negative.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_tiled_MTL(std::ostream& os, const PolygonMesh& pm,
                     const CGAL_NP_CLASS& np)
{
  internal::require_face_cluster_map<CGAL_NP_CLASS>();
  const std::vector<CGAL::IO::Color> colors = cluster_colors(
    internal::number_of_face_clusters(pm, parameters::get_parameter(np, internal_np::face_cluster)));
  internal::Stream_format_guard guard(os);
  os.unsetf(std::ios::floatfield);
  os.precision(std::numeric_limits<double>::max_digits10);
  os << "# K-set tilable surface: one material per tile (S-quad), " << colors.size() << " tiles\n";
  for(std::size_t c = 0; c < colors.size(); ++c)
  {
    os << "\nnewmtl " << internal::tile_name(c) << "\n"
       << "# colour " << int(colors[c].red()) << " " << int(colors[c].green()) << " "
       << int(colors[c].blue()) << "\n"
       << "Kd " << colors[c].red() / 255.0 << " " << colors[c].green() / 255.0 << " "
       << colors[c].blue() / 255.0 << "\n"
       << "Ka 0 0 0\nKs 0 0 0\nd 1\nillum 1\n";
  }
  return bool(os);
}

/// \ingroup PkgTilableSurfacesRef
/// Writes `pm` to `os` in Wavefront OBJ: a `mtllib` line naming
/// `material_library` (the `.mtl` file written by `write_tiled_MTL()`, a path
/// relative to the OBJ file), the vertices in the order of `vertices(pm)` with
/// their coordinates at full precision (`std::numeric_limits<double>::max_digits10`
/// significant digits, so that they read back bit-exactly), then the faces
/// cluster by cluster: for each cluster c in 0..K-1 that has faces, the lines
/// `g tile_<c>` and `usemtl tile_<c>` followed by its faces, each with its
/// vertices in the order of `vertices_around_face()`, the faces of a cluster
/// in the order of `faces(pm)`.
///
/// The orientations of the faces are not written: OBJ has no place for
/// them; `write_tiled_PLY()` keeps them.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} cluster ids 0..K-1 (required) \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether the stream is good after writing.
/// \throws Invalid_input if a cluster id is negative; nothing is written then.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_tiled_OBJ(std::ostream& os, const PolygonMesh& pm, const std::string& material_library,
                     const CGAL_NP_CLASS& np)
{
  internal::require_face_cluster_map<CGAL_NP_CLASS>();
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;

  const auto clusters = get_parameter(np, internal_np::face_cluster);
  const auto vpm = Tilable_surfaces::internal::const_vertex_point_map(pm, np);

  // The faces cluster by cluster, checked before anything is written.
  std::vector<std::pair<std::size_t, face_descriptor> > by_cluster;
  for(face_descriptor f : faces(pm))
    by_cluster.emplace_back(internal::cluster_index(get(clusters, f)), f);
  std::stable_sort(by_cluster.begin(), by_cluster.end(),
                   [](const std::pair<std::size_t, face_descriptor>& a,
                      const std::pair<std::size_t, face_descriptor>& b) { return a.first < b.first; });

  internal::Stream_format_guard guard(os);
  os.unsetf(std::ios::floatfield);
  os.precision(std::numeric_limits<double>::max_digits10);
  os << "# K-set tilable surface: " << num_vertices(pm) << " vertices, " << num_faces(pm)
     << " faces, one group and one material per tile (S-quad)\n"
     << "mtllib " << material_library << "\n";

  std::unordered_map<vertex_descriptor, std::size_t> obj_index;
  for(vertex_descriptor v : vertices(pm))
  {
    const Eigen::Vector3d p = Tilable_surfaces::internal::to_eigen(get(vpm, v));
    os << "v " << p.x() << " " << p.y() << " " << p.z() << "\n";
    obj_index.emplace(v, obj_index.size() + 1);
  }

  for(std::size_t i = 0; i < by_cluster.size(); ++i)
  {
    if(i == 0 || by_cluster[i].first != by_cluster[i - 1].first)
      os << "g " << internal::tile_name(by_cluster[i].first) << "\n"
         << "usemtl " << internal::tile_name(by_cluster[i].first) << "\n";
    os << "f";
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(by_cluster[i].second, pm), pm))
      os << " " << obj_index.at(v);
    os << "\n";
  }
  return bool(os);
}

/// \ingroup PkgTilableSurfacesRef
/// Writes `pm` to the file `obj_path` with `write_tiled_OBJ()` and its
/// materials with `write_tiled_MTL()` to the file beside it whose name is
/// that of `obj_path` with the extension replaced by `.mtl` (`facade.obj`
/// gives `facade.mtl`).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} cluster ids 0..K-1 (required) \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether both files were written completely.
/// \throws Invalid_input if a cluster id is negative; no file is created then.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_tiled_OBJ(const std::string& obj_path, const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  internal::require_face_cluster_map<CGAL_NP_CLASS>();
  // Checks the ids before any file is created.
  internal::number_of_face_clusters(pm, parameters::get_parameter(np, internal_np::face_cluster));
  const std::filesystem::path mtl_path = std::filesystem::path(obj_path).replace_extension(".mtl");
  std::ofstream obj(obj_path), mtl(mtl_path);
  return obj && mtl && write_tiled_OBJ(obj, pm, mtl_path.filename().string(), np) &&
         write_tiled_MTL(mtl, pm, np) && obj.flush() && mtl.flush();
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_OBJ_H
