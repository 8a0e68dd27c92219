// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_PARALLEL_FOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_PARALLEL_FOR_H

// Runs body(i) for i in [0, n), in parallel with TBB when CGAL is linked with
// it. Callers only write slot i of their outputs in body(i) and combine the
// slots sequentially afterwards, so results do not depend on the threads.
// The public functions choose the parallelism with their ConcurrencyTag
// (run_with_concurrency()), so no signature below them carries it.

#include <CGAL/config.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <type_traits>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
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

// Whether a parallel_for() called here may run on more than one thread: in
// this arena, within the process's limit. Only for choosing whether work
// done ahead may pay; never for what a result is.
inline bool several_threads_available()
{
#ifdef CGAL_LINKED_WITH_TBB
  return tbb::this_task_arena::max_concurrency() > 1 &&
         tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) > 1;
#else
  return false;
#endif
}

// Runs f() with the parallelism `ConcurrencyTag` asks for. With
// `CGAL::Sequential_tag`, in a TBB arena of one thread, where every
// parallel_for() is a plain loop; with `CGAL::Parallel_tag` or
// `CGAL::Parallel_if_available_tag`, in the caller's arena. Exceptions pass
// through.
template <typename ConcurrencyTag, typename F>
void run_with_concurrency(const F& f)
{
  // (CGAL::Parallel_if_available_tag is one of the two.)
  static_assert(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value ||
                std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "ConcurrencyTag must be CGAL::Sequential_tag, CGAL::Parallel_tag or "
                "CGAL::Parallel_if_available_tag");
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(std::is_same<ConcurrencyTag, CGAL::Sequential_tag>::value)
  {
    tbb::task_arena one_thread(1);
    one_thread.execute(f);
  }
  else
    f();
#else
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL::Parallel_tag needs TBB (CGAL::TBB_support); use "
                "CGAL::Parallel_if_available_tag or CGAL::Sequential_tag");
  f();
#endif
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_PARALLEL_FOR_H
