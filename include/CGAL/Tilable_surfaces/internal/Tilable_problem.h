// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_H

// The mesh and its clustering turned into plain arrays indexed by vertex
// index: the solvers and the measurements work on these, never on the mesh.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Positions of the n vertices as an n x 3 row-major matrix, so that a flat
// vector of 3n coordinates (x0 y0 z0 x1 ...) maps onto it without a copy.
typedef Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> Point_matrix;

// Sets of scalar quantities that must be equal on a tiled surface: group g is
// items[begin[g] .. begin[g+1]). An item lists vertex indices; a squared
// distance uses the first two, a signed volume all four.
struct Equality_groups
{
  std::vector<std::array<int, 4>> items;
  std::vector<std::size_t> begin{0};

  std::size_t number_of_groups() const { return begin.size() - 1; }
  void close_group() { begin.push_back(items.size()); }
};

struct Tilable_problem
{
  Point_matrix points;                          // in the mesh's own units
  std::vector<std::array<int, 4>> face_corners; // corner i = template corner t_i; -1 after a triangle's 3
  std::vector<std::size_t> face_cluster;
  std::size_t number_of_clusters = 0;
  std::size_t degree_of_flexibility = 0;
  std::vector<std::array<int, 2>> edges;
  Equality_groups edge_groups;     // F_e: mesh edges, one group per component
  Equality_groups diagonal_groups; // F_a: diagonals t0t2 and t1t3, two groups per quad cluster
  Equality_groups volume_groups;   // F_o: corners, one group per quad cluster
  // (A triangle is fixed by its edges: its clusters have no diagonal or volume group.)
  // ALLOW_MIRRORED_PANELS: an instance may be the mirror image of its
  // S-quad. Then the volume groups list each instance of negative signed
  // volume with t1 and t3 swapped, which negates the volume and keeps the
  // diagonals: equal volumes up to the sign each instance has in the input.
  // (Dropping the volumes would do in exact arithmetic, since 4 edges and 2
  // diagonals fix a quad up to a mirror, but near a planar quad the
  // distances fix its height only to the square root of their residual:
  // monkey saddle, K = 3, stalled at a congruence error of 6e-5.)
  bool allow_mirror = false;
  // planar_tiles: every panel planar too. The constraints pin each
  // cluster's volume to 0 and the congruence error counts the distance
  // between the diagonals of every face.
  bool planar = false;

  std::size_t number_of_vertices() const { return std::size_t(points.rows()); }
};

template <typename PolygonMesh, typename VertexPointMap, typename VertexIndexMap>
Point_matrix read_points(const PolygonMesh& pm, const VertexPointMap& vpm, const VertexIndexMap& vim)
{
  Point_matrix points(num_vertices(pm), 3);
  for(auto v : vertices(pm))
  {
    const auto& p = get(vpm, v);
    points.row(get(vim, v)) << CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                               CGAL::to_double(p.z());
  }
  return points;
}

// The number of corners of face `face`: 3 or 4.
inline int corner_count(const Tilable_problem& problem, std::size_t face)
{
  return problem.face_corners[face][3] < 0 ? 3 : 4;
}

// Corner i of face `face` is t_i of its S-quad (or S-triangle).
CGAL_TILABLE_SURFACES_INLINE
Panel instance(const Tilable_problem& problem, const Point_matrix& points, std::size_t face);

// Fills the corners and clusters of the faces, the edges and the edge groups
// (one per edge-sharing component). The faces in index order, the edges in the
// order the faces reach them: the groups' first items and the solvers'
// rounding follow these orders, which the index map, not the mesh's storage,
// decides.
template <typename PolygonMesh, typename VertexIndexMap, typename FaceIndexMap>
void add_faces_and_edge_groups(const PolygonMesh& pm, const VertexIndexMap& vim, const FaceIndexMap& fim,
                               const Face_clustering& clustering, const Edge_sharing_graph<PolygonMesh>& graph,
                               Tilable_problem& problem)
{
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> face_of(num_faces(pm));
  for(auto f : faces(pm))
    face_of[std::size_t(get(fim, f))] = f;
  const auto eim = CGAL::get_initialized_edge_index_map(pm);
  std::vector<bool> reached(num_edges(pm), false);
  std::vector<std::vector<std::array<int, 4>>> by_component(problem.degree_of_flexibility);
  for(std::size_t i = 0; i < face_of.size(); ++i)
  {
    std::array<int, 4> face_order;
    int n = 0;
    for(auto v : CGAL::vertices_around_face(halfedge(face_of[i], pm), pm))
      face_order[std::size_t(n++)] = int(get(vim, v));
    const Panel_orientation o = clustering.orientation[i];
    std::array<int, 4> corners{{-1, -1, -1, -1}};
    for(int k = 0; k < n; ++k)
      corners[std::size_t(k)] = face_order[std::size_t(o(k, n))];
    problem.face_corners.push_back(corners);
    problem.face_cluster.push_back(clustering.label[i]);
    for(auto h : face_edge_halfedges(face_of[i], pm))
    {
      const auto e = edge(h, pm);
      if(reached[get(eim, e)])
        continue;
      reached[get(eim, e)] = true;
      const std::array<int, 2> ends{{int(get(vim, source(e, pm))), int(get(vim, target(e, pm)))}};
      problem.edges.push_back(ends);
      by_component[graph.component(e)].push_back({{ends[0], ends[1], -1, -1}});
    }
  }
  for(const auto& group : by_component)
  {
    problem.edge_groups.items.insert(problem.edge_groups.items.end(), group.begin(), group.end());
    problem.edge_groups.close_group();
  }
}

// Fills the diagonal and volume groups: per quad cluster, its instances'
// diagonals t0t2, then t1t3, and their corners.
CGAL_TILABLE_SURFACES_INLINE
void add_cluster_groups(Tilable_problem& problem);

// The clustering of `pm` read from the named parameters `face_cluster_map`
// and `face_orientation_map` (both required), with K = 1 + the largest id.
// Throws Invalid_input for ids or orientations out of range; the mesh itself
// is checked by validate_panel_mesh() beforehand.
template <typename PolygonMesh, typename NamedParameters>
Tilable_problem make_tilable_problem(const PolygonMesh& pm, const NamedParameters& np)
{
  using parameters::get_parameter;
  namespace TS_np = CGAL::Tilable_surfaces::internal_np;
  require_face_maps<NamedParameters>();
  const auto cluster_map = get_parameter(np, TS_np::face_cluster);
  const auto orientation_map = get_parameter(np, TS_np::face_orientation);
  const auto vpm = internal::const_vertex_point_map(pm, np);
  const auto vim = CGAL::get_initialized_vertex_index_map(pm, np);
  const auto fim = CGAL::get_initialized_face_index_map(pm, np);

  Tilable_problem problem;
  problem.allow_mirror =
    parameter_or(np, TS_np::orientation_policy, defaults::orientation_policy) == ALLOW_MIRRORED_PANELS;
  problem.planar = parameter_or(np, TS_np::planar_tiles, defaults::planar_tiles);
  const Face_clustering clustering = read_face_clustering(pm, fim, cluster_map, orientation_map);
  problem.number_of_clusters = clustering.number_of_clusters;
  const Edge_sharing_graph<PolygonMesh> graph(Validated_mesh(true), pm, fim, vpm, clustering);
  problem.degree_of_flexibility = graph.degree_of_flexibility();
  problem.points = read_points(pm, vpm, vim);
  add_faces_and_edge_groups(pm, vim, fim, clustering, graph, problem);
  add_cluster_groups(problem);
  return problem;
}

// Mean edge length of the mesh with vertex positions `points`.
CGAL_TILABLE_SURFACES_INLINE
double mean_edge_length(const Tilable_problem& problem, const Point_matrix& points);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Tilable_problem_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_PROBLEM_H
