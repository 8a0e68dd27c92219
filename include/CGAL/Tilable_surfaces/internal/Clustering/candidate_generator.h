// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H

// The types of the concept CandidateGenerator
// (doc/Tilable_surfaces/Concepts/CandidateGenerator.h): the context a
// generator reads, the candidates it returns, and the per-origin traits that
// say what the pipeline does with them. The origins, their traits and the
// list of generators the clusterer runs are in candidate_generators.h,
// included at the end of this file, so that adding a generator touches its
// own header, that registration and its documentation only.
//
// A model is a class with a const member template
//   template <typename Context>
//   std::vector<typename Context::Candidate> operator()(const Context& context) const;
// It needs no include of this file: it reads the context's members and names
// its origin through the context (`Context::KMEANS`), which derives from
// `Candidate_origins`.

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/beam_search.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>

#include <CGAL/Random.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Holds `Clustering_candidate::Origin`, the generator a candidate comes
/// from; its values are listed, each with its traits, in
/// internal/Clustering/candidate_generators.h.
struct Candidate_origins
{
  enum Origin : int;
};

namespace internal {

// What the pipeline does with the candidates of one origin (one generator).
struct Candidate_origin_traits
{
  const char* name;               // as in the choice strings and reports: "hierarchical", "k-means",
                                  // "quad-strip", "grid-segment", "sweep", "patch-segment"
  bool selectable_by_score;       // may be cluster_panels()'s chosen candidate (false for sweeps)
  bool solved_first_from_start;   // the fidelity search solves it first, from the exact start its
                                  // generator made, and does not rank it (the sweeps, the multilevel start)
  std::size_t extra_quota_divisor;// after the ranked candidates, ceil(optimized / divisor) more of this
                                  // origin are optimized, in pool order (4 for grid segments; 0: none)
  bool ranked;                    // competes for the places of the ranking; if not, it is optimized
                                  // through its extra quota only, beside the candidates of the others
};

// The traits of the candidates of `origin` (defined in candidate_generators.h).
inline const Candidate_origin_traits& origin_traits(Candidate_origins::Origin origin);

// One candidate as a generator returns it. The clusterer measures it (weight,
// DOF, length deviation), scores it and pools it.
struct Generated_candidate
{
  Candidate_origins::Origin origin;
  // The cluster of every face by canonical index, 0..K-1.
  std::vector<std::size_t> label;
  // The orientation of every face the DOF and length deviation are measured
  // with; empty: each face's best match on its cluster's S-quad
  // (cluster_shapes()).
  std::vector<Panel_orientation> orientation;
  // Set by a generator that tracks the measures itself (the beam keeps an
  // edge-sharing graph and a weight per configuration): used as they are.
  bool measured = false;
  double weight = 0;
  std::size_t degree_of_flexibility = 0;
  double length_deviation = 0;
  // The clustering is exact at positions that sweep_start() builds from the
  // input (the sweeps). The search builds them when it solves the candidate:
  // they cost O(V) per candidate, and only K_set_tilable_surface has the
  // vertex indices.
  bool has_exact_start = false;
  // The generator built the exact start and checked it (the multilevel start).
  bool start_is_exact = false;
};

// The multilevel candidate at K clusters, if its start is exact
// (multilevel_start_hook()); the coarse solve reports its iterations to the visitor.
typedef std::function<std::optional<Generated_candidate>(std::size_t k, Visitor_ref visitor)> Multilevel_start_hook;

// What cluster_panels() reads from its named parameters, besides K and the maps.
struct Clustering_settings
{
  std::size_t width;          // number_of_candidates
  double relative_threshold;  // similarity_threshold
  double lambda, mu;          // flexibility_penalty, structure_penalty
  bool use_kmeans, auto_merge, use_strips, use_segments;
  bool separate_twists;       // not with planar_tiles: twist-separated variants join the pool
  Clustering_path path;
  std::size_t exact_limit;
  Orientation_policy policy;
  unsigned int seed;
  double panel_tolerance = 0; // panel_tolerance, model units; 0: exact mode
  // Set by K_set_tilable_surface::cluster() when an exact start would end
  // its search (above large_mesh_faces, no other candidate to optimize):
  // whether the sweep clustering (by canonical index) has an exact start.
  // If one has, the generators after it are not run.
  std::function<bool(const std::vector<std::size_t>&)> sweep_ends_search;
  // Set by K_set_tilable_surface::cluster() on a mesh the multilevel start
  // applies to (multilevel_start.h): the candidate it makes at K, reporting
  // the coarse solve's iterations to the visitor, if that start is exact.
  Multilevel_start_hook multilevel_start;
};

// Everything a generator reads. Faces are indexed by the canonical order
// (canonical_face_order.h); the random generator is shared, so the
// generators draw in the order of the registration list. Members that only
// the beam of merges reads (the threshold clustering and the score's
// references) are set from the end of Panel_clusterer::initialize() on.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
struct Generator_context : Candidate_origins
{
  typedef Generated_candidate Candidate;

  const PolygonMesh& mesh;
  FaceIndexMap face_index;
  VertexPointMap vertex_point;
  const std::vector<Panel>& panels;              // the face panels (quads or triangles)
  const std::vector<Quad_descriptor>& descriptors;
  std::size_t k;                                 // the number of clusters of every candidate
  Orientation_policy policy;
  unsigned int seed;                             // for generators with a random generator of their own
  CGAL::Random& random;
  const Clustering_settings& settings;
  bool has_triangles;                            // the mesh has triangles as well as quads (or only triangles)
  bool exact;                                    // the exact path: `affinity` holds the n x n dissimilarities
  const std::vector<double>& affinity;
  const Initial_clustering& initial;             // the threshold clustering, split to at least K
  const Edge_sharing_graph<PolygonMesh>* initial_graph;
  const Configuration_score& score;
  Visitor_ref visitor;                           // the clustering's caller's, or one that does nothing
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generators.h>

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H
