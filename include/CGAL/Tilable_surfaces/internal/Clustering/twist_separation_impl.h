// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_IMPL_H

// The bodies of the non-template functions declared in twist_separation.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/twist_separation.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Twist_separation::Twist_separation(const std::vector<Panel>& quads, Orientation_policy policy)
  : m_quads(quads), m_policy(policy)
{
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> Twist_separation::operator()(const std::vector<std::size_t>& label, std::size_t k)
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

CGAL_TILABLE_SURFACES_INLINE
std::size_t Twist_separation::split_mixed(std::vector<std::size_t>& label, std::size_t k) const
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

CGAL_TILABLE_SURFACES_INLINE
void Twist_separation::update_partner(std::size_t a)
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

CGAL_TILABLE_SURFACES_INLINE
void Twist_separation::merge_to(std::size_t k)
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

CGAL_TILABLE_SURFACES_INLINE
std::size_t Twist_separation::closest_pair()
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> Twist_separation::relabelled() const
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

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TWIST_SEPARATION_IMPL_H
