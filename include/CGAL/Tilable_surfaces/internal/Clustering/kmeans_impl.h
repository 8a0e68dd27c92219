// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_IMPL_H

// The bodies of the non-template functions declared in kmeans.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> kmeans(const std::vector<Quad_descriptor>& points,
                                const std::vector<std::size_t>& subset,
                                std::size_t k, CGAL::Random& random,
                                int iterations)
{
  const std::size_t m = subset.size();
  if(k == 0 || k > m)
    return {};
  // k-means++ seeding: next seed drawn with probability proportional to the
  // squared distance to the nearest seed so far.
  std::vector<Quad_descriptor> centers;
  centers.push_back(points[subset[random.get_int(0, int(m))]]);
  std::vector<double> d2(m, (std::numeric_limits<double>::max)());
  while(centers.size() < k)
  {
    double total = 0;
    for(std::size_t i = 0; i < m; ++i)
    {
      d2[i] = (std::min)(d2[i], squared_distance(points[subset[i]], centers.back()));
      total += d2[i];
    }
    if(!(total > 0))
      return {};
    double pick = random.get_double(0, total);
    std::size_t i = 0;
    for(; i + 1 < m && (pick -= d2[i]) >= 0; ++i) {}
    while(d2[i] == 0) i = (i + 1) % m;   // rounding landed on a seed
    centers.push_back(points[subset[i]]);
  }

  std::vector<std::size_t> label(m, 0);
  for(int it = 0; it < iterations; ++it)
  {
    std::vector<std::size_t> next_label(m);
    parallel_for(m, [&](std::size_t i) {
      std::size_t best = 0;
      double best_d = squared_distance(points[subset[i]], centers[0]);
      for(std::size_t c = 1; c < k; ++c)
      {
        const double d = squared_distance(points[subset[i]], centers[c]);
        if(d < best_d) { best_d = d; best = c; }
      }
      next_label[i] = best;
    });
    const bool changed = (it == 0) || next_label != label;
    label.swap(next_label);
    std::vector<std::size_t> count(k, 0);
    for(auto& c : centers) c.fill(0);
    for(std::size_t i = 0; i < m; ++i)
    {
      ++count[label[i]];
      for(std::size_t j = 0; j < centers[label[i]].size(); ++j)
        centers[label[i]][j] += points[subset[i]][j];
    }
    for(std::size_t c = 0; c < k; ++c)
    {
      if(count[c] == 0)
        return {};
      for(double& x : centers[c]) x /= double(count[c]);
    }
    if(!changed)
      break;
  }
  return label;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_IMPL_H
