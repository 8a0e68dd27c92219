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

// Threshold clustering on the descriptor path: the threshold doubles until
// at most max(this, 4K) initial clusters remain (the beam's cost grows with N).
constexpr std::size_t descriptor_path_initial_clusters = 1000;
// Threshold clustering: a zero threshold restarts at this fraction of the
// mean edge length before doubling.
constexpr double restart_threshold = 1e-3;
// Threshold clustering with fewer than K clusters: the threshold is divided
// by 4 while above this fraction of the mean edge length (round-off level).
constexpr double smallest_threshold = 1e-9;
// How many segment clusterings of fewer molds, split to K, join the pool:
// those of least length deviation (split_segment_clusterings()).
constexpr std::size_t split_segment_candidates = 4;
// The search optimizes ceil(optimized / this) grid-segment candidates beyond
// the ranked ones (origin_traits()): grids gain from their structure more
// than the prediction ranks.
constexpr std::size_t grid_segment_extra_quota_divisor = 4;


// ---------------------------------------------------------------------------
// Search: which candidates are solved, how far, and the rounds after them
// ---------------------------------------------------------------------------



} // namespace tuning
} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
