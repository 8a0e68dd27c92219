// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_H

// The threshold clustering of the paper (§3, "Initial Clustering"): leader
// clustering. Faces are visited in order; an unassigned face becomes the
// leader of a new cluster, which takes every unassigned face q with
// s(leader, q) < tau. Candidates come from the descriptor kd-tree, an exact
// prefilter, so the result is the same on both clustering paths.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Initial_clustering
{
  std::vector<std::size_t> cluster;             // per face
  std::vector<Panel_orientation> orientation;    // per face, w.r.t. its leader
  std::vector<std::size_t> leaders;             // per cluster, increasing
};

// Returns false, leaving `out` incomplete, as soon as more than
// `max_clusters` clusters would be needed.
CGAL_TILABLE_SURFACES_INLINE
bool leader_clustering(const std::vector<Panel>& quads,
                       const std::vector<Quad_descriptor>& descriptors,
                       const Descriptor_index& index, double tau,
                       Orientation_policy policy, std::size_t max_clusters,
                       Initial_clustering& out);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_INITIAL_CLUSTERING_H
