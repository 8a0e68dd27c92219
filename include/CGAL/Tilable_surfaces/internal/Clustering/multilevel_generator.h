// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MULTILEVEL_GENERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MULTILEVEL_GENERATOR_H

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The multilevel candidate generator (CandidateGenerator, origin
// MULTILEVEL): the exact start prolongated from a coarser mesh, made by the
// hook Clustering_settings::multilevel_start (internal/Search/multilevel_start.h),
// which K_set_tilable_surface::cluster() sets where that start applies; it
// needs the whole pipeline on the coarse mesh, which the clusterer cannot
// run itself.
struct Multilevel_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    std::vector<typename Context::Candidate> result;
    if(context.settings.multilevel_start)
      if(auto candidate = context.settings.multilevel_start(context.k, context.visitor))
        result.push_back(std::move(*candidate));
    return result;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MULTILEVEL_GENERATOR_H
