// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_H
#define CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_H

// Distances between two surfaces with the same faces (the input and a result),
// with CGAL's AABB tree. A quad is the fan of 4 triangles around its vertex
// centroid: no diagonal is preferred, and the centroid lies on the bilinear
// patch of the quad. The sampled surface is the same kind of surface, sampled
// at the vertices of its faces and, on each face, at the apex of the fan, the
// midpoints of the 4 edges and the centroids of the 4 fan triangles; so a
// surface measured against itself is at distance 0. Both directions are
// needed: samples of the result near the input say nothing of parts of the
// input the result left.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Distance_summary
{
  double max = 0, mean = 0;
};

// Max and mean distance of the samples of `sampled` to the surface
// `reference` (both with the faces of `problem`), in the units of the points.
CGAL_TILABLE_SURFACES_INLINE
Distance_summary one_sided_distance(const Tilable_problem& problem,
                                    const Point_matrix& reference,
                                    const Point_matrix& sampled);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Measure/approximation_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_MEASURE_APPROXIMATION_H
