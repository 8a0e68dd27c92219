// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_IMPL_H

// The bodies of the non-template functions declared in quad_coarsening.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_coarsening.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Face_clustering prolongated_clustering(const Quad_coarsening& coarsening, const Face_clustering& coarse)
{
  const std::size_t n = coarsening.coarse_face.size();
  Face_clustering fine;
  fine.label.resize(n);
  fine.orientation.resize(n);
  fine.number_of_clusters = 4 * coarse.number_of_clusters;
  for(std::size_t f = 0; f < n; ++f)
  {
    const std::size_t q = coarsening.coarse_face[f];
    const Panel_orientation o = coarse.orientation[q];
    const int t = o.inverse()(coarsening.coarse_corner[f]);
    fine.label[f] = 4 * coarse.label[q] + std::size_t(t);
    fine.orientation[f] = Panel_orientation(coarsening.own_corner[f] + (o.is_reversed() ? 4 : 0));
  }
  return fine;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_IMPL_H
