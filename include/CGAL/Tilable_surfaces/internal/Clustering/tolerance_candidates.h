// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_H

// The panel-tolerance candidate generator (CandidateGenerator, origin
// TOLERANCE_GROUPS): with a panel tolerance T, the panels that already fit
// one mold within T share a cluster, at no cost in displacement. Leader
// clustering with a radius of T / 2 in the dissimilarity (the sum of the
// corner distances after the best rigid fit, so every corner of a member is
// within T / 2 of its leader's); the mean of such a cluster lies within
// about T / 2 of the leader too, so every member is within about T of it,
// and the solver closes what is left. When the input needs more than K such
// groups there is no candidate; with fewer, the largest groups are halved
// until there are K: a part of a group fits its mold as well.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The groups of `panels` within `tolerance` (absolute) of one mold, at most
// `k` of them, halved up to `k`; empty when more than `k` are needed.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> tolerance_groups(const std::vector<Panel>& panels,
                                          const std::vector<Quad_descriptor>& descriptors,
                                          double tolerance, Orientation_policy policy, std::size_t k);

// With `panel_tolerance` > 0: the tolerance groups, if at most K, each face
// oriented by its best match on its cluster's S-quad.
struct Tolerance_group_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!(context.settings.panel_tolerance > 0))
      return {};
    std::vector<std::size_t> label = tolerance_groups(context.panels, context.descriptors,
                                                      context.settings.panel_tolerance, context.policy, context.k);
    if(label.empty())
      return {};
    std::vector<typename Context::Candidate> result(1);
    result[0].origin = Context::TOLERANCE_GROUPS;
    result[0].label = std::move(label);
    return result;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/tolerance_candidates_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TOLERANCE_CANDIDATES_H
