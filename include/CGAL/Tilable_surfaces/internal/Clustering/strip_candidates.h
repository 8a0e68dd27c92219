// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_H

// Clusterings that follow the quad strips of the mesh, for the final pool of
// cluster_panels().
//
// A quad strip (a polychord) is a sequence of faces, each entered and left
// through two opposite edges. Every face lies on two strips, one per pair of
// opposite edges; on a tube, the strips of one direction are its rings. A
// ring of quads between two circular vertex loops is one shape, whatever its
// neighbours, and clusters made of whole rings tie no ring to another. Shape
// clustering does the opposite on tubes and shells: quads of the same
// position in a lobe are alike across rings, so clusters cross the rings,
// and through the edge-sharing graph every ring is forced to one size (the
// tunnel stand-in became a cylinder, the seashell lost its taper). Whole
// strips give up the variation along a strip (lobes) instead, which is often
// cheaper; the displacement prediction decides (K_set_tilable_surface::
// optimize_closest()).
//
// The strips of one direction are merged greedily (least spread of the edge
// lengths they tie together) down to K, or, if there are fewer than K, the
// largest clusters are split by shape until K.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/Random.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Splits the largest initial clusters until there are k of them.
CGAL_TILABLE_SURFACES_INLINE
void split_to(std::size_t k, const std::vector<Panel>& quads,
              const std::vector<Quad_descriptor>& descriptors, Orientation_policy policy,
              CGAL::Random& random, Initial_clustering& init);

// Greedy merges of the clusters of `label` (S of them) down to each count
// of `targets`: each time the pair whose merge spreads the input's edge
// lengths least (Edge_sharing_graph::length_deviation_after_merge(), the
// S-quads matched by their best correspondence), so that merged strips tie
// few lengths together (on a tube: congruent rings first, then rings of
// close radii). A merge depends only on the clusters before it, so one
// sequence serves every target. The labels at each target, renumbered by
// first face. A quad cluster and a triangle cluster never merge: with fewer
// than k clusters of one kind left, the merges stop early.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
merge_strips_to_each(const std::vector<std::size_t>& targets, const PolygonMesh& pm, FaceIndexMap fim,
                     VertexPointMap vpm, const std::vector<Panel>& quads, Orientation_policy policy,
                     const std::vector<std::size_t>& label, std::size_t s)
{
  const Cluster_shapes shapes = cluster_shapes(quads, label, s, policy);
  Edge_sharing_graph<PolygonMesh> graph = edge_sharing_graph(pm, fim, vpm, label, shapes.orientation, s);
  std::vector<std::size_t> parent(s);
  for(std::size_t c = 0; c < s; ++c)
    parent[c] = c;
  std::vector<Panel_orientation> correspondence(s * s);
  parallel_for(s, [&](std::size_t a) {
    for(std::size_t b = a + 1; b < s; ++b)
      correspondence[a * s + b] = fast_best_match(shapes.s_quads[a], shapes.s_quads[b], policy).orientation;
  });
  std::vector<std::vector<std::size_t> > merged(targets.size());
  auto take = [&](std::size_t count) {
    for(std::size_t t = 0; t < targets.size(); ++t)
      if(merged[t].empty() && targets[t] >= count)
      {
        merged[t] = label;
        for(std::size_t& l : merged[t])
          while(parent[l] != l) l = parent[l];
        relabel_by_first_face(merged[t]);
      }
  };
  const std::size_t k = *std::min_element(targets.begin(), targets.end());
  for(std::size_t count = s; count > k; --count)
  {
    take(count);
    double best = (std::numeric_limits<double>::max)();
    std::size_t kept = 0, removed = 0;
    for(std::size_t a = 0; a < s; ++a)
      for(std::size_t b = a + 1; graph.is_alive(a) && b < s; ++b)
        if(graph.is_alive(b))
        {
          const double x = graph.length_deviation_after_merge(a, b, correspondence[a * s + b]);
          if(x < best) { best = x; kept = a; removed = b; }
        }
    if(kept == removed)
      break;
    graph.merge_clusters(kept, removed, correspondence[kept * s + removed]);
    parent[removed] = kept;
  }
  take(0);
  return merged;
}

// `label` (with s clusters) brought to exactly k clusters: merged by least
// spread, or split by shape.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
void bring_to(std::size_t k, const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
              const std::vector<Panel>& quads, const std::vector<Quad_descriptor>& descriptors,
              Orientation_policy policy, CGAL::Random& random, std::vector<std::size_t>& label,
              std::size_t s)
{
  if(s > k)
    label = merge_strips_to_each({k}, pm, fim, vpm, quads, policy, label, s)[0];
  else if(s < k)
  {
    Initial_clustering init;
    init.cluster = label;
    init.orientation.assign(label.size(), Panel_orientation());
    init.leaders.assign(s, no_index());
    for(std::size_t f = label.size(); f-- > 0;)
      init.leaders[label[f]] = f;
    split_to(k, quads, descriptors, policy, random, init);
    label = init.cluster;
    relabel_by_first_face(label);
  }
}

// The strip clusterings with k clusters. For a pair (a, b), the strips of
// the first direction are merged into a groups, those of the second into b
// groups, and each face is labelled by its pair of groups; then the labels
// are brought to k. b = 1 gives whole strips (the rings of a tube); on a
// bent tube (a shell) the rings hold different shapes on their inner and
// outer sides, and a few groups of consecutive rings (a) times the
// positions around (b) keep the bend while giving up some growth. The pairs
// tried: b in {1, 2, 3, 4, 6, 8, 12, 16} with a = ceil(k / b), and the same
// with the directions swapped. A direction with more than `max_strips`
// strips (O(S^3) greedy merges) is left out. On a mesh with triangles, the
// strips and the final clusters are split by kind first (separate_kinds()).
// `strips` as quad_strips() gives them (see candidate_strips()).
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
strip_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, const std::vector<Panel>& quads,
                  const std::vector<Quad_descriptor>& descriptors, std::size_t k,
                  Orientation_policy policy, CGAL::Random& random,
                  std::array<std::vector<std::size_t>, 2> strips,
                  std::size_t max_strips = tuning::strip_max_strips)
{
  const bool triangles = has_triangles(quads);
  std::array<std::size_t, 2> count;
  for(int d = 0; d < 2; ++d)
    count[d] = triangles ? separate_kinds(quads, strips[d])
                         : 1 + *std::max_element(strips[d].begin(), strips[d].end());
  const std::size_t(&group_counts)[8] = tuning::strip_group_counts;
  auto pair_groups = [&](int first, std::size_t b) {
    const std::size_t a = (k + b - 1) / b;
    return std::array<std::size_t, 2>{{first == 0 ? a : b, first == 0 ? b : a}};
  };
  auto skipped = [&](const std::array<std::size_t, 2>& groups) {
    return groups[0] > count[0] || groups[1] > count[1] || (groups[0] > 1 && count[0] > max_strips) ||
           (groups[1] > 1 && count[1] > max_strips);
  };
  // Per direction, the merges to every group count used, in one sequence.
  std::array<std::vector<std::size_t>, 2> targets;
  for(int first = 0; first < 2; ++first)
    for(std::size_t b : group_counts)
      if(!skipped(pair_groups(first, b)))
        for(int d = 0; d < 2; ++d)
          if(pair_groups(first, b)[d] > 1)
            targets[d].push_back(pair_groups(first, b)[d]);
  std::array<std::vector<std::vector<std::size_t> >, 2> merged;
  for(int d = 0; d < 2; ++d)
    if(!targets[d].empty())
      merged[d] = merge_strips_to_each(targets[d], pm, fim, vpm, quads, policy, strips[d], count[d]);
  std::vector<std::vector<std::size_t> > result;
  for(int first = 0; first < 2; ++first)
    for(std::size_t b : group_counts)
    {
      const std::array<std::size_t, 2> groups = pair_groups(first, b);
      if(skipped(groups))
        continue;
      std::array<std::vector<std::size_t>, 2> grouped;
      for(int d = 0; d < 2; ++d)
        if(groups[d] == 1)
          grouped[d].assign(strips[d].size(), 0);
        else
          grouped[d] = merged[d][std::size_t(std::find(targets[d].begin(), targets[d].end(), groups[d]) -
                                             targets[d].begin())];
      // (Without triangles, grouped[1] is below groups[1].)
      const std::size_t columns = 1 + *std::max_element(grouped[1].begin(), grouped[1].end());
      std::vector<std::size_t> label(strips[0].size());
      for(std::size_t f = 0; f < label.size(); ++f)
        label[f] = grouped[0][f] * columns + grouped[1][f];
      const std::size_t s = triangles ? separate_kinds(quads, label) : relabel_by_first_face(label);
      bring_to(k, pm, fim, vpm, quads, descriptors, policy, random, label, s);
      if(std::find(result.begin(), result.end(), label) == result.end())
        result.push_back(label);
    }
  return result;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_STRIP_CANDIDATES_H
