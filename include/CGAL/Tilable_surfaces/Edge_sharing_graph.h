// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_EDGE_SHARING_GRAPH_H
#define CGAL_TILABLE_SURFACES_EDGE_SHARING_GRAPH_H

/// \file Edge_sharing_graph.h
/// The edge-sharing graph of a clustering (paper §3; user manual, section Definitions): its
/// connected components are the distinct edge lengths of the tiled surface,
/// their number the degree of flexibility.

#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Union_find.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The distance between two points of any kernel, in double precision.
template <typename Point>
double distance(const Point& a, const Point& b)
{
  const double dx = CGAL::to_double(a.x()) - CGAL::to_double(b.x());
  const double dy = CGAL::to_double(a.y()) - CGAL::to_double(b.y());
  const double dz = CGAL::to_double(a.z()) - CGAL::to_double(b.z());
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The edge-sharing graph of a clustering of the faces of a mesh of quads and
/// triangles (each cluster holds one kind).
///
/// Its nodes are the template edges (c, k) of the K clusters, 4 per S-quad and
/// 3 per S-triangle: edge k of cluster c's template joins corners t_k and
/// t_{k+1}. Every interior mesh edge, shared by faces f
/// and g, links the node of f's template edge that maps onto it with that of
/// g's; links from a node to itself are ignored and boundary edges link
/// nothing. Each connected component must take a single length on the tiled
/// surface; the number of components is the *degree of flexibility* (DOF).
///
/// The components are kept in a union-find structure, so merging two clusters
/// amends the graph in O(1) amortized unions instead of rebuilding it.
///
/// The graph also says what a clustering forces on the surface: every edge of
/// a component must take one length, so the spread of the input's edge
/// lengths within each component (`length_deviation()`) is a cost that shape
/// dissimilarity alone does not see. Two quads of different rings of a tube
/// may have the same shape, but a cluster holding both links the edges of
/// the two rings, and through their neighbours every ring, to one length.
///
/// \tparam PolygonMesh a model of `FaceListGraph` whose faces are quads and triangles.
template <typename PolygonMesh>
class Edge_sharing_graph
{
  CGAL_TILABLE_SURFACES_ASSERT_EDGE_INDICES(PolygonMesh);
  typedef boost::graph_traits<PolygonMesh> GT;

public:
  typedef typename GT::face_descriptor face_descriptor;          ///< faces of the mesh
  typedef typename GT::edge_descriptor edge_descriptor;          ///< edges of the mesh
  typedef typename GT::halfedge_descriptor halfedge_descriptor;  ///< halfedges of the mesh

  /// Readable property map: the component (0..DOF-1) of every mesh edge, for
  /// colouring edges as in the paper's Fig. 6.
  class Edge_component_map
  {
  public:
    typedef edge_descriptor key_type;                   ///< a mesh edge
    typedef std::size_t value_type;                     ///< its component
    typedef std::size_t reference;                      ///< returned by value
    typedef boost::readable_property_map_tag category;  ///< read only

    Edge_component_map() : m_graph(nullptr) {}
    /// The map reading graph `g`.
    explicit Edge_component_map(const Edge_sharing_graph* g) : m_graph(g) {}
    /// The component of `e`.
    friend std::size_t get(const Edge_component_map& m, edge_descriptor e)
    { return m.m_graph->component(e); }

  private:
    const Edge_sharing_graph* m_graph;
  };

  /// Builds the graph of a clustering of `pm` into `number_of_clusters`
  /// clusters, read from `face_cluster_map` (values 0..K-1) and
  /// `face_orientation_map` (values 0..7, or `Panel_orientation`; those of a
  /// triangle in 0, 1, 2, 4, 5, 6).
  ///
  /// \cgalNamedParamsBegin
  ///   \cgalParamNBegin{vertex_point_map} the points, checked by `validate_panel_mesh()` and used for
  ///     the edge lengths of `length_deviation()` \cgalParamNEnd
  ///   \cgalParamNBegin{face_index_map} indices of the faces, for messages \cgalParamNEnd
  /// \cgalNamedParamsEnd
  /// Mesh edges are identified by the mesh's internal edge index
  /// (`CGAL::get_initialized_edge_index_map(pm)`); `pm` must not change
  /// while the graph is used.
  /// \throws Invalid_input if `pm` fails `validate_panel_mesh()` (with the
  /// `vertex_point_map` of `np`, if any), a face has a cluster out of
  /// 0..K-1 or an orientation that is not one of its own, or a cluster holds
  /// both quads and triangles.
  template <typename FaceClusterMap, typename FaceOrientationMap, typename CGAL_NP_TEMPLATE_PARAMETERS>
  Edge_sharing_graph(const PolygonMesh& pm, std::size_t number_of_clusters, FaceClusterMap face_cluster_map,
                     FaceOrientationMap face_orientation_map,
                     const CGAL_NP_CLASS& np = parameters::default_values())
    : Edge_sharing_graph(
        internal::Validated_mesh(true), pm, CGAL::get_initialized_face_index_map(pm, np),
        internal::const_vertex_point_map(pm, np),
        validated_clustering(pm, number_of_clusters, face_cluster_map, face_orientation_map, np))
  {}

  /// \cond SKIP_IN_MANUAL
  // For the package's own use on a mesh `validate_panel_mesh()` accepted,
  // with a clustering already read and checked.
  template <typename FaceIndexMap, typename VertexPointMap>
  Edge_sharing_graph(internal::Validated_mesh, const PolygonMesh& pm, FaceIndexMap fim,
                     VertexPointMap vpm, const internal::Face_clustering& clustering)
    : m_edge_index_map(CGAL::get_initialized_edge_index_map(pm))
  {
    reset(internal::cluster_corner_counts(pm, fim, clustering));
    // The S-quad edges of the two sides of every mesh edge. Each mesh edge's
    // length goes to the lower of the two, and every S-quad edge gets its
    // lengths before any link, so that the spread the links add depends on
    // the clustering only, not on which face comes first. The faces, and so
    // the edges, are taken in index order, since the sums are rounded in the
    // order they are made.
    std::vector<face_descriptor> face_of(num_faces(pm));
    for(face_descriptor f : faces(pm))
      face_of[std::size_t(get(fim, f))] = f;
    std::vector<std::array<std::size_t, 2> > sides(num_edges(pm), {{no_node(), no_node()}});
    std::vector<double> lengths(num_edges(pm), 0.0);
    std::vector<std::size_t> edge_order;
    edge_order.reserve(num_edges(pm));
    for(std::size_t fi = 0; fi < face_of.size(); ++fi)
    {
      const face_descriptor f = face_of[fi];
      const std::size_t c = clustering.label[fi];
      const Panel_orientation orientation = clustering.orientation[fi];
      const auto face_edges = face_edge_halfedges(f, pm);
      const int n = int(face_edges.size());
      for(int j = 0; j < n; ++j)
      {
        const halfedge_descriptor h = face_edges[std::size_t(j)];
        const std::size_t e = get(m_edge_index_map, edge(h, pm));
        const std::size_t node = 4 * c + std::size_t(orientation.template_edge(j, n));
        if(sides[e][0] == no_node())
        {
          edge_order.push_back(e);
          sides[e][0] = node;
          lengths[e] = internal::distance(get(vpm, source(h, pm)), get(vpm, target(h, pm)));
        }
        else
          sides[e][1] = node;
      }
    }
    std::vector<std::size_t> edge_nodes(num_edges(pm), no_node());
    std::vector<std::array<std::size_t, 2> > links;
    for(std::size_t e : edge_order)
    {
      std::array<std::size_t, 2>& side = sides[e];
      if(side[1] != no_node())
      {
        if(side[1] < side[0])
          std::swap(side[0], side[1]);
        links.push_back(side);
      }
      edge_nodes[e] = side[0];
      m_lengths[side[0]].add(lengths[e]);
    }
    for(const auto& l : links)
      link(l[0], l[1]);
    m_edge_node = std::make_shared<const std::vector<std::size_t> >(std::move(edge_nodes));
  }
  /// \endcond

  /// The number of cluster ids: K as built, merged clusters included (their
  /// ids stay reserved until `compact_cluster_ids()`).
  std::size_t number_of_clusters() const { return m_slot.size(); }

  /// Whether cluster `c` still exists (it was not merged into another one).
  bool is_alive(std::size_t c) const { return m_alive.at(m_slot.at(c)); }

  /// The degree of flexibility: the number of components among the S-quad
  /// edges of the clusters that are alive.
  std::size_t degree_of_flexibility() const { return m_number_of_components; }

  /// The number of corners (and edges) of cluster `c`'s template: 4 for an
  /// S-quad, 3 for an S-triangle.
  int corner_count(std::size_t c) const { return m_corners.at(m_slot.at(c)); }

  /// The component (0..DOF-1) of edge `k` (0..`corner_count(c)`-1) of
  /// cluster `c`'s template. Component ids are numbered by first appearance
  /// over (c, k) in lexicographic order, so they are deterministic.
  std::size_t component(std::size_t c, int k) const
  {
    if(c >= m_slot.size() || !m_alive[m_slot[c]] || k < 0 || k >= m_corners[m_slot[c]])
      throw Invalid_input("no S-quad edge (" + std::to_string(c) + ", " + std::to_string(k) +
                          ") in the edge-sharing graph", Invalid_input::PARAMETER);
    update_component_ids();
    return m_component_id[find(4 * m_slot[c] + std::size_t(k))];
  }

  /// The component of mesh edge `e`.
  std::size_t component(edge_descriptor e) const
  {
    const std::size_t node = m_edge_node->at(get(m_edge_index_map, e));
    update_component_ids();
    return m_component_id[find(node)];
  }

  /// The components of cluster `c`'s template edges: its *pattern*. An
  /// S-triangle's has the largest `std::size_t` as its fourth entry.
  std::array<std::size_t, 4> cluster_pattern(std::size_t c) const
  {
    return {{component(c, 0), component(c, 1), component(c, 2),
             corner_count(c) == 4 ? component(c, 3) : no_node()}};
  }

  /// The spread of the input edge lengths that the links force together: the
  /// sum, over the unions of S-quad edges that built the components, of the
  /// squared deviations between the two groups joined (a component's sum of
  /// squared deviations from its mean length, minus those of the S-quad edges
  /// it joined). The spread among the mesh edges that one S-quad edge holds
  /// by itself is not counted, so the value depends on how the clustering was
  /// reached: after `merge_clusters()` it includes the spread between the
  /// merged clusters' edges; for a clustering given at once, only that of its
  /// links. Counting the within-edge spread too ranks the candidates worse
  /// (tunnel stand-in, K = 10: 3.1% of the diagonal instead of 1.6%).
  double length_deviation() const { return m_length_deviation; }

  /// `length_deviation()` after `merge_clusters(kept, removed,
  /// correspondence)`, without merging; infinite if the two clusters are not
  /// of the same kind.
  double length_deviation_after_merge(std::size_t kept, std::size_t removed,
                                      Panel_orientation correspondence) const
  {
    const int n = corner_count(kept);
    if(corner_count(removed) != n)
      return std::numeric_limits<double>::infinity();
    // At most 8 components take part, each with its statistics at its slot.
    internal::Small_union_find<8> components;
    std::array<Length_statistics, 8> merged;
    auto slot = [&](std::size_t node) {
      const std::size_t r = find(node);
      const std::pair<std::size_t, bool> s = components.slot(r);
      if(s.second) merged[s.first] = m_lengths[r];
      return components.sets().find(s.first);
    };
    double deviation = m_length_deviation;
    for(int k = 0; k < n; ++k)
    {
      const std::size_t a = slot(4 * m_slot.at(kept) + std::size_t(k)),
                        b = slot(4 * m_slot.at(removed) + std::size_t(correspondence.face_edge(k, n)));
      if(a == b)
        continue;
      deviation += merged[a].deviation_if_joined(merged[b]);
      merged[a].join(merged[b]);
      components.sets().unite(a, b);
      merged[components.sets().find(a)] = merged[a];
    }
    return deviation;
  }

  /// A property map with the component of every mesh edge. It reads this
  /// graph, so it must not outlive it.
  Edge_component_map edge_component_map() const { return Edge_component_map(this); }

  /// Amends the graph after cluster `removed` was merged into cluster `kept`:
  /// template corner `j` of `kept` corresponds to corner `correspondence(j)`
  /// of `removed` (so the faces of `removed` get orientation
  /// `o * correspondence` in `kept`'s labelling; updating the maps is the
  /// caller's job). Returns the new degree of flexibility, which can only
  /// decrease. An S-quad and an S-triangle cannot be merged.
  std::size_t merge_clusters(std::size_t kept, std::size_t removed,
                             Panel_orientation correspondence)
  {
    if(kept == removed || kept >= m_slot.size() || removed >= m_slot.size() ||
       !m_alive[m_slot[kept]] || !m_alive[m_slot[removed]])
      throw Invalid_input("cannot merge cluster " + std::to_string(removed) + " into cluster " +
                          std::to_string(kept), Invalid_input::PARAMETER);
    const int n = m_corners[m_slot[kept]];
    if(m_corners[m_slot[removed]] != n)
      throw Invalid_input("cannot merge cluster " + std::to_string(removed) + " into cluster " +
                          std::to_string(kept) + ": a quad cluster and a triangle cluster",
                          Invalid_input::PARAMETER);
    for(int k = 0; k < n; ++k)
      link(4 * m_slot[kept] + std::size_t(k),
           4 * m_slot[removed] + std::size_t(correspondence.face_edge(k, n)));
    m_alive[m_slot[removed]] = false;
    m_ids_valid = false;
    return m_number_of_components;
  }

  /// Drops the ids of the merged clusters: the clusters alive keep their
  /// order and are numbered 0..K'-1, as `Tilable_surfaces::merge_clusters()`
  /// renumbers the maps. O(K); the components do not change.
  void compact_cluster_ids()
  {
    std::vector<std::size_t> alive;
    for(std::size_t s : m_slot)
      if(m_alive[s])
        alive.push_back(s);
    m_slot.swap(alive);
  }

private:
  // The mesh checked first, then the clustering of the maps.
  template <typename FaceClusterMap, typename FaceOrientationMap, typename NamedParameters>
  static internal::Face_clustering validated_clustering(const PolygonMesh& pm, std::size_t number_of_clusters,
                                                        FaceClusterMap face_cluster_map,
                                                        FaceOrientationMap face_orientation_map,
                                                        const NamedParameters& np)
  {
    validate_panel_mesh(pm, np);
    return internal::read_face_clustering(pm, CGAL::get_initialized_face_index_map(pm, np), face_cluster_map,
                                          face_orientation_map, number_of_clusters);
  }

  static std::size_t no_node() { return (std::numeric_limits<std::size_t>::max)(); }

  // Count, sum and sum of squares of the lengths of a component's mesh edges.
  struct Length_statistics
  {
    double count = 0, sum = 0, sum_of_squares = 0;
    void add(double length) { count += 1; sum += length; sum_of_squares += length * length; }
    // The increase of the squared deviations from the mean if joined with `o`.
    double deviation_if_joined(const Length_statistics& o) const
    {
      if(count == 0 || o.count == 0) return 0.0;
      const double gap = sum / count - o.sum / o.count;
      return count * o.count / (count + o.count) * gap * gap;
    }
    void join(const Length_statistics& o)
    {
      count += o.count; sum += o.sum; sum_of_squares += o.sum_of_squares;
    }
  };

  // Cluster c has nodes 4c .. 4c + corners[c] - 1.
  void reset(const std::vector<int>& corners)
  {
    const std::size_t number_of_clusters = corners.size();
    const std::size_t n = 4 * number_of_clusters;
    m_alive.assign(number_of_clusters, true);
    m_corners = corners;
    m_slot.resize(number_of_clusters);
    m_number_of_components = 0;
    for(std::size_t c = 0; c < number_of_clusters; ++c)
    {
      m_slot[c] = c;
      m_number_of_components += std::size_t(corners[c]);
    }
    m_sets.reset(n);
    m_lengths.assign(n, Length_statistics());
    m_length_deviation = 0;
    m_ids_valid = false;
  }

  void link(std::size_t a, std::size_t b)
  {
    const std::size_t ra = find(a), rb = find(b);
    if(ra == rb)
      return;
    m_length_deviation += m_lengths[ra].deviation_if_joined(m_lengths[rb]);
    Length_statistics joined = m_lengths[ra];
    joined.join(m_lengths[rb]);
    m_sets.unite(ra, rb);
    m_lengths[find(ra)] = joined;
    --m_number_of_components;
    m_ids_valid = false;
  }

  std::size_t find(std::size_t node) const { return m_sets.find(node); }

  void update_component_ids() const
  {
    if(m_ids_valid)
      return;
    m_component_id.assign(4 * m_alive.size(), no_node());
    std::size_t next_id = 0;
    for(std::size_t s : m_slot) // in the order of the ids
    {
      if(!m_alive[s])
        continue;
      for(std::size_t k = 0; k < std::size_t(m_corners[s]); ++k)
      {
        std::size_t& id = m_component_id[find(4 * s + k)];
        if(id == no_node())
          id = next_id++;
      }
    }
    m_ids_valid = true;
  }

  typedef typename CGAL::GetInitializedEdgeIndexMap<PolygonMesh>::const_type Edge_index_map;

  Edge_index_map m_edge_index_map;
  // One S-quad edge node per mesh edge. Never modified after construction,
  // so copies share it: copying the graph costs O(K), not O(#edges).
  std::shared_ptr<const std::vector<std::size_t> > m_edge_node;
  std::vector<bool> m_alive;          // by slot
  std::vector<int> m_corners;         // by slot: 4, or 3 for an S-triangle
  std::vector<std::size_t> m_slot;   // the slot (nodes 4 s .. 4 s + 3) of every cluster id
  internal::Union_find<> m_sets;
  std::size_t m_number_of_components = 0;
  std::vector<Length_statistics> m_lengths; // valid at the roots
  double m_length_deviation = 0;
  mutable std::vector<std::size_t> m_component_id;
  mutable bool m_ids_valid = false;
};

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_EDGE_SHARING_GRAPH_H
