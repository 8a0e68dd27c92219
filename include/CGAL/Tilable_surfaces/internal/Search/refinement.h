// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_H

// The choice of K_set_tilable_surface::refine_to() between two solves of a
// result refined to more clusters: the splits re-tag on the input quads and
// may pick another symmetry of an S-quad, so the current positions are then
// no longer exact and the solve from the input sometimes ends closer
// (De Beers 28 -> 30: 1.35% against 1.62% of the diagonal with the
// orientations kept).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Search/candidate_solver.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_parameters.h>

#include <cstddef>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The clustering `current`, its largest clusters split to `k`, solved two
// ways, the better kept (is_better()): every face keeping its orientation in
// `current`, from the mesh's points when they are exact and kept when the
// solve does not end better; and with the orientations the splits chose,
// from the input. Both solves run at once with several threads.
// `retagged_wins` tells whether the second was kept.
template <typename ConcurrencyTag, typename Solver, typename NP>
typename Solver::Solution refined_solution(const Solver& solver, const Face_clustering& current, std::size_t k,
                                           const NP& np, bool& retagged_wins)
{
  typedef typename Solver::Solution Solution;
  const Point_matrix start = solver.current_points();
  // The splits on a copy of the model: the edge-sharing graph that
  // K_set_tilable_surface::split_cluster() rebuilds is not needed between them.
  const Face_clustering retagged = with_concurrency<ConcurrencyTag>([&] { return solver.split_to(current, k); });
  Face_clustering kept = retagged;
  kept.orientation = current.orientation;
  const std::size_t ways = kept.orientation == retagged.orientation ? 1 : 2;
  auto&& visitor = visitor_of(np);
  std::mutex mutex;
  Locked_visitor locked(visitor, mutex);
  Visitor_ref shared(locked);
  const auto solve_np = with_visitor(np, shared);
  std::vector<Solution> solved(ways);
  with_concurrency<ConcurrencyTag>([&] {
    parallel_for(ways, [&](std::size_t j) {
      solved[j] = j == 0 ? solver.solved_model(kept, solve_np, &start)
                         : solver.solved_model(retagged, solve_np, nullptr);
    });
  });
  retagged_wins = ways == 2 && is_better(solved[1].optimization, solved[0].optimization);
  return std::move(solved[retagged_wins ? 1 : 0]);
}

// Why refine_to() chose its result, in words.
CGAL_TILABLE_SURFACES_INLINE
std::string refinement_reason(std::size_t refined_k, std::size_t k, bool retagged_wins);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Search/refinement_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_REFINEMENT_H
