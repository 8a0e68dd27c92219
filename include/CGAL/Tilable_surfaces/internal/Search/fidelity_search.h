// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_FIDELITY_SEARCH_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_FIDELITY_SEARCH_H

// The fidelity search of K_set_tilable_surface::optimize_closest() (user
// manual, section "Fidelity"): which clusterings of the candidate pool are
// solved, how far, and the edit rounds after them, looking for the tilable
// result closest to the input.
//
// 1. The candidates solved first from an exact start (origin_traits(): the
//    sweep clusterings, user manual, section TS_Sweeps, and the multilevel
//    start, section TS_Multilevel) are solved from the surface at which they
//    are exact, for at most tuning::sweep_polish_iterations (none above
//    large_mesh_faces, where each iteration costs seconds for little: cmc1
//    subdivided 3 times, 15k quads, is 0.323% of the diagonal away from its
//    multilevel start and 0.317% after ten iterations that take 44 s; at 61k
//    they take 285 s and do not end exact), that surface kept when the solve
//    does not end exact. The best of them
//    is a fallback the final result must beat; it is not ranked, sets no
//    iteration cap and starts no round. When number_of_optimized_candidates
//    is 0 (its default above large_mesh_faces) and one is exact, the search
//    ends there. Without an exact one, 0 counts as 1.
// 2. The other candidates are ranked two ways: by predicted displacement
//    (one candidate per thread, each a serial factorization, so the values
//    are those of one thread; none above large_mesh_faces, where each would
//    factorize the solver's whole matrix: the spread alone ranks there), and
//    by the spread of the input's edge lengths their edge-sharing graph ties
//    together (Clustering_candidate::length_deviation). Shape similarity and
//    DOF do not say how far a clustering moves the surface; these do, the
//    first to first order, the second for the long-range equalities the
//    linearization underrates (tunnel stand-in, K = 10: the ring clustering
//    ranks below the hierarchical ones by prediction, first by spread, and
//    ends 2x closer than the first by prediction). Taking the two rankings in
//    turn, the number_of_optimized_candidates first are solved fully from the
//    input, then each origin with an extra quota (origin_traits(): the grid
//    segments, a quarter as many) adds that many more in pool order: both
//    rankings underrate them (seashell stand-in, K = 60: the one that keeps
//    the spiral ends at 2.2% of the diagonal, the best of the others 5.7%).
//    Each solve after the first may take tuning::iteration_cap_factor times
//    the iterations of the best result so far (at least
//    tuning::minimum_iteration_cap): one that cannot converge in them is
//    unlikely to end closer, and non-converging solves would otherwise cost
//    the whole budget. With several threads the next candidate is solved
//    beside the current one with the same cap, and kept if the cap has not
//    changed when its turn comes: solves are deterministic, so the results
//    are those of one candidate at a time.
// 3. Then number_of_improvement_rounds rounds of edits, K fixed: the cluster
//    whose instances moved most (mean off-input distance of their corners)
//    is split in two; of the tuning::predicted_merge_pairs pairs of clusters
//    whose merge spreads the input's edge lengths least, the one of smallest
//    predicted displacement is merged (above large_mesh_faces the one of
//    least spread); orientations are re-tagged and the result solved again
//    from the input. A round that does not improve the result is not
//    repeated: the next one splits the next cluster in that order.
// 4. While the best result is not tilable, up to tuning::repair_rounds more
//    rounds (none when number_of_improvement_rounds is 0) repair it the same
//    way, splitting the cluster whose instances fit their S-quad worst: its
//    clustering may have no exact realization near the input (6-sub-lifted,
//    K = 7: every candidate and a local-global projection stall near 5e-2).
//
// A result replaces the best one only if is_better(). The search runs on the
// public steps of the surface (optimize(), the edits, restore_input()) and
// on its state (Tilable_surface_state), through which it solves candidates on
// copies (Candidate_solver), keeps and restores results (Solution), and
// reads the pool and writes the choice (Clustering_result).

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>
#include <CGAL/Tilable_surfaces/internal/Search/candidate_solver.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Real_timer.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The number_of_optimized_candidates of `np` for a mesh of `number_of_faces` faces.
template <typename NP>
std::size_t optimized_candidate_count(const NP& np, std::size_t number_of_faces)
{
  return parameter_or(np, internal_np::number_of_optimized_candidates,
                      default_number_of_optimized_candidates(number_of_faces));
}

// Whether the fidelity search with the parameters `np` ends at an exact sweep
// clustering whenever the pool has one (above large_mesh_faces, 0 optimized
// candidates): the clusterer then need not make the other candidates.
template <typename NP>
bool exact_sweep_ends_search(const NP& np, std::size_t number_of_faces)
{
  return number_of_faces > large_mesh_faces && optimized_candidate_count(np, number_of_faces) == 0;
}

// The fidelity search on `Surface` (a K_set_tilable_surface with a
// candidate pool) and its `State`, with the parameters `NamedParameters` of
// its optimize(), which pass `Visitor` on by reference.
template <typename ConcurrencyTag, typename Surface, typename State, typename NamedParameters, typename Visitor>
class Fidelity_search
{
  typedef typename State::Solution Solution;

public:
  Fidelity_search(Surface& surface, State& state, const NamedParameters& np, Visitor& visitor)
    : m_surface(surface), m_state(state), m_np(np), m_visitor(visitor), m_solver(state.candidate_solver())
  {
    m_optimized = optimized_candidate_count(np, m_solver.number_of_faces());
    m_rounds = parameter_or(np, internal_np::number_of_improvement_rounds, defaults::number_of_improvement_rounds);
    m_timer.start();
    m_user_iterations =
      parameter_or(np, CGAL::internal_np::number_of_iterations, default_number_of_iterations(CONSTRAINED_GAUSS_NEWTON));
  }

  // Runs the search; the surface holds the best result at the end, its
  // clustering() says why it was chosen.
  const Optimization_result& run()
  {
    solve_exact_starts();
    m_sweep_suffices = m_optimized == 0 && has_exact_start();
    if(!m_stopped && !m_sweep_suffices)
      rank_candidates();
    solve_ranked_candidates();
    if(m_ranked.empty() && m_best_sweep) // a sweep suffices, or the visitor stopped one's solve
    {
      m_best = std::move(*m_best_sweep);
      m_best_sweep.reset();
      m_state.clustering.chosen_candidate = m_best_sweep_index;
    }
    m_state.set_solution(m_best);
    run_edit_rounds();
    // The sweep, if the result did not beat it.
    const bool sweep_chosen =
      m_ranked.empty() || (m_best_sweep && is_better(m_best_sweep->optimization, m_best.optimization));
    if(m_best_sweep && sweep_chosen)
    {
      m_state.set_solution(*m_best_sweep);
      m_state.clustering.chosen_candidate = m_best_sweep_index;
    }
    Clustering_result& clustering = m_state.clustering;
    clustering.choice_reason = choice_reason(sweep_chosen) + "; " + clustering.choice_reason;
    clustering.number_of_edit_rounds = std::size_t(m_rounds_done);
    return m_surface.optimization();
  }

private:
  template <typename F>
  static auto with_concurrency(const F& f) { return internal::with_concurrency<ConcurrencyTag>(f); }

  const std::vector<Clustering_candidate>& pool() const { return m_state.clustering.candidates; }

  // Step 1: the candidates solved first from their exact start (the sweep
  // clusterings, the multilevel start), a tilable result within seconds
  // whatever the size. Kept apart: a result that beats the best of them is
  // the one found without it.
  void solve_exact_starts()
  {
    for(std::size_t i = 0; i < pool().size() && !m_stopped; ++i)
    {
      const Candidate_origins::Origin origin = pool()[i].origin;
      if(!origin_traits(origin).solved_first_from_start)
        continue;
      m_timer.reset();
      const int polish = m_solver.number_of_faces() > large_mesh_faces ? 0 : tuning::sweep_polish_iterations;
      Solution solved = with_concurrency([&] {
        return m_solver.solved_candidate(i, m_np.number_of_iterations((std::min)(m_user_iterations, polish)));
      });
      keep_exact_start(std::move(solved), i);
      m_visitor.phase(origin == Clustering_candidate::MULTILEVEL ? "multilevel start" : "sweep candidate",
                      m_timer.time());
    }
  }

  // Whether a sweep or the multilevel start ended exact.
  bool has_exact_start() const { return m_best_sweep && m_best_sweep->optimization.converged; }

  // A candidate `i` solved from its exact start becomes the fallback if it is better.
  void keep_exact_start(Solution solved, std::size_t i)
  {
    m_stopped = solved.optimization.stopped_by_visitor;
    if(!m_best_sweep || is_better(solved.optimization, m_best_sweep->optimization))
    {
      m_best_sweep = std::move(solved);
      m_best_sweep_index = i;
    }
  }

  // Whether the candidates are ranked by predicted displacement. Above
  // large_mesh_faces a prediction factorizes the solver's whole matrix, one
  // per candidate and thread (spot_quadrangulated subdivided to 187k quads:
  // 8 GB and 2 minutes each): there the length spread ranks alone.
  bool predicts_displacements() const { return m_solver.number_of_faces() <= large_mesh_faces; }

  // Step 2: the candidates most likely to end closest.
  void rank_candidates()
  {
    m_timer.reset();
    const bool predict = predicts_displacements();
    m_ranked = ranked_candidates((std::max)(std::size_t(1), m_optimized), predict);
    if(predict)
      m_visitor.phase("displacement prediction", m_timer.time());
  }

  // The candidates to solve: ranked two ways, taken in turn, by predicted
  // displacement (unless not `predict`: then by spread alone) and by the
  // spread of edge lengths they tie together, the `optimized` first; then
  // the extra quota of each origin that has one.
  std::vector<std::size_t> ranked_candidates(std::size_t optimized, bool predict)
  {
    if(predict)
      predict_candidates();
    std::vector<std::pair<double, std::size_t> > by_prediction, by_spread;
    for(std::size_t i = 0; i < pool().size(); ++i)
    {
      const Clustering_candidate& candidate = pool()[i];
      if(!origin_traits(candidate.origin).ranked)
        continue;
      by_prediction.push_back({candidate.predicted_displacement, i});
      by_spread.push_back({candidate.length_deviation, i});
    }
    std::sort(by_prediction.begin(), by_prediction.end());
    std::sort(by_spread.begin(), by_spread.end());
    std::vector<std::size_t> ranked;
    for(std::size_t r = 0; r < by_prediction.size(); ++r)
      for(std::size_t i : {predict ? by_prediction[r].second : by_spread[r].second, by_spread[r].second})
        if(std::find(ranked.begin(), ranked.end(), i) == ranked.end())
          ranked.push_back(i);
    ranked.resize((std::min)(optimized, ranked.size()));
    add_extra_quotas(ranked, optimized);
    return ranked;
  }

  // After the ranked candidates, ceil(optimized / divisor) more of each
  // origin with an extra_quota_divisor, in pool order, since both rankings
  // underrate their long-range ties.
  void add_extra_quotas(std::vector<std::size_t>& ranked, std::size_t optimized) const
  {
    std::map<Clustering_candidate::Origin, std::size_t> extra;
    for(std::size_t i = 0; i < pool().size(); ++i)
    {
      const Clustering_candidate::Origin origin = pool()[i].origin;
      const std::size_t divisor = origin_traits(origin).extra_quota_divisor;
      if(divisor == 0 || std::find(ranked.begin(), ranked.end(), i) != ranked.end())
        continue;
      auto quota = extra.emplace(origin, (optimized + divisor - 1) / divisor).first;
      if(quota->second > 0)
      {
        ranked.push_back(i);
        --quota->second;
      }
    }
  }

  // Sets `predicted_displacement` of every ranked candidate of the pool,
  // from the input positions: in parallel, each into its own slot with its
  // own maps. One prediction is one serial factorization (sparse_solver.h),
  // so this is where the threads pay, and every value is the one a single
  // thread computes.
  void predict_candidates()
  {
    m_surface.restore_input();
    std::vector<Clustering_candidate>& pool = m_state.clustering.candidates;
    with_concurrency([&] {
      internal::parallel_for(pool.size(), [&](std::size_t i) {
        if(!origin_traits(pool[i].origin).ranked)
          return;
        std::size_t unused_dof;
        pool[i].predicted_displacement = m_solver.predicted_displacement(m_solver.candidate_model(i, unused_dof), m_np);
      });
    });
  }

  // Each ranked candidate solved fully from the input; the best kept.
  void solve_ranked_candidates()
  {
    Solved_ahead ahead;
    for(std::size_t r = 0; r < m_ranked.size() && !m_stopped; ++r)
    {
      m_timer.reset();
      const int cap = r == 0 ? m_user_iterations : iteration_cap();
      Solution solved = solve_ranked_candidate(r, cap, ahead);
      m_stopped = solved.optimization.stopped_by_visitor;
      if(r == 0 || is_better(solved.optimization, m_best.optimization))
      {
        m_best = std::move(solved);
        m_state.clustering.chosen_candidate = m_ranked[r];
      }
      m_visitor.phase("candidate optimization", m_timer.time());
    }
  }

  // A few times the iterations the best result took, at least a minimum, at
  // most the user's limit.
  int iteration_cap() const
  {
    return (std::min)(m_user_iterations, (std::max)(tuning::minimum_iteration_cap,
                                                    tuning::iteration_cap_factor * m_best.optimization.iterations));
  }

  // A candidate solved before its turn, with the iteration cap it was given.
  struct Solved_ahead
  {
    std::optional<Solution> solution;
    std::size_t rank = 0;
    int cap = 0;
  };

  // The solve of candidate m_ranked[r] with `cap` iterations, from the
  // input. With several threads, candidate m_ranked[r + 1] is solved beside
  // it with the same cap and kept in `ahead`: it is exactly the next solve if
  // the cap does not change, that is, unless candidate r becomes the best
  // with a different iteration count (the cap of the first candidate is the
  // user's, so its successor is not solved ahead).
  Solution solve_ranked_candidate(std::size_t r, int cap, Solved_ahead& ahead)
  {
    if(ahead.solution && ahead.rank == r && ahead.cap == cap)
    {
      Solution solved = std::move(*ahead.solution);
      ahead.solution.reset();
      return solved;
    }
    ahead.solution.reset();
    auto&& visitor = internal::visitor_of(m_np);
    std::mutex mutex;
    Locked_visitor locked(visitor, mutex);
    Visitor_ref shared(locked);
    const auto solve_np = internal::with_visitor(m_np, shared).number_of_iterations(cap);
    const bool solve_ahead =
      r > 0 && r + 1 < m_ranked.size() && with_concurrency([] { return internal::several_threads_available(); });
    std::vector<Solution> solved(solve_ahead ? 2 : 1);
    with_concurrency([&] {
      internal::parallel_for(solved.size(),
                             [&](std::size_t j) { solved[j] = m_solver.solved_candidate(m_ranked[r + j], solve_np); });
    });
    if(solve_ahead)
      ahead = Solved_ahead{std::move(solved[1]), r + 1, cap};
    return std::move(solved[0]);
  }

  // Steps 3 and 4: the improvement rounds, then the repair rounds while the
  // best is not tilable.
  void run_edit_rounds()
  {
    std::size_t failed_in_a_row = 0;
    for(int round = 0; (round < m_rounds || (m_rounds > 0 && round < m_rounds + tuning::repair_rounds &&
                                             !m_best.optimization.converged)) &&
                       m_surface.number_of_clusters() > 1 && !m_stopped && !m_sweep_suffices;
        ++round)
    {
      m_timer.reset();
      if(!improvement_edit(failed_in_a_row))
        break;
      ++m_rounds_done;
      m_surface.optimize(m_np.number_of_iterations(iteration_cap()));
      if(is_better(m_surface.optimization(), m_best.optimization))
      {
        m_best = m_state.solution();
        failed_in_a_row = 0;
      }
      else
        ++failed_in_a_row;
      const bool round_stopped = m_surface.optimization().stopped_by_visitor;
      m_state.set_solution(m_best);
      m_visitor.phase("improvement round", m_timer.time());
      if(round_stopped)
        break;
    }
  }

  // One edit of an improvement round on the current (best) result: split
  // the `rank`-th cluster of cluster_to_split()'s order, merge the pair of
  // pair_to_merge(), re-tag. False when no edit applies.
  bool improvement_edit(std::size_t rank)
  {
    const std::optional<std::size_t> worst = cluster_to_split(rank);
    if(!worst)
      return false;
    m_surface.restore_input();
    m_surface.split_cluster(*worst);
    const std::optional<std::pair<std::size_t, std::size_t> > pair = pair_to_merge(*worst);
    if(!pair)
      return false;
    m_surface.merge_clusters(pair->first, pair->second);
    m_surface.retag_orientations();
    return true;
  }

  // The `rank`-th (0 first) of the clusters that can be split, the worst
  // first: the one whose instances moved most, or, if the result is not
  // tilable, the one whose instances fit their S-quad worst. The merge that
  // follows joins two clusters of one kind (quads and triangles never share
  // one) other than the two parts: some kind must have two clusters besides
  // the one split.
  std::optional<std::size_t> cluster_to_split(std::size_t rank) const
  {
    const std::size_t k = m_surface.number_of_clusters();
    std::vector<double> moved;
    std::vector<std::size_t> size;
    m_solver.corner_displacements(m_state.model, moved, size);
    const Optimization_result& current = m_surface.optimization();
    const bool repair = !current.converged;
    const std::vector<double>& misfit = current.measure.cluster_congruence_errors;
    auto badness = [&](std::size_t c) {
      return repair && c < misfit.size() ? misfit[c] : moved[c] / double(size[c]);
    };
    std::size_t clusters_of_kind[5] = {0, 0, 0, 0, 0};  // by corner count, 3 or 4
    for(std::size_t c = 0; c < k; ++c)
      ++clusters_of_kind[m_surface.edge_sharing_graph().corner_count(c)];
    std::vector<std::size_t> splittable;
    for(std::size_t c = 0; c < k; ++c)
    {
      const int kind = m_surface.edge_sharing_graph().corner_count(c);
      if(size[c] >= 2 && (clusters_of_kind[kind] >= 2 || clusters_of_kind[7 - kind] >= 2))
        splittable.push_back(c);
    }
    if(rank >= splittable.size())
      return std::nullopt;
    std::stable_sort(splittable.begin(), splittable.end(),
                     [&](std::size_t a, std::size_t b) { return badness(a) > badness(b); });
    return splittable[rank];
  }

  // After cluster `split` was split (its second part the last cluster): of
  // the pairs of clusters whose merge spreads the input's edge lengths least
  // (the correspondence is not known before the merge: the least spread over
  // the 8), the one of smallest predicted displacement, each merged in a copy
  // and predicted in parallel; the least spread alone when no displacement
  // is predicted. None when no pair can merge.
  std::optional<std::pair<std::size_t, std::size_t> > pair_to_merge(std::size_t split)
  {
    const auto& graph = m_surface.edge_sharing_graph();
    const std::size_t k = m_surface.number_of_clusters();
    std::vector<std::pair<double, std::pair<std::size_t, std::size_t> > > pairs;
    for(std::size_t a = 0; a < k; ++a)
      for(std::size_t b = a + 1; b < k; ++b)
      {
        if((a == split && b == k - 1) || graph.corner_count(a) != graph.corner_count(b))
          continue; // that would undo the split, or mix quads and triangles
        double spread = std::numeric_limits<double>::infinity();
        for(int o = 0; o < 8; ++o)
          spread = (std::min)(spread, graph.length_deviation_after_merge(a, b, Panel_orientation(o)));
        pairs.push_back({spread, {a, b}});
      }
    if(pairs.empty())
      return std::nullopt;
    std::sort(pairs.begin(), pairs.end());
    pairs.resize((std::min)(pairs.size(), predicts_displacements() ? tuning::predicted_merge_pairs : std::size_t(1)));
    std::vector<double> prediction(pairs.size());
    if(pairs.size() > 1)
      with_concurrency([&] {
        internal::parallel_for(pairs.size(), [&](std::size_t i) {
          prediction[i] = m_solver.predicted_displacement_after_merge(m_state.model,
                                                                      pairs[i].second.first, pairs[i].second.second,
                                                                      m_np);
        });
      });
    return pairs[std::size_t(std::min_element(prediction.begin(), prediction.end()) - prediction.begin())].second;
  }

  // Why the result was chosen, in words.
  std::string choice_reason(bool sweep_chosen) const
  {
    const std::string start = origin_traits(pool()[m_best_sweep_index].origin).name; // sweep or multilevel
    if(m_sweep_suffices)
      return "an exact " + start + " clustering, no other candidate optimized (number_of_optimized_candidates 0)";
    const Clustering_candidate& chosen = m_state.clustering.candidates[m_state.clustering.chosen_candidate];
    return std::string(sweep_chosen ? "a " + start + " clustering, better than "
                                    : "closest result (from a " + std::string(origin_traits(chosen.origin).name) +
                                        " candidate) among ") +
           "the " + std::to_string(m_ranked.size()) +
           " candidates of smallest predicted displacement or length spread, or first segment clusterings, then " +
           std::to_string(m_rounds_done) + " improvement or repair rounds";
  }

  Surface& m_surface;
  State& m_state;
  const NamedParameters& m_np;
  Visitor& m_visitor;
  const Candidate_solver<State> m_solver;
  std::size_t m_optimized = 0;  // number_of_optimized_candidates
  int m_rounds = 0;             // number_of_improvement_rounds
  int m_user_iterations = 0;    // number_of_iterations
  CGAL::Real_timer m_timer;     // of the current phase
  bool m_stopped = false;       // by the visitor: nothing more is solved
  std::optional<Solution> m_best_sweep;
  std::size_t m_best_sweep_index = 0;
  bool m_sweep_suffices = false;
  std::vector<std::size_t> m_ranked;  // the candidates solved, in that order
  Solution m_best;
  int m_rounds_done = 0;
};

// K_set_tilable_surface::optimize_closest() on `surface` and its `state`,
// whose pool is not empty.
template <typename ConcurrencyTag, typename Surface, typename State, typename NamedParameters>
const Optimization_result& optimize_closest(Surface& surface, State& state, const NamedParameters& user_np)
{
  auto&& visitor = visitor_of(user_np);
  const auto np = with_visitor(user_np, visitor);
  typedef std::remove_reference_t<decltype(visitor)> Visitor;
  Fidelity_search<ConcurrencyTag, Surface, State, std::remove_cv_t<decltype(np)>, Visitor> search(surface, state, np,
                                                                                                  visitor);
  return search.run();
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_FIDELITY_SEARCH_H
