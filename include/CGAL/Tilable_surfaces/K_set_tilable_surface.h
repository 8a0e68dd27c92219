// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H
#define CGAL_TILABLE_SURFACES_K_SET_TILABLE_SURFACE_H

/// \file K_set_tilable_surface.h
/// The step-by-step interface: cluster, inspect and edit the clusters,
/// optimize, measure, export. `make_k_set_tilable()` runs it in one call.

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_quads.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
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
  typedef typename CGAL::GetInitializedFaceIndexMap<PolygonMesh>::const_type Original_face_index_map;
  // The steps index the faces in the canonical order (cluster_quads(), "Canonical face order").
  typedef internal::Canonical_face_index_map<Original_face_index_map> Face_index_map;
  typedef typename CGAL::GetInitializedVertexIndexMap<PolygonMesh>::const_type Vertex_index_map;
  typedef typename boost::property_traits<VertexPointMap>::value_type Point;

public:
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

  /// Checks `pm` (`validate_quad_mesh()`) and keeps the points of `vpm` as
  /// the input.
  /// \throws Invalid_input if `pm` is not a valid quad mesh.
  K_set_tilable_surface(PolygonMesh& pm, VertexPointMap vpm)
    : m_mesh(pm)
    , m_vpm(vpm)
    , m_vim(CGAL::get_initialized_vertex_index_map(pm))
    , m_cluster(num_faces(pm), 0)
    , m_orientation(num_faces(pm), 0)
  {
    m_clustering_model.label.assign(num_faces(pm), 0);
    m_clustering_model.orientation.assign(num_faces(pm), Quad_orientation());
    const auto original_index = CGAL::get_initialized_face_index_map(pm);
    const auto np = parameters::vertex_point_map(m_vpm).face_index_map(original_index);
    validate_quad_mesh(pm, np);
    m_input_points.resize(num_vertices(pm));
    for(auto v : vertices(pm))
      m_input_points[get(m_vim, v)] = get(m_vpm, v);
    m_faces = internal::Canonical_faces<Original_face_index_map>(pm, original_index,
                                                                 internal::face_quads(pm, original_index, np));
    m_fim = m_faces.index_map();
    m_mean_edge_length = mean_edge_length(pm, np);
  }

  /// The same, with the mesh's internal vertex point map.
  explicit K_set_tilable_surface(PolygonMesh& pm)
    : K_set_tilable_surface(pm, get(CGAL::vertex_point, pm))
  {}

  /// Clusters the faces into `number_of_tiles` S-quads as `cluster_quads()`
  /// does (whose named parameters `np` takes, except the two maps: the
  /// object's own are used), from the input quads: the four stages below in
  /// turn, each reported to the visitor's `phase()`. The previous clustering
  /// and optimization are forgotten.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  const Clustering_result& cluster(const CGAL_NP_CLASS& np)
  {
    start_clustering(np);
    auto&& visitor = internal::visitor_of(np);
    adopt_selected_candidate(with_concurrency([&] { return m_clusterer->run(m_clustering, visitor); }));
    return m_clustering;
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
    with_concurrency([&] { m_clusterer->initialize(m_clustering); });
    return m_clustering.number_of_initial_clusters;
  }

  /// Stage 2: merges the initial clusters down to K by a beam search on the
  /// score of paper §4.2, adding the beam to the candidate pool
  /// (`Clustering_result::candidates`). Returns the size of the pool.
  std::size_t merge_to_tile_count()
  {
    with_concurrency([&] { clusterer().merge_to_tile_count(m_clustering); });
    return m_clustering.candidates.size();
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
    with_concurrency([&] { clusterer().add_other_candidates(m_clustering); });
    return m_clustering.candidates.size();
  }

  /// Stage 4: makes the candidate of lowest score the current clustering,
  /// with each cluster's S-quad and every face tagged with an orientation
  /// chosen for flexibility (`Clustering_result::chosen_candidate`).
  const Clustering_result& select_candidate()
  {
    adopt_selected_candidate(with_concurrency([&] { return clusterer().select(m_clustering); }));
    return m_clustering;
  }

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
    internal::Face_clustering clustering =
      internal::in_canonical_order(internal::read_face_clustering(m_mesh, m_faces.original_index,
                                                                  face_cluster_map, face_orientation_map,
                                                                  internal::unknown_number_of_clusters,
                                                                  internal::CONTIGUOUS_IDS),
                                   m_faces.rank);
    m_clustering = Clustering_result();
    m_clustering.weights_are_exact = false;
    m_policy = policy;
    m_is_clustered = true;
    set_clustering_model(std::move(clustering));
  }
  /// The orientation policy under which the instances of the current
  /// clustering match their S-quads (`cluster()`'s or `set_clustering()`'s).
  Orientation_policy orientation_policy() const { return m_policy; }

  /// Whether a clustering exists (`cluster()` or `set_clustering()`).
  bool is_clustered() const { return m_is_clustered; }

  /// The number of clusters K.
  std::size_t number_of_clusters() const { return m_clustering_model.number_of_clusters; }

  /// The current clustering: after `cluster()`, its result; after an edit,
  /// `use_candidate()`, `set_clustering()` or the fidelity search of
  /// `optimize_closest()`, the same description of the clustering now in the
  /// maps (S-quads and sizes, DOF, weights: exact if `cluster()` took the
  /// exact path, else estimated), with the candidate pool of the last
  /// `cluster()` (none after `set_clustering()` or `refine_to()`).
  const Clustering_result& clustering() const
  {
    if(m_summary_is_stale)
      describe_current_clustering();
    return m_clustering;
  }

  /// The cluster of every face.
  Face_cluster_map face_cluster_map() { return Face_cluster_map(m_cluster.begin(), m_fim); }

  /// The S-quad orientation of every face.
  Face_orientation_map face_orientation_map() { return Face_orientation_map(m_orientation.begin(), m_fim); }

  /// The edge-sharing graph of the current clustering, with the input's edge
  /// lengths. The object keeps it: a merge amends it, other edits rebuild it
  /// when it is next asked for.
  const Edge_sharing_graph<PolygonMesh>& edge_sharing_graph() const
  {
    require_clustering();
    if(!m_graph)
      m_graph.emplace(internal::Validated_mesh(true), m_mesh, m_fim, input_point_map(), m_clustering_model);
    return *m_graph;
  }

  /// Makes candidate `i` of the pool of the last `cluster()`
  /// (`clustering().candidates`) the current clustering, with S-quads and
  /// flexible orientations computed as `cluster_quads()` does for the one it
  /// returns, from the input quads. Returns its degree of flexibility.
  std::size_t use_candidate(std::size_t i)
  {
    if(i >= m_clustering.candidates.size())
      throw Invalid_input("no clustering candidate " + std::to_string(i), Invalid_input::PARAMETER);
    std::size_t degree_of_flexibility = 0;
    set_clustering_model(with_concurrency([&] { return candidate_model(i, degree_of_flexibility); }));
    return degree_of_flexibility;
  }

  /// The displacement the default solver is predicted to need for the
  /// current clustering (`predict_displacement()`), from the input
  /// positions; takes the parameters of `optimize()`.
  template <typename CGAL_NP_TEMPLATE_PARAMETERS>
  Displacement_prediction predict_displacement(const CGAL_NP_CLASS& np = parameters::default_values())
  {
    require_clustering();
    restore_input();
    return with_concurrency([&] {
      return internal::predict_displacement(internal::Validated_mesh(true), m_mesh, with_own_maps(np));
    });
  }

  /// Looks for the tilable result closest to the input among several
  /// clusterings, then improves it; the default of `make_k_set_tilable()`.
  ///
  /// -# The sweep clusterings of the pool (`Clustering_candidate::GRID_SWEEPS`)
  ///    are solved first, each from the swept surface at which it is exact
  ///    (user manual, section TS_Sweeps) for at most 10 iterations (none above
  ///    5,000 faces), the swept surface kept when the solve does not end
  ///    exact. The best of them is a fallback that the final result (after
  ///    the rounds below) must beat; it is not ranked, sets no iteration cap
  ///    and starts no round. When `number_of_optimized_candidates` is 0 (its
  ///    default above 5,000 faces) and a sweep is exact, the search ends
  ///    there: the best sweep is the result and the steps below are skipped.
  ///    Without an exact sweep, 0 counts as 1.
  /// -# The other candidates of the last `cluster()` are ranked two ways: by their
  ///    predicted displacement (`predict_displacement()`; with a parallel
  ///    `ConcurrencyTag`, one candidate per thread, with the same values;
  ///    none above 5,000 faces, where each would factorize the solver's whole
  ///    matrix: the spread alone ranks there), and by the spread
  ///    of the input's edge lengths that their edge-sharing graph ties
  ///    together (`Clustering_candidate::length_deviation`). Shape
  ///    similarity and DOF do not say how far a clustering moves the surface;
  ///    these do, the first to first order, the second for the long-range
  ///    equalities that the linearization underrates (tunnel stand-in,
  ///    K = 10: the ring clustering ranks below the hierarchical ones by prediction, first by
  ///    spread, and ends 2x closer than the first by prediction). Taking the
  ///    two rankings in turn, the `number_of_optimized_candidates` first are
  ///    optimized fully from the input (default
  ///    `default_number_of_optimized_candidates()`), then a quarter as many
  ///    more segment clusterings of a quad grid
  ///    (`Clustering_candidate::GRID_SEGMENTS`), in the order they were made:
  ///    both rankings underrate them (seashell stand-in, K = 60: the one that
  ///    keeps the spiral ends at 2.2% of the diagonal, the best of the others
  ///    at 5.7%). Each solve after the first may take at most 3 times the
  ///    iterations of the best result so far (at least 30). With a parallel
  ///    `ConcurrencyTag` and more than one thread, the next candidate is
  ///    solved beside the current one with the same cap, and kept if the cap
  ///    has not changed when its turn comes: the same results as one
  ///    candidate at a time, since the solves are deterministic. The
  ///    visitor's `iteration()` may then be called by two solves in turn
  ///    (under a lock), one of which may be discarded.
  /// -# Then `number_of_improvement_rounds` rounds of edits, K fixed: the
  ///    cluster whose instances moved most (mean off-input distance of its
  ///    corners) is split in two, and of the pairs of clusters whose merge
  ///    spreads the input's edge lengths least
  ///    (`Edge_sharing_graph::length_deviation_after_merge()`), the one with
  ///    the smallest predicted displacement is merged (above 5,000 faces the
  ///    one of least spread, unpredicted); orientations are
  ///    re-tagged and the result optimized again from the input. A round
  ///    that does not improve the result is not repeated: the next one splits
  ///    the next cluster in that order.
  /// -# While the best result is not tilable, up to 4 more rounds (none when
  ///    `number_of_improvement_rounds` is 0) repair it the same way, except
  ///    that they split the cluster whose instances fit their S-quad worst
  ///    (`Tilability_measure::cluster_congruence_errors`).
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
    using parameters::choose_parameter;
    using parameters::get_parameter;
    require_clustering();
    if(m_clustering.candidates.empty())
      return optimize(user_np);
    auto&& visitor = internal::visitor_of(user_np);
    const auto np = internal::with_visitor(user_np, visitor);
    const std::size_t optimized = choose_parameter(get_parameter(np, internal_np::number_of_optimized_candidates),
                                                   default_number_of_optimized_candidates(num_faces(m_mesh)));
    const int rounds = choose_parameter(get_parameter(np, internal_np::number_of_improvement_rounds),
                                      defaults::number_of_improvement_rounds);
    CGAL::Real_timer timer;
    timer.start();

    const int user_iterations = choose_parameter(get_parameter(np, CGAL::internal_np::number_of_iterations),
                                                 default_number_of_iterations(CONSTRAINED_GAUSS_NEWTON));
    // 0. The sweep clusterings, exact from their start: a tilable result
    // within seconds whatever the size, which the final result must beat.
    // Kept apart: it sets no iteration cap and starts no improvement round,
    // so a result that beats it is the one found without it.
    std::optional<State> best_sweep;
    std::size_t best_sweep_index = 0;
    bool stopped = false;
    for(std::size_t i = 0; i < m_clustering.candidates.size() && !stopped; ++i)
      if(m_clustering.candidates[i].origin == Clustering_candidate::GRID_SWEEPS)
      {
        timer.reset();
        const int polish = num_faces(m_mesh) > large_mesh_faces ? 0 : sweep_polish_iterations;
        State solved = with_concurrency(
          [&] { return solved_candidate(i, np.number_of_iterations((std::min)(user_iterations, polish))); });
        stopped = solved.optimization.stopped_by_visitor;
        if(!best_sweep || internal::is_better(solved.optimization, best_sweep->optimization))
        {
          best_sweep = std::move(solved);
          best_sweep_index = i;
        }
        visitor.phase("sweep candidate", timer.time());
      }

    // 1. The candidates most likely to end closest, each optimized fully;
    // none when 0 are asked for and a sweep is exact.
    const bool sweep_suffices = optimized == 0 && best_sweep && best_sweep->optimization.converged;
    std::vector<std::size_t> ranked;
    if(!stopped && !sweep_suffices)
    {
      timer.reset();
      const bool predict = predicts_displacements();
      ranked = ranked_candidates(np, (std::max)(std::size_t(1), optimized), predict);
      if(predict)
        visitor.phase("displacement prediction", timer.time());
    }
    State best;
    Solved_ahead ahead;
    for(std::size_t r = 0; r < ranked.size() && !stopped; ++r)
    {
      timer.reset();
      // Later solves get a few times the iterations of the best so far: one
      // that cannot converge in them is unlikely to end closer, and
      // non-converging solves would otherwise cost the whole budget.
      const int cap = r == 0 ? user_iterations : iteration_cap(best, user_iterations);
      State solved = solve_ranked_candidate(ranked, r, cap, np, ahead);
      stopped = solved.optimization.stopped_by_visitor;
      if(r == 0 || internal::is_better(solved.optimization, best.optimization))
      {
        best = std::move(solved);
        m_clustering.chosen_candidate = ranked[r];
      }
      visitor.phase("candidate optimization", timer.time());
    }
    if(ranked.empty() && best_sweep) // a sweep suffices, or the visitor stopped one's solve
    {
      best = std::move(*best_sweep);
      best_sweep.reset();
      m_clustering.chosen_candidate = best_sweep_index;
    }
    set_state(best);

    // 2. Improvement rounds, and repair rounds while the best is not tilable:
    // its clustering may have no exact realization near the input (6-sub-lifted,
    // K = 7: every candidate and a local-global projection stall near 5e-2).
    // A round that does not improve is not repeated: the next one splits the
    // next cluster in the order.
    int rounds_done = 0;
    std::size_t failed_in_a_row = 0;
    for(int round = 0; (round < rounds || (rounds > 0 && round < rounds + repair_rounds &&
                                           !best.optimization.converged)) &&
                       number_of_clusters() > 1 && !stopped && !sweep_suffices;
        ++round)
    {
      timer.reset();
      if(!improvement_edit(np, failed_in_a_row))
        break;
      ++rounds_done;
      optimize(np.number_of_iterations(iteration_cap(best, user_iterations)));
      if(internal::is_better(m_optimization, best.optimization))
      {
        best = state();
        failed_in_a_row = 0;
      }
      else
        ++failed_in_a_row;
      const bool round_stopped = m_optimization.stopped_by_visitor;
      set_state(best);
      visitor.phase("improvement round", timer.time());
      if(round_stopped)
        break;
    }

    // 3. The sweep, if the result did not beat it.
    const bool sweep_chosen = ranked.empty() || (best_sweep && internal::is_better(best_sweep->optimization, best.optimization));
    if(best_sweep && sweep_chosen)
    {
      set_state(*best_sweep);
      m_clustering.chosen_candidate = best_sweep_index;
    }
    m_clustering.choice_reason =
      (sweep_suffices ? std::string("an exact sweep clustering, no other candidate optimized "
                                    "(number_of_optimized_candidates 0)")
                      : std::string(sweep_chosen ? "a sweep clustering, better than " : "closest result among ") +
                          "the " + std::to_string(ranked.size()) +
                          " candidates of smallest predicted displacement or length spread, or first segment "
                          "clusterings, then " + std::to_string(rounds_done) + " improvement or repair rounds") +
      "; " + m_clustering.choice_reason;
    m_clustering.number_of_edit_rounds = std::size_t(rounds_done);
    return m_optimization;
  }

  /// The degree of flexibility of the current clustering.
  std::size_t degree_of_flexibility() const { return edge_sharing_graph().degree_of_flexibility(); }

  /// Merges clusters `a` and `b` as `Tilable_surfaces::merge_clusters()`
  /// does, judged on the input quads, and amends the edge-sharing graph
  /// (O(K) unions, no rebuild); returns the new degree of flexibility.
  /// \throws Invalid_input if `a == b` or a cluster does not exist; nothing
  /// changes then.
  std::size_t merge_clusters(std::size_t a, std::size_t b)
  {
    require_clustering();
    edge_sharing_graph(); // built if it was not: it is amended below
    with_concurrency([&] {
      const Quad_orientation correspondence =
        internal::merge_clusters(m_clustering_model, m_faces.quads, a, b, m_policy);
      m_graph->merge_clusters((std::min)(a, b), (std::max)(a, b), correspondence);
      m_graph->compact_cluster_ids();
    });
    publish_clustering_model();
    return m_graph->degree_of_flexibility();
  }

  /// Splits cluster `c` in two as `Tilable_surfaces::split_cluster()` does,
  /// judged on the input quads; returns the new degree of flexibility.
  /// \throws Invalid_input if `c` does not exist or has a single face;
  /// nothing changes then.
  std::size_t split_cluster(std::size_t c, unsigned int random_seed = defaults::random_seed)
  {
    require_clustering();
    with_concurrency([&] {
      CGAL::Random random(random_seed);
      internal::split_cluster(m_clustering_model, m_faces.quads, c, m_policy, random);
    });
    m_graph.reset(); // a union-find cannot undo a union
    publish_clustering_model();
    return degree_of_flexibility();
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
    require_clustering();
    if(k < number_of_clusters() || k > num_faces(m_mesh))
      throw Invalid_input("cannot refine " + std::to_string(number_of_clusters()) + " clusters to K = " +
                            std::to_string(k) + " (the mesh has " + std::to_string(num_faces(m_mesh)) + " faces)",
                          Invalid_input::PARAMETER);
    const std::size_t refined_k = number_of_clusters();
    const internal::Point_matrix start = internal::read_points(m_mesh, m_vpm, m_vim);
    // The splits of split_cluster() on a copy of the model: the edge-sharing
    // graph split_cluster() rebuilds for its DOF is not needed between them.
    internal::Face_clustering retagged = m_clustering_model;
    with_concurrency([&] {
      while(retagged.number_of_clusters < k)
      {
        const std::vector<std::size_t> size = retagged.cluster_sizes();
        CGAL::Random random(defaults::random_seed);
        internal::split_cluster(retagged, m_faces.quads,
                                std::size_t(std::max_element(size.begin(), size.end()) - size.begin()), m_policy,
                                random);
      }
    });
    // The splits re-tag on the input quads and may pick another symmetry of
    // an S-quad: the current positions are then no longer exact, and the
    // solve from the input sometimes ends closer (De Beers 28 -> 30: 1.35%
    // against 1.62% of the diagonal with the orientations kept).
    internal::Face_clustering kept = retagged;
    kept.orientation = m_clustering_model.orientation;
    const std::size_t ways = kept.orientation == retagged.orientation ? 1 : 2;
    auto&& visitor = internal::visitor_of(np);
    std::mutex mutex;
    Locked_visitor<std::remove_reference_t<decltype(visitor)> > locked{&visitor, &mutex};
    const auto solve_np = internal::with_visitor(np, locked);
    std::vector<State> solved(ways);
    with_concurrency([&] {
      internal::parallel_for(ways, [&](std::size_t j) {
        solved[j] = j == 0 ? solved_model(kept, solve_np, &start) : solved_model(retagged, solve_np, nullptr);
      });
    });
    const bool retagged_wins = ways == 2 && internal::is_better(solved[1].optimization, solved[0].optimization);
    set_state(solved[retagged_wins ? 1 : 0]);
    m_clustering = Clustering_result();
    m_clustering.weights_are_exact = false;
    m_clustering.choice_reason = "the result at K = " + std::to_string(refined_k) +
                                 ", its largest clusters split to K = " + std::to_string(k) + ", solved " +
                                 (retagged_wins ? "from the input with the orientations the splits chose"
                                                : "from there with every face's orientation kept") +
                                 " (refine_to())";
    return m_optimization;
  }

  /// Re-tags every face with the orientation that best matches its cluster's
  /// S-quad, as `Tilable_surfaces::retag_orientations()` does with the
  /// clustering's similarity threshold, judged on the input quads; returns
  /// the new degree of flexibility.
  std::size_t retag_orientations()
  {
    require_clustering();
    with_concurrency([&] {
      internal::retag_orientations(m_clustering_model, m_mesh, m_fim, m_faces.quads, m_policy,
                                   m_similarity_threshold * m_mean_edge_length);
    });
    m_graph.reset();
    publish_clustering_model();
    return degree_of_flexibility();
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
    restore_input();
    m_optimization = with_concurrency([&] {
      return internal::optimize_tilable_surface(internal::Validated_mesh(true), m_mesh, with_own_maps(np));
    });
    return m_optimization;
  }

  /// The result of the last `optimize()` call.
  const Optimization_result& optimization() const { return m_optimization; }

  /// Measures the current mesh against the input (`measure_tilability()`):
  /// the same connectivity with the input positions.
  Tilability_measure measure()
  {
    require_clustering();
    return with_concurrency([&] {
      return internal::measure_tilability(
        internal::Validated_mesh(true), m_mesh, m_mesh, own_maps(),
        parameters::vertex_point_map(input_point_map()).vertex_index_map(m_vim));
    });
  }

  /// The positions of the input, as they were when the object was made: a
  /// readable property map from the vertices of the mesh to points.
  Input_point_map input_point_map() const { return Input_point_map(m_input_points.cbegin(), m_vim); }

  /// Puts the input positions back in the mesh. Clustering, edits and solves
  /// call it first: they start from the input, never from a result.
  void restore_input() { write_points(m_input_points); }

  /// The tile catalog of the current mesh: one tile per S-quad, with the
  /// measured worst deviation of its instances, in the mesh's units.
  std::vector<Tile> tile_catalog()
  {
    return Tilable_surfaces::tile_catalog(measure());
  }

private:
  // What the fidelity search keeps of the best result so far.
  // (The graph is kept too: a copy costs O(K).)
  struct State
  {
    std::vector<Point> points;
    internal::Face_clustering clustering;
    std::optional<Edge_sharing_graph<PolygonMesh> > graph;
    Optimization_result optimization;
  };

  State state() const
  {
    State st;
    st.points.resize(num_vertices(m_mesh));
    for(auto v : vertices(m_mesh))
      st.points[get(m_vim, v)] = get(m_vpm, v);
    st.clustering = m_clustering_model;
    st.graph = m_graph;
    st.optimization = m_optimization;
    return st;
  }

  void set_state(const State& st)
  {
    write_points(st.points);
    m_clustering_model = st.clustering;
    m_graph = st.graph;
    publish_clustering_model();
    m_optimization = st.optimization;
  }

  // Makes `clustering` the current one; the graph is rebuilt when needed.
  void set_clustering_model(internal::Face_clustering clustering)
  {
    m_clustering_model = std::move(clustering);
    m_graph.reset();
    publish_clustering_model();
  }

  // Writes the model into the storage of the maps handed out (in place: they
  // stay valid) and marks the description of clustering() stale.
  void publish_clustering_model()
  {
    m_clustering_model.write_ids(m_cluster, m_orientation);
    m_summary_is_stale = true;
  }

  void describe_current_clustering() const
  {
    const internal::Face_clustering& fc = m_clustering_model;
    const internal::Cluster_shapes shapes =
      internal::cluster_shapes(m_faces.quads, fc.label, fc.number_of_clusters, m_policy);
    internal::describe_clustering(fc.label, fc.number_of_clusters, shapes, degree_of_flexibility(),
                                  m_clustering.weights_are_exact, [&](std::size_t p, std::size_t q) {
                                    return internal::fast_best_match(m_faces.quads[p], m_faces.quads[q],
                                                                     m_policy).dissimilarity;
                                  }, m_clustering);
    m_summary_is_stale = false;
  }

  void write_points(const std::vector<Point>& points)
  {
    for(auto v : vertices(m_mesh))
      put(m_vpm, v, points[get(m_vim, v)]);
  }

  // The iterations of a sweep candidate's solve from its exact start, kept
  // only if it ends exact and closer. Few: a solve that leaves the exact
  // surfaces comes back to them slowly (seashell parametrization, K = 100:
  // 1.2e-6 after 30 iterations at 1k quads, 5e-6 after 300 at 10k, 1 s each
  // there). None above large_mesh_faces (defaults.h).
  static constexpr int sweep_polish_iterations = 10;

  // Three times the iterations the best result took, at least 30, at most
  // the user's limit.
  static int iteration_cap(const State& best, int user_iterations)
  {
    return (std::min)(user_iterations, (std::max)(30, 3 * best.optimization.iterations));
  }

  // A candidate solved before its turn, with the iteration cap it was given.
  struct Solved_ahead
  {
    std::optional<State> state;
    std::size_t rank = 0;
    int cap = 0;
  };

  // The solve of candidate ranked[r] with `cap` iterations, from the input.
  // With several threads, candidate ranked[r + 1] is solved beside it with
  // the same cap and kept in `ahead`: it is exactly the next solve if the
  // cap does not change, that is, unless candidate r becomes the best with a
  // different iteration count (the cap of the first candidate is the user's,
  // so its successor is not solved ahead). Solves are deterministic, so the
  // result is the same with or without the solves ahead.
  template <typename NP>
  State solve_ranked_candidate(const std::vector<std::size_t>& ranked, std::size_t r, int cap,
                               const NP& np, Solved_ahead& ahead)
  {
    if(ahead.state && ahead.rank == r && ahead.cap == cap)
    {
      State solved = std::move(*ahead.state);
      ahead.state.reset();
      return solved;
    }
    ahead.state.reset();
    auto&& visitor = internal::visitor_of(np);
    std::mutex mutex;
    Locked_visitor<std::remove_reference_t<decltype(visitor)> > locked{&visitor, &mutex};
    const auto solve_np = internal::with_visitor(np, locked).number_of_iterations(cap);
    const bool solve_ahead =
      r > 0 && r + 1 < ranked.size() && with_concurrency([] { return internal::several_threads_available(); });
    std::vector<State> solved(solve_ahead ? 2 : 1);
    with_concurrency([&] {
      internal::parallel_for(solved.size(), [&](std::size_t j) { solved[j] = solved_candidate(ranked[r + j], solve_np); });
    });
    if(solve_ahead)
      ahead = Solved_ahead{std::move(solved[1]), r + 1, cap};
    return std::move(solved[0]);
  }

  // Forwards to a visitor under a lock: two solves may call it at once.
  template <typename Visitor>
  struct Locked_visitor
  {
    Visitor* visitor;
    std::mutex* mutex;

    bool iteration(int iteration, double congruence_error, double objective)
    {
      std::lock_guard<std::mutex> lock(*mutex);
      return visitor->iteration(iteration, congruence_error, objective);
    }
    void phase(const char* name, double seconds)
    {
      std::lock_guard<std::mutex> lock(*mutex);
      visitor->phase(name, seconds);
    }
  };

  // Candidate `i` optimized from the input on copies (its clustering, maps
  // and points): what use_candidate(i) then optimize() give, without
  // touching the object; safe to call from several threads.
  template <typename NP>
  State solved_candidate(std::size_t i, const NP& np) const
  {
    std::size_t unused_dof;
    internal::Face_clustering model = candidate_model(i, unused_dof);
    internal::Point_matrix start;
    if(m_clustering.candidates[i].origin == Clustering_candidate::GRID_SWEEPS)
      start = swept_start(model);
    return solved_model(std::move(model), np, start.rows() > 0 ? &start : nullptr);
  }

  // The solve of clustering `model` from the input on a copy of the points,
  // from `start` when it is not null and `model` is exact there.
  template <typename NP>
  State solved_model(internal::Face_clustering model, const NP& np, const internal::Point_matrix* start) const
  {
    State solved;
    solved.clustering = std::move(model);
    Model_maps maps(solved.clustering);
    solved.points = m_input_points;
    const Point_storage_map points(solved.points.begin(), m_vim);
    solved.optimization = internal::optimize_tilable_surface(internal::Validated_mesh(true), m_mesh,
                                                             with_model_maps(np, points, maps), start);
    return solved;
  }

  // The positions at which the sweep clustering `model` is exact
  // (sweep_start()), with its orientations re-tagged there: the ones chosen
  // on the input for flexibility need not be those of the sweep, whose
  // quads correspond in grid order. Empty when there is none.
  internal::Point_matrix swept_start(internal::Face_clustering& model) const
  {
    std::vector<Quad_orientation> orientation(model.orientation.size());
    const internal::Point_matrix start =
      internal::sweep_start(m_mesh, m_fim, m_vim, input_point_map(),
                            internal::read_points(m_mesh, input_point_map(), m_vim), model.label, &orientation);
    if(start.rows() > 0)
      model.orientation.swap(orientation);
    return start;
  }

  // Rounds of optimize_closest() beyond the user's that repair a result that
  // is not tilable.
  static constexpr int repair_rounds = 4;

  // One edit of an improvement round on the current (best) result: split
  // the cluster that moved most, or, if the result is not tilable, the one
  // whose instances fit their S-quad worst (the `rank`-th in that order, 0
  // first); merge the cheapest pair (see optimize_closest()), re-tag. False
  // when no edit applies.
  template <typename NP>
  bool improvement_edit(const NP& np, std::size_t rank)
  {
    std::vector<double> moved(number_of_clusters(), 0.0);
    std::vector<std::size_t> size(number_of_clusters(), 0);
    for(auto f : faces(m_mesh))
    {
      double sum = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m_mesh), m_mesh))
        sum += internal::distance(get(m_vpm, v), m_input_points[get(m_vim, v)]);
      moved[std::size_t(m_cluster[get(m_fim, f)])] += sum;
      ++size[std::size_t(m_cluster[get(m_fim, f)])];
    }
    const bool repair = !m_optimization.converged;
    const std::vector<double>& misfit = m_optimization.measure.cluster_congruence_errors;
    auto badness = [&](std::size_t c) {
      return repair && c < misfit.size() ? misfit[c] : moved[c] / double(size[c]);
    };
    // The merge that follows a split joins two clusters of one kind (quads
    // and triangles never share one), other than the two parts: some kind
    // must have two clusters besides the one split.
    std::size_t clusters_of_kind[5] = {0, 0, 0, 0, 0};
    for(std::size_t c = 0; c < number_of_clusters(); ++c)
      ++clusters_of_kind[edge_sharing_graph().corner_count(c)];
    std::vector<std::size_t> splittable;
    for(std::size_t c = 0; c < number_of_clusters(); ++c)
    {
      const int kind = edge_sharing_graph().corner_count(c);
      if(size[c] >= 2 && (clusters_of_kind[kind] >= 2 || clusters_of_kind[7 - kind] >= 2))
        splittable.push_back(c);
    }
    if(rank >= splittable.size())
      return false;
    std::stable_sort(splittable.begin(), splittable.end(),
                     [&](std::size_t a, std::size_t b) { return badness(a) > badness(b); });
    const std::size_t worst = splittable[rank];
    restore_input();
    split_cluster(worst);

    // The pairs that spread the edge lengths least, judged by prediction.
    const Edge_sharing_graph<PolygonMesh>& graph = edge_sharing_graph();
    std::vector<std::pair<double, std::pair<std::size_t, std::size_t> > > pairs;
    const std::size_t new_part = number_of_clusters() - 1;
    for(std::size_t a = 0; a < number_of_clusters(); ++a)
      for(std::size_t b = a + 1; b < number_of_clusters(); ++b)
      {
        if((a == worst && b == new_part) || graph.corner_count(a) != graph.corner_count(b))
          continue; // that would undo the split, or mix quads and triangles
        // The correspondence is not known before the merge: the least spread.
        double spread = std::numeric_limits<double>::infinity();
        for(int o = 0; o < 8; ++o)
          spread = (std::min)(spread, graph.length_deviation_after_merge(a, b, Quad_orientation(o)));
        pairs.push_back({spread, {a, b}});
      }
    if(pairs.empty())
      return false;
    std::sort(pairs.begin(), pairs.end());
    // Each pair merged in a copy and predicted, in parallel (predict_candidates());
    // the least spread alone when no displacement is predicted.
    pairs.resize((std::min)(pairs.size(), std::size_t(predicts_displacements() ? 4 : 1)));
    std::vector<double> prediction(pairs.size());
    if(pairs.size() > 1)
      with_concurrency([&] {
        internal::parallel_for(pairs.size(), [&](std::size_t i) {
          internal::Face_clustering merged = m_clustering_model;
          internal::merge_clusters(merged, m_faces.quads, pairs[i].second.first, pairs[i].second.second, m_policy);
          prediction[i] = predicted_displacement(merged, np);
        });
      });
    const std::size_t best = std::size_t(std::min_element(prediction.begin(), prediction.end()) - prediction.begin());
    merge_clusters(pairs[best].second.first, pairs[best].second.second);
    retag_orientations();
    return true;
  }

  // Whether optimize_closest() ranks by predicted displacement. Above
  // large_mesh_faces a prediction factorizes the solver's whole matrix, one
  // per candidate and thread (spot_quadrangulated subdivided to 187k quads:
  // 8 GB and 2 minutes each): there the length spread ranks alone.
  bool predicts_displacements() const { return num_faces(m_mesh) <= large_mesh_faces; }

  // The candidates of the last cluster() that optimize_closest() optimizes:
  // ranked two ways, taken in turn, by predicted displacement (unless not
  // `predict`: then by spread alone) and by the spread of edge lengths they
  // tie together, the `optimized` first; then a
  // quarter as many segment clusterings, in the order they were made, since
  // both rankings underrate their long-range ties.
  template <typename NP>
  std::vector<std::size_t> ranked_candidates(const NP& np, std::size_t optimized, bool predict)
  {
    if(predict)
      predict_candidates(np);
    std::vector<std::pair<double, std::size_t> > by_prediction, by_spread;
    for(std::size_t i = 0; i < m_clustering.candidates.size(); ++i)
    {
      const Clustering_candidate& candidate = m_clustering.candidates[i];
      if(candidate.origin == Clustering_candidate::GRID_SWEEPS)
        continue;
      by_prediction.push_back({candidate.predicted_displacement, i});
      by_spread.push_back({candidate.length_deviation, i});
    }
    std::sort(by_prediction.begin(), by_prediction.end());
    std::sort(by_spread.begin(), by_spread.end());
    std::vector<std::size_t> ranked;
    for(std::size_t r = 0; r < by_prediction.size(); ++r)
      for(std::size_t i : {predict ? by_prediction[r].second : by_spread[r].second, by_spread[r].second})
        if(std::find(ranked.begin(), ranked.end(), i) == ranked.end())
          ranked.push_back(i);
    ranked.resize((std::min)(optimized, ranked.size()));
    std::size_t extra = (optimized + 3) / 4;
    for(std::size_t i = 0; i < m_clustering.candidates.size() && extra > 0; ++i)
      if(m_clustering.candidates[i].origin == Clustering_candidate::GRID_SEGMENTS &&
         std::find(ranked.begin(), ranked.end(), i) == ranked.end())
      {
        ranked.push_back(i);
        --extra;
      }
    return ranked;
  }

  typedef internal::Quad_clusterer<PolygonMesh, Original_face_index_map, Input_point_map> Clusterer;

  // What cluster() and initialize_clusters() start with: the parameters
  // checked and kept, the clusterer made, the description emptied.
  template <typename NamedParameters>
  void start_clustering(const NamedParameters& np)
  {
    static_assert(!parameters::is_default_parameter<NamedParameters, internal_np::number_of_tiles_t>::value,
                  "the named parameter number_of_tiles is required");
    const std::size_t k = internal::tile_count(np, num_faces(m_mesh));
    restore_input();
    m_policy = internal::orientation_policy(np);
    m_similarity_threshold = parameters::choose_parameter(
      parameters::get_parameter(np, internal_np::similarity_threshold), defaults::similarity_threshold);
    internal::Clustering_settings settings = internal::clustering_settings(np);
    // optimize_closest() with the same parameters ends its search at an
    // exact sweep there: the clusterer need not make the other candidates.
    const std::size_t optimized =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::number_of_optimized_candidates),
                                   default_number_of_optimized_candidates(num_faces(m_mesh)));
    if(num_faces(m_mesh) > large_mesh_faces && optimized == 0)
      settings.sweep_ends_search = [mesh = &m_mesh, fim = m_fim, vim = m_vim, vpm = input_point_map(),
                                    points = internal::read_points(m_mesh, input_point_map(), m_vim)](
                                     const std::vector<std::size_t>& label) {
        return internal::sweep_start(*mesh, fim, vim, vpm, points, label).rows() > 0;
      };
    m_clusterer.reset(new Clusterer(m_mesh, m_faces, input_point_map(), m_mean_edge_length, k, settings));
    m_clustering = Clustering_result();
    m_summary_is_stale = false;
  }

  // The chosen candidate, with the orientations of `shapes`, becomes the
  // current clustering; the clusterer's n x n dissimilarities are freed.
  void adopt_selected_candidate(const internal::Cluster_shapes& shapes)
  {
    m_clusterer.reset();
    set_clustering_model(internal::Face_clustering{candidate_labels(m_clustering.chosen_candidate),
                                                   shapes.orientation, m_clustering.cluster_sizes.size()});
    m_summary_is_stale = false;
    m_is_clustered = true;
  }

  // The clusters of candidate `i` (by face index), by canonical index.
  std::vector<std::size_t> candidate_labels(std::size_t i) const
  {
    return internal::by_canonical_index(m_clustering.candidates[i].face_cluster, m_faces.rank);
  }

  // Candidate `i` with S-quads and flexible orientations as use_candidate()
  // makes it current; reads the input quads only.
  internal::Face_clustering candidate_model(std::size_t i, std::size_t& degree_of_flexibility) const
  {
    const std::vector<std::size_t> label = candidate_labels(i);
    const std::size_t k = m_clustering.cluster_sizes.size();
    const internal::Cluster_shapes shapes =
      internal::finished_clustering(m_mesh, m_fim, input_point_map(), m_faces.quads, label, k, m_policy,
                                    m_similarity_threshold * m_mean_edge_length);
    degree_of_flexibility = shapes.degree_of_flexibility;
    return internal::Face_clustering{label, shapes.orientation, k};
  }

  // Sets `predicted_displacement` of every candidate of the pool, from the
  // input positions. The candidates are predicted in parallel, each into its
  // own slot with its own maps: one prediction is one serial factorization
  // (sparse_solver.h), so this is where the threads pay, and every value is
  // the one a single thread computes. The index maps the predictions read
  // were initialized by the constructor's validation.
  template <typename NP>
  void predict_candidates(const NP& np)
  {
    restore_input();
    std::vector<Clustering_candidate>& pool = m_clustering.candidates;
    with_concurrency([&] {
      internal::parallel_for(pool.size(), [&](std::size_t i) {
        if(pool[i].origin == Clustering_candidate::GRID_SWEEPS)
          return;
        std::size_t unused_dof;
        pool[i].predicted_displacement = predicted_displacement(candidate_model(i, unused_dof), np);
      });
    });
  }

  // The predicted displacement (`Displacement_prediction::max`) of the
  // clustering `model`, with maps of its own: safe to call from several
  // threads once the mesh holds the input positions.
  template <typename NP>
  double predicted_displacement(const internal::Face_clustering& model, const NP& np) const
  {
    Model_maps maps(model);
    return internal::predict_displacement(internal::Validated_mesh(true), m_mesh, with_model_maps(np, m_vpm, maps))
      .max;
  }

  Clusterer& clusterer()
  {
    if(!m_clusterer)
      throw Invalid_input("no clustering under way: call initialize_clusters() first",
                          Invalid_input::PARAMETER);
    return *m_clusterer;
  }

  // Runs f with the parallelism of ConcurrencyTag (the steps that compute)
  // and returns what it returns.
  template <typename F>
  static auto with_concurrency(const F& f)
  {
    typedef decltype(f()) Result;
    if constexpr(std::is_void<Result>::value)
      internal::run_with_concurrency<ConcurrencyTag>(f);
    else
    {
      std::optional<Result> result;
      internal::run_with_concurrency<ConcurrencyTag>([&] { result.emplace(f()); });
      return std::move(*result);
    }
  }

  // The parameters every step shares: the object's maps and indices, and the
  // orientation policy and similarity threshold of the clustering, so that
  // edits, solves and measurements match instances to S-quads as it did.
  auto own_maps()
  {
    return parameters::vertex_point_map(m_vpm)
      .face_index_map(m_fim)
      .face_cluster_map(face_cluster_map())
      .face_orientation_map(face_orientation_map())
      .orientation_policy(m_policy)
      .similarity_threshold(m_similarity_threshold);
  }

  // The user's parameters with the object's maps in front (found first); the
  // user's orientation policy, if given, else the clustering's.
  template <typename NP>
  auto with_own_maps(const NP& np)
  {
    return with_maps(np, m_vpm, face_cluster_map(), face_orientation_map());
  }

  // Points stored by vertex index: the positions of a solve on a copy.
  typedef boost::iterator_property_map<typename std::vector<Point>::iterator, Vertex_index_map, Point, Point&>
    Point_storage_map;

  // A clustering as the ints the maps read, in storage of its own: for the
  // steps that work on a copy of the current clustering, several at once.
  struct Model_maps
  {
    std::vector<int> cluster, orientation;
    explicit Model_maps(const internal::Face_clustering& model)
      : cluster(model.label.size()), orientation(model.label.size())
    {
      model.write_ids(cluster, orientation);
    }
  };

  // with_maps() with the clustering in `maps`, which must outlive the result.
  template <typename NP, typename PointMap>
  auto with_model_maps(const NP& np, PointMap vpm, Model_maps& maps) const
  {
    return with_maps(np, vpm, Face_cluster_map(maps.cluster.begin(), m_fim),
                     Face_orientation_map(maps.orientation.begin(), m_fim));
  }

  // The same with the points in `vpm` and the clustering in `cluster` and
  // `orientation`.
  template <typename NP, typename PointMap>
  auto with_maps(const NP& np, PointMap vpm, Face_cluster_map cluster, Face_orientation_map orientation) const
  {
    return parameters::extend(np)
      .vertex_point_map(vpm)
      .vertex_index_map(m_vim)
      .face_index_map(m_fim)
      .face_cluster_map(cluster)
      .face_orientation_map(orientation)
      .orientation_policy(parameters::choose_parameter(
        parameters::get_parameter(np, internal_np::orientation_policy), m_policy));
  }

  void require_clustering() const
  {
    if(!m_is_clustered)
      throw Invalid_input("no clustering yet: call cluster() or set_clustering() first",
                          Invalid_input::PARAMETER);
  }

  PolygonMesh& m_mesh;
  VertexPointMap m_vpm;
  internal::Canonical_faces<Original_face_index_map> m_faces;  // the input quads, in canonical order
  Face_index_map m_fim;                                        // m_faces.index_map()
  Vertex_index_map m_vim;
  std::vector<Point> m_input_points;  // positions of the input, by m_vim
  double m_mean_edge_length = 0;      // of the input
  // The clustering parameters of the last cluster() (or set_clustering()).
  bool m_is_clustered = false;
  Orientation_policy m_policy = PROPER_RIGID_MOTIONS;
  double m_similarity_threshold = defaults::similarity_threshold;
  // The current clustering, and a copy of it as ints that the maps handed out read.
  internal::Face_clustering m_clustering_model;
  std::vector<int> m_cluster;
  std::vector<int> m_orientation;
  mutable std::optional<Edge_sharing_graph<PolygonMesh> > m_graph;  // built when asked for
  mutable Clustering_result m_clustering;
  mutable bool m_summary_is_stale = false;
  std::unique_ptr<Clusterer> m_clusterer;  // between initialize_clusters() and select_candidate()
  Optimization_result m_optimization;
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
