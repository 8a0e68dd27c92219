// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_H

// Clusterings whose clusters keep the sign of the twist.
//
// Congruence keeps the signed volume det[t1 - t0, t2 - t0, t3 - t0] of a
// panel in its S-quad's labelling, so a cluster holding quads twisted both
// ways becomes congruent only by flattening them, and a surface whose twist
// changes sign becomes a mesh of planar quads far from the input. The twist
// separation of a clustering splits every cluster that mixes significant
// twists of both signs by sign, then merges the cheapest pairs of clusters
// whose S-quads twist the same way (a Ward cost on their dissimilarity)
// until K clusters remain.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/twist_sign.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

class Twist_separation
{
public:
  Twist_separation(const std::vector<Panel>& quads, Orientation_policy policy);

  // The twist separation of `label` (clusters by any ids) with `k` clusters,
  // or an empty vector when no cluster mixes twists or the split leaves
  // fewer than `k`.
  std::vector<std::size_t> operator()(const std::vector<std::size_t>& label, std::size_t k);

private:
  // Splits every cluster that mixes twists, by sign, in the labelling of each
  // face's best match on its cluster's S-quad; returns the number of clusters.
  std::size_t split_mixed(std::vector<std::size_t>& label, std::size_t k) const;

  // The Ward cost of merging clusters a and b; +inf when their S-quads twist
  // opposite ways in their best correspondence.
  double merge_cost(std::size_t a, std::size_t b) const
  {
    const Quad_match m = fast_best_match(m_s_quads[a], m_s_quads[b], m_policy);
    if(twists_oppose(relative_twist(m_s_quads[a]), relative_twist(reoriented(m_s_quads[b], m.orientation))))
      return std::numeric_limits<double>::infinity();
    const double na = double(m_members[a].size()), nb = double(m_members[b].size());
    return na * nb / (na + nb) * m.dissimilarity * m.dissimilarity;
  }

  // Each live cluster's cheapest partner among the live clusters.
  void update_partner(std::size_t a);

  // Greedy merges of the cheapest pair until `k` clusters are left; when
  // every pair twists oppositely, the pair of the closest S-quads merges.
  void merge_to(std::size_t k);

  // The live cluster whose S-quad is closest to another's, its partner set
  // to that other, whatever the twists.
  std::size_t closest_pair();

  // Labels 0..K-1 of the live clusters, in cluster order.
  std::vector<std::size_t> relabelled() const;

  const std::vector<Panel>& m_quads;
  const Orientation_policy m_policy;
  std::vector<std::vector<std::size_t> > m_members;
  std::vector<Panel> m_s_quads;
  std::vector<double> m_cost;
  std::vector<std::size_t> m_partner;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/twist_separation_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_H
