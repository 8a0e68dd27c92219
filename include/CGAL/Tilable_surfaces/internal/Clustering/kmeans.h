// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H

// Lloyd's k-means on quad descriptors (paper §5: a k-means configuration
// enriches the candidate pool; also the first step of splitting a cluster).
// Seeding is k-means++ with a `CGAL::Random`, so results follow the seed.

#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/Random.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

inline double squared_distance(const Quad_descriptor& a, const Quad_descriptor& b)
{
  double r = 0;
  for(std::size_t k = 0; k < a.size(); ++k) r += (a[k] - b[k]) * (a[k] - b[k]);
  return r;
}

// Labels in 0..k-1 of points[subset[i]], or an empty vector when k distinct
// non-empty clusters cannot be formed (fewer than k distinct descriptors).
inline std::vector<std::size_t> kmeans(const std::vector<Quad_descriptor>& points,
                                       const std::vector<std::size_t>& subset,
                                       std::size_t k, CGAL::Random& random,
                                       int iterations = tuning::kmeans_iterations)
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

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_KMEANS_H
