// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_BEAM_SEARCH_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_BEAM_SEARCH_H

// Hierarchical clustering by binary merges with a beam of candidate
// configurations (paper §3 "Cluster Merge", §5 "Clustering Enhancement").
//
// A configuration groups the N initial clusters; group g keeps the id of one
// of its initial clusters, and that cluster's leader quad labels its S-quad.
// From each configuration of the beam with k groups, every pair of groups is
// proposed when k <= 128, as in the paper's exhaustive search with early
// termination (proposing fewer pairs misses flexible configurations: on the
// TUNNEL at K = 12, clusters that follow the rings keep DOF 24 where the
// cheapest-partner proposals end at 15). Above 128 groups, every group
// proposes its merge with its cheapest partner (kept exactly up to date after
// every merge; proposing only the globally cheapest merges loses much
// flexibility). With auto-merge, the pairs of groups whose S-quad edges lie
// in the same 4 components of the edge-sharing graph (merging them keeps the
// degree of flexibility) are proposed too. Every proposal is scored
//   score = W' / W1 + lambda * (D0 - D') / D0 + mu * V' / V1,
// W' the configuration's weight after the merge, W1 the weight of the
// single-cluster configuration, D' its degree of flexibility (from a tiny
// union-find over the components the merge joins), D0 the degree of
// flexibility of the initial clustering, V' the spread of the input's edge
// lengths within the components after the merge
// (Edge_sharing_graph::length_deviation_after_merge()) and V1 that of all the
// edges. V sees what shape alone does not: two quads of the same shape in
// different rings of a tube tie the lengths of both rings together. The
// `width` best distinct proposals form the beam for k - 1 groups.
//
// Since a merge never raises the DOF nor lowers V, the score with the DOF
// and V before the merge bounds a proposal's score from below. A proposal whose
// bound exceeds the worst of the `width` best distinct proposals found so far
// cannot enter the next beam and is not evaluated further; pairs are visited
// by increasing cost, so the rest of them is skipped too.
// The beam is the same as without this pruning.

#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/link_count.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

inline std::uint64_t mix64(std::uint64_t x)
{
  // splitmix64 finalizer: a fixed, seed-free hash for partition signatures.
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// The score of a configuration of weight w, degree of flexibility d and
// length deviation v (Edge_sharing_graph::length_deviation()):
//   w / w1 + lambda (d0 - d) / d0 + mu v / v1,
// with w1 the single-cluster weight, d0 the initial DOF and v1 the deviation
// of all edge lengths from their mean (see the file comment).
struct Configuration_score
{
  double single_cluster_weight = 1, flexibility_penalty = 0;
  std::size_t initial_dof = 1;
  double structure_penalty = 0, total_length_deviation = 1;

  double operator()(double w, std::size_t d, double v) const
  {
    const double w1 = single_cluster_weight > 0 ? single_cluster_weight : 1.0;
    const double v1 = total_length_deviation > 0 ? total_length_deviation : 1.0;
    return w / w1 +
           flexibility_penalty * (double(initial_dof) - double(d)) /
             double((std::max)(initial_dof, std::size_t(1))) +
           structure_penalty * v / v1;
  }
};

template <typename PolygonMesh, typename MergeCosts>
struct Beam_state
{
  typedef typename MergeCosts::Group Group;

  std::vector<std::vector<std::size_t> > members;  // initial clusters; empty: merged away
  std::vector<Group> groups;
  std::vector<std::size_t> faces;                  // number of faces per group
  std::vector<std::size_t> partner;                // cheapest partner of each group
  std::vector<double> partner_cost;
  std::vector<std::uint64_t> key;                  // sum of member hashes
  Edge_sharing_graph<PolygonMesh> graph;
  double weight = 0;
  std::size_t alive = 0;
  std::uint64_t hash = 0;                          // partition signature

  explicit Beam_state(const Edge_sharing_graph<PolygonMesh>& g) : graph(g) {}
};

template <typename PolygonMesh, typename MergeCosts>
class Beam_search
{
public:
  typedef Beam_state<PolygonMesh, MergeCosts> State;

  // `leaders[c]` is the quad labelling initial cluster c's S-quad.
  Beam_search(const MergeCosts& costs, const std::vector<Panel>& leaders,
              Orientation_policy policy, const Configuration_score& score,
              std::size_t width, bool auto_merge)
    : m_costs(costs), m_leaders(leaders), m_policy(policy)
    , m_score(score), m_width((std::max)(width, std::size_t(1)))
    , m_auto_merge(auto_merge)
  {}

  // The initial configuration: one group per initial cluster.
  State initial_state(const Edge_sharing_graph<PolygonMesh>& graph,
                      const std::vector<std::size_t>& faces_per_cluster) const
  {
    const std::size_t n = faces_per_cluster.size();
    State s(graph);
    s.members.resize(n);
    s.groups.resize(n);
    s.key.resize(n);
    s.faces = faces_per_cluster;
    for(std::size_t c = 0; c < n; ++c)
    {
      s.members[c] = {c};
      s.groups[c] = m_costs.initial_group(c);
      s.key[c] = mix64(c);
      s.hash += mix64(s.key[c]);
      s.weight += s.groups[c].weight;
    }
    s.alive = n;
    s.partner.assign(n, no_group());
    s.partner_cost.assign(n, 0.0);
    parallel_for(n, [&](std::size_t c) { find_partner(s, c); });
    return s;
  }

  // Merges down to `k` groups; returns the final beam, best score first.
  std::vector<State> run(State initial, std::size_t k) const
  {
    std::vector<State> beam;
    beam.push_back(std::move(initial));
    while(beam.front().alive > k)
    {
      std::vector<Proposal> proposals;
      Score_bound bound(m_width);
      for(std::size_t b = 0; b < beam.size(); ++b)
        propose(beam[b], b, bound, proposals);
      std::sort(proposals.begin(), proposals.end());
      std::vector<Proposal> chosen;
      std::unordered_set<std::uint64_t> seen;
      for(const Proposal& p : proposals)
      {
        if(chosen.size() == m_width)
          break;
        if(seen.insert(p.hash).second)
          chosen.push_back(p);
      }
      // The last child of a parent takes the parent's storage.
      std::vector<std::size_t> last_child(beam.size(), no_group());
      for(std::size_t i = 0; i < chosen.size(); ++i)
        last_child[chosen[i].parent] = i;
      std::vector<State> next;
      next.reserve(chosen.size());
      for(std::size_t i = 0; i < chosen.size(); ++i)
      {
        const Proposal& p = chosen[i];
        next.push_back(last_child[p.parent] == i ? std::move(beam[p.parent]) : beam[p.parent]);
        apply(next.back(), p);
      }
      beam.swap(next);
    }
    return beam;
  }

private:
  struct Proposal
  {
    double score;
    std::size_t parent, kept, removed;
    Panel_orientation correspondence;
    double cost;
    std::uint64_t hash;
    bool operator<(const Proposal& o) const
    {
      if(score != o.score) return score < o.score;
      if(parent != o.parent) return parent < o.parent;
      if(kept != o.kept) return kept < o.kept;
      return removed < o.removed;
    }
  };

  // The best score of each of the `width` best distinct partitions proposed so
  // far; `value()` only decreases as proposals are added.
  class Score_bound
  {
  public:
    explicit Score_bound(std::size_t width) : m_width(width) {}

    double value() const
    {
      return m_best.size() < m_width ? (std::numeric_limits<double>::max)()
                                     : m_best.back().first;
    }

    void add(double score, std::uint64_t hash)
    {
      auto it = std::find_if(m_best.begin(), m_best.end(),
                             [&](const std::pair<double, std::uint64_t>& b) { return b.second == hash; });
      if(it != m_best.end())
        it->first = (std::min)(it->first, score);
      else if(m_best.size() < m_width)
        m_best.push_back({score, hash});
      else if(score < m_best.back().first)
        m_best.back() = {score, hash};
      std::sort(m_best.begin(), m_best.end());
    }

  private:
    std::size_t m_width;
    std::vector<std::pair<double, std::uint64_t> > m_best;  // increasing scores
  };

  static std::size_t no_group() { return std::size_t(-1); }

  // Up to this many groups, every pair is proposed (see the file comment).
  static std::size_t exhaustive_limit() { return tuning::beam_exhaustive_groups; }

  // Groups of quads and of triangles never merge: their cost is infinite,
  // which no bound admits.
  double cost(const State& s, std::size_t a, std::size_t b) const
  {
    if(m_leaders[a].size() != m_leaders[b].size())
      return std::numeric_limits<double>::infinity();
    return m_costs.cost(s.members[a], s.groups[a], s.members[b], s.groups[b]);
  }

  // Cheapest partner of group c among the live groups (ties: smallest id).
  void find_partner(State& s, std::size_t c) const
  {
    s.partner[c] = no_group();
    for(std::size_t d = 0; d < s.members.size(); ++d)
    {
      if(d == c || s.members[d].empty())
        continue;
      const double x = cost(s, c, d);
      if(s.partner[c] == no_group() || x < s.partner_cost[c])
      {
        s.partner[c] = d;
        s.partner_cost[c] = x;
      }
    }
  }

  static std::uint64_t pair_key(const std::pair<std::size_t, std::size_t>& p)
  {
    return (std::uint64_t(p.first) << 32) | std::uint64_t(p.second);
  }

  // Template corner i of group a's S-quad <-> corner correspondence(i) of b's.
  Panel_orientation correspondence(std::size_t a, std::size_t b) const
  {
    const bool swapped = b < a;
    const std::pair<std::size_t, std::size_t> key = swapped ? std::make_pair(b, a)
                                                             : std::make_pair(a, b);
    auto it = m_correspondences.find(pair_key(key));
    if(it == m_correspondences.end())
      it = m_correspondences.emplace(pair_key(key), fast_best_match(m_leaders[key.first],
                                                                    m_leaders[key.second],
                                                                    m_policy).orientation).first;
    return swapped ? it->second.inverse(m_leaders[a].size()) : it->second;
  }

  // Computes the missing correspondences of `pairs` (a < b) in parallel: the
  // sequential part of the beam is dominated by them otherwise.
  void prefetch_correspondences(const std::vector<std::pair<std::size_t, std::size_t> >& pairs) const
  {
    std::vector<std::pair<std::size_t, std::size_t> > missing;
    for(const auto& p : pairs)
      if(!m_correspondences.count(pair_key(p))) missing.push_back(p);
    std::vector<Panel_orientation> found(missing.size());
    parallel_for(missing.size(), [&](std::size_t i) {
      found[i] = fast_best_match(m_leaders[missing[i].first], m_leaders[missing[i].second],
                                 m_policy).orientation;
    });
    for(std::size_t i = 0; i < missing.size(); ++i)
      m_correspondences.emplace(pair_key(missing[i]), found[i]);
  }

  // Number of components joined by merging `removed` into `kept`.
  static std::size_t joined_components(const State& s, std::size_t kept, std::size_t removed,
                                        Panel_orientation corr)
  {
    const int n = s.graph.corner_count(kept);
    std::array<std::pair<std::size_t, std::size_t>, 4> links;
    for(int k = 0; k < n; ++k)
      links[std::size_t(k)] = {s.graph.component(kept, k), s.graph.component(removed, corr.face_edge(k, n))};
    return number_of_joins(links, std::size_t(n));
  }

  // The lowest score a merge of cost `cost` can get from `s` (see the file comment).
  double score_lower_bound(const State& s, double cost) const
  {
    return m_score(s.weight + cost, s.graph.degree_of_flexibility(), s.graph.length_deviation());
  }

  void add_proposal(const State& s, std::size_t parent, std::size_t a, std::size_t b,
                    double cost, Score_bound& bound,
                    std::vector<Proposal>& out) const
  {
    const bool a_kept = s.faces[a] > s.faces[b] || (s.faces[a] == s.faces[b] && a < b);
    Proposal p;
    p.parent = parent;
    p.kept = a_kept ? a : b;
    p.removed = a_kept ? b : a;
    p.correspondence = correspondence(p.kept, p.removed);
    p.cost = cost;
    const std::size_t dof = s.graph.degree_of_flexibility() -
                            joined_components(s, p.kept, p.removed, p.correspondence);
    p.score = m_score(s.weight + p.cost, dof,
                      m_score.structure_penalty > 0
                        ? s.graph.length_deviation_after_merge(p.kept, p.removed, p.correspondence)
                        : 0.0);
    p.hash = s.hash - mix64(s.key[a]) - mix64(s.key[b]) + mix64(s.key[a] + s.key[b]);
    bound.add(p.score, p.hash);
    out.push_back(p);
  }

  void propose(const State& s, std::size_t parent, Score_bound& bound,
               std::vector<Proposal>& out) const
  {
    std::vector<std::pair<double, std::pair<std::size_t, std::size_t> > > cheapest;
    if(s.alive <= exhaustive_limit())
    {
      for(std::size_t c = 0; c < s.members.size(); ++c)
        if(!s.members[c].empty())
          for(std::size_t d = c + 1; d < s.members.size(); ++d)
            if(!s.members[d].empty())
              cheapest.push_back({cost(s, c, d), {c, d}});
    }
    else
    {
      for(std::size_t c = 0; c < s.members.size(); ++c)
      {
        if(s.members[c].empty())
          continue;
        const std::size_t d = s.partner[c];
        if(d < c && s.partner[d] == c)
          continue;  // mutual partners: proposed once
        cheapest.push_back({s.partner_cost[c], {(std::min)(c, d), (std::max)(c, d)}});
      }
    }
    // Only pairs that can still enter the beam are sorted.
    cheapest.erase(std::remove_if(cheapest.begin(), cheapest.end(), [&](const auto& c) {
                     return score_lower_bound(s, c.first) > bound.value();
                   }), cheapest.end());
    std::sort(cheapest.begin(), cheapest.end());
    std::vector<std::pair<std::size_t, std::size_t> > pairs;
    for(const auto& c : cheapest)
    {
      if(score_lower_bound(s, c.first) > bound.value())
        break;
      pairs.push_back(c.second);
    }
    prefetch_correspondences(pairs);
    for(std::size_t i = 0; i < pairs.size(); ++i)
    {
      if(score_lower_bound(s, cheapest[i].first) > bound.value())
        break;
      add_proposal(s, parent, pairs[i].first, pairs[i].second, cheapest[i].first, bound, out);
    }
    if(!m_auto_merge)
      return;

    // Auto-merge: groups whose 4 components coincide (as a set first, then
    // edge by edge under the correspondence of their S-quads).
    std::vector<std::pair<std::array<std::size_t, 4>, std::size_t> > patterns;
    for(std::size_t c = 0; c < s.members.size(); ++c)
      if(!s.members[c].empty())
      {
        std::array<std::size_t, 4> p = s.graph.cluster_pattern(c);
        std::sort(p.begin(), p.end());
        patterns.push_back({p, c});
      }
    std::sort(patterns.begin(), patterns.end());
    for(std::size_t i = 0; i + 1 < patterns.size(); ++i)
    {
      if(patterns[i].first != patterns[i + 1].first)
        continue;
      // A pair proposed above again has the same hash: the beam keeps one.
      const std::size_t a = patterns[i].second, b = patterns[i + 1].second;
      const double c = cost(s, a, b);
      if(score_lower_bound(s, c) > bound.value())
        continue;
      const Panel_orientation corr = correspondence(a, b);
      const int n = s.graph.corner_count(a);
      bool identical = true;
      for(int k = 0; k < n; ++k)
        identical = identical &&
                    s.graph.component(a, k) == s.graph.component(b, corr.face_edge(k, n));
      if(identical)
        add_proposal(s, parent, a, b, c, bound, out);
    }
  }

  void apply(State& s, const Proposal& p) const
  {
    const std::size_t kept = p.kept, removed = p.removed;
    s.graph.merge_clusters(kept, removed, p.correspondence);
    s.groups[kept] = m_costs.merged(s.groups[kept], s.groups[removed], p.cost);
    s.members[kept].insert(s.members[kept].end(), s.members[removed].begin(),
                           s.members[removed].end());
    s.members[removed].clear();
    s.faces[kept] += s.faces[removed];
    s.key[kept] += s.key[removed];
    s.hash = p.hash;
    s.weight += p.cost;
    --s.alive;

    // Only costs involving `kept` changed; groups whose partner was one of
    // the two merged groups look again among all groups.
    std::vector<double> to_kept(s.members.size(), 0.0);
    parallel_for(s.members.size(), [&](std::size_t c) {
      if(c != kept && !s.members[c].empty())
        to_kept[c] = cost(s, kept, c);
    });
    std::vector<std::size_t> stale;
    s.partner[kept] = no_group();
    for(std::size_t c = 0; c < s.members.size(); ++c)
    {
      if(c == kept || s.members[c].empty())
        continue;
      if(s.partner[kept] == no_group() || to_kept[c] < s.partner_cost[kept])
      {
        s.partner[kept] = c;
        s.partner_cost[kept] = to_kept[c];
      }
      if(s.partner[c] == kept || s.partner[c] == removed)
        stale.push_back(c);
      else if(to_kept[c] < s.partner_cost[c] ||
              (to_kept[c] == s.partner_cost[c] && kept < s.partner[c]))
      {
        s.partner[c] = kept;
        s.partner_cost[c] = to_kept[c];
      }
    }
    parallel_for(stale.size(), [&](std::size_t i) { find_partner(s, stale[i]); });
  }

  const MergeCosts& m_costs;
  const std::vector<Panel>& m_leaders;
  Orientation_policy m_policy;
  Configuration_score m_score;
  std::size_t m_width;
  bool m_auto_merge;
  mutable std::unordered_map<std::uint64_t, Panel_orientation> m_correspondences;
};

// The candidate generator of the last beam (CandidateGenerator, origin
// HIERARCHICAL): the `settings.width` best configurations of K groups of the
// threshold clustering, best score first, each with the weight and the
// edge-sharing graph the beam kept for it.
struct Hierarchical_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    typedef typename std::remove_cv<typename std::remove_reference<decltype(context.mesh)>::type>::type
      PolygonMesh;
    const Initial_clustering& init = context.initial;
    const std::size_t big_n = init.leaders.size(), n = init.cluster.size();
    std::vector<std::size_t> faces_per_cluster(big_n, 0);
    for(std::size_t c : init.cluster) ++faces_per_cluster[c];
    std::vector<Panel> leaders(big_n);
    for(std::size_t c = 0; c < big_n; ++c) leaders[c] = context.panels[init.leaders[c]];
    std::vector<typename Context::Candidate> result;
    auto collect = [&](const auto& beam_search) {
      for(const auto& s : beam_search.run(beam_search.initial_state(*context.initial_graph, faces_per_cluster),
                                          context.k))
      {
        std::vector<std::size_t> group_of(big_n);
        for(std::size_t g = 0; g < s.members.size(); ++g)
          for(std::size_t c : s.members[g]) group_of[c] = g;
        typename Context::Candidate candidate;
        candidate.origin = Context::HIERARCHICAL;
        candidate.label.resize(n);
        for(std::size_t f = 0; f < n; ++f) candidate.label[f] = group_of[init.cluster[f]];
        relabel_by_first_face(candidate.label);
        candidate.measured = true;
        candidate.weight = s.weight;
        candidate.degree_of_flexibility = s.graph.degree_of_flexibility();
        candidate.length_deviation = s.graph.length_deviation();
        result.push_back(std::move(candidate));
      }
    };
    const auto& settings = context.settings;
    if(context.exact)
      collect(Beam_search<PolygonMesh, Exact_merge_costs>(
        Exact_merge_costs(context.affinity, init.cluster, big_n), leaders, context.policy, context.score,
        settings.width, settings.auto_merge));
    else
      collect(Beam_search<PolygonMesh, Descriptor_merge_costs>(
        Descriptor_merge_costs(context.descriptors, init.cluster, big_n), leaders, context.policy,
        context.score, settings.width, settings.auto_merge));
    return result;
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_BEAM_SEARCH_H
