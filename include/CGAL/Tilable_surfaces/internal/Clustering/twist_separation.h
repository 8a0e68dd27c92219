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
  Twist_separation(const std::vector<Panel>& quads, Orientation_policy policy)
    : m_quads(quads), m_policy(policy)
  {
  }

  // The twist separation of `label` (clusters by any ids) with `k` clusters,
  // or an empty vector when no cluster mixes twists or the split leaves
  // fewer than `k`.
  std::vector<std::size_t> operator()(const std::vector<std::size_t>& label, std::size_t k)
  {
    std::vector<std::size_t> separated = label;
    const std::size_t used = relabel_by_first_face(separated);
    const std::size_t split = split_mixed(separated, used);
    if(split == used || split < k)
      return std::vector<std::size_t>();
    m_members = cluster_members(separated, split);
    m_s_quads.resize(split);
    for(std::size_t c = 0; c < split; ++c)
      m_s_quads[c] = procrustes_mean(m_quads, m_members[c], m_policy);
    merge_to(k);
    return relabelled();
  }

private:
  // Splits every cluster that mixes twists, by sign, in the labelling of each
  // face's best match on its cluster's S-quad; returns the number of clusters.
  std::size_t split_mixed(std::vector<std::size_t>& label, std::size_t k) const
  {
    const Cluster_shapes shapes = cluster_shapes(m_quads, label, k, m_policy);
    std::vector<double> twist(m_quads.size());
    std::vector<double> low(k, 0), high(k, 0);
    for(std::size_t f = 0; f < m_quads.size(); ++f)
    {
      twist[f] = relative_twist(reoriented(m_quads[f], shapes.orientation[f]));
      low[label[f]] = (std::min)(low[label[f]], twist[f]);
      high[label[f]] = (std::max)(high[label[f]], twist[f]);
    }
    std::vector<std::size_t> negative_part(k, no_index());
    std::size_t clusters = k;
    for(std::size_t c = 0; c < k; ++c)
      if(twists_oppose(low[c], high[c]))
        negative_part[c] = clusters++;
    for(std::size_t f = 0; f < m_quads.size(); ++f)
      if(negative_part[label[f]] != no_index() && twist[f] < 0)
        label[f] = negative_part[label[f]];
    return clusters;
  }

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
  void update_partner(std::size_t a)
  {
    m_cost[a] = std::numeric_limits<double>::infinity();
    m_partner[a] = a;
    for(std::size_t b = 0; b < m_members.size(); ++b)
      if(b != a && !m_members[b].empty())
      {
        const double c = merge_cost(a, b);
        if(c < m_cost[a]) { m_cost[a] = c; m_partner[a] = b; }
      }
  }

  // Greedy merges of the cheapest pair until `k` clusters are left; when
  // every pair twists oppositely, the pair of the closest S-quads merges.
  void merge_to(std::size_t k)
  {
    const std::size_t n = m_members.size();
    m_cost.assign(n, 0);
    m_partner.assign(n, 0);
    for(std::size_t a = 0; a < n; ++a)
      update_partner(a);
    for(std::size_t live = n; live > k; --live)
    {
      std::size_t a = n;
      for(std::size_t c = 0; c < n; ++c)
        if(!m_members[c].empty() && m_partner[c] != c && (a == n || m_cost[c] < m_cost[a]))
          a = c;
      if(a == n || m_cost[a] == std::numeric_limits<double>::infinity())
        a = closest_pair();
      const std::size_t b = m_partner[a];
      m_members[a].insert(m_members[a].end(), m_members[b].begin(), m_members[b].end());
      m_members[b].clear();
      m_s_quads[a] = procrustes_mean(m_quads, m_members[a], m_policy);
      for(std::size_t c = 0; c < n; ++c)
        if(!m_members[c].empty() && (c == a || m_partner[c] == a || m_partner[c] == b))
          update_partner(c);
    }
  }

  // The live cluster whose S-quad is closest to another's, its partner set
  // to that other, whatever the twists.
  std::size_t closest_pair()
  {
    double best = std::numeric_limits<double>::infinity();
    std::size_t found = 0;
    for(std::size_t a = 0; a < m_members.size(); ++a)
      for(std::size_t b = a + 1; b < m_members.size() && !m_members[a].empty(); ++b)
        if(!m_members[b].empty())
        {
          const double d = fast_best_match(m_s_quads[a], m_s_quads[b], m_policy).dissimilarity;
          if(d < best) { best = d; found = a; m_partner[a] = b; }
        }
    return found;
  }

  // Labels 0..K-1 of the live clusters, in cluster order.
  std::vector<std::size_t> relabelled() const
  {
    std::vector<std::size_t> label(m_quads.size(), 0);
    std::size_t next = 0;
    for(const std::vector<std::size_t>& members : m_members)
    {
      if(members.empty())
        continue;
      for(std::size_t f : members)
        label[f] = next;
      ++next;
    }
    return label;
  }

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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_H
