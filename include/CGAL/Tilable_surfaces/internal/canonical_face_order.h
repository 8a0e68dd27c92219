// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_FACE_ORDER_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_FACE_ORDER_H

// The order in which the pipeline visits the faces, taken from the surface
// instead of from the face indices: the greedy clustering, its tie-breaks, the
// k-means seeds and each cluster's template face all follow it, so renumbering
// the faces does not change the result, and a similarity of the input does
// not change the order.
//
// The order is a breadth-first search over the faces that share an edge. It
// starts at the face farthest from the centroid of the face centroids (near
// ties, within a relative 1e-9, go to the larger face; exact ties, which only
// a symmetric surface has, to the lower index), and takes each face's
// neighbours in the order of its edges, from halfedge(f). A mesh with several
// components restarts the same way on the faces not reached yet.

#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cstddef>
#include <deque>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The rank of every face in the canonical order, by the index of `fim`;
// `quads` are the faces' corners by the same index.
template <typename PolygonMesh, typename FaceIndexMap>
std::vector<std::size_t> canonical_face_ranks(const PolygonMesh& pm, FaceIndexMap fim,
                                              const std::vector<Panel>& quads)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  const std::size_t n = quads.size();
  std::vector<face_descriptor> face_of(n);
  for(face_descriptor f : faces(pm))
    face_of[std::size_t(get(fim, f))] = f;

  std::vector<Eigen::Vector3d> centroid(n);
  Eigen::Vector3d middle = Eigen::Vector3d::Zero();
  for(std::size_t i = 0; i < n; ++i)
  {
    centroid[i] = quads[i].centroid();
    middle += centroid[i];
  }
  if(n > 0)
    middle /= double(n);
  std::vector<double> distance(n), area(n);
  for(std::size_t i = 0; i < n; ++i)
  {
    distance[i] = (centroid[i] - middle).squaredNorm();
    area[i] = quads[i].doubled_vector_area().norm();
  }
  auto near = [](double a, double b) { return std::abs(a - b) <= tuning::canonical_start_tie * (std::max)(a, b); };
  // Start candidates, farthest first: a start is the first unranked one after
  // its near ties are resolved by area.
  std::vector<std::size_t> by_distance(n);
  std::iota(by_distance.begin(), by_distance.end(), std::size_t(0));
  std::stable_sort(by_distance.begin(), by_distance.end(),
                   [&](std::size_t a, std::size_t b) { return distance[a] > distance[b]; });

  const std::size_t unranked = std::size_t(-1);
  std::vector<std::size_t> rank(n, unranked);
  std::size_t next_rank = 0;
  std::deque<std::size_t> queue;
  for(std::size_t s = 0; s < n; ++s)
  {
    if(rank[by_distance[s]] != unranked)
      continue;
    std::size_t start = by_distance[s];
    for(std::size_t t = s + 1; t < n && near(distance[by_distance[t]], distance[by_distance[s]]); ++t)
    {
      const std::size_t other = by_distance[t];
      if(rank[other] == unranked && !near(area[other], area[start]) && area[other] > area[start])
        start = other;
    }
    rank[start] = next_rank++;
    queue.push_back(start);
    while(!queue.empty())
    {
      const std::size_t i = queue.front();
      queue.pop_front();
      for(auto h : face_edge_halfedges(face_of[i], pm))
      {
        const face_descriptor g = face(opposite(h, pm), pm);
        if(g == boost::graph_traits<PolygonMesh>::null_face())
          continue;
        const std::size_t j = std::size_t(get(fim, g));
        if(rank[j] == unranked)
        {
          rank[j] = next_rank++;
          queue.push_back(j);
        }
      }
    }
  }
  return rank;
}

// `values` (by the index of the canonical order) by the index `rank` came from.
template <typename T>
std::vector<T> by_original_index(const std::vector<T>& values, const std::vector<std::size_t>& rank)
{
  std::vector<T> result(values.size());
  for(std::size_t i = 0; i < rank.size(); ++i)
    result[i] = values[rank[i]];
  return result;
}

// `values` (by the index `rank` came from) by the index of the canonical order.
template <typename T>
std::vector<T> by_canonical_index(const std::vector<T>& values, const std::vector<std::size_t>& rank)
{
  std::vector<T> result(values.size());
  for(std::size_t i = 0; i < rank.size(); ++i)
    result[rank[i]] = values[i];
  return result;
}

// `fc` (by the index `rank` came from) by the index of the canonical order.
inline Face_clustering in_canonical_order(Face_clustering fc, const std::vector<std::size_t>& rank)
{
  fc.label = by_canonical_index(fc.label, rank);
  fc.orientation = by_canonical_index(fc.orientation, rank);
  return fc;
}

// The faces' index map in the canonical order, from a map of their indices.
template <typename FaceIndexMap>
using Canonical_face_index_map =
  boost::iterator_property_map<std::vector<std::size_t>::const_iterator, FaceIndexMap, std::size_t,
                               const std::size_t&>;

// The faces of a checked quad mesh in the canonical order: the rank of each
// (by its original index) and their corners (by rank).
template <typename FaceIndexMap>
struct Canonical_faces
{
  FaceIndexMap original_index;
  std::vector<std::size_t> rank;
  std::vector<Panel> quads;

  Canonical_faces() = default;

  // `original_quads`: the corners by the index of `fim`.
  template <typename PolygonMesh>
  Canonical_faces(const PolygonMesh& pm, FaceIndexMap fim, const std::vector<Panel>& original_quads)
    : original_index(fim)
    , rank(canonical_face_ranks(pm, fim, original_quads))
    , quads(by_canonical_index(original_quads, rank))
  {}

  // Refers to `rank`: valid while this object lives (a move keeps it valid).
  Canonical_face_index_map<FaceIndexMap> index_map() const
  {
    return Canonical_face_index_map<FaceIndexMap>(rank.begin(), original_index);
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CANONICAL_FACE_ORDER_H
