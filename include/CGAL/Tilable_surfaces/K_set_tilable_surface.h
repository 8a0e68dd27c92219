// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H
#define CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H

/// \file K_set_tilable_surface.h
/// The step-by-step interface: cluster, inspect and edit the clusters,
/// optimize, measure, export. `make_k_set_tilable()` runs it in one call.

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Search/fidelity_search.h>
#include <CGAL/Tilable_surfaces/internal/Search/refinement.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_state.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// A quad mesh on its way to a K-set tilable surface, one step at a time, as
/// `Variational_shape_approximation` does for VSA (user manual, section "Step
/// by step"); `make_k_set_tilable()` is a thin wrapper over it.
/// `cluster()` groups the faces into K S-quads (or its four stages,
/// `initialize_clusters()` to `select_candidate()`), `merge_clusters()`,
/// `split_cluster()` and `retag_orientations()` edit the clustering (paper
/// §5) and report the new degree of flexibility, `optimize()` moves the
/// vertices of the mesh so that every face is congruent to its S-quad, and
/// `measure()` / `tile_catalog()` report on the result.
///
/// The object is the state the steps share: the input positions (against
/// which every result is measured) and the quads they form, the clustering
/// parameters of the last `cluster()` (orientation policy, similarity
/// threshold), the cluster and orientation of every face (readable through
/// `face_cluster_map()` and `face_orientation_map()`, which stay valid for
/// the object's lifetime), the edge-sharing graph of the clustering, and the
/// candidate pool. The mesh is checked once, by the constructor; the steps
/// reuse that state instead of checking and re-reading the mesh, and an edit
/// updates the graph (incrementally for a merge) instead of rebuilding
/// everything. It refers to the mesh passed to the constructor, whose vertices
/// only the optimizing steps move; the connectivity must not change while the
/// object is used.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or
///   `CGAL::Parallel_if_available_tag`: whether the steps may use several
///   threads (TBB); the results are the same. First, as in
///   Polygon_mesh_processing; class template argument deduction makes it
///   `CGAL::Sequential_tag` when no argument is given:
///   `K_set_tilable_surface surface(mesh);`, or
///   `K_set_tilable_surface<CGAL::Parallel_if_available_tag, Mesh> surface(mesh);`.
/// \tparam PolygonMesh a model of `FaceListGraph` and `MutableFaceGraph`
///   with quad faces.
/// \tparam VertexPointMap a model of `ReadWritePropertyMap` from vertices to
///   points, by default the mesh's internal one.
template <typename ConcurrencyTag, typename PolygonMesh,
          typename VertexPointMap = typename CGAL::GetVertexPointMap<PolygonMesh>::type>
class K_set_tilable_surface
{
  typedef internal::Tilable_surface_state<PolygonMesh, VertexPointMap> State;  // the input and the clustering
  typedef typename State::Face_index_map Face_index_map;
  typedef typename State::Vertex_index_map Vertex_index_map;
  typedef typename State::Point Point;

public:
  /// \name Types
  /// @{

  /// The faces of the mesh.
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  /// Readable map from vertices to their input positions.
  typedef boost::iterator_property_map<typename std::vector<Point>::const_iterator, Vertex_index_map, Point,
                                       const Point&>
    Input_point_map;
  /// Readable and writable map from faces to their cluster id (0..K-1).
  typedef boost::iterator_property_map<std::vector<int>::iterator, Face_index_map, int, int&>
    Face_cluster_map;
  /// Readable and writable map from faces to their orientation (0..7,
  /// user manual, section Definitions) relative to their cluster's S-quad.
  typedef Face_cluster_map Face_orientation_map;
  /// @}

  /// \name Construction
  /// @{

  /// Checks `pm` (`validate_panel_mesh()`) and keeps the points of `vpm` as
  /// the input.
  /// \throws Invalid_input if `pm` is not a valid quad mesh.
  K_set_tilable_surface(PolygonMesh& pm, VertexPointMap vpm)
    : m_state(pm, vpm)
  {}

  /// The same, with the mesh's internal vertex point map.
  explicit K_set_tilable_surface(PolygonMesh& pm)
    : K_set_tilable_surface(pm, get(CGAL::vertex_point, pm))
  {}
  /// @}

  /// \name Clustering
  /// The four stages of `cluster()` may also be run one by one.
  /// @{

  /// Clusters the faces into `number_of_tiles` S-quads as `cluster_panels()`
  /// does (whose named parameters `np` takes, except the two maps: the
  /// object's own are used), from the input quads: the four stages below in
  /// turn, each reported to the visitor's `phase()`. The previous clustering
  /// and optimization are forgotten.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Clustering_result& cluster(const CGAL_NP_CLASS& np)
  {
    start_clustering(np);
    auto&& visitor = internal::visitor_of(np);
    m_state.adopt_selected_candidate(
      with_concurrency([&] { return m_state.clusterer->run(m_state.clustering, visitor); }));
    return m_state.clustering;
  }

  /// Stage 1 of `cluster()`: reads its parameters and chooses the path
  /// (`Clustering_result::path`), then clusters the faces by a similarity
  /// threshold, split up to K clusters if it gives fewer (paper §4.1).
  /// Returns the number N of these initial clusters. The clustering in the
  /// maps stays the previous one until `select_candidate()`;
  /// `clustering()` shows the pool being built.
  /// \throws Invalid_input if K is out of 1..number of faces.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  std::size_t initialize_clusters(const CGAL_NP_CLASS& np)
  {
    start_clustering(np);
    with_concurrency([&] { m_state.clusterer->initialize(m_state.clustering); });
    return m_state.clustering.number_of_initial_clusters;
  }

  /// Stage 2: merges the initial clusters down to K by a beam search on the
  /// score of paper §4.2, adding the beam to the candidate pool
  /// (`Clustering_result::candidates`). Returns the size of the pool.
  std::size_t merge_to_tile_count()
  {
    with_concurrency([&] { m_state.clusterer_under_way().merge_to_tile_count(m_state.clustering); });
    return m_state.clustering.candidates.size();
  }

  /// Stage 3: adds the k-means, quad-strip and grid-segment candidates that
  /// the parameters of `initialize_clusters()` ask for, and the sweep
  /// clusterings (user manual, section TS_Sweeps). Above `large_mesh_faces`,
  /// when those parameters leave `number_of_optimized_candidates` at 0 (its
  /// default there) and a sweep clustering has an exact start, only the
  /// sweeps are added: `optimize_closest()` with the same parameters ends
  /// its search at that sweep and would never optimize the others. Returns
  /// the size of the pool.
  std::size_t add_other_candidates()
  {
    with_concurrency([&] { m_state.clusterer_under_way().add_other_candidates(m_state.clustering); });
    return m_state.clustering.candidates.size();
  }

  /// Stage 4: makes the candidate of lowest score the current clustering,
  /// with each cluster's S-quad and every face tagged with an orientation
  /// chosen for flexibility (`Clustering_result::chosen_candidate`).
  const Clustering_result& select_candidate()
  {
    m_state.adopt_selected_candidate(
      with_concurrency([&] { return m_state.clusterer_under_way().select(m_state.clustering); }));
    return m_state.clustering;
  }
  /// @}

  /// \name The current clustering
  /// @{

  /// The orientation policy under which the instances of the current
  /// clustering match their S-quads (`cluster()`'s or `set_clustering()`'s).
  Orientation_policy orientation_policy() const { return m_state.policy; }

  /// Whether a clustering exists (`cluster()` or `set_clustering()`).
  bool is_clustered() const { return m_state.is_clustered; }

  /// The number of clusters K.
  std::size_t number_of_clusters() const { return m_state.model.number_of_clusters; }

  /// The current clustering: after `cluster()`, its result; after an edit,
  /// `use_candidate()`, `set_clustering()` or the fidelity search of
  /// `optimize_closest()`, the same description of the clustering now in the
  /// maps (S-quads and sizes, DOF, weights: exact if `cluster()` took the
  /// exact path, else estimated), with the candidate pool of the last
  /// `cluster()` (none after `set_clustering()` or `refine_to()`).
  const Clustering_result& clustering() const
  {
    if(m_state.summary_is_stale)
      m_state.describe();
    return m_state.clustering;
  }

  /// The cluster of every face.
  Face_cluster_map face_cluster_map() { return m_state.cluster_map(); }

  /// The S-quad orientation of every face.
  Face_orientation_map face_orientation_map() { return m_state.orientation_map(); }

  /// The edge-sharing graph of the current clustering, with the input's edge
  /// lengths. The object keeps it: a merge amends it, other edits rebuild it
  /// when it is next asked for.
  const Edge_sharing_graph<PolygonMesh>& edge_sharing_graph() const
  {
    m_state.require_clustering();
    return m_state.edge_sharing_graph();
  }

  /// The degree of flexibility of the current clustering.
  std::size_t degree_of_flexibility() const { return edge_sharing_graph().degree_of_flexibility(); }
  /// @}

  /// \name Editing
  /// Each edit is judged on the input quads.
  /// @{

  /// Uses the clustering of the maps `face_cluster_map` (ids 0..K-1, all
  /// used) and `face_orientation_map` (0..7) instead of computing one; its
  /// instances match their S-quads under `policy`, which the edits, solves
  /// and measurements then use as `cluster()`'s own.
  /// \throws Invalid_input if an id or an orientation is out of range or a
  /// cluster id in 0..K-1 is unused.
  template <typename FaceClusterMap, typename FaceOrientationMap>
  void set_clustering(FaceClusterMap face_cluster_map, FaceOrientationMap face_orientation_map,
                      Orientation_policy policy = PROPER_RIGID_MOTIONS)
  {
    internal::Face_clustering clustering = internal::in_canonical_order(
      internal::read_face_clustering(m_state.mesh, m_state.input_faces.original_index, face_cluster_map,
                                     face_orientation_map, internal::unknown_number_of_clusters,
                                     internal::CONTIGUOUS_IDS),
      m_state.input_faces.rank);
    m_state.set_clustering(std::move(clustering), policy);
  }

  /// Makes candidate `i` of the pool of the last `cluster()`
  /// (`clustering().candidates`) the current clustering, with S-quads and
  /// flexible orientations computed as `cluster_panels()` does for the one it
  /// returns, from the input quads. Returns its degree of flexibility.
  std::size_t use_candidate(std::size_t i)
  {
    if(i >= m_state.clustering.candidates.size())
      throw Invalid_input("no clustering candidate " + std::to_string(i), Invalid_input::PARAMETER);
    std::size_t degree_of_flexibility = 0;
    m_state.set_model(
      with_concurrency([&] { return m_state.candidate_solver().candidate_model(i, degree_of_flexibility); }));
    return degree_of_flexibility;
  }

  /// Merges clusters `a` and `b` as `Tilable_surfaces::merge_clusters()`
  /// does, judged on the input quads, and amends the edge-sharing graph
  /// (O(K) unions, no rebuild); returns the new degree of flexibility.
  /// \throws Invalid_input if `a == b` or a cluster does not exist; nothing
  /// changes then.
  std::size_t merge_clusters(std::size_t a, std::size_t b)
  {
    m_state.require_clustering();
    edge_sharing_graph(); // built if it was not: it is amended below
    with_concurrency([&] { m_state.merge_clusters(a, b); });
    return m_state.graph->degree_of_flexibility();
  }

  /// Splits cluster `c` in two as `Tilable_surfaces::split_cluster()` does,
  /// judged on the input quads; returns the new degree of flexibility.
  /// \throws Invalid_input if `c` does not exist or has a single face;
  /// nothing changes then.
  std::size_t split_cluster(std::size_t c, unsigned int random_seed = defaults::random_seed)
  {
    m_state.require_clustering();
    with_concurrency([&] { m_state.split_cluster(c, random_seed); });
    return degree_of_flexibility();
  }

  /// Re-tags every face with the orientation that best matches its cluster's
  /// S-quad, as `Tilable_surfaces::retag_orientations()` does with the
  /// clustering's similarity threshold, judged on the input quads; returns
  /// the new degree of flexibility.
  std::size_t retag_orientations()
  {
    m_state.require_clustering();
    with_concurrency([&] { m_state.retag_orientations(); });
    return degree_of_flexibility();
  }
  /// @}

  /// \name Optimization
  /// @{

  /// The displacement the default solver is predicted to need for the
  /// current clustering (`predict_displacement()`), from the input
  /// positions; takes the parameters of `optimize()`.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  Displacement_prediction predict_displacement(const CGAL_NP_CLASS& np = parameters::default_values())
  {
    m_state.require_clustering();
    restore_input();
    return with_concurrency([&] {
      return internal::predict_displacement(internal::Validated_mesh(true), m_state.mesh, with_own_maps(np));
    });
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
    m_state.require_clustering();
    restore_input();
    m_state.optimization = with_concurrency([&] {
      return internal::optimize_tilable_surface(internal::Validated_mesh(true), m_state.mesh, with_own_maps(np));
    });
    return m_state.optimization;
  }

  /// The result of the last `optimize()` call.
  const Optimization_result& optimization() const { return m_state.optimization; }

  /// Looks for the tilable result closest to the input among several
  /// clusterings, then improves it; the default of `make_k_set_tilable()`
  /// (user manual, section "Fidelity"). The sweep clusterings of the pool
  /// (`Clustering_candidate::GRID_SWEEPS`) are solved first, from the swept
  /// surface at which they are exact; the other candidates of the last
  /// `cluster()` most likely to end closest (by `predict_displacement()`
  /// and by `Clustering_candidate::length_deviation`), the
  /// `number_of_optimized_candidates` first (default
  /// `default_number_of_optimized_candidates()`), are optimized from the
  /// input; then `number_of_improvement_rounds` rounds of split-and-merge
  /// edits, K fixed, and repair rounds while the best is not tilable. When
  /// `number_of_optimized_candidates` is 0 (its default above
  /// `large_mesh_faces`) and a sweep is exact, the search ends there.
  ///
  /// A result replaces the best one only if it is better: tilable
  /// (`congruence_tolerance`) before not, then the smaller symmetric
  /// Hausdorff distance (or, among non-tilable ones, the smaller congruence
  /// error). So the rounds never return a worse result than the candidates.
  /// The mesh, the maps and `optimization()` hold the best result at the
  /// end. Takes the parameters of `optimize()`; the visitor's
  /// `phase(name, seconds)` is called after each candidate and round.
  /// Once the visitor stops a solve (`Optimization_result::stopped_by_visitor`),
  /// no further candidate or round is optimized.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Optimization_result& optimize_closest(const CGAL_NP_CLASS& user_np = parameters::default_values())
  {
    m_state.require_clustering();
    if(m_state.clustering.candidates.empty())
      return optimize(user_np);
    return internal::optimize_closest<ConcurrencyTag>(*this, m_state, internal::canonical_inputs(user_np));
  }

  /// Refines the current result to `k` clusters: splits the cluster with
  /// the most faces (the first such) as `split_cluster()` does until there
  /// are `k`, then optimizes it two ways and keeps the better (tilable before
  /// not, then not crossing itself, then closer to the input): every face
  /// keeping the orientation it has now, from the current positions when
  /// they are exact (`congruence_tolerance`; default solver, without
  /// `planar_tiles`) and keeping them when the solve does not end better;
  /// and with the orientations the splits chose on the input quads, from
  /// the input as `optimize()` does. `np` takes the named parameters of
  /// `optimize()`. Both parts of a split cluster are instances of its
  /// S-quad, so an exact result stays exact: the refined result is at least
  /// as good as the one refined, and as the split clustering optimized from
  /// the input, with `k` S-quads. `k_set_tilable_curve()` and the deviation
  /// search of `make_k_set_tilable()` use it so that more molds do not end
  /// farther than fewer.
  /// \throws Invalid_input if there is no clustering yet, or `k` is less
  /// than the number of clusters or more than the number of faces; nothing
  /// changes then.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Optimization_result& refine_to(std::size_t k, const CGAL_NP_CLASS& np = parameters::default_values())
  {
    m_state.require_clustering();
    if(k < number_of_clusters() || k > num_faces(m_state.mesh))
      throw Invalid_input("cannot refine " + std::to_string(number_of_clusters()) + " clusters to K = " +
                            std::to_string(k) + " (the mesh has " + std::to_string(num_faces(m_state.mesh)) +
                            " faces)",
                          Invalid_input::PARAMETER);
    const std::size_t refined_k = number_of_clusters();
    bool retagged_wins = false;
    m_state.set_solution(internal::refined_solution<ConcurrencyTag>(
      m_state.candidate_solver(), m_state.model, k, internal::canonical_inputs(np), retagged_wins));
    m_state.clustering = Clustering_result();
    m_state.clustering.weights_are_exact = false;
    m_state.clustering.choice_reason = internal::refinement_reason(refined_k, k, retagged_wins);
    return m_state.optimization;
  }
  /// @}

  /// \name Input and measurement
  /// @{

  /// The positions of the input, as they were when the object was made: a
  /// readable property map from the vertices of the mesh to points.
  Input_point_map input_point_map() const { return m_state.input_point_map(); }

  /// Puts the input positions back in the mesh. Clustering, edits and solves
  /// call it first: they start from the input, never from a result.
  void restore_input() { m_state.write_points(m_state.input_points); }

  /// Measures the current mesh against the input (`measure_tilability()`):
  /// the same connectivity with the input positions.
  Tilability_measure measure()
  {
    m_state.require_clustering();
    return with_concurrency([&] {
      return internal::measure_tilability(
        internal::Validated_mesh(true), m_state.mesh, m_state.mesh,
        m_state.step_parameters().own_maps(m_state.vpm, face_cluster_map(), face_orientation_map()),
        parameters::vertex_point_map(input_point_map()).vertex_index_map(m_state.vim));
    });
  }

  /// The tile catalog of the current mesh: one tile per S-quad, with the
  /// measured worst deviation of its instances, in the mesh's units.
  std::vector<Tile> tile_catalog()
  {
    return Tilable_surfaces::tile_catalog(measure());
  }
  /// @}

private:
  // cluster()'s and initialize_clusters()' start: the parameters read, the clusterer made.
  template <typename NamedParameters>
  void start_clustering(const NamedParameters& np)
  {
    static_assert(!parameters::is_default_parameter<NamedParameters, internal_np::number_of_tiles_t>::value,
                  "the named parameter number_of_tiles is required");
    const auto cnp = internal::canonical_inputs(np);
    m_state.start_clustering(cnp, internal::exact_sweep_ends_search(cnp, num_faces(m_state.mesh)),
                             internal::multilevel_start_hook<ConcurrencyTag>(m_state, cnp));
  }

  // Runs f with the parallelism of ConcurrencyTag (the steps that compute).
  template <typename F>
  static auto with_concurrency(const F& f) { return internal::with_concurrency<ConcurrencyTag>(f); }

  // The user's parameters with the object's maps in front (found first); the
  // user's orientation policy, if given, else the clustering's.
  template <typename NP>
  auto with_own_maps(const NP& np)
  {
    return m_state.step_parameters().with_maps(internal::canonical_inputs(np), m_state.vpm, face_cluster_map(),
                                               face_orientation_map());
  }

  State m_state;  // the input, the clustering, the pool, the graph, the last optimization
};

/// \cond SKIP_IN_MANUAL
// Without template arguments: one thread, the mesh's type and point map.
template <typename PolygonMesh>
K_set_tilable_surface(PolygonMesh&) -> K_set_tilable_surface<CGAL::Sequential_tag, PolygonMesh>;
template <typename PolygonMesh, typename VertexPointMap>
K_set_tilable_surface(PolygonMesh&, VertexPointMap)
  -> K_set_tilable_surface<CGAL::Sequential_tag, PolygonMesh, VertexPointMap>;
/// \endcond

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H
