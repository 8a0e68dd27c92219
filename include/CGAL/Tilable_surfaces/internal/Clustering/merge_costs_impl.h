// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_IMPL_H

// The bodies of the non-template functions declared in merge_costs.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Exact_merge_costs::Exact_merge_costs(const std::vector<double>& affinity, const std::vector<std::size_t>& cluster,
                  std::size_t number_of_clusters)
  : m_n(number_of_clusters), m_cross(m_n * m_n, 0.0), m_initial(m_n)
{
  const std::size_t faces = cluster.size();
  for(std::size_t p = 0; p < faces; ++p)
    for(std::size_t q = p + 1; q < faces; ++q)
    {
      const double a = affinity[p * faces + q];
      const std::size_t cp = cluster[p], cq = cluster[q];
      if(cp == cq)
        m_initial[cp].weight += a;
      else
      {
        m_cross[cp * m_n + cq] += a;
        m_cross[cq * m_n + cp] += a;
      }
    }
}

CGAL_TILABLE_SURFACES_INLINE
Descriptor_merge_costs::Descriptor_merge_costs(const std::vector<Quad_descriptor>& descriptors,
                       const std::vector<std::size_t>& cluster, std::size_t number_of_clusters)
  : m_initial(number_of_clusters)
{
  for(std::size_t f = 0; f < cluster.size(); ++f)
  {
    Group& g = m_initial[cluster[f]];
    g.n += 1;
    for(std::size_t k = 0; k < g.mean.size(); ++k) g.mean[k] += descriptors[f][k];
  }
  for(Group& g : m_initial)
    for(double& x : g.mean) x /= g.n;
  for(std::size_t f = 0; f < cluster.size(); ++f)
  {
    Group& g = m_initial[cluster[f]];
    for(std::size_t k = 0; k < g.mean.size(); ++k)
      g.scatter += (descriptors[f][k] - g.mean[k]) * (descriptors[f][k] - g.mean[k]);
  }
  for(Group& g : m_initial)
    g.weight = g.n * g.scatter;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_IMPL_H
