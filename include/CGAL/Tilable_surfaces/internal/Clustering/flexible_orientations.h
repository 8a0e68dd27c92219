// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_H

// Orientations chosen for flexibility among near-ties.
//
// Tagging each face with its best-matching orientation, face by face, can lose
// much of the degree of flexibility: symmetric or nearly symmetric quads (a
// rectangle matches its S-quad equally well turned by 180 degrees or turned
// over) pick correspondences that link S-quad edges at random. The weights of
// the clusters do not depend on the orientations, so an orientation is
// admissible when its dissimilarity to the S-quad is within a tolerance of the
// face's best: a near-tie.
//
// Among admissible orientations, a local search re-tags one face at a time
// and keeps a change when it improves, lexicographically,
//   (1) the DOF, (2) the number of interior mesh edges that link two different
//   S-quad edges (self-loops constrain nothing: fewer links make components
//   easier to split, e.g. alternately turned-over rows on a grid), (3) the sum
//   of the faces' dissimilarities to their S-quads.
// Each criterion is integral or strictly decreasing, so the search ends.
// Links are counted with multiplicity, so a re-tagging tells which distinct
// links appear or vanish: new ones are joined in the current union-find over
// the 4K S-quad edges; only a vanished one (which may split a component)
// needs a recount.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/link_count.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// An interior mesh edge: face edge `edge[0]` of face `face[0]` and face edge
// `edge[1]` of face `face[1]` (face edge j joins v_j and v_{j+1}).
struct Shared_edge
{
  std::array<std::size_t, 2> face;
  std::array<int, 2> edge;
};

template <typename PolygonMesh, typename FaceIndexMap>
std::vector<Shared_edge> shared_edges(const PolygonMesh& pm, FaceIndexMap fim)
{
  const auto eim = CGAL::get_initialized_edge_index_map(pm);
  std::vector<std::size_t> first(num_edges(pm), std::size_t(-1));
  std::vector<int> first_edge(num_edges(pm), 0);
  std::vector<Shared_edge> r;
  // In index order, which the searches' sweeps follow.
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> face_of(num_faces(pm));
  for(auto f : faces(pm))
    face_of[std::size_t(get(fim, f))] = f;
  for(auto f : face_of)
  {
    const auto face_edges = face_edge_halfedges(f, pm);
    for(int j = 0; j < int(face_edges.size()); ++j)
    {
      const std::size_t e = get(eim, edge(face_edges[std::size_t(j)], pm));
      if(first[e] == std::size_t(-1))
      {
        first[e] = get(fim, f);
        first_edge[e] = j;
      }
      else
        r.push_back(Shared_edge{{{first[e], get(fim, f)}}, {{first_edge[e], j}}});
    }
  }
  return r;
}

class Flexible_orientations
{
public:
  // `dissimilarity[f][o]`: of face f to its S-quad under orientation o, +inf
  // if o is not admissible; `corners[f]`: 3 or 4; `orientation`: the start,
  // admissible.
  Flexible_orientations(const std::vector<Shared_edge>& edges, const std::vector<std::size_t>& label,
                        std::size_t k, const std::vector<std::array<double, 8> >& dissimilarity,
                        const std::vector<int>& corners, std::vector<Panel_orientation> orientation);

  // Local search; at most `sweeps` passes over the faces.
  void improve(int sweeps);

  const std::vector<Panel_orientation>& orientations() const { return m_orientation; }
  std::size_t degree_of_flexibility() const { return m_dof; }

  // Whether this tagging is better than `other` by the criteria of the file comment.
  bool is_better_than(const Flexible_orientations& other) const;

private:
  // The distinct links that a re-tagging removed and added.
  struct Change
  {
    std::array<std::uint64_t, 4> vanished, appeared;
    std::size_t nv = 0, na = 0;
  };

  // Node 4c + k of the template edge that shared edge `i` is on its side `s`.
  std::size_t node(std::size_t i, int s) const
  {
    const std::size_t f = m_edges[i].face[s];
    return 4 * m_label[f] + std::size_t(m_orientation[f].template_edge(m_edges[i].edge[s], m_corners[f]));
  }

  // Adds `delta` to the count of the link of shared edge `i`; returns its key
  // if the link appeared or vanished, 0 otherwise (0 is a self-loop's key).
  std::uint64_t add_link(std::size_t i, int delta)
  {
    const std::size_t a = node(i, 0), b = node(i, 1);
    if(a == b)
      return 0;
    const std::uint64_t key = a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
    m_links += delta;
    auto it = m_count.emplace(key, 0).first;
    it->second += delta;
    if(it->second == 0)
    {
      m_count.erase(it);
      return key;
    }
    return delta > 0 && it->second == 1 ? key : 0;
  }

  // Moves the links of face f's edges to orientation o.
  Change retag(std::size_t f, Panel_orientation o)
  {
    Change c;
    for(std::size_t i : m_incident[f])
      if(const std::uint64_t key = add_link(i, -1)) c.vanished[c.nv++] = key;
    m_orientation[f] = o;
    for(std::size_t i : m_incident[f])
      if(const std::uint64_t key = add_link(i, +1)) c.appeared[c.na++] = key;
    // A link that vanished and came back did not change.
    for(std::size_t i = 0; i < c.na;)
    {
      auto v = std::find(c.vanished.begin(), c.vanished.begin() + c.nv, c.appeared[i]);
      if(v == c.vanished.begin() + c.nv) { ++i; continue; }
      *v = c.vanished[--c.nv];
      c.appeared[i] = c.appeared[--c.na];
    }
    return c;
  }

  // Number of components of the current links; fills the union-find `sets`.
  std::size_t count_components(Union_find<>& sets) const;

  // Re-tags face f with o if that improves the criteria of the file comment.
  // Links that only appear join components of the current union-find; a
  // vanished link may split one, which needs a recount.
  bool try_orientation(std::size_t f, Panel_orientation o);

  double total_dissimilarity() const
  {
    double sum = 0;
    for(std::size_t f = 0; f < m_label.size(); ++f) sum += m_d[f][m_orientation[f].index()];
    return sum;
  }

  const std::vector<Shared_edge>& m_edges;
  const std::vector<std::size_t>& m_label;
  std::size_t m_k;
  const std::vector<std::array<double, 8> >& m_d;
  const std::vector<int>& m_corners;
  std::size_t m_unused_nodes = 0;
  std::vector<Panel_orientation> m_orientation;
  std::vector<std::vector<std::size_t> > m_incident;
  std::unordered_map<std::uint64_t, int> m_count;  // distinct links and their multiplicity
  long long m_links = 0;                             // links, with multiplicity
  Union_find<> m_components;                         // of the distinct links
  Union_find<> m_recount;                            // scratch for recounts
  std::size_t m_dof = 0;
};

// A start for the local search: orientations propagated across the shared
// edges inside each cluster (breadth first, from the first face), so that the
// two faces of an edge put the same S-quad edge on it with the same corners
// (`mirrored`: the second instance is the first one turned over the edge, a
// self-loop) or put opposite S-quad edges on it in the same direction (as
// translated copies on a grid do; a triangle has no opposite edge). Faces
// where the propagated orientation is not admissible keep `best`, and the
// propagation goes on from them.
CGAL_TILABLE_SURFACES_INLINE
std::vector<Panel_orientation>
propagated_orientations(const std::vector<Shared_edge>& edges, const std::vector<std::size_t>& label,
                 const std::vector<std::array<double, 8> >& dissimilarity,
                 const std::vector<int>& corners,
                 const std::vector<Panel_orientation>& best, bool mirrored);

// Per face, the dissimilarity to its S-quad under each orientation allowed by
// `policy`, or +inf where the orientation is not admissible: where it exceeds
// the face's best by more than `tolerance` (so every tag is a near-tie of the
// best match, never a worse fit).
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::array<double, 8> >
admissible_dissimilarities(const std::vector<Panel>& quads, const std::vector<std::size_t>& label,
                    const std::vector<Panel>& s_quads, Orientation_policy policy,
                    double tolerance);

// The orientations of the file comment: the best of the local searches
// started from the best orientations and from both propagated ones.
template <typename PolygonMesh, typename FaceIndexMap>
std::vector<Panel_orientation>
flexible_orientations(const PolygonMesh& pm, FaceIndexMap fim, const std::vector<Panel>& quads,
                      const std::vector<std::size_t>& label, const std::vector<Panel>& s_quads,
                      const std::vector<Panel_orientation>& best, Orientation_policy policy,
                      double tolerance)
{
  const std::vector<Shared_edge> edges = shared_edges(pm, fim);
  const std::vector<std::array<double, 8> > d =
    admissible_dissimilarities(quads, label, s_quads, policy, tolerance);
  std::vector<int> corners(quads.size());
  for(std::size_t f = 0; f < quads.size(); ++f) corners[f] = quads[f].size();
  const std::vector<Panel_orientation> starts[3] = {
    best, propagated_orientations(edges, label, d, corners, best, true),
    propagated_orientations(edges, label, d, corners, best, false)};
  std::vector<Flexible_orientations> searches;
  searches.reserve(3);
  std::size_t chosen = 0;
  for(std::size_t i = 0; i < 3; ++i)
  {
    searches.emplace_back(edges, label, s_quads.size(), d, corners, starts[i]);
    searches.back().improve(3);  // further sweeps changed no DOF on the test surfaces
    if(searches[i].is_better_than(searches[chosen]))
      chosen = i;
  }
  return searches[chosen].orientations();
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/flexible_orientations_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_FLEXIBLE_ORIENTATIONS_H
