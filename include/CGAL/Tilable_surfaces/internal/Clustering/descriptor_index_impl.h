// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_IMPL_H

// The bodies of the non-template functions declared in descriptor_index.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Descriptor_index::Descriptor_index(const std::vector<Quad_descriptor>& descriptors)
{
  std::vector<Length_point> points(descriptors.size());
  for(std::size_t i = 0; i < descriptors.size(); ++i)
  {
    std::copy(descriptors[i].begin(), descriptors[i].begin() + 6, points[i].c.begin());
    points[i].index = i;
  }
  m_tree.insert(points.begin(), points.end());
  m_tree.build();
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> Descriptor_index::in_box(const Quad_descriptor& d, double half_width) const
{
  Length_point lo, hi;
  for(int k = 0; k < 6; ++k)
  {
    lo.c[k] = d[k] - half_width;
    hi.c[k] = d[k] + half_width;
  }
  std::vector<Length_point> found;
  m_tree.search(std::back_inserter(found), Box(lo, hi));
  std::vector<std::size_t> r;
  r.reserve(found.size());
  for(const Length_point& p : found) r.push_back(p.index);
  std::sort(r.begin(), r.end());
  return r;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_IMPL_H
