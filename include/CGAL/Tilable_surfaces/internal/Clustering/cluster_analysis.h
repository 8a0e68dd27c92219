// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_H

// What every clustering ends with, and what the editing functions redo: the
// S-quad of each cluster, the orientation of each face that best matches it,
// the split of a cluster into two, and the edge-sharing graph of a labelling.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Cluster_shapes
{
  std::vector<Panel> s_quads;                   // per cluster
  std::vector<Panel_orientation> orientation;   // per face
  std::vector<double> distance;                // per face: s(S-quad, face)
  std::size_t degree_of_flexibility = 0;       // when known (finished_clustering())
};

// S-quads by Procrustes averaging, then each face tagged with its best match.
CGAL_TILABLE_SURFACES_INLINE
Cluster_shapes cluster_shapes(const std::vector<Panel>& quads,
                              const std::vector<std::size_t>& label, std::size_t k,
                              Orientation_policy policy);

// The best 2-clustering we look for when splitting `members` (size >= 2):
// 2-means on descriptors, then exact refinement (each face goes to the nearer
// of the two S-quads, twice). Returns, per member, whether it goes to the new
// part; the part with members[0] is never the new one. When all descriptors
// coincide the members are cut in two halves in index order.
CGAL_TILABLE_SURFACES_INLINE
std::vector<bool> split_in_two(const std::vector<Panel>& quads,
                               const std::vector<Quad_descriptor>& descriptors,
                               const std::vector<std::size_t>& members,
                               Orientation_policy policy, CGAL::Random& random);

// The edge-sharing graph of a labelling given as per-face vectors indexed by
// `fim`.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Edge_sharing_graph<PolygonMesh>
edge_sharing_graph(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                   const std::vector<std::size_t>& label,
                   const std::vector<Panel_orientation>& orientation, std::size_t k)
{
  return Edge_sharing_graph<PolygonMesh>(Validated_mesh(true), pm, fim, vpm,
                                         Face_clustering{label, orientation, k});
}

// The squared deviations of all the edge lengths of `pm` from their mean:
// Edge_sharing_graph::length_deviation() with every edge in one component.
template <typename PolygonMesh, typename VertexPointMap>
double total_length_deviation(const PolygonMesh& pm, VertexPointMap vpm)
{
  // Sorted, so that the rounded sums do not depend on the order of the edges.
  std::vector<double> lengths;
  lengths.reserve(num_edges(pm));
  for(auto e : edges(pm))
    lengths.push_back(internal::distance(get(vpm, source(e, pm)), get(vpm, target(e, pm))));
  std::sort(lengths.begin(), lengths.end());
  double count = 0, sum = 0, sum_of_squares = 0;
  for(double l : lengths)
  {
    count += 1;
    sum += l;
    sum_of_squares += l * l;
  }
  return count > 0 ? (std::max)(sum_of_squares - sum * sum / count, 0.0) : 0.0;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_CLUSTER_ANALYSIS_H
