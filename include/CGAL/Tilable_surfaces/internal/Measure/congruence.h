// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_H

// Congruence of the instances of each cluster, by rigid fits only (no energy):
// the S-quad is the Procrustes mean of the instances, and a cluster's error is
// its worst instance's largest corner deviation after the best rigid fit of
// the S-quad onto it: a proper one, or either kind when the problem allows
// mirrored panels.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// `q` moved rigidly so that t0 is at the origin, t1 on the +x axis and t2 in
// the xy plane with y >= 0 (a proper motion: the signed volume is kept).
CGAL_TILABLE_SURFACES_INLINE
Panel canonical_frame(const Panel& q);

struct Cluster_congruence
{
  std::vector<Panel> s_quads;       // canonical frame; empty clusters get zeros
  std::vector<std::size_t> sizes;  // instances per cluster
  std::vector<double> errors;      // absolute lengths
  std::vector<std::size_t> mirrored; // instances whose best fit is a mirror
  std::vector<double> face_errors;   // per face: its instance's deviation, absolute
};

CGAL_TILABLE_SURFACES_INLINE
Cluster_congruence cluster_congruence(const Tilable_problem& problem, const Point_matrix& X);

// The mold of each cluster: each S-quad of a cluster with faces (`sizes`)
// joins the first earlier mold whose S-quad fits it, every corner within
// `tolerance` (absolute) after the best rigid fit under a correspondence the
// policy admits, else it makes a new one; molds numbered from 0 in cluster
// order, `s_quads.size()` for a cluster without faces. The sorted edge and
// diagonal lengths of two such shapes (their shape_descriptor() but the
// volume term, whose cube root is not Lipschitz) differ by at most
// 2 `tolerance`, which spares most fits.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> cluster_molds(const std::vector<Panel>& s_quads, const std::vector<std::size_t>& sizes,
                                       bool allow_mirror, double tolerance);

// The largest distance between the diagonals of a face (absolute length).
CGAL_TILABLE_SURFACES_INLINE
double worst_diagonal_distance(const Tilable_problem& problem, const Point_matrix& X);

// The congruence error (user manual, section Definitions): worst cluster error / mean edge
// length; with planar tiles, the worst distance between the diagonals of a
// face too, so that the solvers stop only on planar panels.
CGAL_TILABLE_SURFACES_INLINE
double congruence_error(const Tilable_problem& problem, const Point_matrix& X);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Measure/congruence_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_CONGRUENCE_H
