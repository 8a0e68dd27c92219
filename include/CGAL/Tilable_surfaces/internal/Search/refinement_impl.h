// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_IMPL_H

// The bodies of the non-template functions declared in refinement.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Search/refinement.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::string refinement_reason(std::size_t refined_k, std::size_t k, bool retagged_wins)
{
  return "the result at K = " + std::to_string(refined_k) + ", its largest clusters split to K = " +
         std::to_string(k) + ", solved " +
         (retagged_wins ? "from the input with the orientations the splits chose"
                        : "from there with every face's orientation kept") +
         " (refine_to())";
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_IMPL_H
