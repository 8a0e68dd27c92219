// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_GENERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_GENERATOR_H

// The quad-strip candidate generator (CandidateGenerator, origin
// QUAD_STRIPS): the adapter of strip_clusterings() to the candidate pool,
// beside strip_candidates.h because the strips it groups are chosen with the
// grid test of sweep_candidates.h (candidate_strips()).

#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// With `use_strip_candidates` and K > 1, the strip clusterings
// (strip_clusterings(), drawing from the shared random generator), each
// face oriented by its best match.
struct Quad_strip_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!context.settings.use_strips || context.k <= 1)
      return {};
    return best_match_candidates<typename Context::Candidate>(
      strip_clusterings(context.mesh, context.face_index, context.vertex_point, context.panels,
                        context.descriptors, context.k, context.policy, context.random,
                        candidate_strips(context.mesh, context.face_index, context.vertex_point)),
      Context::QUAD_STRIPS);
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_GENERATOR_H
