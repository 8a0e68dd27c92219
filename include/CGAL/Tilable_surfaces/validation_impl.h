// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_VALIDATION_IMPL_H
#define CGAL_TILABLE_SURFACES_VALIDATION_IMPL_H

// The bodies of the non-template functions declared in validation.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/validation.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
void check_face_label(std::size_t fi, long long c, long long o, std::size_t number_of_clusters,
                      int corners)
{
  if(c < 0 || std::size_t(c) >= number_of_clusters)
    throw Invalid_input("face " + std::to_string(fi) + " has cluster " + std::to_string(c) +
                        (number_of_clusters == (std::numeric_limits<std::size_t>::max)()
                           ? std::string(", a cluster id must be >= 0")
                           : ", not in 0.." + std::to_string(number_of_clusters - 1)),
                        Invalid_input::FACE, fi);
  if(o < 0 || o > 7)
    throw Invalid_input("face " + std::to_string(fi) + " has orientation " + std::to_string(o) +
                        ", not in 0..7", Invalid_input::FACE, fi);
  if(!Panel_orientation(int(o)).is_valid_for(corners))
    throw Invalid_input("face " + std::to_string(fi) + " is a triangle and has orientation " +
                        std::to_string(o) + ", not one of a triangle's (0, 1, 2, 4, 5, 6)",
                        Invalid_input::FACE, fi);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_VALIDATION_IMPL_H
