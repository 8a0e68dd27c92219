/*!
\ingroup PkgTilableSurfacesConcepts
\cgalConcept

The concept `CandidateGenerator` describes a source of candidate clusterings
for the pool of `Tilable_surfaces::cluster_panels()` and of
`Tilable_surfaces::K_set_tilable_surface` (user manual, section
\ref TS_Candidate_generators).

A generator is run once per clustering, on one context, and returns its
candidates; the clusterer measures each one (weight, degree of flexibility,
length deviation), scores it and pools it, in the order of the registration
list (internal/Clustering/candidate_generators.h). What the pipeline does
with the candidates of an origin (whether the score may choose them, whether
the fidelity search solves them first from their exact start, how many more
of them it optimizes) comes from that origin's `Candidate_origin_traits`, not
from the generator.

<b>The context</b> (`Context`, a `Generator_context`) holds, with the faces
indexed in the canonical face order:
- `mesh`, `face_index`, `vertex_point`: the mesh and its maps;
- `panels`, `descriptors`: the face panels and their shape descriptors;
- `k`: the number of clusters of every candidate;
- `policy`: the `Orientation_policy`;
- `seed` and `random`: the `random_seed`, and the random generator shared by
  the generators, which draw from it in the order of the list;
- `settings`: the clusterer's settings (the named parameters that switch
  generators on, the beam width, the callback that says when a candidate
  with an exact start ends the search, the multilevel start's hook);
- `visitor`: the visitor of the clustering's caller while the exact starts
  are made (the multilevel start's coarse solve reports its iterations to
  it), else one that does nothing;
- `has_triangles`, and for the beam the threshold clustering (`initial`,
  `initial_graph`), the score's references (`score`) and, on the exact path
  (`exact`), the n x n dissimilarities (`affinity`).
Limits (grid sizes, work budgets, numbers of candidates) are named constants
of internal/tuning.h, read by the generators.

<b>A candidate</b> (`Context::Candidate`, a `Generated_candidate`) holds its
`origin` (a `Clustering_candidate::Origin`, named through the context, which
derives from `Candidate_origins`: `Context::KMEANS`), its `label` (the
cluster of every face, 0..K-1), optionally the `orientation` of every face
to measure it with (empty: each face's best match on its cluster's S-quad),
optionally its own measures (`measured`, `weight`, `degree_of_flexibility`,
`length_deviation`), and `has_exact_start`: the clustering is exact at the
positions `sweep_start()` builds from the input, which the fidelity search
solves it from, or, with `start_is_exact`, at positions its generator built
and checked (the multilevel start keeps them for the search).

\cgalHasModel `Hierarchical_generator` (beam_search.h)
\cgalHasModel `Sweep_generator` (sweep_candidates.h)
\cgalHasModel `Multilevel_generator` (multilevel_generator.h)
\cgalHasModel `Kmeans_generator` (kmeans_generator.h)
\cgalHasModel `Quad_strip_generator` (strip_generator.h)
\cgalHasModel `Grid_segment_generator` (segment_candidates.h)
\cgalHasModel `Split_segment_generator` (segment_candidates.h)
\cgalHasModel `Patch_segment_generator` (patch_candidates.h)
\cgalHasModel `Tolerance_group_generator` (tolerance_candidates.h)
*/
class CandidateGenerator
{
public:
  /// \name Operations
  /// @{

  /// The candidates of this generator for `context`, in the order they join
  /// the pool; none when the generator does not apply (its named parameter
  /// is off, K = 1, the mesh is not of its kind). Draws from
  /// `context.random` only in a fixed order, so that the pool follows
  /// `random_seed`.
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const;

  /// @}
};
