// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATORS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATORS_H

// The registration of the candidate generators (models of CandidateGenerator,
// candidate_generator.h): their origins, the traits of each origin, and the
// lists Panel_clusterer runs. A new generator adds here its origin (if new)
// with its traits row, its include, and its place in a list; its model lives
// in its own header, and its documentation on the concept page and in the
// user manual's table: three places in all.

#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Tilable_surfaces/internal/Clustering/beam_search.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans_generator.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/multilevel_generator.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/patch_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_generator.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/tolerance_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {

/// Where a candidate of the pool of `cluster_panels()` comes from: the
/// generator that made it (user manual, section Candidate generators).
/// `HIERARCHICAL`: the last beam of binary merges.
/// `KMEANS`: k-means on the quad descriptors.
/// `QUAD_STRIPS`: quad strips merged greedily.
/// `GRID_SEGMENTS`: runs of rows of a quad grid, each a segment of column
/// molds or a band of one mold, with K molds, or with fewer and their
/// largest clusters split by shape until K (user manual, section
/// TS_Fidelity).
/// `GRID_SWEEPS`: every column of a run of rows of a quad grid is one
/// cluster; such a clustering is exact on a swept surface built directly
/// (user manual, section TS_Sweeps). These are never the configuration
/// `cluster_panels()` returns; `K_set_tilable_surface::optimize_closest()`
/// solves them first, from that surface.
/// `TWIST_SEPARATED`: a candidate of another origin whose clusters mixing
/// quads twisted both ways are split by the sign of the twist, then merged
/// back to K clusters that each keep one sign (user manual, section
/// TS_Candidate_generators).
/// `PATCH_SEGMENTS`: on a quad mesh that is not one grid, the grid segments
/// of every patch of its quad layout, with molds shared across patches whose
/// panels agree, never mixing quads twisted both ways.
/// `TOLERANCE_GROUPS`: with a `panel_tolerance`, the panels that already fit
/// one mold within it grouped, when at most K groups are needed (user
/// manual, section TS_Panel_tolerance).
/// `MULTILEVEL`: above `large_mesh_faces`, on a mesh that is a 2 x 2
/// refinement and has no exact sweep, the exact result of a coarser mesh
/// prolongated; `K_set_tilable_surface::optimize_closest()` solves it first,
/// from there (user manual, section TS_Multilevel).
enum Candidate_origins::Origin : int {
  HIERARCHICAL, KMEANS, QUAD_STRIPS, GRID_SEGMENTS, GRID_SWEEPS, TWIST_SEPARATED, PATCH_SEGMENTS, TOLERANCE_GROUPS,
  MULTILEVEL
};

namespace internal {

// One row per origin, in the order of the enumerators.
inline const Candidate_origin_traits& origin_traits(Candidate_origins::Origin origin)
{
  static const Candidate_origin_traits traits[] = {
    // name, selectable_by_score, solved_first_from_start, extra_quota_divisor, ranked
    {"hierarchical", true, false, 0, true},
    {"k-means", true, false, 0, true},
    {"quad-strip", true, false, 0, true},
    {"grid-segment", true, false, tuning::grid_segment_extra_quota_divisor, true},
    {"sweep", false, true, 0, false},
    {"twist-separated", true, false, tuning::twist_separated_extra_quota_divisor, false},
    {"patch-segment", true, false, tuning::patch_segment_extra_quota_divisor, true},
    {"tolerance-group", true, false, 0, true},
    {"multilevel", false, true, 0, false}};
  return traits[origin];
}

// A list of generators, run in its order.
template <typename... Generators>
struct Generator_list
{
};

// Step 2 of Panel_clusterer: the generators whose candidates are solved
// first from their exact start, pooled after all the others; when one of
// their candidates ends the search, no other generator runs (the multilevel
// start, then, is tried only where no sweep is exact).
typedef Generator_list<Sweep_generator, Multilevel_generator> Exact_start_generators;

// Step 3: the beam of merges down to K.
typedef Generator_list<Hierarchical_generator> Merge_generators;

// Step 4: the other candidates, pooled in this order.
typedef Generator_list<Kmeans_generator, Quad_strip_generator, Grid_segment_generator,
                       Split_segment_generator, Patch_segment_generator, Tolerance_group_generator>
  Other_generators;

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATORS_H
