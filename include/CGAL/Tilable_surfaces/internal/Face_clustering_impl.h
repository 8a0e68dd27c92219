// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_IMPL_H

// The bodies of the non-template functions declared in Face_clustering.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::vector<std::size_t> >
cluster_members(const std::vector<std::size_t>& label, std::size_t k)
{
  std::vector<std::vector<std::size_t> > members(k);
  for(std::size_t f = 0; f < label.size(); ++f)
    members[label[f]].push_back(f);
  return members;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_IMPL_H
