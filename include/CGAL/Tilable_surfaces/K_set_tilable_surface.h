// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H
#define CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H

/// \file K_set_tilable_surface.h
/// The step-by-step interface: cluster, inspect and edit the clusters,
/// optimize, measure, export. `make_k_set_tilable()` runs it in one call.

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_quads.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <memory>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// A quad mesh on its way to a K-set tilable surface, one step at a time, as
/// `Variational_shape_approximation` does for VSA:
/// `cluster()` groups the faces into K S-quads, `merge_clusters()`,
/// `split_cluster()` and `retag_orientations()` edit the clustering (paper
/// §5) and report the new degree of flexibility, `optimize()` moves the
/// vertices of the mesh so that every face is congruent to its S-quad, and
/// `measure()` / `tile_catalog()` report on the result.
///
/// The object keeps the cluster and orientation of every face (readable
/// through `face_cluster_map()` and `face_orientation_map()`) and a copy of
/// the input, against which the result is measured. It refers to the mesh
/// passed to the constructor, whose vertices only `optimize()` moves; the
/// connectivity must not change while the object is used.
///
/// \tparam PolygonMesh a model of `FaceListGraph` and `MutableFaceGraph`
///   with quad faces, copy constructible.
/// \tparam VertexPointMap a model of `ReadWritePropertyMap` from vertices to
///   points, by default the mesh's internal one.
template <typename PolygonMesh,
          typename VertexPointMap = typename CGAL::GetVertexPointMap<PolygonMesh>::type>
class K_set_tilable_surface
{
  typedef typename CGAL::GetInitializedFaceIndexMap<PolygonMesh>::const_type Face_index_map;
  typedef typename CGAL::GetInitializedVertexIndexMap<PolygonMesh>::const_type Vertex_index_map;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

public:
  /// The faces of the mesh.
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  /// Readable and writable map from faces to their cluster id (0..K-1).
  typedef boost::iterator_property_map<std::vector<int>::iterator, Face_index_map, int, int&>
    Face_cluster_map;
  /// Readable and writable map from faces to their orientation (0..7,
  /// method notes §1) relative to their cluster's S-quad.
  typedef Face_cluster_map Face_orientation_map;

  /// Checks `pm` (`validate_quad_mesh()`) and keeps a copy of it, with the
  /// points of `vpm`, as the input.
  /// \throws Invalid_input if `pm` is not a valid quad mesh.
  K_set_tilable_surface(PolygonMesh& pm, VertexPointMap vpm)
    : m_mesh(pm)
    , m_vpm(vpm)
    , m_fim(CGAL::get_initialized_face_index_map(pm))
    , m_cluster(num_faces(pm), 0)
    , m_orientation(num_faces(pm), 0)
  {
    validate_quad_mesh(pm, parameters::vertex_point_map(m_vpm));
    m_input.reset(new PolygonMesh(pm));
    m_input_vim = CGAL::get_initialized_vertex_index_map(*m_input);
    const Vertex_index_map vim = CGAL::get_initialized_vertex_index_map(pm);
    m_input_points.resize(num_vertices(pm));
    for(auto v : vertices(pm))
      m_input_points[get(vim, v)] = get(m_vpm, v);
  }

  /// The same, with the mesh's internal vertex point map.
  explicit K_set_tilable_surface(PolygonMesh& pm)
    : K_set_tilable_surface(pm, get(CGAL::vertex_point, pm))
  {}

  /// Clusters the faces into `number_of_tiles` S-quads (`cluster_quads()`,
  /// whose named parameters `np` takes, except the two maps: the object's
  /// own are used). The previous clustering and optimization are forgotten.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Clustering_result& cluster(const CGAL_NP_CLASS& np)
  {
    m_clustering = cluster_quads(m_mesh, with_own_maps(np));
    m_number_of_clusters = m_clustering.cluster_sizes.size();
    m_is_clustered = true;
    return m_clustering;
  }

  /// Uses the clustering of the maps `face_cluster_map` (ids 0..K-1, all
  /// used) and `face_orientation_map` (0..7) instead of computing one.
  /// \throws Invalid_input if an id or an orientation is out of range or a
  /// cluster id in 0..K-1 is unused.
  template <typename FaceClusterMap, typename FaceOrientationMap>
  void set_clustering(FaceClusterMap face_cluster_map, FaceOrientationMap face_orientation_map)
  {
    std::vector<int> cluster(m_cluster.size()), orientation(m_orientation.size());
    std::size_t k = 0;
    for(face_descriptor f : faces(m_mesh))
    {
      cluster[get(m_fim, f)] = int(get(face_cluster_map, f));
      orientation[get(m_fim, f)] = int(get(face_orientation_map, f));
      k = (std::max)(k, std::size_t((std::max)(0, cluster[get(m_fim, f)])) + 1);
    }
    std::vector<bool> used(k, false);
    for(std::size_t f = 0; f < cluster.size(); ++f)
    {
      internal::check_face_label(f, cluster[f], orientation[f], k);
      used[std::size_t(cluster[f])] = true;
    }
    for(std::size_t c = 0; c < k; ++c)
      if(!used[c])
        throw Invalid_input("cluster " + std::to_string(c) + " has no face; ids must be 0..K-1",
                            Invalid_input::PARAMETER);
    m_cluster.swap(cluster);
    m_orientation.swap(orientation);
    m_number_of_clusters = k;
    m_clustering = Clustering_result();
    m_is_clustered = true;
  }

  /// Whether a clustering exists (`cluster()` or `set_clustering()`).
  bool is_clustered() const { return m_is_clustered; }

  /// The number of clusters K.
  std::size_t number_of_clusters() const { return m_number_of_clusters; }

  /// The result of the last `cluster()` call (empty after `set_clustering()`).
  const Clustering_result& clustering() const { return m_clustering; }

  /// The cluster of every face.
  Face_cluster_map face_cluster_map() { return Face_cluster_map(m_cluster.begin(), m_fim); }

  /// The S-quad orientation of every face.
  Face_orientation_map face_orientation_map() { return Face_orientation_map(m_orientation.begin(), m_fim); }

  /// The edge-sharing graph of the current clustering.
  Edge_sharing_graph<PolygonMesh> edge_sharing_graph()
  {
    require_clustering();
    return Edge_sharing_graph<PolygonMesh>(m_mesh, m_number_of_clusters, face_cluster_map(),
                                           face_orientation_map(),
                                           parameters::vertex_point_map(m_vpm).face_index_map(m_fim));
  }

  /// The degree of flexibility of the current clustering.
  std::size_t degree_of_flexibility() { return edge_sharing_graph().degree_of_flexibility(); }

  /// Merges clusters `a` and `b` (see `Tilable_surfaces::merge_clusters()`);
  /// returns the new degree of flexibility.
  std::size_t merge_clusters(std::size_t a, std::size_t b)
  {
    require_clustering();
    const std::size_t dof = Tilable_surfaces::merge_clusters(m_mesh, a, b, own_maps());
    --m_number_of_clusters;
    return dof;
  }

  /// Splits cluster `c` in two (see `Tilable_surfaces::split_cluster()`);
  /// returns the new degree of flexibility.
  std::size_t split_cluster(std::size_t c, unsigned int random_seed = 0)
  {
    require_clustering();
    const std::size_t dof =
      Tilable_surfaces::split_cluster(m_mesh, c, own_maps().random_seed(random_seed));
    ++m_number_of_clusters;
    return dof;
  }

  /// Re-tags every face with the orientation that best matches its cluster's
  /// S-quad (see `Tilable_surfaces::retag_orientations()`); returns the new
  /// degree of flexibility.
  std::size_t retag_orientations()
  {
    require_clustering();
    return Tilable_surfaces::retag_orientations(m_mesh, own_maps());
  }

  /// Moves the vertices of the mesh so that every face becomes congruent to
  /// its cluster's S-quad (`optimize_tilable_surface()`, whose named
  /// parameters `np` takes, except the two maps). The optimization starts
  /// from the current positions and is measured against them; `measure()`
  /// measures against the input.
  /// \throws Invalid_input if there is no clustering yet or a parameter is invalid.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Optimization_result& optimize(const CGAL_NP_CLASS& np = parameters::default_values())
  {
    require_clustering();
    m_optimization = optimize_tilable_surface(m_mesh, with_own_maps(np));
    return m_optimization;
  }

  /// The result of the last `optimize()` call.
  const Optimization_result& optimization() const { return m_optimization; }

  /// Measures the current mesh against the input (`measure_tilability()`).
  Tilability_measure measure()
  {
    require_clustering();
    return measure_tilability(m_mesh, *m_input, own_maps(),
                              parameters::vertex_point_map(boost::make_iterator_property_map(
                                m_input_points.begin(), m_input_vim)));
  }

  /// The input mesh, as it was when the object was made.
  const PolygonMesh& input_mesh() const { return *m_input; }

  /// The tile catalog of the current mesh: one tile per S-quad, with the
  /// measured worst deviation of its instances, in the mesh's units.
  std::vector<IO::Tile> tile_catalog()
  {
    return tile_catalog(measure());
  }

  /// The tile catalog of a measurement made with this object.
  static std::vector<IO::Tile> tile_catalog(const Tilability_measure& m)
  {
    std::vector<IO::Tile> tiles(m.s_quads.size());
    for(std::size_t c = 0; c < tiles.size(); ++c)
    {
      tiles[c].id = c;
      tiles[c].instance_count = m.cluster_sizes[c];
      tiles[c].corners = m.s_quads[c];
      tiles[c].worst_deviation = m.cluster_congruence_errors[c] * m.mean_edge_length;
    }
    return tiles;
  }

private:
  // The parameters every step shares: the object's maps and indices.
  auto own_maps()
  {
    return parameters::vertex_point_map(m_vpm)
      .face_index_map(m_fim)
      .face_cluster_map(face_cluster_map())
      .face_orientation_map(face_orientation_map());
  }

  // The user's parameters with the object's maps in front (found first).
  template <typename NP>
  auto with_own_maps(const NP& np)
  {
    return parameters::extend(np)
      .vertex_point_map(m_vpm)
      .face_index_map(m_fim)
      .face_cluster_map(face_cluster_map())
      .face_orientation_map(face_orientation_map());
  }

  void require_clustering() const
  {
    if(!m_is_clustered)
      throw Invalid_input("no clustering yet: call cluster() or set_clustering() first",
                          Invalid_input::PARAMETER);
  }

  PolygonMesh& m_mesh;
  VertexPointMap m_vpm;
  Face_index_map m_fim;
  std::unique_ptr<const PolygonMesh> m_input;  // connectivity of the input
  Vertex_index_map m_input_vim;
  std::vector<Point> m_input_points;           // positions of the input
  std::vector<int> m_cluster;
  std::vector<int> m_orientation;
  std::size_t m_number_of_clusters = 0;
  bool m_is_clustered = false;
  Clustering_result m_clustering;
  Optimization_result m_optimization;
};

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H
