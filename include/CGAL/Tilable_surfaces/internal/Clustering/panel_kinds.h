// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H

// Quads and triangles never share a cluster (an S-quad or an S-triangle). The
// candidate generators that do not see kinds (k-means on descriptors, quad
// strips) have their clusters split by kind here before anything is matched.

#include <CGAL/Tilable_surfaces/internal/config.h>
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
CGAL_TILABLE_SURFACES_INLINE
std::size_t number_of_panel_kinds(const std::vector<Panel>& panels);

// Each cluster of `label` that holds both kinds split in two; the clusters
// numbered by first face. Returns their number.
CGAL_TILABLE_SURFACES_INLINE
std::size_t separate_kinds(const std::vector<Panel>& panels, std::vector<std::size_t>& label);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PANEL_KINDS_H
