// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_COMPILED_PIPELINE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_COMPILED_PIPELINE_H

// With CGAL_TILABLE_SURFACES_COMPILED_LIBRARY (internal/config.h): the
// pipeline below make_k_set_tilable() and k_set_tilable_curve() on a
// CGAL::Surface_mesh of Simple_cartesian<double> points with its own maps,
// as the canonical parameters carry it (internal/canonical_parameters.h),
// is instantiated once, in the library (its source pipeline_*.cpp), and
// declared `extern` here for every other unit. Instantiating it costs about
// 30 s of compilation at -O2 for each concurrency tag, in each unit that
// calls it. Other mesh types, maps and parameter kinds are instantiated
// where they are used, as header-only.

#include <CGAL/Tilable_surfaces/K_set_tilable_surface.h>
#include <CGAL/Tilable_surfaces/internal/Search/tile_count_search.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/visitor.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <utility>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

typedef CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3> Compiled_mesh;
typedef CGAL::GetVertexPointMap<Compiled_mesh>::type Compiled_vertex_point_map;
typedef decltype(CGAL::get_initialized_face_index_map(std::declval<Compiled_mesh&>())) Compiled_face_index_map;
typedef CGAL::Simple_cartesian<double>::Point_3 Compiled_point;
// The parameters that make_k_set_tilable() and k_set_tilable_curve() hand to the pipeline.
typedef decltype(canonical_inputs(with_visitor(parameters::default_values(), std::declval<Visitor_ref&>())))
  Compiled_parameters;

template <typename ConcurrencyTag>
using Compiled_surface = K_set_tilable_surface<ConcurrencyTag, Compiled_mesh, Compiled_vertex_point_map>;

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

// The explicit instantiations, `extern` (EXTERN = extern) or not (EXTERN
// empty, in the library), for one concurrency tag.
#define CGAL_TILABLE_SURFACES_PIPELINE_INSTANTIATIONS(EXTERN, TAG)                                        \
  namespace CGAL {                                                                                         \
  namespace Tilable_surfaces {                                                                             \
  namespace internal {                                                                                     \
  EXTERN template void cluster_and_optimize<Compiled_surface<TAG>, Compiled_parameters, Visitor_ref>(      \
    Compiled_surface<TAG>&, const Compiled_parameters&, Visitor_ref&, K_set_tilable_result&);             \
  EXTERN template Kept_result<Compiled_point>                                                              \
  result_at<Compiled_surface<TAG>, Compiled_mesh, Compiled_vertex_point_map, Compiled_face_index_map,      \
            Compiled_point, Compiled_parameters, Visitor_ref>(                                             \
    std::size_t, Compiled_surface<TAG>&, Compiled_mesh&, Compiled_vertex_point_map, Compiled_face_index_map, \
    const Refinement_sources<Compiled_point>&, const Compiled_parameters&, Visitor_ref&, bool&);          \
  }                                                                                                        \
  }                                                                                                        \
  }

CGAL_TILABLE_SURFACES_PIPELINE_INSTANTIATIONS(extern, CGAL::Sequential_tag)
#ifdef CGAL_LINKED_WITH_TBB
CGAL_TILABLE_SURFACES_PIPELINE_INSTANTIATIONS(extern, CGAL::Parallel_tag)
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_COMPILED_PIPELINE_H
