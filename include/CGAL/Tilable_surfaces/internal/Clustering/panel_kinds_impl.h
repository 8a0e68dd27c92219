// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_IMPL_H

// The bodies of the non-template functions declared in panel_kinds.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::size_t number_of_panel_kinds(const std::vector<Panel>& panels)
{
  bool quads = false, triangles = false;
  for(const Panel& p : panels)
    (p.is_triangle() ? triangles : quads) = true;
  return std::size_t(quads) + std::size_t(triangles);
}

CGAL_TILABLE_SURFACES_INLINE
std::size_t separate_kinds(const std::vector<Panel>& panels, std::vector<std::size_t>& label)
{
  std::map<std::pair<std::size_t, int>, std::size_t> id;
  for(std::size_t f = 0; f < label.size(); ++f)
    label[f] = id.emplace(std::make_pair(label[f], panels[f].size()), id.size()).first->second;
  return id.size();
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_IMPL_H
