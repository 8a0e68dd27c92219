// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_KEPT_RESULTS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_KEPT_RESULTS_H

// What the searches over K (the curve, the deviation search) set aside of
// the results they met: one K's result, and the results a larger K may be
// refined from.

#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// A result at K set aside: positions in vertex order, cluster and
// orientation by face index, what was measured and its trial.
template <typename Point>
struct Kept_result
{
  std::size_t k = 0;
  K_set_tilable_result result;
  Tile_count_trial trial;
  std::vector<Point> points;
  std::vector<int> cluster, orientation;

  // Tilable and not crossing itself: a result that can be built.
  bool is_buildable() const
  {
    return result.is_tilable() && result.optimization.measure.self_intersecting_face_pairs == 0;
  }

  // Sets aside the positions of `pm` and the maps of `surface`.
  template <typename PolygonMesh, typename VertexPointMap, typename Surface, typename FaceIndexMap>
  void save(const PolygonMesh& pm, VertexPointMap vpm, Surface& surface, FaceIndexMap fim)
  {
    points.clear();
    for(auto v : vertices(pm))
      points.push_back(get(vpm, v));
    cluster.resize(num_faces(pm));
    orientation.resize(num_faces(pm));
    for(auto f : faces(pm))
    {
      cluster[get(fim, f)] = get(surface.face_cluster_map(), f);
      orientation[get(fim, f)] = get(surface.face_orientation_map(), f);
    }
  }

  template <typename PolygonMesh, typename VertexPointMap>
  void put_points(PolygonMesh& pm, VertexPointMap vpm) const
  {
    auto point = points.begin();
    for(auto v : vertices(pm))
      put(vpm, v, *point++);
  }

  template <typename FaceIndexMap>
  auto cluster_map(FaceIndexMap fim) const { return boost::make_iterator_property_map(cluster.cbegin(), fim); }
  template <typename FaceIndexMap>
  auto orientation_map(FaceIndexMap fim) const { return boost::make_iterator_property_map(orientation.cbegin(), fim); }
};

// The buildable results a larger K may be refined from: by increasing K,
// each better (is_better()) than every one of fewer clusters, since a
// result no better than one of fewer clusters is never the one refined.
template <typename Point>
class Refinement_sources
{
public:
  // The best result of fewer than k clusters, or null.
  const Kept_result<Point>* best_below(std::size_t k) const
  {
    const Kept_result<Point>* best = nullptr;
    for(const Kept_result<Point>& s : m_sources)
      if(s.k < k)
        best = &s;
    return best;
  }

  void offer(const Kept_result<Point>& r)
  {
    if(!r.is_buildable())
      return;
    for(const Kept_result<Point>& s : m_sources)
      if(s.k <= r.k && !is_better(r.result.optimization, s.result.optimization))
        return;
    m_sources.erase(std::remove_if(m_sources.begin(), m_sources.end(),
                                   [&](const Kept_result<Point>& s) {
                                     return s.k >= r.k && !is_better(s.result.optimization, r.result.optimization);
                                   }),
                    m_sources.end());
    m_sources.insert(std::find_if(m_sources.begin(), m_sources.end(),
                                  [&](const Kept_result<Point>& s) { return s.k > r.k; }),
                     r);
  }

private:
  std::vector<Kept_result<Point> > m_sources;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_KEPT_RESULTS_H
