// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_STATE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_STATE_H

// The state that the steps of a K_set_tilable_surface share: the input, read
// and checked once, and the current clustering with what is derived from it
// (the ints the maps read, the edge-sharing graph, the description with the
// candidate pool) and the last optimization result. The class offers the
// steps; this keeps the data consistent between them.

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Search/candidate_solver.h>
#include <CGAL/Tilable_surfaces/internal/Search/multilevel_start.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_parameters.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename PolygonMesh, typename VertexPointMap>
struct Tilable_surface_state
{
  typedef typename CGAL::GetInitializedFaceIndexMap<PolygonMesh>::const_type Original_face_index_map;
  // The steps index the faces in the canonical order (cluster_panels(), "Canonical face order").
  typedef Canonical_face_index_map<Original_face_index_map> Face_index_map;
  typedef typename CGAL::GetInitializedVertexIndexMap<PolygonMesh>::const_type Vertex_index_map;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;
  typedef boost::iterator_property_map<typename std::vector<Point>::const_iterator, Vertex_index_map, Point,
                                       const Point&>
    Input_point_map;
  typedef boost::iterator_property_map<std::vector<int>::iterator, Face_index_map, int, int&> Face_int_map;
  typedef internal::Solution<PolygonMesh, Point> Solution;
  typedef Panel_clusterer<PolygonMesh, Original_face_index_map, Input_point_map> Clusterer;

  // The input.
  PolygonMesh& mesh;  // whose vertices only the optimizing steps move
  VertexPointMap vpm;
  Vertex_index_map vim;
  Canonical_faces<Original_face_index_map> input_faces;  // the input quads, in canonical order
  Face_index_map fim;                                     // input_faces.index_map()
  std::vector<Point> input_points;                        // by vim
  double mean_length = 0;                                 // of the input's edges
  // The clustering parameters of the last cluster() (or set_clustering()).
  bool is_clustered = false;
  Orientation_policy policy = PROPER_RIGID_MOTIONS;
  double similarity_threshold = defaults::similarity_threshold;
  // The current clustering, and a copy of it as ints that the maps handed out read.
  Face_clustering model;
  std::vector<int> cluster_ids;
  std::vector<int> orientation_ids;
  mutable std::optional<Edge_sharing_graph<PolygonMesh> > graph;  // built when asked for
  mutable Clustering_result clustering;  // its description, with the pool of the last cluster()
  mutable bool summary_is_stale = false;
  Optimization_result optimization;  // of the last solve
  std::unique_ptr<Clusterer> clusterer;  // between initialize_clusters() and select_candidate()
  // The exact start of the pool's MULTILEVEL candidate, if it has one.
  std::optional<Multilevel_start<Point> > multilevel_start;

  // Checks `pm` (validate_panel_mesh()) and keeps the points of `point_map`
  // as the input.
  Tilable_surface_state(PolygonMesh& pm, VertexPointMap point_map)
    : mesh(pm), vpm(point_map), vim(CGAL::get_initialized_vertex_index_map(pm)), cluster_ids(num_faces(pm), 0),
      orientation_ids(num_faces(pm), 0)
  {
    model.label.assign(num_faces(pm), 0);
    model.orientation.assign(num_faces(pm), Panel_orientation());
    const auto original_index = CGAL::get_initialized_face_index_map(pm);
    const auto np = parameters::vertex_point_map(vpm).face_index_map(original_index);
    validate_panel_mesh(pm, np);
    input_points.resize(num_vertices(pm));
    for(auto v : vertices(pm))
      input_points[get(vim, v)] = get(vpm, v);
    input_faces = Canonical_faces<Original_face_index_map>(pm, original_index, face_quads(pm, original_index, np));
    fim = input_faces.index_map();
    mean_length = Tilable_surfaces::mean_edge_length(pm, np);
  }

  // fim refers to input_faces: a copy would refer to the original's.
  Tilable_surface_state(const Tilable_surface_state&) = delete;
  Tilable_surface_state& operator=(const Tilable_surface_state&) = delete;

  Input_point_map input_point_map() const { return Input_point_map(input_points.cbegin(), vim); }
  Face_int_map cluster_map() { return Face_int_map(cluster_ids.begin(), fim); }
  Face_int_map orientation_map() { return Face_int_map(orientation_ids.begin(), fim); }

  // The maps and parameters every step passes on, so that edits, solves and
  // measurements match instances to S-quads as the clustering did.
  Surface_parameters<Face_index_map, Vertex_index_map> step_parameters() const
  {
    return {fim, vim, policy, similarity_threshold};
  }

  // The solves on copies of the fidelity search and of refine_to().
  Candidate_solver<Tilable_surface_state> candidate_solver() const
  {
    return Candidate_solver<Tilable_surface_state>(*this);
  }

  void require_clustering() const
  {
    if(!is_clustered)
      throw Invalid_input("no clustering yet: call cluster() or set_clustering() first", Invalid_input::PARAMETER);
  }

  void write_points(const std::vector<Point>& points)
  {
    for(auto v : vertices(mesh))
      put(vpm, v, points[get(vim, v)]);
  }

  const Edge_sharing_graph<PolygonMesh>& edge_sharing_graph() const
  {
    if(!graph)
      graph.emplace(Validated_mesh(true), mesh, fim, input_point_map(), model);
    return *graph;
  }

  // Makes `fc` the current clustering; the graph is rebuilt when needed.
  void set_model(Face_clustering fc)
  {
    model = std::move(fc);
    graph.reset();
    publish_model();
  }

  // Writes the model into the storage of the maps handed out (in place: they
  // stay valid) and marks the description of the clustering stale.
  void publish_model()
  {
    model.write_ids(cluster_ids, orientation_ids);
    summary_is_stale = true;
  }

  // What cluster() and initialize_clusters() start with: the parameters
  // checked and kept, the clusterer made, the description emptied. When
  // `sweep_ends_search`, the clusterer is told that an exact sweep
  // clustering ends the fidelity search (exact_sweep_ends_search()), as the
  // multilevel start `multilevel_hook` does (multilevel_start_hook(), exact
  // by construction) when it applies.
  template <typename NamedParameters>
  void start_clustering(const NamedParameters& np, bool sweep_ends_search, Multilevel_start_hook multilevel_hook)
  {
    const std::size_t k = tile_count(np, num_faces(mesh));
    write_points(input_points);
    policy = orientation_policy(np);
    similarity_threshold = parameter_or(np, internal_np::similarity_threshold, defaults::similarity_threshold);
    Clustering_settings settings = clustering_settings(np);
    if(sweep_ends_search)
      settings.sweep_ends_search = [pm = &mesh, face_index = fim, vertex_index = vim, input = input_point_map(),
                                    points = read_points(mesh, input_point_map(), vim)](
                                     const std::vector<std::size_t>& label) {
        return sweep_start(*pm, face_index, vertex_index, input, points, label).rows() > 0;
      };
    settings.multilevel_start = std::move(multilevel_hook);
    multilevel_start.reset();
    clusterer.reset(new Clusterer(mesh, input_faces, input_point_map(), mean_length, k, settings));
    clustering = Clustering_result();
    summary_is_stale = false;
  }

  // The clusterer, between initialize_clusters() and select_candidate().
  Clusterer& clusterer_under_way()
  {
    if(!clusterer)
      throw Invalid_input("no clustering under way: call initialize_clusters() first", Invalid_input::PARAMETER);
    return *clusterer;
  }

  // The chosen candidate, with the orientations of `shapes`, becomes the
  // current clustering; the clusterer's n x n dissimilarities are freed.
  void adopt_selected_candidate(const Cluster_shapes& shapes)
  {
    clusterer.reset();
    set_model(Face_clustering{candidate_solver().candidate_labels(clustering.chosen_candidate), shapes.orientation,
                              clustering.cluster_sizes.size()});
    summary_is_stale = false;
    is_clustered = true;
  }

  // `fc` in canonical order becomes the current clustering, under `p`.
  void set_clustering(Face_clustering fc, Orientation_policy p)
  {
    clustering = Clustering_result();
    clustering.weights_are_exact = false;
    policy = p;
    is_clustered = true;
    set_model(std::move(fc));
  }

  // The edits on the model, judged on the input quads (cluster_editing.h),
  // then published; a merge amends the graph (built first), the others drop
  // it: a union-find cannot undo a union.
  void merge_clusters(std::size_t a, std::size_t b)
  {
    const Panel_orientation correspondence = internal::merge_clusters(model, input_faces.quads, a, b, policy);
    graph->merge_clusters((std::min)(a, b), (std::max)(a, b), correspondence);
    graph->compact_cluster_ids();
    publish_model();
  }
  void split_cluster(std::size_t c, unsigned int random_seed)
  {
    CGAL::Random random(random_seed);
    internal::split_cluster(model, input_faces.quads, c, policy, random);
    graph.reset();
    publish_model();
  }
  void retag_orientations()
  {
    internal::retag_orientations(model, mesh, fim, input_faces.quads, policy, similarity_threshold * mean_length);
    graph.reset();
    publish_model();
  }

  // The description of the current clustering in `clustering`.
  void describe() const
  {
    require_clustering();
    const Cluster_shapes shapes = cluster_shapes(input_faces.quads, model.label, model.number_of_clusters, policy);
    describe_clustering(model.label, model.number_of_clusters, shapes, edge_sharing_graph().degree_of_flexibility(),
                        clustering.weights_are_exact, [&](std::size_t p, std::size_t q) {
                          return fast_best_match(input_faces.quads[p], input_faces.quads[q], policy).dissimilarity;
                        }, clustering);
    summary_is_stale = false;
  }

  // The current result, to be restored by set_solution().
  Solution solution() const
  {
    Solution s;
    s.points.resize(num_vertices(mesh));
    for(auto v : vertices(mesh))
      s.points[get(vim, v)] = get(vpm, v);
    s.clustering = model;
    s.graph = graph;
    s.optimization = optimization;
    return s;
  }

  void set_solution(const Solution& s)
  {
    write_points(s.points);
    model = s.clustering;
    graph = s.graph;
    publish_model();
    optimization = s.optimization;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_STATE_H
