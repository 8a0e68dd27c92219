// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_H

// The two ways the beam search prices a merge, S(A u B) - S(A) - S(B).
// Both act on groups of initial clusters (the beam's unit).
//
// - Exact_merge_costs: S is the paper's weight, the sum of pairwise
//   dissimilarities. The cross sums between initial clusters are computed once
//   from the n x n affinity matrix; the merge cost of two groups is the sum of
//   the cross sums of their members.
// - Descriptor_merge_costs: S(C) is the sum over pairs of the squared distance
//   between quad descriptors, which only needs per group the size n, the mean
//   mu and the scatter SSE = sum |d - mu|^2:
//     S(C) = n SSE,  S(A u B) - S(A) - S(B) = nA SSE_B + nB SSE_A + nA nB |muA - muB|^2.
//   O(1) per merge, linear memory: the scalable path.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

class Exact_merge_costs
{
public:
  struct Group { double weight = 0; };

  // `affinity` is the n x n dissimilarity matrix (row major), `cluster` the
  // initial cluster of every face, in 0..N-1.
  Exact_merge_costs(const std::vector<double>& affinity, const std::vector<std::size_t>& cluster,
                    std::size_t number_of_clusters);

  Group initial_group(std::size_t c) const { return m_initial[c]; }

  double cost(const std::vector<std::size_t>& a, const Group&,
              const std::vector<std::size_t>& b, const Group&) const
  {
    double sum = 0;
    for(std::size_t i : a)
      for(std::size_t j : b)
        sum += m_cross[i * m_n + j];
    return sum;
  }

  Group merged(const Group& a, const Group& b, double cost) const
  {
    return Group{a.weight + b.weight + cost};
  }

private:
  std::size_t m_n;
  std::vector<double> m_cross;
  std::vector<Group> m_initial;
};

class Descriptor_merge_costs
{
public:
  struct Group
  {
    double n = 0;
    Quad_descriptor mean{};
    double scatter = 0;
    double weight = 0;
  };

  Descriptor_merge_costs(const std::vector<Quad_descriptor>& descriptors,
                         const std::vector<std::size_t>& cluster, std::size_t number_of_clusters);

  Group initial_group(std::size_t c) const { return m_initial[c]; }

  double cost(const std::vector<std::size_t>&, const Group& a,
              const std::vector<std::size_t>&, const Group& b) const
  {
    return a.n * b.scatter + b.n * a.scatter + a.n * b.n * squared_mean_distance(a, b);
  }

  Group merged(const Group& a, const Group& b, double cost) const
  {
    Group r;
    r.n = a.n + b.n;
    for(std::size_t k = 0; k < r.mean.size(); ++k)
      r.mean[k] = (a.n * a.mean[k] + b.n * b.mean[k]) / r.n;
    r.scatter = a.scatter + b.scatter + a.n * b.n / r.n * squared_mean_distance(a, b);
    r.weight = a.weight + b.weight + cost;
    return r;
  }

private:
  static double squared_mean_distance(const Group& a, const Group& b)
  {
    double d = 0;
    for(std::size_t k = 0; k < a.mean.size(); ++k)
      d += (a.mean[k] - b.mean[k]) * (a.mean[k] - b.mean[k]);
    return d;
  }

  std::vector<Group> m_initial;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_MERGE_COSTS_H
