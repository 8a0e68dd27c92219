// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_IMPL_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_IMPL_H

// The bodies of the non-template functions declared in patch_candidates.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/internal/Clustering/patch_candidates.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
void Mold_sum::add(const Panel& q)
{
  ++count;
  distances += corner_distances(q);
  const double twist = 6 * signed_volume(q);
  double& largest = twist > 0 ? positive_twist : negative_twist;
  largest = (std::max)(largest, std::abs(twist));
}

CGAL_TILABLE_SURFACES_INLINE
Mold_sum Mold_sum::merged(const Mold_sum& other, Panel_orientation o) const
{
  Mold_sum m = *this;
  m.count += other.count;
  m.distances += reoriented(other.distances, o);
  const bool same = orientation_sign(o) > 0;
  m.positive_twist = (std::max)(positive_twist, same ? other.positive_twist : other.negative_twist);
  m.negative_twist = (std::max)(negative_twist, same ? other.negative_twist : other.positive_twist);
  return m;
}

CGAL_TILABLE_SURFACES_INLINE
double Mold_sum::merge_cost(const Mold_sum& other, Panel_orientation o) const
{
  const Eigen::Matrix<double, 6, 1> d =
    distances / double(count) - reoriented(other.distances, o) / double(other.count);
  return d.squaredNorm() * double(count * other.count) / double(count + other.count);
}

CGAL_TILABLE_SURFACES_INLINE
Patch_runs::Patch_runs(const std::array<const Quad_grid*, 2>& grid, std::size_t max_molds, Orientation_policy policy)
{
  for(const Quad_grid* g : grid)
  {
    if(g->rows == 0 || double(g->rows) * double(g->rows) * double(max_molds) > tuning::segment_runs_work)
      continue;
    grids.emplace_back(new Segment_options);
    grids.back()->grid = *g;
    add_run_options(*grids.back(), max_molds, policy);
    for(const std::vector<const Run_option*>& set : grids.back()->sets)
      partitions.emplace_back(new Run_partitions(grids.back()->grid, set, max_molds));
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_IMPL_H
