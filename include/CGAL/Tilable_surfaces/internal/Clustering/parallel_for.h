// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PARALLEL_FOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PARALLEL_FOR_H

// Runs body(i) for i in [0, n), in parallel with TBB when CGAL is linked with
// it. Callers only write slot i of their outputs in body(i) and combine the
// slots sequentially afterwards, so results do not depend on the threads.

#include <CGAL/config.h>

#include <cstddef>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename Body>
void parallel_for(std::size_t n, const Body& body)
{
#ifdef CGAL_LINKED_WITH_TBB
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for(std::size_t i = r.begin(); i != r.end(); ++i)
                        body(i);
                    });
#else
  for(std::size_t i = 0; i < n; ++i)
    body(i);
#endif
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PARALLEL_FOR_H
