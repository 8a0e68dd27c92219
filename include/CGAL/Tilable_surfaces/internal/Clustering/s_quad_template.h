// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H

// The S-quad of a cluster: the mean shape of its instances in a common frame
// (generalized Procrustes analysis). Each instance is brought onto the current
// reference by its best match (orientation and rigid fit), the aligned copies
// are averaged, and the mean becomes the next reference.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Inverse motion of `fit` applied to `target`: the instance in the frame of
// the template.
CGAL_TILABLE_SURFACES_INLINE
Panel pulled_back(const Panel& target, const Rigid_fit& fit);

CGAL_TILABLE_SURFACES_INLINE
Panel centred(Panel q);

// How far the corners of `b` are from those of `a`, relative to the size of
// `a` (0 when they coincide, even for a degenerate `a`).
CGAL_TILABLE_SURFACES_INLINE
double relative_move(const Panel& a, const Panel& b);

// The mean shape of quads[members[i]], centred at the origin: the package's
// one Procrustes mean. With `orientations`, instance i is taken in the
// labelling orientations[i] (only the rigid fit is searched, a mirror too under
// ALLOW_MIRRORED_PANELS); otherwise the best orientation is searched too,
// starting from the first member as reference. At most `max_passes` passes;
// with a `tolerance`, they stop once the mean moves by at most that fraction
// of its size. The clustering takes 3 passes: the mean only has to rank and
// match shapes there. The measure runs to 1e-14: its error is judged against
// the mean, and congruent instances give it exactly.
CGAL_TILABLE_SURFACES_INLINE
Panel procrustes_mean(const std::vector<Panel>& quads,
                     const std::vector<std::size_t>& members,
                     Orientation_policy policy,
                     const std::vector<Panel_orientation>* orientations = nullptr,
                     int max_passes = tuning::procrustes_passes, double tolerance = 0);

// The S-quad of instances congruent up to proper rigid motions (and mirrors
// with `allow_mirror`), in their labelling: their Procrustes mean, to
// convergence.
CGAL_TILABLE_SURFACES_INLINE
Panel converged_procrustes_mean(const std::vector<Panel>& instances, bool allow_mirror);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_S_QUAD_TEMPLATE_H
