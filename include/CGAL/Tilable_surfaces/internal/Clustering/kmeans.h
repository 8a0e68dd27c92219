// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H

// Lloyd's k-means on quad descriptors (paper §5: a k-means configuration
// enriches the candidate pool; also the first step of splitting a cluster).
// Seeding is k-means++ with a `CGAL::Random`, so results follow the seed.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/Random.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

inline double squared_distance(const Quad_descriptor& a, const Quad_descriptor& b)
{
  double r = 0;
  for(std::size_t k = 0; k < a.size(); ++k) r += (a[k] - b[k]) * (a[k] - b[k]);
  return r;
}

// Labels in 0..k-1 of points[subset[i]], or an empty vector when k distinct
// non-empty clusters cannot be formed (fewer than k distinct descriptors).
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> kmeans(const std::vector<Quad_descriptor>& points,
                                const std::vector<std::size_t>& subset,
                                std::size_t k, CGAL::Random& random,
                                int iterations = tuning::kmeans_iterations);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H
