// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_QUAD_SHAPE_IMPL_H
#define CGAL_TILABLE_SURFACES_QUAD_SHAPE_IMPL_H

// The bodies of the non-template functions declared in quad_shape.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/quad_shape.h>

namespace CGAL {
namespace Tilable_surfaces {

CGAL_TILABLE_SURFACES_INLINE
Panel_orientation compose(const Panel_orientation& a, const Panel_orientation& b, int n)
{
  // Both maps are determined by the image of 0 and the direction.
  const int image_of_zero = a(b(0, n), n);
  const bool reversed = a.is_reversed() != b.is_reversed();
  return Panel_orientation(reversed ? 4 + image_of_zero : image_of_zero);
}

CGAL_TILABLE_SURFACES_INLINE
std::array<double, 4> edge_lengths(const Panel& q)
{
  const int n = q.size();
  std::array<double, 4> r{{0, 0, 0, 0}};
  for(int k = 0; k < n; ++k)
    r[std::size_t(k)] = (q[(k + 1) % n] - q[k]).norm();
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
double relative_twist(const Panel& q)
{
  if(q.is_triangle())
    return 0;
  const std::array<double, 4> e = edge_lengths(q);
  const double mean = (e[0] + e[1] + e[2] + e[3]) / 4;
  return mean > 0 ? 6 * signed_volume(q) / (mean * mean * mean) : 0.0;
}

CGAL_TILABLE_SURFACES_INLINE
double planarity_defect(const Panel& q)
{
  if(q.is_triangle())
    return 0;
  // 6|V| = (twice the base area) * height.
  const double six_volume = 6.0 * std::abs(signed_volume(q));
  const double base = (q[1] - q[0]).cross(q[2] - q[0]).norm();
  double scale = 0;
  for(int i = 0; i < 4; ++i)
    scale = (std::max)(scale, (q[(i + 1) & 3] - q[i]).squaredNorm());
  if(base > internal::tuning::collinear_base * scale)
    return six_volume / base;
  double largest_base = 0;
  for(int i = 0; i < 4; ++i)
    largest_base = (std::max)(largest_base,
      (q[(i + 1) & 3] - q[i]).cross(q[(i + 2) & 3] - q[i]).norm());
  return largest_base == 0 ? 0.0 : six_volume / largest_base;
}

CGAL_TILABLE_SURFACES_INLINE
double diagonal_distance(const Panel& q)
{
  if(q.is_triangle())
    return 0;
  const Eigen::Vector3d n = (q[2] - q[0]).cross(q[3] - q[1]);
  const double length = n.norm();
  return length > 0 ? std::abs((q[1] - q[0]).dot(n)) / length : 0.0;
}

CGAL_TILABLE_SURFACES_INLINE
Quad_descriptor shape_descriptor(const Panel& q)
{
  const std::array<double, 4> e = edge_lengths(q);
  const std::array<double, 2> d = diagonal_lengths(q);
  Quad_descriptor r{{e[0], e[1], e[2], e[3], d[0], d[1],
                     std::cbrt(6.0 * std::abs(signed_volume(q)))}};
  std::sort(r.begin(), r.begin() + 4);
  std::sort(r.begin() + 4, r.begin() + 6);
  return r;
}

CGAL_TILABLE_SURFACES_INLINE
Rigid_fit best_rigid_fit(const Panel& source, const Panel& target, bool allow_mirror)
{
  return source.is_triangle() ? internal::best_rigid_fit<3>(source, target, allow_mirror)
                              : internal::best_rigid_fit<4>(source, target, allow_mirror);
}

CGAL_TILABLE_SURFACES_INLINE
double rigid_fit_deviation(const Panel& source, const Panel& target, bool allow_mirror)
{
  const Rigid_fit fit = best_rigid_fit(source, target, allow_mirror);
  double worst = 0;
  for(int i = 0; i < source.size(); ++i)
    worst = (std::max)(worst, (target[i] - fit(source[i])).norm());
  return worst;
}

CGAL_TILABLE_SURFACES_INLINE
Quad_match best_match(const Panel& p, const Panel& q,
                      Orientation_policy policy)
{
  const bool allow_mirror = (policy == ALLOW_MIRRORED_PANELS);
  Quad_match best;
  if(p.size() != q.size())
    return best;
  for(int o = 0; o < 8; ++o)
  {
    const Panel_orientation orientation(o);
    if(!is_admissible(orientation, q.size(), policy))
      continue;
    const Panel target = reoriented(q, orientation);
    const Rigid_fit fit = best_rigid_fit(p, target, allow_mirror);
    double sum = 0;
    for(int i = 0; i < q.size(); ++i)
      sum += (target[i] - fit(p[i])).norm();
    if(sum < best.dissimilarity)
    {
      best.dissimilarity = sum;
      best.orientation = orientation;
      best.fit = fit;
    }
  }
  return best;
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_QUAD_SHAPE_IMPL_H
