// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_CLUSTER_QUADS_H
#define CGAL_TILABLE_SURFACES_CLUSTER_QUADS_H

/// \file cluster_quads.h
/// Clustering of the quads of a mesh into K S-quads (paper §3 and §5,
/// method notes §2).

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/beam_search.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/flexible_orientations.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// How `cluster_quads()` evaluates the weights of clusters.
enum Clustering_path
{
  /// `EXACT_PATH` for meshes with at most `exact_clustering_limit` faces,
  /// `DESCRIPTOR_PATH` above.
  AUTOMATIC_PATH = 0,
  /// The paper's method: the n x n affinity matrix of dissimilarities;
  /// O(n^2) time and memory, exact weights.
  EXACT_PATH,
  /// Scalable: dissimilarities only between quads whose descriptors are
  /// close (kd-tree), merge costs from descriptor statistics; linear memory.
  DESCRIPTOR_PATH
};

/// \ingroup PkgTilableSurfacesRef
/// One configuration of the final candidate pool of `cluster_quads()`.
struct Clustering_candidate
{
  /// Where the configuration comes from.
  enum Origin { HIERARCHICAL, KMEANS, QUAD_STRIPS, GRID_SEGMENTS };
  Origin origin = HIERARCHICAL;  ///< the search that produced it
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
  /// The selection score (lower is better); see `cluster_quads()`.
  double score = 0;
  /// Its predicted displacement (`Displacement_prediction::max`) once
  /// `K_set_tilable_surface::optimize_closest()` ranked it; else 0.
  double predicted_displacement = 0;
  /// The cluster of every face (by face index), 0..K-1 numbered by first
  /// face; `K_set_tilable_surface` optimizes the most promising candidates.
  std::vector<std::size_t> face_cluster;
};

/// \ingroup PkgTilableSurfacesRef
/// What `cluster_quads()` found, besides the two face maps it fills.
struct Clustering_result
{
  /// The path that was used: `EXACT_PATH` or `DESCRIPTOR_PATH`.
  Clustering_path path = EXACT_PATH;
  /// The number of faces of each cluster (none is empty).
  std::vector<std::size_t> cluster_sizes;
  /// The S-quad of each cluster: the mean shape of its instances, each brought
  /// by its best match onto the current mean (3 Procrustes iterations),
  /// centred at the origin. Face orientations refer to its corner labels.
  std::vector<Quad> s_quads;
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
  /// `cluster_quads()`): the number of components of its edge-sharing graph.
  std::size_t degree_of_flexibility = 0;
  /// The number N of clusters of the threshold clustering.
  std::size_t number_of_initial_clusters = 0;
  /// The absolute threshold that produced them (the descriptor path doubles
  /// the threshold until N is at most max(1000, 4K)).
  double initial_threshold = 0;
  /// The final candidate pool: the beam, best score first, then the k-means
  /// configuration if it was asked for and has K non-empty clusters.
  std::vector<Clustering_candidate> candidates;
  /// Index in `candidates` of the returned configuration.
  std::size_t chosen_candidate = 0;
  /// Why it was chosen, in words.
  std::string choice_reason;
};

namespace internal {

template <typename Map>
void put_orientation(Map map, typename boost::property_traits<Map>::key_type f,
                     Quad_orientation o)
{
  put(map, f, typename boost::property_traits<Map>::value_type(o.index()));
}

// The corners of every face, indexed by `fim`.
template <typename PolygonMesh, typename FaceIndexMap, typename NP>
std::vector<Quad> face_quads(const PolygonMesh& pm, FaceIndexMap fim, const NP& np)
{
  std::vector<Quad> quads(num_faces(pm));
  for(auto f : faces(pm))
    quads[get(fim, f)] = face_quad(f, pm, Quad_orientation(), np);
  return quads;
}

// The S-quads of labelling `label` (Procrustes means of the quads of `pm`),
// each face tagged with an admissible orientation chosen for flexibility
// (flexible_orientations(), near-ties within `tau`), and the resulting DOF.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Cluster_shapes finished_clustering(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                                   const std::vector<Quad>& quads, const std::vector<std::size_t>& label,
                                   std::size_t k, Orientation_policy policy, double tau)
{
  Cluster_shapes shapes = cluster_shapes(quads, label, k, policy);
  shapes.orientation =
    flexible_orientations(pm, fim, quads, label, shapes.s_quads, shapes.orientation, policy, tau);
  shapes.degree_of_flexibility =
    edge_sharing_graph(pm, fim, vpm, label, shapes.orientation, k).degree_of_flexibility();
  return shapes;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Clusters the faces of the quad mesh `pm` into exactly K clusters of
/// similar shape, computes each cluster's S-quad and tags each face with the
/// orientation of its S-quad instance (paper §3, §5).
///
/// <b>Method.</b>
/// -# <i>Threshold clustering</i>: faces are visited in index order; an
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
///    <center>score = W / W1 + flexibility_penalty x (D0 - D) / D0</center>
///    with W the configuration's weight, W1 the weight of the single-cluster
///    configuration, D its degree of flexibility (a copy of the parent's
///    `Edge_sharing_graph` amended by `merge_clusters()`) and D0 that of the
///    threshold clustering. The `number_of_candidates` best distinct proposals
///    form the beam of the next K.
/// -# <i>Final choice</i>: the pool is the last beam plus, with
///    `use_kmeans_candidate`, a k-means configuration (k-means++ seeded by
///    `random_seed`, on the 7 descriptor components), with
///    `use_strip_candidates` the quad-strip clusterings, and with
///    `use_segment_candidates`, on a mesh whose quads form a grid, the
///    segment clusterings (runs of rows, each a segment of column molds or a
///    band of one mold, chosen by dynamic programming; see the user manual);
///    the configuration with the lowest score is returned (on a tie, the
///    first in the pool).
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
/// Clusters are numbered 0..K-1 by their first face in face-index order.
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
///     map from faces to an integral type or `Quad_orientation`, filled with 0..7. \cgalParamNEnd
///   \cgalParamNBegin{number_of_candidates} beam width; default 10. \cgalParamNEnd
///   \cgalParamNBegin{similarity_threshold} initial clustering threshold, relative to
///     the mean edge length; default 0.01 (the 4 corners of two quads deviate
///     by 0.25% of an edge on average). \cgalParamNEnd
///   \cgalParamNBegin{flexibility_penalty} weight lambda of the lost degrees of
///     flexibility in the score; default 0.5. 0 reproduces the paper's pure weight
///     criterion. \cgalParamNEnd
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
///   \cgalParamNBegin{verbose} progress on `std::cerr`; default `false`. \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if K < 1, K > num_faces(pm), or `pm` fails
/// `validate_quad_mesh()`; the maps are not modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Clustering_result cluster_quads(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  namespace TS_np = CGAL::Tilable_surfaces::internal_np;

  static_assert(!is_default_parameter<CGAL_NP_CLASS, TS_np::number_of_tiles_t>::value,
                "cluster_quads(): the named parameter number_of_tiles is required");
  static_assert(!is_default_parameter<CGAL_NP_CLASS, TS_np::face_cluster_t>::value,
                "cluster_quads(): the named parameter face_cluster_map is required");
  static_assert(!is_default_parameter<CGAL_NP_CLASS, TS_np::face_orientation_t>::value,
                "cluster_quads(): the named parameter face_orientation_map is required");

  const long long requested_k = static_cast<long long>(get_parameter(np, TS_np::number_of_tiles));
  const auto cluster_map = get_parameter(np, TS_np::face_cluster);
  const auto orientation_map = get_parameter(np, TS_np::face_orientation);
  typedef typename boost::property_traits<
    typename std::remove_const<decltype(cluster_map)>::type>::value_type Cluster_id;
  const std::size_t width = choose_parameter(get_parameter(np, TS_np::number_of_candidates), 10);
  const double relative_threshold =
    choose_parameter(get_parameter(np, TS_np::similarity_threshold), 0.01);
  const double lambda = choose_parameter(get_parameter(np, TS_np::flexibility_penalty), 0.5);
  const double mu = choose_parameter(get_parameter(np, TS_np::structure_penalty), 1.0);
  const bool use_kmeans = choose_parameter(get_parameter(np, TS_np::use_kmeans_candidate), true);
  const bool auto_merge = choose_parameter(get_parameter(np, TS_np::use_auto_merge), true);
  const bool use_strips = choose_parameter(get_parameter(np, TS_np::use_strip_candidates), true);
  const bool use_segments = choose_parameter(get_parameter(np, TS_np::use_segment_candidates), true);
  const Clustering_path requested_path =
    choose_parameter(get_parameter(np, TS_np::clustering_path), AUTOMATIC_PATH);
  const std::size_t exact_limit =
    choose_parameter(get_parameter(np, TS_np::exact_clustering_limit), 1500);
  const Orientation_policy policy =
    choose_parameter(get_parameter(np, TS_np::orientation_policy), PROPER_RIGID_MOTIONS);
  const unsigned int seed = choose_parameter(get_parameter(np, CGAL::internal_np::random_seed), 0u);
  const bool verbose = choose_parameter(get_parameter(np, CGAL::internal_np::verbose), false);

  if(requested_k < 1)
    throw Invalid_input("number_of_tiles is " + std::to_string(requested_k) +
                        ", it must be at least 1", Invalid_input::PARAMETER);
  validate_quad_mesh(pm, np);
  const std::size_t n = num_faces(pm);
  const std::size_t k = std::size_t(requested_k);
  if(k > n)
    throw Invalid_input("number_of_tiles is " + std::to_string(k) + ", more than the " +
                        std::to_string(n) + " faces of the mesh", Invalid_input::PARAMETER);

  const auto fim = CGAL::get_initialized_face_index_map(pm, np);
  const std::vector<Quad> quads = internal::face_quads(pm, fim, np);
  std::vector<Quad_descriptor> descriptors(n);
  for(std::size_t f = 0; f < n; ++f) descriptors[f] = shape_descriptor(quads[f]);
  const double length = mean_edge_length(pm, np);
  CGAL::Random random(seed);

  Clustering_result result;
  result.path = requested_path != AUTOMATIC_PATH ? requested_path
              : (n <= exact_limit ? EXACT_PATH : DESCRIPTOR_PATH);
  const bool exact = (result.path == EXACT_PATH);
  result.weights_are_exact = exact;

  // Affinity matrix (exact path only).
  std::vector<double> affinity;
  if(exact)
  {
    affinity.assign(n * n, 0.0);
    internal::parallel_for(n, [&](std::size_t p) {
      for(std::size_t q = p + 1; q < n; ++q)
        affinity[p * n + q] = internal::fast_best_match(quads[p], quads[q], policy).dissimilarity;
    });
    for(std::size_t p = 0; p < n; ++p)
      for(std::size_t q = p + 1; q < n; ++q)
        affinity[q * n + p] = affinity[p * n + q];
  }

  // 1. Threshold clustering.
  const internal::Descriptor_index index(descriptors);
  internal::Initial_clustering init;
  double tau = relative_threshold * length;
  const std::size_t max_initial = exact ? n : (std::max)(std::size_t(1000), 4 * k);
  while(!internal::leader_clustering(quads, descriptors, index, tau, policy, max_initial, init))
    tau = tau > 0 ? 2 * tau : 1e-3 * length;
  // Too few clusters: a finer threshold first (symmetric meshes have groups of
  // congruent quads that no threshold separates; splits handle those).
  while(init.leaders.size() < k && tau > 1e-9 * length)
  {
    tau /= 4;
    internal::leader_clustering(quads, descriptors, index, tau, policy, n, init);
  }
  result.initial_threshold = tau;
  result.number_of_initial_clusters = init.leaders.size();
  internal::split_to(k, quads, descriptors, policy, random, init);
  const std::size_t big_n = init.leaders.size();
  if(verbose)
    std::cerr << "cluster_quads: " << n << " faces, " << (exact ? "exact" : "descriptor")
              << " path, " << result.number_of_initial_clusters << " initial clusters (tau = "
              << tau << ")" << std::endl;

  std::vector<std::size_t> faces_per_cluster(big_n, 0);
  for(std::size_t c : init.cluster) ++faces_per_cluster[c];
  std::vector<Quad> leaders(big_n);
  for(std::size_t c = 0; c < big_n; ++c) leaders[c] = quads[init.leaders[c]];
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, pm));
  const Edge_sharing_graph<PolygonMesh> initial_graph =
    internal::edge_sharing_graph(pm, fim, vpm, init.cluster, init.orientation, big_n);
  const std::size_t d0 = initial_graph.degree_of_flexibility();

  // Weights of whole labellings, in the units of the path.
  // (The final pool's labellings are kept in the candidates.)
  auto labelling_weight = [&](const std::vector<std::size_t>& label, std::size_t kk) {
    double w = 0;
    if(exact)
    {
      for(std::size_t p = 0; p < n; ++p)
        for(std::size_t q = p + 1; q < n; ++q)
          if(label[p] == label[q]) w += affinity[p * n + q];
      return w;
    }
    const internal::Descriptor_merge_costs stats(descriptors, label, kk);
    for(std::size_t c = 0; c < kk; ++c) w += stats.initial_group(c).weight;
    return w;
  };
  internal::Configuration_score score;
  score.single_cluster_weight = labelling_weight(std::vector<std::size_t>(n, 0), 1);
  score.flexibility_penalty = lambda;
  score.initial_dof = d0;
  score.structure_penalty = mu;
  score.total_length_deviation = internal::total_length_deviation(pm, vpm);
  const double w1 = score.single_cluster_weight;

  // 2. Beam of merges.
  auto collect = [&](const auto& beam_search, const auto& initial_state) {
    for(const auto& s : beam_search.run(initial_state, k))
    {
      std::vector<std::size_t> group_of(big_n);
      for(std::size_t g = 0; g < s.members.size(); ++g)
        for(std::size_t c : s.members[g]) group_of[c] = g;
      std::vector<std::size_t> label(n);
      for(std::size_t f = 0; f < n; ++f) label[f] = group_of[init.cluster[f]];
      internal::relabel_by_first_face(label);
      Clustering_candidate cand;
      cand.face_cluster = label;
      cand.weight = s.weight;
      cand.degree_of_flexibility = s.graph.degree_of_flexibility();
      cand.length_deviation = s.graph.length_deviation();
      cand.score = score(s.weight, cand.degree_of_flexibility, cand.length_deviation);
      result.candidates.push_back(cand);
    }
  };
  if(exact)
  {
    const internal::Exact_merge_costs costs(affinity, init.cluster, big_n);
    const internal::Beam_search<PolygonMesh, internal::Exact_merge_costs> beam(
      costs, leaders, policy, score, width, auto_merge, verbose);
    collect(beam, beam.initial_state(initial_graph, faces_per_cluster));
  }
  else
  {
    const internal::Descriptor_merge_costs costs(descriptors, init.cluster, big_n);
    const internal::Beam_search<PolygonMesh, internal::Descriptor_merge_costs> beam(
      costs, leaders, policy, score, width, auto_merge, verbose);
    collect(beam, beam.initial_state(initial_graph, faces_per_cluster));
  }

  // 3. The k-means configuration, oriented on the face nearest to each centre.
  if(use_kmeans && k > 1)
  {
    std::vector<std::size_t> all(n);
    for(std::size_t f = 0; f < n; ++f) all[f] = f;
    std::vector<std::size_t> label = internal::kmeans(descriptors, all, k, random);
    if(!label.empty())
    {
      internal::relabel_by_first_face(label);
      const internal::Descriptor_merge_costs stats(descriptors, label, k);
      std::vector<std::size_t> representative(k, internal::no_index());
      std::vector<double> best(k, 0.0);
      for(std::size_t f = 0; f < n; ++f)
      {
        Quad_descriptor centre = stats.initial_group(label[f]).mean;
        const double d = internal::squared_distance(descriptors[f], centre);
        if(representative[label[f]] == internal::no_index() || d < best[label[f]])
        {
          representative[label[f]] = f;
          best[label[f]] = d;
        }
      }
      std::vector<Quad_orientation> orientation(n);
      internal::parallel_for(n, [&](std::size_t f) {
        orientation[f] =
          internal::fast_best_match(quads[representative[label[f]]], quads[f], policy).orientation;
      });
      Clustering_candidate cand;
      cand.origin = Clustering_candidate::KMEANS;
      cand.weight = labelling_weight(label, k);
      const Edge_sharing_graph<PolygonMesh> graph =
        internal::edge_sharing_graph(pm, fim, vpm, label, orientation, k);
      cand.degree_of_flexibility = graph.degree_of_flexibility();
      cand.length_deviation = graph.length_deviation();
      cand.score = score(cand.weight, cand.degree_of_flexibility, cand.length_deviation);
      cand.face_cluster = label;
      result.candidates.push_back(cand);
    }
  }

  // 3b. Clusterings that follow the quad strips, and segment clusterings of
  // quad grids, oriented by best match.
  auto add_candidate = [&](const std::vector<std::size_t>& label, Clustering_candidate::Origin origin) {
    const internal::Cluster_shapes shapes = internal::cluster_shapes(quads, label, k, policy);
    const Edge_sharing_graph<PolygonMesh> graph =
      internal::edge_sharing_graph(pm, fim, vpm, label, shapes.orientation, k);
    Clustering_candidate cand;
    cand.origin = origin;
    cand.weight = labelling_weight(label, k);
    cand.degree_of_flexibility = graph.degree_of_flexibility();
    cand.length_deviation = graph.length_deviation();
    cand.score = score(cand.weight, cand.degree_of_flexibility, cand.length_deviation);
    cand.face_cluster = label;
    result.candidates.push_back(cand);
  };
  if(use_strips && k > 1)
    for(const std::vector<std::size_t>& label :
          internal::strip_clusterings(pm, fim, vpm, quads, descriptors, k, policy, random))
      add_candidate(label, Clustering_candidate::QUAD_STRIPS);
  if(use_segments && k > 1)
    for(const std::vector<std::size_t>& label : internal::segment_clusterings(pm, fim, vpm, k, policy))
      add_candidate(label, Clustering_candidate::GRID_SEGMENTS);

  // 4. The lowest score wins.
  for(std::size_t i = 1; i < result.candidates.size(); ++i)
    if(result.candidates[i].score < result.candidates[result.chosen_candidate].score)
      result.chosen_candidate = i;
  const Clustering_candidate& chosen = result.candidates[result.chosen_candidate];
  result.choice_reason =
    std::string(chosen.origin == Clustering_candidate::KMEANS ? "k-means"
                : chosen.origin == Clustering_candidate::QUAD_STRIPS ? "quad-strip"
                : chosen.origin == Clustering_candidate::GRID_SEGMENTS ? "grid-segment" : "hierarchical") +
    " configuration with the lowest score " + std::to_string(chosen.score) + " = weight " +
    std::to_string(chosen.weight) + " / " + std::to_string(w1) + " + " + std::to_string(lambda) +
    " x (" + std::to_string(d0) + " - DOF " + std::to_string(chosen.degree_of_flexibility) +
    ") / " + std::to_string(d0) + ", among " + std::to_string(result.candidates.size()) +
    " candidates";

  // 5. S-quads, orientations, weights, degree of flexibility.
  const std::vector<std::size_t>& label = chosen.face_cluster;
  internal::Cluster_shapes shapes =
    internal::finished_clustering(pm, fim, vpm, quads, label, k, policy, relative_threshold * length);
  result.s_quads = shapes.s_quads;
  result.degree_of_flexibility = shapes.degree_of_flexibility;
  result.cluster_sizes.assign(k, 0);
  result.cluster_weights.assign(k, 0.0);
  for(std::size_t f = 0; f < n; ++f) ++result.cluster_sizes[label[f]];
  if(exact)
  {
    for(std::size_t p = 0; p < n; ++p)
      for(std::size_t q = p + 1; q < n; ++q)
        if(label[p] == label[q]) result.cluster_weights[label[p]] += affinity[p * n + q];
  }
  else
  {
    for(std::size_t f = 0; f < n; ++f) result.cluster_weights[label[f]] += shapes.distance[f];
    for(std::size_t c = 0; c < k; ++c)
      result.cluster_weights[c] *= double(result.cluster_sizes[c] - 1);
  }
  for(double w : result.cluster_weights) result.total_weight += w;

  for(auto f : faces(pm))
  {
    const std::size_t i = get(fim, f);
    put(cluster_map, f, Cluster_id(label[i]));
    internal::put_orientation(orientation_map, f, shapes.orientation[i]);
  }
  if(verbose)
    std::cerr << "cluster_quads: " << result.choice_reason << "; DOF "
              << result.degree_of_flexibility << std::endl;
  return result;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_CLUSTER_QUADS_H
