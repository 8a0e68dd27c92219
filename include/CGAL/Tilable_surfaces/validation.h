// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_VALIDATION_H
#define CGAL_TILABLE_SURFACES_VALIDATION_H

/// \file validation.h
/// Input checks shared by every entry point of the package.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Polyhedron_3_fwd.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

namespace internal {

// Tag of the internal entry points that skip validate_panel_mesh(): the mesh
// passed with it was accepted by it (the public functions check first, the
// stateful K_set_tilable_surface once, in its constructor).
struct Validated_mesh
{
  explicit Validated_mesh(bool) {}
};

// CGAL::Polyhedron_3 gives edge indices only through halfedge ids: its items
// must be CGAL::Polyhedron_items_with_id_3 (or others with ids).
template <typename Halfedge, typename = void>
struct Halfedge_has_id : std::false_type {};
template <typename Halfedge>
struct Halfedge_has_id<Halfedge, std::void_t<decltype(std::declval<const Halfedge&>().id())> >
  : std::true_type {};
template <typename PolygonMesh>
struct Has_edge_indices : std::true_type {};
template <class K, class Items, template <class, class, class> class HDS, class Alloc>
struct Has_edge_indices<CGAL::Polyhedron_3<K, Items, HDS, Alloc> >
  : Halfedge_has_id<typename CGAL::Polyhedron_3<K, Items, HDS, Alloc>::Halfedge> {};
#define CGAL_TILABLE_SURFACES_ASSERT_EDGE_INDICES(PolygonMesh)                                    \
  static_assert(CGAL::Tilable_surfaces::internal::Has_edge_indices<PolygonMesh>::value,          \
                "Tilable_surfaces: CGAL::Polyhedron_3 needs items with ids "                      \
                "(CGAL::Polyhedron_items_with_id_3): the package indexes edges by halfedge id")

// The defect of a halfedge's links (next, opposite, target, edge, face), or
// an empty string.
template <typename PolygonMesh>
std::string halfedge_defect(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h,
                            const PolygonMesh& pm)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  const auto n = next(h, pm), o = opposite(h, pm);
  if(n == GT::null_halfedge() || o == GT::null_halfedge() || target(h, pm) == GT::null_vertex())
    return "a halfedge has no next, opposite or target";
  if(halfedge(edge(h, pm), pm) != h && halfedge(edge(h, pm), pm) != o)
    return "an edge does not own its halfedges";
  if(o == h || opposite(o, pm) != h || prev(n, pm) != h || next(prev(h, pm), pm) != h)
    return "the opposite, next and previous halfedges are not reciprocal";
  if(n == h || target(h, pm) != source(n, pm) || target(h, pm) == target(o, pm))
    return "a halfedge does not join two distinct vertices in sequence";
  if(face(h, pm) == face(o, pm) || next(n, pm) == h || target(h, pm) == target(n, pm) ||
     target(h, pm) == target(next(n, pm), pm))
    return "the surface is not a 2-manifold (an edge or face folds onto itself)";
  return std::string();
}

// The defect of the halfedge cycles around the vertices, or an empty string:
// together they must hold each of the `nh` halfedges once.
template <typename PolygonMesh>
std::string vertex_cycles_defect(const PolygonMesh& pm, std::size_t nh)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  std::size_t around_vertices = 0;
  for(auto v : vertices(pm))
  {
    const auto h0 = halfedge(v, pm);
    if(h0 == GT::null_halfedge())
      continue; // isolated vertex: accepted
    if(target(h0, pm) != v)
      return "a vertex's halfedge does not point to it";
    auto h = h0;
    do
    {
      if(target(h, pm) != v || ++around_vertices > nh)
        return "a vertex is non-manifold or its halfedge cycle is broken";
      h = opposite(next(h, pm), pm);
    } while(h != h0);
  }
  if(around_vertices != nh)
    return "a vertex is non-manifold (two fans of faces meet at a single vertex)";
  return std::string();
}

// The defect of the halfedge cycles around the faces, or an empty string:
// with the border halfedges they must hold each of the `nh` halfedges once.
template <typename PolygonMesh>
std::string face_cycles_defect(const PolygonMesh& pm, std::size_t nh)
{
  typedef boost::graph_traits<PolygonMesh> GT;
  std::size_t around_faces = 0;
  for(auto f : faces(pm))
  {
    const auto h0 = halfedge(f, pm);
    if(h0 == GT::null_halfedge() || face(h0, pm) != f)
      return "a face's halfedge is not on the face";
    auto h = h0;
    do
    {
      if(face(h, pm) != f || ++around_faces > nh)
        return "a face's halfedge cycle is broken";
      h = next(h, pm);
    } while(h != h0);
  }
  for(auto h : halfedges(pm))
    if(face(h, pm) == GT::null_face())
      ++around_faces;
  if(around_faces != nh)
    return "some halfedges are on no face and not on the border";
  return std::string();
}

// What `CGAL::is_valid_polygon_mesh()` checks, except that a vertex without a
// halfedge (isolated, used by no face) is accepted. Returns an empty string
// for a valid structure, else what is wrong. Every walk is bounded by the
// number of halfedges, so a broken structure cannot make it loop.
template <typename PolygonMesh>
std::string structure_defect(const PolygonMesh& pm)
{
  const std::size_t nh = std::size_t(std::distance(halfedges(pm).begin(), halfedges(pm).end()));
  const std::size_t ne = std::size_t(std::distance(edges(pm).begin(), edges(pm).end()));
  if(nh != 2 * ne)
    return "the numbers of halfedges and edges disagree";
  for(auto h : halfedges(pm))
  {
    std::string defect = halfedge_defect(h, pm);
    if(!defect.empty())
      return defect;
  }
  std::string defect = vertex_cycles_defect(pm, nh);
  return defect.empty() ? face_cycles_defect(pm, nh) : defect;
}

// Whether `index` maps the `range` onto 0..n-1 without repetition, n being
// the number of elements the BGL functions report (num_vertices(), ...).
template <typename Range, typename IndexMap>
bool is_compact_index_map(const Range& range, IndexMap index, std::size_t n)
{
  std::vector<bool> seen(n, false);
  std::size_t count = 0;
  for(auto x : range)
  {
    const std::size_t i = std::size_t(get(index, x));
    if(i >= n || seen[i])
      return false;
    seen[i] = true;
    ++count;
  }
  return count == n;
}

// Whether vertex `v` is used by no face.
template <typename PolygonMesh>
bool is_isolated(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  return halfedge(v, pm) == boost::graph_traits<PolygonMesh>::null_halfedge();
}

// The number of corners of face `f` of a mesh validate_panel_mesh() accepted: 3 or 4.
template <typename PolygonMesh>
int face_corner_count(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& pm)
{
  return int(face_edge_halfedges(f, pm).size());
}

// Checks the cluster `c` and orientation `o` of face `fi`, of `corners`
// corners, against K clusters (K unknown: the largest size_t) and the
// orientations of its kind.
CGAL_TILABLE_SURFACES_INLINE
void check_face_label(std::size_t fi, long long c, long long o, std::size_t number_of_clusters,
                      int corners);

// The same for every face, the clusters and orientations read from maps.
template <typename PolygonMesh, typename FaceIndexMap, typename ClusterMap, typename OrientationMap>
void check_face_labels(const PolygonMesh& pm, FaceIndexMap fim, ClusterMap clusters,
                       OrientationMap orientations)
{
  for(auto f : faces(pm))
    check_face_label(std::size_t(get(fim, f)), static_cast<long long>(get(clusters, f)),
                     static_cast<long long>(static_cast<int>(get(orientations, f))),
                     (std::numeric_limits<std::size_t>::max)(), face_corner_count(f, pm));
}

// Throws unless the vertex, face and (where the mesh has them) edge indices
// number the elements 0..n-1.
template <typename PolygonMesh, typename VertexIndexMap, typename FaceIndexMap>
void check_index_maps(const PolygonMesh& pm, const VertexIndexMap& vim, const FaceIndexMap& fim)
{
  bool compact = is_compact_index_map(vertices(pm), vim, num_vertices(pm)) &&
                 is_compact_index_map(faces(pm), fim, num_faces(pm));
  if constexpr(Has_edge_indices<PolygonMesh>::value)
  {
    // Where the mesh keeps halfedge ids (Polyhedron_items_with_id_3), they
    // give the edge indices: this numbers them if they are not numbered yet.
    CGAL::get_initialized_halfedge_index_map(pm);
    compact = compact && is_compact_index_map(
                           edges(pm), CGAL::get_initialized_edge_index_map(pm), num_edges(pm));
  }
  if(!compact)
    throw Invalid_input("the vertex, edge or face indices are not 0..n-1 (a Surface_mesh with removed "
                        "elements must be garbage-collected first: collect_garbage())");
}

// The diagonal of the bounding box of the vertices; throws for a coordinate
// that is not finite or whose square overflows, and for a box too small.
template <typename PolygonMesh, typename VertexPointMap, typename VertexIndexMap>
double checked_bbox_diagonal(const PolygonMesh& pm, const VertexPointMap& vpm, const VertexIndexMap& vim)
{
  Eigen::Vector3d lo = Eigen::Vector3d::Constant((std::numeric_limits<double>::max)());
  Eigen::Vector3d hi = -lo;
  for(auto v : vertices(pm))
  {
    const Eigen::Vector3d x = to_eigen(get(vpm, v));
    const bool finite = x.allFinite();
    if(!finite || x.cwiseAbs().maxCoeff() > tuning::coordinate_limit)
    {
      std::ostringstream out;
      out << "vertex " << get(vim, v) << " has a "
          << (finite ? "coordinate beyond 1e150 in absolute value, whose square overflows ("
                     : "non-finite coordinate (")
          << x.x() << ", " << x.y() << ", " << x.z() << ")";
      throw Invalid_input(out.str(), Invalid_input::VERTEX, get(vim, v));
    }
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  const double diagonal = (hi - lo).norm();
  const double largest = (std::max)(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if(!(diagonal > tuning::extent_limit) || !(diagonal > tuning::relative_extent_limit * largest))
  {
    std::ostringstream out;
    out << "the bounding box is too small (diagonal " << diagonal << ", coordinates up to "
        << largest << "): "
        << (diagonal > tuning::extent_limit
              ? "doubles cannot resolve its shape to the congruence tolerance; move the mesh "
                "near the origin"
              : "squared lengths underflow; scale the mesh up");
    throw Invalid_input(out.str());
  }
  return diagonal;
}

// Throws unless face `f` (index `fi`) is a quad or a triangle of distinct
// vertices, with no edge of length `min_length` or less and a vector area
// above `min_area`.
template <typename PolygonMesh, typename NamedParameters, typename VertexIndexMap>
void check_face(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& pm,
                const NamedParameters& np, std::size_t fi, const VertexIndexMap& vim,
                double min_length, double min_area)
{
  auto fail = [&](const std::string& what) {
    throw Invalid_input("face " + std::to_string(fi) + " " + what, Invalid_input::FACE, fi);
  };
  std::vector<std::size_t> ids;
  for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
    ids.push_back(get(vim, v));
  const std::size_t n = ids.size();
  if(n != 3 && n != 4)
    fail("has " + std::to_string(n) +
         " vertices; only quads and triangles are supported");
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t j = i + 1; j < n; ++j)
      if(ids[i] == ids[j])
        fail("uses vertex " + std::to_string(ids[i]) + " twice");

  const Panel q = face_panel(f, pm, Panel_orientation(), np);
  for(std::size_t k = 0; k < n; ++k)
    if(!((q[int((k + 1) % n)] - q[int(k)]).norm() > min_length))
      fail("has a zero-length edge between vertices " + std::to_string(ids[k]) +
           " and " + std::to_string(ids[(k + 1) % n]));
  if(!(0.5 * q.doubled_vector_area().norm() > min_area))
    fail("is collapsed: its area is zero");
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The number of vertices of `pm` used by no face (isolated vertices, as CAD
/// exports often have). The package accepts them and never moves them; they
/// take no part in the clustering, the constraints or the measurements
/// (except the bounding box of the input, which contains every vertex).
template <typename PolygonMesh>
std::size_t number_of_isolated_vertices(const PolygonMesh& pm)
{
  std::size_t n = 0;
  for(auto v : vertices(pm))
    n += internal::is_isolated(v, pm) ? 1 : 0;
  return n;
}

/// \ingroup PkgTilableSurfacesRef
/// Checks that `pm` can be processed by the package and throws otherwise.
///
/// The mesh must have at least one face and a valid halfedge structure (what
/// `CGAL::is_valid_polygon_mesh()` checks, except that isolated vertices,
/// used by no face, are accepted: see `number_of_isolated_vertices()`); its
/// vertex, edge and face indices must number them 0..n-1 (a
/// `Surface_mesh` with removed elements must be garbage-collected first);
/// every coordinate must be finite and at most 1e150 in absolute value (the
/// squares of larger ones overflow); the bounding-box diagonal must exceed
/// 1e-140 (smaller squares underflow) and 1e-7 times the largest coordinate
/// (doubles would resolve the shape more coarsely than the congruence
/// tolerance); every face must be a quad or a triangle with distinct
/// vertices, no edge shorter than 1e-12 times the bounding-box diagonal and a
/// vector area (|(v2 - v0) x (v3 - v1)| / 2 for a quad, |(v1 - v0) x (v2 -
/// v0)| / 2 for a triangle) larger than 1e-12 times the squared diagonal (a
/// face collapsed to a point or a segment has vector area 0). Faces of 5 or
/// more vertices are refused.
///
/// (The other entry points need edge indices: there, a `CGAL::Polyhedron_3`
/// must have items with ids, `CGAL::Polyhedron_items_with_id_3`, and a
/// `static_assert` says so otherwise.)
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map} the points of the vertices \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} indices used in the messages \cgalParamNEnd
///   \cgalParamNBegin{face_index_map} indices used in the messages \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input naming the first offending vertex or face (in the
/// order of `vertices(pm)` and `faces(pm)`) and the problem. Never modifies `pm`.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
void validate_panel_mesh(const PolygonMesh& pm,
                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  if(faces(pm).empty())
    throw Invalid_input("the mesh has no face");
  const std::string defect = internal::structure_defect(pm);
  if(!defect.empty())
    throw Invalid_input("the mesh is not a valid polygon mesh (broken halfedge structure: " +
                        defect + ")");
  const auto vpm = internal::const_vertex_point_map(pm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  const auto fim = CGAL::get_initialized_face_index_map(pm, np);
  // Checked before any index is used: other indices would address arrays
  // of num_vertices() and num_faces() elements out of bounds.
  internal::check_index_maps(pm, vim, fim);
  const double diagonal = internal::checked_bbox_diagonal(pm, vpm, vim);
  const double min_length = internal::tuning::min_edge_length * diagonal;
  const double min_area = internal::tuning::min_face_area * diagonal * diagonal;
  for(auto f : faces(pm))
    internal::check_face(f, pm, np, get(fim, f), vim, min_length, min_area);
}

#ifndef CGAL_NO_DEPRECATED_CODE
/// \ingroup PkgTilableSurfacesRef
/// \deprecated The name of `validate_panel_mesh()` until 1.0.0.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
CGAL_DEPRECATED_MSG("use validate_panel_mesh()")
void validate_quad_mesh(const PolygonMesh& pm, const CGAL_NP_CLASS& np = parameters::default_values())
{
  validate_panel_mesh(pm, np);
}
#endif

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/validation_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_VALIDATION_H
