// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_H

// Whether a surface crosses itself, which no congruence or distance number
// shows: a tube folded flat can be exact and within two radii of its input.
// Each face is the fan of triangles around its vertex centroid, the surface
// the distances of approximation.h measure; CGAL's self-intersection test
// decides with exact predicates, and ignores what adjacent faces share.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The number of pairs of distinct faces of the surface `x` (with the faces of
// `problem`) that intersect other than along what they share.
CGAL_TILABLE_SURFACES_INLINE
std::size_t self_intersecting_face_pairs(const Tilable_problem& problem, const Point_matrix& x);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Measure/self_intersections_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_SELF_INTERSECTIONS_H
