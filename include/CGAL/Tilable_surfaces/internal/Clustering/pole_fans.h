// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_H

// Quad grids capped by fans of triangles around poles: a dome meshed with a
// pole at its top, or a closed shell with two. Its quads alone form a grid
// closed across its rows (the meridian strips), whose sweep is a rotation
// that closes up (sweep_candidates.h): each fan's rim, the loop of its
// triangles' outer edges, is then one orbit of that rotation, a regular
// polygon about its axis. With the pole put on the axis, the rotation maps
// every triangle of the fan onto the next, corner by corner from the pole:
// the fan is one S-triangle. So such a mesh sweeps as its quads do, with one
// more mold per fan.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The quads of a mesh whose triangles all lie in pole fans, as a mesh of
// their own, and the fans.
struct Pole_fans
{
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Quad_part;

  Quad_part quads;                      // the quad faces alone, in face index order
  std::vector<std::size_t> face_of;     // per face of `quads`: its face index in the mesh
  std::vector<std::size_t> vertex_of;   // per vertex of `quads`: its vertex index in the mesh
  // Per face of `quads`: the vertex indices in the mesh of its face's vertices, in order.
  std::vector<std::array<std::size_t, 4> > quad_corners;
  std::vector<std::size_t> pole;        // per fan: the vertex index of its pole
  std::vector<std::vector<std::size_t> > triangles;  // per fan: its faces' indices, in index order
  std::vector<std::vector<int> > pole_corner;        // per fan and triangle: the pole's place in the face (0..2)
  // Per fan and triangle: the vertex indices of its corners from the pole on.
  std::vector<std::vector<std::array<std::size_t, 3> > > corners;
};

// What the triangles of a mesh are.
enum class Triangle_layout { NONE, POLE_FANS, OTHER };

// Whether `v` is a pole: an interior vertex all of whose faces are triangles.
template <typename PolygonMesh>
bool is_pole(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  if(is_border(v, pm))
    return false;
  for(face_descriptor f : faces_around_target(halfedge(v, pm), pm))
    if(degree(f, pm) != 3)
      return false;
  return true;
}

// Adds the quad `f` of face index `i` to the quad part of `fans`, with its
// vertices not yet there (`sub_vertex`: the quad part's vertex of every
// vertex index, or no_index()). False when the quad part refuses the face.
template <typename PolygonMesh, typename VertexIndexMap, typename VertexPointMap>
bool add_quad_to_quad_part(typename boost::graph_traits<PolygonMesh>::face_descriptor f, std::size_t i,
                           const PolygonMesh& pm, VertexIndexMap vim, VertexPointMap vpm, Pole_fans& fans,
                           std::vector<std::size_t>& sub_vertex)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  std::vector<Pole_fans::Quad_part::Vertex_index> corners;
  std::array<std::size_t, 4> quad;
  auto h = halfedge(f, pm);
  for(int j = 0; j < 4; ++j, h = next(h, pm))
  {
    const vertex_descriptor v = target(h, pm);
    const std::size_t index = std::size_t(get(vim, v));
    quad[std::size_t(j)] = index;
    if(sub_vertex[index] == no_index())
    {
      sub_vertex[index] = fans.vertex_of.size();
      fans.vertex_of.push_back(index);
      const Eigen::Vector3d p = to_eigen(get(vpm, v));
      fans.quads.add_vertex(Pole_fans::Quad_part::Point(p.x(), p.y(), p.z()));
    }
    corners.push_back(Pole_fans::Quad_part::Vertex_index(std::uint32_t(sub_vertex[index])));
  }
  // Same vertex order as the face (its first halfedge may differ:
  // sweep_start() maps orientations through quad_corners).
  if(fans.quads.add_face(corners) == Pole_fans::Quad_part::null_face())
    return false;
  fans.face_of.push_back(i);
  fans.quad_corners.push_back(quad);
  return true;
}

// Adds the triangle `f` of face index `i` to the fan of its pole, a new fan
// for a new pole (`fan_of_pole`: the fan of every vertex index, or
// no_index()). False when the triangle has no pole or two.
template <typename PolygonMesh, typename VertexIndexMap>
bool add_triangle_to_fan(typename boost::graph_traits<PolygonMesh>::face_descriptor f, std::size_t i,
                         const PolygonMesh& pm, VertexIndexMap vim, Pole_fans& fans,
                         std::vector<std::size_t>& fan_of_pole)
{
  int pole_corner = -1, poles = 0;
  auto h = halfedge(f, pm);
  for(int j = 0; j < 3; ++j, h = next(h, pm))
    if(is_pole(target(h, pm), pm))
    {
      pole_corner = j;
      ++poles;
    }
  if(poles != 1)
    return false;
  auto p = halfedge(f, pm);
  for(int j = 0; j < pole_corner; ++j)
    p = next(p, pm);
  std::array<std::size_t, 3> triangle;
  for(int j = 0; j < 3; ++j, p = next(p, pm))
    triangle[std::size_t(j)] = std::size_t(get(vim, target(p, pm)));
  std::size_t& fan = fan_of_pole[triangle[0]];
  if(fan == no_index())
  {
    fan = fans.pole.size();
    fans.pole.push_back(triangle[0]);
    fans.triangles.emplace_back();
    fans.pole_corner.emplace_back();
    fans.corners.emplace_back();
  }
  fans.triangles[fan].push_back(i);
  fans.pole_corner[fan].push_back(pole_corner);
  fans.corners[fan].push_back(triangle);
  return true;
}

// Whether `pm` has no triangle, or has quads and triangles all in pole fans
// (filled in `fans`), or something else: a face of another size, a triangle
// with no pole or two, no quad. A pole is an interior vertex all of whose
// faces are triangles.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Triangle_layout pole_fans(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                          Pole_fans& fans)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  fans = Pole_fans();
  std::vector<face_descriptor> face_by_index(num_faces(pm));
  bool triangles = false;
  for(face_descriptor f : faces(pm))
  {
    face_by_index[std::size_t(get(fim, f))] = f;
    const std::size_t n = degree(f, pm);
    if(n != 3 && n != 4)
      return Triangle_layout::OTHER;
    triangles = triangles || n == 3;
  }
  if(!triangles)
    return Triangle_layout::NONE;
  // Vertex indices need not be dense (a Surface_mesh with removed elements).
  std::size_t vertex_slots = 0;
  for(vertex_descriptor v : vertices(pm))
    vertex_slots = (std::max)(vertex_slots, std::size_t(get(vim, v)) + 1);
  std::vector<std::size_t> fan_of_pole(vertex_slots, no_index()), sub_vertex(vertex_slots, no_index());
  for(std::size_t i = 0; i < face_by_index.size(); ++i)
  {
    const face_descriptor f = face_by_index[i];
    const bool added = degree(f, pm) == 4 ? add_quad_to_quad_part(f, i, pm, vim, vpm, fans, sub_vertex)
                                          : add_triangle_to_fan(f, i, pm, vim, fans, fan_of_pole);
    if(!added)
      return Triangle_layout::OTHER;
  }
  return fans.face_of.empty() ? Triangle_layout::OTHER : Triangle_layout::POLE_FANS;
}

// A clustering of the quad part lifted to the mesh of `face_count` faces:
// the quads keep theirs, each fan is one more cluster; numbered by first
// face.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> with_fan_clusters(const Pole_fans& fans, const std::vector<std::size_t>& quad_label,
                                           std::size_t face_count);

// The quads' part of `label` (by face index of the mesh), by face of the
// quad part; empty when a fan's triangles are not one cluster of their own.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> quad_part_label(const Pole_fans& fans, const std::vector<std::size_t>& label);

// Puts each fan's pole of `points` (by vertex index of the mesh) on the axis
// of its rim, which is a regular polygon when the quads are swept: the
// rim's centre, moved along the normal of its plane to the height of the
// pole of `input`. False when the fan's triangles do not all come out
// congruent (their edge lengths within 1e-9 of `length`, the mean edge
// length): the rim is not such a polygon.
CGAL_TILABLE_SURFACES_INLINE
bool put_poles_on_axes(const Pole_fans& fans, Point_matrix& points, const Point_matrix& input, double length);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/pole_fans_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_POLE_FANS_H
