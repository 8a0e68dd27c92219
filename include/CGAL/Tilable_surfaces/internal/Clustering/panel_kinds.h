// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H

// Quads and triangles never share a cluster (an S-quad or an S-triangle). The
// candidate generators that do not see kinds (k-means on descriptors, quad
// strips) have their clusters split by kind here before anything is matched.

#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <cstddef>
#include <map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Whether some panel is a triangle.
inline bool has_triangles(const std::vector<Panel>& panels)
{
  for(const Panel& p : panels)
    if(p.is_triangle()) return true;
  return false;
}

// The number of kinds among `panels`: 1, or 2 with quads and triangles (the
// smallest possible K).
inline std::size_t number_of_panel_kinds(const std::vector<Panel>& panels)
{
  bool quads = false, triangles = false;
  for(const Panel& p : panels)
    (p.is_triangle() ? triangles : quads) = true;
  return std::size_t(quads) + std::size_t(triangles);
}

// Each cluster of `label` that holds both kinds split in two; the clusters
// numbered by first face. Returns their number.
inline std::size_t separate_kinds(const std::vector<Panel>& panels, std::vector<std::size_t>& label)
{
  std::map<std::pair<std::size_t, int>, std::size_t> id;
  for(std::size_t f = 0; f < label.size(); ++f)
    label[f] = id.emplace(std::make_pair(label[f], panels[f].size()), id.size()).first->second;
  return id.size();
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H
