// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_IMPL_H

// The bodies of the non-template functions declared in quad_layout.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::vector<std::size_t> > patch_faces(const std::vector<std::size_t>& patch_of_face)
{
  std::vector<std::vector<std::size_t> > faces;
  for(std::size_t f = 0; f < patch_of_face.size(); ++f)
  {
    if(patch_of_face[f] >= faces.size()) faces.resize(patch_of_face[f] + 1);
    faces[patch_of_face[f]].push_back(f);
  }
  return faces;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_IMPL_H
