// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_IMPL_H

// The bodies of the non-template functions declared in flexible_orientations.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/flexible_orientations.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<Panel_orientation>
propagated_orientations(const std::vector<Shared_edge>& edges, const std::vector<std::size_t>& label,
                 const std::vector<std::array<double, 8> >& dissimilarity,
                 const std::vector<int>& corners,
                 const std::vector<Panel_orientation>& best, bool mirrored)
{
  const std::size_t n = label.size();
  std::vector<std::vector<std::pair<std::size_t, int> > > incident(n);  // (edge, side)
  for(std::size_t i = 0; i < edges.size(); ++i)
    for(int s = 0; s < 2; ++s) incident[edges[i].face[s]].push_back({i, s});
  std::vector<Panel_orientation> r = best;
  std::vector<bool> seen(n, false);
  std::vector<std::size_t> queue;
  for(std::size_t root = 0; root < n; ++root)
  {
    if(seen[root]) continue;
    seen[root] = true;
    queue.assign(1, root);
    for(std::size_t next = 0; next < queue.size(); ++next)
    {
      const std::size_t f = queue[next];
      for(const auto& is : incident[f])
      {
        const Shared_edge& e = edges[is.first];
        const std::size_t g = e.face[1 - is.second];
        if(seen[g] || label[g] != label[f]) continue;
        seen[g] = true;
        queue.push_back(g);
        // Opposite halfedges: the edge runs the other way in g, so equal
        // corners need the other direction of travel around the template.
        const int n = corners[f];
        if(!mirrored && n == 3) continue;
        const int k = r[f].template_edge(e.edge[is.second], n);
        for(int o = 0; o < 8; ++o)
        {
          const Panel_orientation c(o);
          const bool fits = mirrored
            ? c.is_reversed() != r[f].is_reversed() && c.face_edge(k, n) == e.edge[1 - is.second]
            : c.is_reversed() == r[f].is_reversed() && c.face_edge((k + 2) & 3) == e.edge[1 - is.second];
          if(fits && dissimilarity[g][o] < std::numeric_limits<double>::infinity())
            r[g] = c;
        }
      }
    }
  }
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::array<double, 8> >
admissible_dissimilarities(const std::vector<Panel>& quads, const std::vector<std::size_t>& label,
                    const std::vector<Panel>& s_quads, Orientation_policy policy,
                    double tolerance)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<std::array<double, 8> > d(quads.size());
  parallel_for(quads.size(), [&](std::size_t f) {
    const Prepared_quad p(s_quads[label[f]]), q(quads[f]);
    d[f].fill(inf);
    double best = inf;
    for(Panel_orientation o : admissible_orientations(q.corners.size(), policy))
    {
      d[f][std::size_t(o.index())] = correspondence_match(p, q, o, policy == ALLOW_MIRRORED_PANELS).first;
      best = (std::min)(best, d[f][std::size_t(o.index())]);
    }
    for(double& dissimilarity : d[f])
      if(dissimilarity > best + tolerance)
        dissimilarity = inf;
  });
  return d;
}

CGAL_TILABLE_SURFACES_INLINE
Flexible_orientations::Flexible_orientations(const std::vector<Shared_edge>& edges, const std::vector<std::size_t>& label,
                      std::size_t k, const std::vector<std::array<double, 8> >& dissimilarity,
                      const std::vector<int>& corners, std::vector<Panel_orientation> orientation)
  : m_edges(edges), m_label(label), m_k(k), m_d(dissimilarity), m_corners(corners)
  , m_orientation(std::move(orientation)), m_incident(label.size())
{
  // Node 4c + 3 of a triangle cluster c is no template edge.
  std::vector<bool> triangle_cluster(k, false);
  for(std::size_t f = 0; f < label.size(); ++f)
    if(corners[f] == 3) triangle_cluster[label[f]] = true;
  m_unused_nodes = std::size_t(std::count(triangle_cluster.begin(), triangle_cluster.end(), true));
  for(std::size_t i = 0; i < edges.size(); ++i)
    for(int s = 0; s < 2; ++s)
      m_incident[edges[i].face[s]].push_back(i);
  for(std::size_t i = 0; i < edges.size(); ++i)
    add_link(i, +1);
  m_dof = count_components(m_components);
}

CGAL_TILABLE_SURFACES_INLINE
void Flexible_orientations::improve(int sweeps)
{
  for(int sweep = 0; sweep < sweeps; ++sweep)
  {
    bool changed = false;
    for(std::size_t f = 0; f < m_label.size(); ++f)
      for(int o = 0; o < 8; ++o)
        changed = try_orientation(f, Panel_orientation(o)) || changed;
    if(!changed)
      break;
  }
}

CGAL_TILABLE_SURFACES_INLINE
bool Flexible_orientations::is_better_than(const Flexible_orientations& other) const
{
  if(m_dof != other.m_dof) return m_dof > other.m_dof;
  if(m_links != other.m_links) return m_links < other.m_links;
  return total_dissimilarity() < other.total_dissimilarity();
}

CGAL_TILABLE_SURFACES_INLINE
std::size_t Flexible_orientations::count_components(Union_find<>& sets) const
{
  sets.reset(4 * m_k);
  std::size_t components = 4 * m_k - m_unused_nodes;
  for(const auto& l : m_count)
    if(sets.unite(std::size_t(l.first >> 32), std::size_t(l.first & 0xffffffffu)))
      --components;
  return components;
}

CGAL_TILABLE_SURFACES_INLINE
bool Flexible_orientations::try_orientation(std::size_t f, Panel_orientation o)
{
  const Panel_orientation old = m_orientation[f];
  if(o == old || !(m_d[f][o.index()] < std::numeric_limits<double>::infinity()))
    return false;
  const long long old_links = m_links;
  const Change c = retag(f, o);
  std::size_t dof = m_dof;
  if(c.nv > 0)
    dof = count_components(m_recount);
  else
  {
    std::array<std::pair<std::size_t, std::size_t>, 4> joined;
    for(std::size_t i = 0; i < c.na; ++i)
      joined[i] = {m_components.find(std::size_t(c.appeared[i] >> 32)),
                   m_components.find(std::size_t(c.appeared[i] & 0xffffffffu))};
    dof -= number_of_joins(joined, c.na);
  }
  const bool better =
    dof != m_dof ? dof > m_dof
                 : (m_links != old_links ? m_links < old_links
                                         : m_d[f][o.index()] < m_d[f][old.index()]);
  if(!better)
  {
    retag(f, old);
    return false;
  }
  if(c.nv > 0)
    m_components.swap(m_recount);
  else
    for(std::size_t i = 0; i < c.na; ++i)
      m_components.unite(std::size_t(c.appeared[i] >> 32), std::size_t(c.appeared[i] & 0xffffffffu));
  m_dof = dof;
  return true;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_IMPL_H
