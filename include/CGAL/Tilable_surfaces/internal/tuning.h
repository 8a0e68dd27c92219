// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H

// The tuning values of the pipeline that the user does not set, each under a
// name that the code and the user manual cite. Values the user can set are in
// defaults.h. Grouped by the stage of the pipeline that reads them.

#include <cstddef>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {
namespace tuning {

// ---------------------------------------------------------------------------
// Shape analysis, optimization and measurement
// ---------------------------------------------------------------------------



// ---------------------------------------------------------------------------
// Clustering: candidate generators and their selection by score
// ---------------------------------------------------------------------------



// ---------------------------------------------------------------------------
// Search: which candidates are solved, how far, and the rounds after them
// ---------------------------------------------------------------------------

// Iterations polishing a sweep's exact start: a solve that leaves exact surfaces returns slowly.
constexpr int sweep_polish_iterations = 10;
// Times the best result's iterations a later candidate may take: one slower is unlikely closer.
constexpr int iteration_cap_factor = 3;
// The least iteration cap of a later candidate, so that a quickly converged best does not starve it.
constexpr int minimum_iteration_cap = 30;
// Rounds beyond number_of_improvement_rounds that repair a result that is not tilable.
constexpr int repair_rounds = 4;
// Merges (least length spread first) an improvement round predicts: each one factorizes the matrix.
constexpr std::size_t predicted_merge_pairs = 4;
// Faces per tile of the deviation search's first K: a guess the gallop corrects in a few trials.
constexpr std::size_t faces_per_first_tile = 25;
// The least first K of the deviation search: one tile fits only a mesh of congruent faces.
constexpr std::size_t smallest_first_tile_count = 2;

} // namespace tuning
} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
