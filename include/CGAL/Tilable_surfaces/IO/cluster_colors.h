// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_H
#define CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_H

/// \file cluster_colors.h
/// A distinct, deterministic colour per cluster, for coloured output meshes.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/IO/Color.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// Returns `number_of_colors` pairwise distinct RGB colours. Hues follow the
/// golden angle, so neighbouring ids get far-apart hues; saturation and value
/// cycle through a few levels so that large counts stay distinct; an exact
/// repeat (possible only for thousands of ids) is nudged to the next unused
/// RGB triple. The same count always gives the same colours.
CGAL_TILABLE_SURFACES_INLINE
std::vector<CGAL::IO::Color> cluster_colors(std::size_t number_of_colors);

namespace internal {

// The cluster id `id` as an index; a negative id is refused.
template <typename Id>
std::size_t cluster_index(const Id& id)
{
  if constexpr(std::is_signed<Id>::value)
    if(id < 0)
      throw Invalid_input("a face has the negative cluster id " + std::to_string(id) +
                          " (cluster ids are 0..K-1)", Invalid_input::FACE);
  return std::size_t(id);
}

// The number of clusters of the faces of `pm`: 1 + the largest id in
// `clusters` (0 for a mesh without faces), the number of colours and
// materials the writers emit.
template <typename PolygonMesh, typename FaceClusterMap>
std::size_t number_of_face_clusters(const PolygonMesh& pm, const FaceClusterMap& clusters)
{
  std::size_t n = 0;
  for(auto f : faces(pm))
    n = (std::max)(n, cluster_index(get(clusters, f)) + 1);
  return n;
}

} // namespace internal

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/cluster_colors_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_H
