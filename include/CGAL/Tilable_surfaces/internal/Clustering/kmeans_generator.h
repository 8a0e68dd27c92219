// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_GENERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_GENERATOR_H

// The k-means candidate generator (CandidateGenerator, origin KMEANS): the
// adapter of kmeans() to the candidate pool, beside kmeans.h because it needs
// the strip merges and splits (bring_to()) that kmeans.h itself is a step of.

#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// With `use_kmeans_candidate` and K > 1, one candidate: k-means (k-means++
// seeded by the shared random generator) on the descriptors of all faces,
// brought to K clusters of one panel kind each on a mesh with triangles,
// every face oriented by its best match on the face nearest to its
// cluster's mean descriptor. None when k-means leaves a cluster empty.
struct Kmeans_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    std::vector<typename Context::Candidate> result;
    if(!context.settings.use_kmeans || context.k <= 1)
      return result;
    const std::size_t n = context.panels.size(), k = context.k;
    std::vector<std::size_t> all(n);
    for(std::size_t f = 0; f < n; ++f) all[f] = f;
    std::vector<std::size_t> label = kmeans(context.descriptors, all, k, context.random);
    if(label.empty())
      return result;
    relabel_by_first_face(label);
    if(context.has_triangles)
      bring_to(k, context.mesh, context.face_index, context.vertex_point, context.panels, context.descriptors,
               context.policy, context.random, label, separate_kinds(context.panels, label));
    typename Context::Candidate candidate;
    candidate.origin = Context::KMEANS;
    candidate.orientation = nearest_to_mean_orientations(context, label);
    candidate.label = std::move(label);
    result.push_back(std::move(candidate));
    return result;
  }

private:
  // Each face's best match on the face of its cluster nearest to the
  // cluster's mean descriptor.
  template <typename Context>
  static std::vector<Panel_orientation> nearest_to_mean_orientations(const Context& context,
                                                                    const std::vector<std::size_t>& label)
  {
    const std::size_t n = label.size(), k = context.k;
    const Descriptor_merge_costs stats(context.descriptors, label, k);
    std::vector<std::size_t> representative(k, no_index());
    std::vector<double> best(k, 0.0);
    for(std::size_t f = 0; f < n; ++f)
    {
      Quad_descriptor centre = stats.initial_group(label[f]).mean;
      const double d = squared_distance(context.descriptors[f], centre);
      if(representative[label[f]] == no_index() || d < best[label[f]])
      {
        representative[label[f]] = f;
        best[label[f]] = d;
      }
    }
    std::vector<Panel_orientation> orientation(n);
    parallel_for(n, [&](std::size_t f) {
      orientation[f] =
        fast_best_match(context.panels[representative[label[f]]], context.panels[f], context.policy).orientation;
    });
    return orientation;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_GENERATOR_H
