// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_CLUSTER_PANELS_H
#define CGAL_TILABLE_SURFACES_CLUSTER_PANELS_H

/// \file cluster_panels.h
/// Clustering of the quads of a mesh into K S-quads (paper §3 and §5; user
/// manual, section Clustering).

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/panel_tolerance.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/beam_search.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/flexible_orientations.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/twist_separation.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Random.h>
#include <CGAL/Real_timer.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {


/// \ingroup PkgTilableSurfacesRef
/// One configuration of the final candidate pool of `cluster_panels()`.
/// Its `Origin` (the enum `Candidate_origins::Origin`, whose values are
/// registered with their generators in
/// internal/Clustering/candidate_generators.h) says which candidate
/// generator made it (user manual, section Candidate generators).
struct Clustering_candidate : Candidate_origins
{
  Origin origin = HIERARCHICAL;  ///< the generator that produced it
  /// Its weight, in the units of the clustering path (see `Clustering_result::path`):
  /// sum of pairwise dissimilarities on the exact path, sum of pairwise squared
  /// descriptor distances on the descriptor path.
  double weight = 0;
  /// Its degree of flexibility, with each face oriented as its initial cluster's
  /// leader (hierarchical) or as the face nearest to its k-means centre.
  std::size_t degree_of_flexibility = 0;
  /// Its length deviation (`Edge_sharing_graph::length_deviation()`), with
  /// the same orientations.
  double length_deviation = 0;
  /// The selection score (lower is better): W / W1 + flexibility_penalty x
  /// (D0 - D) / D0 + structure_penalty x V / V1; see `cluster_panels()`.
  double score = 0;
  /// Its predicted displacement (`Displacement_prediction::max`) once
  /// `K_set_tilable_surface::optimize_closest()` ranked it; else 0 (always
  /// for `GRID_SWEEPS`, which are not ranked).
  double predicted_displacement = 0;
  /// The cluster of every face (by face index), 0..K-1 numbered by first
  /// face in the canonical face order (see `cluster_panels()`);
  /// `K_set_tilable_surface` optimizes the most promising candidates.
  std::vector<std::size_t> face_cluster;
};

/// \ingroup PkgTilableSurfacesRef
/// What `cluster_panels()` found, besides the two face maps it fills.
struct Clustering_result
{
  /// The path that was used: `EXACT_PATH` or `DESCRIPTOR_PATH`.
  Clustering_path path = EXACT_PATH;
  /// The number of faces of each cluster (none is empty).
  std::vector<std::size_t> cluster_sizes;
  /// The S-quad of each cluster: the mean shape of its instances, each brought
  /// by its best match onto the current mean (3 Procrustes iterations),
  /// centred at the origin. Face orientations refer to its corner labels.
  std::vector<Panel> s_quads;
  /// The weight S(C) of each cluster: on the exact path the sum of the pairwise
  /// dissimilarities of its quads; on the descriptor path the estimate
  /// (|C| - 1) * sum_{q in C} s(S-quad, q), the triangle-inequality bound that
  /// replaces each s(p, q) by s(p, S-quad) + s(S-quad, q) (within a factor 2 of
  /// the exact value when the S-quad is close to the cluster's medoid).
  std::vector<double> cluster_weights;
  /// Sum of `cluster_weights`.
  double total_weight = 0;
  /// Whether `cluster_weights` are exact (exact path) or estimates.
  bool weights_are_exact = true;
  /// The degree of flexibility of the returned clustering, with the returned
  /// orientations (chosen for flexibility among admissible ones, see
  /// `cluster_panels()`): the number of components of its edge-sharing graph.
  std::size_t degree_of_flexibility = 0;
  /// The number N of clusters of the threshold clustering.
  std::size_t number_of_initial_clusters = 0;
  /// The absolute threshold that produced them (the descriptor path doubles
  /// the threshold until N is at most max(1000, 4K)).
  double initial_threshold = 0;
  /// The final candidate pool: the beam, best score first, then the k-means
  /// configuration if it was asked for and has K non-empty clusters, the
  /// quad-strip, grid-segment and sweep clusterings (`Clustering_candidate::Origin`,
  /// in the order of the registered generators).
  std::vector<Clustering_candidate> candidates;
  /// Index in `candidates` of the returned configuration.
  std::size_t chosen_candidate = 0;
  /// Why it was chosen, in words.
  std::string choice_reason;
  /// The rounds of split-and-merge edits that
  /// `K_set_tilable_surface::optimize_closest()` made after the candidates
  /// (improvement rounds, and repair rounds while the result was not
  /// tilable), whether kept or not; 0 from `cluster_panels()`.
  std::size_t number_of_edit_rounds = 0;
};

namespace internal {

// The corners of every face, indexed by `fim`.
template <typename PolygonMesh, typename FaceIndexMap, typename NP>
std::vector<Panel> face_quads(const PolygonMesh& pm, FaceIndexMap fim, const NP& np)
{
  std::vector<Panel> quads(num_faces(pm));
  for(auto f : faces(pm))
    quads[get(fim, f)] = face_panel(f, pm, Panel_orientation(), np);
  return quads;
}

// The S-quads of labelling `label` (Procrustes means of the quads of `pm`),
// each face tagged with an admissible orientation chosen for flexibility
// (flexible_orientations(), near-ties within `tau`).
template <typename PolygonMesh, typename FaceIndexMap>
Cluster_shapes flexible_cluster_shapes(const PolygonMesh& pm, FaceIndexMap fim, const std::vector<Panel>& quads,
                                       const std::vector<std::size_t>& label, std::size_t k,
                                       Orientation_policy policy, double tau)
{
  Cluster_shapes shapes = cluster_shapes(quads, label, k, policy);
  shapes.orientation =
    flexible_orientations(pm, fim, quads, label, shapes.s_quads, shapes.orientation, policy, tau);
  return shapes;
}

// The same, with the resulting DOF.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Cluster_shapes finished_clustering(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                                   const std::vector<Panel>& quads, const std::vector<std::size_t>& label,
                                   std::size_t k, Orientation_policy policy, double tau)
{
  Cluster_shapes shapes = flexible_cluster_shapes(pm, fim, quads, label, k, policy, tau);
  shapes.degree_of_flexibility =
    edge_sharing_graph(pm, fim, vpm, label, shapes.orientation, k).degree_of_flexibility();
  return shapes;
}

// Describes the clustering `label` into `k` clusters in `result`: its
// S-quads (those of `shapes`), sizes, DOF `dof` and weights, exact (the sum of
// `dissimilarity(p, q)` over the pairs p < q of every cluster) or estimated
// ((|C| - 1) times the sum of s(S-quad, q) over C).
template <typename Dissimilarity>
void describe_clustering(const std::vector<std::size_t>& label, std::size_t k, const Cluster_shapes& shapes,
                         std::size_t dof, bool exact, const Dissimilarity& dissimilarity,
                         Clustering_result& result)
{
  const std::size_t n = label.size();
  result.s_quads = shapes.s_quads;
  result.degree_of_flexibility = dof;
  result.weights_are_exact = exact;
  result.cluster_sizes.assign(k, 0);
  result.cluster_weights.assign(k, 0.0);
  result.total_weight = 0;
  for(std::size_t f = 0; f < n; ++f) ++result.cluster_sizes[label[f]];
  if(exact)
  {
    for(std::size_t p = 0; p < n; ++p)
      for(std::size_t q = p + 1; q < n; ++q)
        if(label[p] == label[q]) result.cluster_weights[label[p]] += dissimilarity(p, q);
  }
  else
  {
    for(std::size_t f = 0; f < n; ++f) result.cluster_weights[label[f]] += shapes.distance[f];
    for(std::size_t c = 0; c < k; ++c)
      result.cluster_weights[c] *= double(result.cluster_sizes[c] - 1);
  }
  for(double w : result.cluster_weights) result.total_weight += w;
}

// The Clustering_settings (candidate_generator.h) of the named parameters `np`.
template <typename NP>
Clustering_settings clustering_settings(const NP& np)
{
  namespace TS_np = CGAL::Tilable_surfaces::internal_np;
  Clustering_settings s;
  s.width = parameter_or(np, TS_np::number_of_candidates, defaults::number_of_candidates);
  s.relative_threshold = parameter_or(np, TS_np::similarity_threshold, defaults::similarity_threshold);
  s.lambda = parameter_or(np, TS_np::flexibility_penalty, defaults::flexibility_penalty);
  s.mu = parameter_or(np, TS_np::structure_penalty, defaults::structure_penalty);
  s.use_kmeans = parameter_or(np, TS_np::use_kmeans_candidate, defaults::use_kmeans_candidate);
  s.auto_merge = parameter_or(np, TS_np::use_auto_merge, defaults::use_auto_merge);
  s.use_strips = parameter_or(np, TS_np::use_strip_candidates, defaults::use_strip_candidates);
  s.use_segments = parameter_or(np, TS_np::use_segment_candidates, defaults::use_segment_candidates);
  s.path = parameter_or(np, TS_np::clustering_path, defaults::clustering_path);
  s.exact_limit = parameter_or(np, TS_np::exact_clustering_limit, defaults::exact_clustering_limit);
  s.policy = parameter_or(np, TS_np::orientation_policy, defaults::orientation_policy);
  s.seed = parameter_or(np, CGAL::internal_np::random_seed, defaults::random_seed);
  s.separate_twists = !parameter_or(np, TS_np::planar_tiles, defaults::planar_tiles);
  s.panel_tolerance = panel_tolerance_of(np);
  return s;
}

// The stages of cluster_panels() on a checked mesh, in their order (the
// random draws of the splits, the k-means and the strips come in that order):
// threshold clustering, beam of merges, the other candidates, the choice, the
// S-quads and orientations of the chosen one. The candidates come from the
// generators registered in candidate_generators.h (Merge_generators, then
// Other_generators), each given the same Generator_context; the clusterer
// measures, scores and pools what they return. The faces are visited in the
// canonical order (canonical_face_order.h), and indexed by it, except in the
// candidate pool, which is by original face index; the returned orientations
// are by canonical index.
template <typename PolygonMesh, typename OriginalFaceIndexMap, typename VertexPointMap>
class Panel_clusterer
{
  typedef Canonical_face_index_map<OriginalFaceIndexMap> FaceIndexMap;
  typedef Generator_context<PolygonMesh, FaceIndexMap, VertexPointMap> Context;

public:
  Panel_clusterer(const PolygonMesh& pm, Canonical_faces<OriginalFaceIndexMap> faces, VertexPointMap vpm,
                 double mean_edge_length, std::size_t k, const Clustering_settings& settings)
    : m_pm(pm), m_faces(std::move(faces)), m_fim(m_faces.index_map()), m_vpm(vpm), m_quads(m_faces.quads)
    , m_n(m_quads.size()), m_k(k), m_length(mean_edge_length), m_settings(settings), m_random(settings.seed)
    , m_triangles(has_triangles(m_quads))
  {
    if(m_k < number_of_panel_kinds(m_quads))
      throw Invalid_input("number_of_tiles is 1, but the mesh has quads and triangles, which never share a "
                          "tile: at least 2 tiles are needed", Invalid_input::PARAMETER);
    m_descriptors.resize(m_n);
    for(std::size_t f = 0; f < m_n; ++f) m_descriptors[f] = shape_descriptor(m_quads[f]);
  }

  // Fills `result`; returns the S-quads and orientations of the chosen
  // candidate. `visitor.phase()` follows the stages.
  template <typename Visitor>
  Cluster_shapes run(Clustering_result& result, Visitor& visitor)
  {
    CGAL::Real_timer timer;
    timer.start();
    auto stage = [&](const char* name) {
      visitor.phase(name, timer.time());
      timer.reset();
    };
    initialize(result);
    stage("threshold clustering");
    m_visitor = Visitor_ref(visitor);
    const bool sweep_ends_search = make_exact_start_candidates(result);
    m_visitor = silent_visitor();
    stage("exact starts");
    if(!sweep_ends_search)
    {
      merge_to_tile_count(result);
      stage("merges");
      add_other_candidates(result);
      stage("other candidates");
    }
    Cluster_shapes shapes = select(result);
    stage("orientations");
    return shapes;
  }

  // 1. The path, and the threshold clustering split up to K clusters if it
  // has fewer, scored.
  void initialize(Clustering_result& result)
  {
    result.path = m_settings.path != AUTOMATIC_PATH ? m_settings.path
                : (m_n <= m_settings.exact_limit ? EXACT_PATH : DESCRIPTOR_PATH);
    m_exact = (result.path == EXACT_PATH);
    result.weights_are_exact = m_exact;
    if(m_exact)
      compute_affinity();
    threshold_clustering(result);
    score_initial_clustering();
  }

  // 2. The candidates solved first from their exact start
  // (Exact_start_generators: the sweeps, the multilevel start), made once,
  // pooled by select().
  // Whether one ends the search (Clustering_settings::sweep_ends_search):
  // run() then makes no other, since none would be optimized, and the beam
  // of merges costs O(K^2) a step (a 100k-quad grid at K = 4,000: 245 s)
  // and the other generators O(F) each (a 100k-quad roof: 44 s).
  bool make_exact_start_candidates(Clustering_result& result)
  {
    if(!m_exact_start_made)
      m_sweep_ends_search = !run_generators(Exact_start_generators(), result);
    m_exact_start_made = true;
    return m_sweep_ends_search;
  }

  // 3. The last beam of binary merges down to K (Merge_generators).
  void merge_to_tile_count(Clustering_result& result) { run_generators(Merge_generators(), result); }

  // 4. The twist separations of the candidates of step 2 (made here when
  // the stages are run one by one), then the other candidates
  // (Other_generators).
  void add_other_candidates(Clustering_result& result)
  {
    make_exact_start_candidates(result);
    for(const Generated_candidate& candidate : m_pooled_last)
      pool_twist_separation(result, candidate.label);
    run_generators(Other_generators(), result);
  }

  // 5. The candidates of step 2 pooled, then the candidate of lowest score,
  // its S-quads and orientations.
  Cluster_shapes select(Clustering_result& result)
  {
    for(const Generated_candidate& candidate : m_pooled_last)
      pool(result, candidate);
    m_pooled_last.clear();
    choose(result);
    return finish(result);
  }

private:
  // Runs the generators of the list in its order on one context, and
  // returns whether they all ran. A generator's candidates are pooled as it
  // returns them, each followed by its twist separation, except those
  // solved first from their exact start (origin_traits()), which are kept
  // for the end of run(); when one of its candidates with an exact start
  // ends the search, the generators after it are not run.
  template <typename... Generators>
  bool run_generators(Generator_list<Generators...>, Clustering_result& result)
  {
    const Context context = generator_context();
    return (true && ... && run_generator(Generators(), context, result));
  }

  // Runs `generator`; whether the generators after it are to run.
  template <typename Generator>
  bool run_generator(const Generator& generator, const Context& context, Clustering_result& result)
  {
    bool ends_search = false;
    for(Generated_candidate& candidate : generator(context))
    {
      ends_search = ends_search || (candidate.has_exact_start && m_settings.sweep_ends_search &&
                                    (candidate.start_is_exact || m_settings.sweep_ends_search(candidate.label)));
      if(origin_traits(candidate.origin).solved_first_from_start)
        m_pooled_last.push_back(std::move(candidate));
      else
      {
        pool_twist_separation(result, candidate.label);
        pool(result, candidate);
      }
    }
    return !ends_search;
  }

  // Pools the twist separation of `label` (twist_separation.h) when a
  // cluster of it mixes twists and planar panels are not asked for, up to
  // large_mesh_faces faces: above, a candidate solved from the input costs
  // 1 to 3 s per iteration, and the separation of every pooled candidate
  // would cost more than the solves it adds.
  void pool_twist_separation(Clustering_result& result, const std::vector<std::size_t>& label)
  {
    if(!m_settings.separate_twists || m_k <= 1 || m_n > large_mesh_faces)
      return;
    Generated_candidate separated;
    separated.origin = Clustering_candidate::TWIST_SEPARATED;
    separated.label = Twist_separation(m_quads, m_settings.policy)(label, m_k);
    if(!separated.label.empty())
      pool(result, separated);
  }

  Context generator_context()
  {
    return Context{{}, m_pm, m_fim, m_vpm, m_quads, m_descriptors, m_k, m_settings.policy, m_settings.seed,
                   m_random, m_settings, m_triangles, m_exact, m_affinity, m_init, m_initial_graph.get(), m_score,
                   m_visitor};
  }

  void compute_affinity()
  {
    m_affinity.assign(m_n * m_n, 0.0);
    parallel_for(m_n, [&](std::size_t p) {
      for(std::size_t q = p + 1; q < m_n; ++q)
        m_affinity[p * m_n + q] = fast_best_match(m_quads[p], m_quads[q], m_settings.policy).dissimilarity;
    });
    for(std::size_t p = 0; p < m_n; ++p)
      for(std::size_t q = p + 1; q < m_n; ++q)
        m_affinity[q * m_n + p] = m_affinity[p * m_n + q];
  }

  // Threshold clustering, split up to K clusters if it has fewer.
  void threshold_clustering(Clustering_result& result)
  {
    const Descriptor_index index(m_descriptors);
    const Orientation_policy policy = m_settings.policy;
    double tau = m_settings.relative_threshold * m_length;
    const std::size_t max_initial = m_exact ? m_n : (std::max)(tuning::descriptor_path_initial_clusters, 4 * m_k);
    while(!leader_clustering(m_quads, m_descriptors, index, tau, policy, max_initial, m_init))
      tau = tau > 0 ? 2 * tau : tuning::restart_threshold * m_length;
    // Too few clusters: a finer threshold first (symmetric meshes have groups of
    // congruent quads that no threshold separates; splits handle those).
    while(m_init.leaders.size() < m_k && tau > tuning::smallest_threshold * m_length)
    {
      tau /= 4;
      leader_clustering(m_quads, m_descriptors, index, tau, policy, m_n, m_init);
    }
    result.initial_threshold = tau;
    result.number_of_initial_clusters = m_init.leaders.size();
    split_to(m_k, m_quads, m_descriptors, policy, m_random, m_init);
  }

  // The score's references: the single cluster's weight and the DOF of the
  // threshold clustering.
  void score_initial_clustering()
  {
    m_initial_graph.reset(new Edge_sharing_graph<PolygonMesh>(
      edge_sharing_graph(m_pm, m_fim, m_vpm, m_init.cluster, m_init.orientation, m_init.leaders.size())));
    // One cluster per kind: a quad and a triangle are never compared.
    std::vector<std::size_t> by_kind(m_n, 0);
    const std::size_t kinds = m_triangles ? separate_kinds(m_quads, by_kind) : 1;
    m_score.single_cluster_weight = labelling_weight(by_kind, kinds);
    m_score.flexibility_penalty = m_settings.lambda;
    m_score.initial_dof = m_initial_graph->degree_of_flexibility();
    m_score.structure_penalty = m_settings.mu;
    m_score.total_length_deviation = total_length_deviation(m_pm, m_vpm);
  }

  // The weight of a whole labelling, in the units of the path.
  double labelling_weight(const std::vector<std::size_t>& label, std::size_t k) const
  {
    double w = 0;
    if(m_exact)
    {
      for(std::size_t p = 0; p < m_n; ++p)
        for(std::size_t q = p + 1; q < m_n; ++q)
          if(label[p] == label[q]) w += m_affinity[p * m_n + q];
      return w;
    }
    const Descriptor_merge_costs stats(m_descriptors, label, k);
    for(std::size_t c = 0; c < k; ++c) w += stats.initial_group(c).weight;
    return w;
  }

  // Measures `candidate` (unless its generator did) and pools it: its
  // weight in the units of the path, its DOF and length deviation with its
  // orientations, or each face's best match when it has none.
  void pool(Clustering_result& result, const Generated_candidate& candidate)
  {
    if(candidate.measured)
    {
      add_candidate(result, candidate.label, candidate.origin, candidate.weight,
                    candidate.degree_of_flexibility, candidate.length_deviation);
      return;
    }
    Cluster_shapes shapes;
    if(candidate.orientation.empty())
      shapes = cluster_shapes(m_quads, candidate.label, m_k, m_settings.policy);
    const std::vector<Panel_orientation>& orientation =
      candidate.orientation.empty() ? shapes.orientation : candidate.orientation;
    const Edge_sharing_graph<PolygonMesh> graph =
      edge_sharing_graph(m_pm, m_fim, m_vpm, candidate.label, orientation, m_k);
    add_candidate(result, candidate.label, candidate.origin, labelling_weight(candidate.label, m_k),
                  graph.degree_of_flexibility(), graph.length_deviation());
  }

  void add_candidate(Clustering_result& result, const std::vector<std::size_t>& label,
                     Clustering_candidate::Origin origin, double weight, std::size_t degree_of_flexibility,
                     double length_deviation)
  {
    Clustering_candidate cand;
    cand.origin = origin;
    std::vector<std::size_t> numbered = label;
    relabel_by_first_face(numbered);
    cand.face_cluster = by_original_index(numbered, m_faces.rank);
    cand.weight = weight;
    cand.degree_of_flexibility = degree_of_flexibility;
    cand.length_deviation = length_deviation;
    cand.score = m_score(cand.weight, cand.degree_of_flexibility, cand.length_deviation);
    result.candidates.push_back(cand);
  }

  // The lowest score among the candidates selectable by score wins (the
  // first on a tie); the reason states the score's three terms
  // (Configuration_score).
  void choose(Clustering_result& result) const
  {
    for(std::size_t i = 1; i < result.candidates.size(); ++i)
      if(origin_traits(result.candidates[i].origin).selectable_by_score &&
         result.candidates[i].score < result.candidates[result.chosen_candidate].score)
        result.chosen_candidate = i;
    const Clustering_candidate& chosen = result.candidates[result.chosen_candidate];
    const std::size_t d0 = m_score.initial_dof;
    result.choice_reason =
      std::string(origin_traits(chosen.origin).name) + " configuration with the lowest score " +
      std::to_string(chosen.score) + " = weight " + std::to_string(chosen.weight) + " / " +
      std::to_string(m_score.single_cluster_weight) + " + " + std::to_string(m_settings.lambda) + " x (" +
      std::to_string(d0) + " - DOF " + std::to_string(chosen.degree_of_flexibility) + ") / " +
      std::to_string(d0) + " + " + std::to_string(m_settings.mu) + " x length deviation " +
      std::to_string(chosen.length_deviation) + " / " + std::to_string(m_score.total_length_deviation) +
      ", among " + std::to_string(result.candidates.size()) + " candidates";
  }

  // S-quads, orientations, weights and DOF of the chosen configuration.
  Cluster_shapes finish(Clustering_result& result) const
  {
    const std::vector<std::size_t> label =
      by_canonical_index(result.candidates[result.chosen_candidate].face_cluster, m_faces.rank);
    Cluster_shapes shapes = finished_clustering(m_pm, m_fim, m_vpm, m_quads, label, m_k, m_settings.policy,
                                                m_settings.relative_threshold * m_length);
    describe_clustering(label, m_k, shapes, shapes.degree_of_flexibility, m_exact,
                        [&](std::size_t p, std::size_t q) { return m_affinity[p * m_n + q]; }, result);
    return shapes;
  }

  const PolygonMesh& m_pm;
  const Canonical_faces<OriginalFaceIndexMap> m_faces;
  FaceIndexMap m_fim;
  VertexPointMap m_vpm;
  const std::vector<Panel>& m_quads;  // m_faces.quads
  std::vector<Quad_descriptor> m_descriptors;
  const std::size_t m_n, m_k;
  const double m_length;
  const Clustering_settings m_settings;
  CGAL::Random m_random;
  const bool m_triangles;  // the mesh has triangles as well as quads (or only triangles)
  std::vector<Generated_candidate> m_pooled_last;  // solved first from their exact start: pooled after the others
  bool m_exact_start_made = false, m_sweep_ends_search = false;
  Visitor_ref m_visitor = silent_visitor();  // run()'s, while it makes the exact starts
  bool m_exact = true;
  std::vector<double> m_affinity;  // n x n dissimilarities, exact path only
  Initial_clustering m_init;
  std::unique_ptr<Edge_sharing_graph<PolygonMesh> > m_initial_graph;
  Configuration_score m_score;
};

// The `number_of_tiles` of `np`, checked against the `n` faces.
template <typename NamedParameters>
std::size_t tile_count(const NamedParameters& np, std::size_t n)
{
  const long long k = parameter_or(np, CGAL::Tilable_surfaces::internal_np::number_of_tiles, 0LL);
  if(k < 1)
    throw Invalid_input("number_of_tiles is " + std::to_string(k) + ", it must be at least 1",
                        Invalid_input::PARAMETER);
  if(std::size_t(k) > n)
    throw Invalid_input("number_of_tiles is " + std::to_string(k) + ", more than the " + std::to_string(n) +
                        " faces of the mesh", Invalid_input::PARAMETER);
  return std::size_t(k);
}

// cluster_panels() on a mesh validate_panel_mesh() accepted, whose face quads
// are `quads` (K_set_tilable_surface keeps them).
template <class PolygonMesh, typename NamedParameters>
Clustering_result cluster_panels(Validated_mesh, const PolygonMesh& pm, const NamedParameters& np,
                                const std::vector<Panel>& quads)
{
  using parameters::get_parameter;
  namespace TS_np = CGAL::Tilable_surfaces::internal_np;
  const std::size_t k = tile_count(np, num_faces(pm));
  const Clustering_settings settings = clustering_settings(np);

  const auto original_index = CGAL::get_initialized_face_index_map(pm, np);
  const auto vpm = internal::const_vertex_point_map(pm, np);
  const Canonical_faces<decltype(original_index)> canonical(pm, original_index, quads);
  Panel_clusterer<PolygonMesh, decltype(original_index), decltype(vpm)> clusterer(
    pm, canonical, vpm, mean_edge_length(pm, np), k, settings);
  Clustering_result result;
  auto&& visitor = visitor_of(np);
  const Cluster_shapes shapes = clusterer.run(result, visitor);
  const Face_clustering chosen{
    by_canonical_index(result.candidates[result.chosen_candidate].face_cluster, canonical.rank),
    shapes.orientation, k};
  write_face_clustering(pm, canonical.index_map(), chosen, get_parameter(np, TS_np::face_cluster),
                        get_parameter(np, TS_np::face_orientation));
  return result;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Clusters the faces of the quad mesh `pm` into exactly K clusters of
/// similar shape, computes each cluster's S-quad and tags each face with the
/// orientation of its S-quad instance (paper §3, §5).
///
/// <b>Method.</b>
/// -# <i>Threshold clustering</i>: faces are visited in the canonical order
///    (below); an
///    unassigned face leads a new cluster that takes every unassigned face q
///    with s(leader, q) < tau, tau = `similarity_threshold` x mean edge length
///    (candidates come from a kd-tree on the quad descriptors, an exact
///    prefilter). This gives N clusters. If N < K, tau is divided by 4 until
///    N >= K or tau < 1e-9 x mean edge length; then, if still N < K, the
///    largest clusters are split in two (2-means on descriptors, then exact
///    refinement) until N = K.
/// -# <i>Beam of binary merges</i> from N down to K clusters. Merge cost:
///    S(Ci u Cj) - S(Ci) - S(Cj), the sum of the cross dissimilarities
///    (exact path: from the affinity matrix; descriptor path: the same formula
///    with squared descriptor distances, in closed form from each cluster's
///    size, mean and scatter). From every configuration of the beam, every
///    pair of clusters is proposed while at most 128 remain (the paper's
///    exhaustive search; proposals whose score cannot enter the beam are cut
///    early), and above that each cluster proposes its merge with its
///    cheapest partner (and, with
///    `use_auto_merge`, every pair of clusters whose S-quad edges lie in the
///    same 4 components of the edge-sharing graph, which keeps the degree of
///    flexibility). Each proposal gets the score
///    score = W / W1 + flexibility_penalty x (D0 - D) / D0 + structure_penalty x V / V1,
///    with W the configuration's weight, W1 the weight of the single-cluster
///    configuration (one cluster per panel kind on a mesh with triangles), D
///    its degree of flexibility (a copy of the parent's `Edge_sharing_graph`
///    amended by `merge_clusters()`), D0 that of the threshold clustering
///    (at least 1 in the division), V its length deviation
///    (`Edge_sharing_graph::length_deviation()`: the spread of the input's
///    edge lengths within the components of the edge-sharing graph) and V1
///    the spread of all the mesh's edge lengths. The `number_of_candidates`
///    best distinct proposals form the beam of the next K.
/// -# <i>Final choice</i>: the pool is the last beam plus the candidates of
///    the other generators (user manual, section Candidate generators): with
///    `use_kmeans_candidate`, a k-means configuration (k-means++ seeded by
///    `random_seed`, on the 7 descriptor components), with
///    `use_strip_candidates` the quad-strip clusterings, and with
///    `use_segment_candidates`, on a mesh whose quads form a grid, the
///    segment clusterings (runs of rows, each a segment of column molds or a
///    band of one mold, chosen by dynamic programming; see the user manual)
///    and, last, the sweep clusterings. Every candidate gets the score above,
///    its D and V measured with each face oriented by its best match (the
///    k-means one: on its cluster's face nearest to the mean descriptor; the
///    beam's: as the beam tracked them). The candidate with the lowest score
///    among those selectable by score (all but the sweeps) is returned (on a
///    tie, the first in the pool); `Clustering_result::choice_reason` states
///    its three terms.
/// -# <i>S-quads and orientations</i>: each cluster's S-quad is the Procrustes
///    mean of its instances. Each face is tagged with an <i>admissible</i>
///    orientation: a near-tie, whose dissimilarity to its S-quad exceeds the
///    best one (`best_match()`) by at most tau. Among those, the tagging maximises the degree of
///    flexibility (cluster weights do not depend on orientations): a local
///    search re-tags one face at a time, keeping changes that raise the DOF,
///    or else lower the number of mesh edges linking two different S-quad
///    edges, or else lower the face's dissimilarity; it starts from the best
///    orientations and from orientations propagated across each cluster (the
///    neighbour turned over the shared edge, or translated across it), and
///    the best result is kept. Symmetric quads benefit most: a grid of equal
///    rectangles at K = 1 gets DOF 4 instead of 2.
///
/// <b>Canonical face order.</b> Every step visits the faces, and breaks ties,
/// in an order taken from the surface rather than from the face indices: a
/// breadth-first search over edge-adjacent faces, each face's neighbours taken
/// in the order of its edges from `halfedge(f, pm)`, started at the face
/// farthest from the centroid of the face centroids (near ties, within a
/// relative 1e-9, go to the larger face), and restarted the same way on each
/// further component. Renumbering the faces (each keeping its `halfedge()`)
/// therefore gives the same clustering renumbered, and a similarity of the
/// input the same clustering; only an exactly symmetric surface, whose start
/// faces tie, falls back on the face indices.
///
/// Clusters are numbered 0..K-1 by their first face in the canonical order.
/// The result is deterministic for a given `random_seed`, whatever the number of
/// threads: parallel loops (TBB, when CGAL is linked with it) only fill
/// independent slots.
///
/// \tparam PolygonMesh a model of `FaceListGraph` with quad faces.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{number_of_tiles} K, required, in 1..num_faces(pm). \cgalParamNEnd
///   \cgalParamNBegin{face_cluster_map} output, required: a writable property map
///     from faces to an integral type, filled with 0..K-1. \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} output, required: a writable property
///     map from faces to an integral type or `Panel_orientation`, filled with 0..7. \cgalParamNEnd
///   \cgalParamNBegin{number_of_candidates} beam width; default 10. \cgalParamNEnd
///   \cgalParamNBegin{similarity_threshold} initial clustering threshold, relative to
///     the mean edge length; default 0.01 (the 4 corners of two quads deviate
///     by 0.25% of an edge on average). \cgalParamNEnd
///   \cgalParamNBegin{flexibility_penalty} weight lambda of the lost degrees of
///     flexibility in the score; default 0.5. 0 reproduces the paper's pure weight
///     criterion. \cgalParamNEnd
///   \cgalParamNBegin{structure_penalty} weight mu of the length deviation in the
///     score; default 1. \cgalParamNEnd
///   \cgalParamNBegin{use_kmeans_candidate} default `true`. \cgalParamNEnd
///   \cgalParamNBegin{use_auto_merge} default `true`. \cgalParamNEnd
///   \cgalParamNBegin{use_strip_candidates} default `true`. \cgalParamNEnd
///   \cgalParamNBegin{use_segment_candidates} default `true`. \cgalParamNEnd
///   \cgalParamNBegin{clustering_path} a `Clustering_path`; default `AUTOMATIC_PATH`. \cgalParamNEnd
///   \cgalParamNBegin{exact_clustering_limit} largest face count for the exact
///     path with `AUTOMATIC_PATH`; default 1500. \cgalParamNEnd
///   \cgalParamNBegin{orientation_policy} an `Orientation_policy`; default
///     `PROPER_RIGID_MOTIONS`. \cgalParamNEnd
///   \cgalParamNBegin{random_seed} seed of the k-means and of splits; default 0. \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of the vertices. \cgalParamNEnd
///   \cgalParamNBegin{face_index_map} indices 0..n-1 of the faces. \cgalParamNEnd
///   \cgalParamNBegin{visitor} a `Default_visitor`, whose `phase()` follows the
///     stages. \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if K < 1, K > num_faces(pm), `pm` fails
/// `validate_panel_mesh()`, or K = 1 on a mesh with quads and triangles; the
/// maps are not modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Clustering_result cluster_panels(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  namespace TS_np = CGAL::Tilable_surfaces::internal_np;
  static_assert(!parameters::is_default_parameter<CGAL_NP_CLASS, TS_np::number_of_tiles_t>::value,
                "cluster_panels(): the named parameter number_of_tiles is required");
  internal::require_face_maps<CGAL_NP_CLASS>();
  validate_panel_mesh(pm, np);
  const auto cnp = internal::canonical_parameters(np);
  return internal::cluster_panels(internal::Validated_mesh(true), pm, cnp,
                                 internal::face_quads(pm, CGAL::get_initialized_face_index_map(pm, cnp), cnp));
}

#ifndef CGAL_NO_DEPRECATED_CODE
/// \ingroup PkgTilableSurfacesRef
/// \deprecated The name of `cluster_panels()` until 1.0.0 (it clusters triangles too).
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
CGAL_DEPRECATED_MSG("use cluster_panels()")
Clustering_result cluster_quads(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  return cluster_panels(pm, np);
}
#endif

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_CLUSTER_PANELS_H
