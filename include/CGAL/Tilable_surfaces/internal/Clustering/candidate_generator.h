// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H

// What the pipeline does with the candidates of each origin: a table of
// traits, so that the clusterer and the fidelity search follow one rule
// instead of testing origins one by one.

#include <CGAL/Tilable_surfaces/cluster_quads.h>

#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// What the pipeline does with the candidates of one origin (one generator).
struct Candidate_origin_traits
{
  const char* name;                 // as in the choice strings and reports
  bool selectable_by_score;         // may be cluster_quads()'s chosen candidate (false for sweeps)
  bool solved_first_from_start;     // the fidelity search solves it first, from the exact start its
                                    // generator made, and does not rank it (true for sweeps only)
  std::size_t extra_quota_divisor;  // after the ranked candidates, ceil(optimized / divisor) more of
                                    // this origin are optimized, in pool order (0: none)
};

// The traits of the candidates of `origin`.
inline const Candidate_origin_traits& origin_traits(Clustering_candidate::Origin origin)
{
  static const Candidate_origin_traits table[] = {
    {"hierarchical", true, false, 0},  // HIERARCHICAL
    {"k-means", true, false, 0},       // KMEANS
    {"quad-strip", true, false, 0},    // QUAD_STRIPS
    {"grid-segment", true, false, 4},  // GRID_SEGMENTS: both rankings underrate their long-range ties
    {"sweep", false, true, 0}};        // GRID_SWEEPS
  return table[origin];
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CANDIDATE_GENERATOR_H
