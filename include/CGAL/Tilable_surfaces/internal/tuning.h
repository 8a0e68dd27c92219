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



} // namespace tuning
} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TUNING_H
