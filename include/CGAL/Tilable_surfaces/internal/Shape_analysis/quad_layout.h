// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_H

// The quad layout of a quad(-dominant) mesh: its split into grid patches
// along separatrices, motorcycle-graph style.
//
// A vertex is irregular when it has valence other than 4 inside, other than
// 3 on the border (a corner of valence 2, a border vertex of valence 4 or
// more). From every irregular vertex and every vertex of a triangle (a
// corner of the quads around it) a separatrix is traced along each of its
// inner edges between quads, straight across regular inner vertices (on to the
// opposite edge), and stops at the border, at an irregular vertex, at a
// vertex of a triangle, or at a vertex an earlier trace has passed (the
// motorcycle rule: traces end where they meet, so patches stay few and
// large). All traces advance one edge per round, in the order of their
// irregular vertices (ranked by first appearance in the faces by
// FaceIndexMap index) and of the edges around each, so the layout depends on
// the mesh only. Triangles are patches of their own. The patches are the
// sets of quads joined across edges that are not traced, not borders and
// not edges of a triangle, numbered by first face; each is a grid
// (quad_grid.h), or is marked as none (a ring whose strips twist, a region
// a trace enters without cutting it through).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid.h>

#include <map>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Quad_layout
{
  std::vector<std::size_t> patch_of_face;  // per face (FaceIndexMap index); patches numbered by first face
  std::vector<Quad_grid> grids;            // per patch; empty (rows == 0) when the patch is not a grid
};

// The faces of every patch (patch_of_face: the patch of every face,
// numbered from 0), increasing.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::vector<std::size_t> > patch_faces(const std::vector<std::size_t>& patch_of_face);

// Whether `v` is an irregular vertex of the quad mesh `pm`: valence other
// than 4 inside, other than 3 on the border.
template <typename PolygonMesh>
bool is_irregular_vertex(typename boost::graph_traits<PolygonMesh>::vertex_descriptor v, const PolygonMesh& pm)
{
  return degree(v, pm) != (is_border(v, pm) ? 3u : 4u);
}

template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
class Quad_layout_builder
{
  typedef boost::graph_traits<PolygonMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;

public:
  Quad_layout_builder(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm)
    : m_pm(pm), m_fim(fim), m_vpm(vpm), m_face_of(faces_by_index(pm, fim)), m_cut(4 * m_face_of.size(), false)
  {}

  Quad_layout operator()(int row_direction)
  {
    cut_along_borders_and_triangles();
    trace_separatrices();
    Quad_layout layout;
    layout.patch_of_face = patches();
    layout.grids = grids(patch_faces(layout.patch_of_face), row_direction);
    return layout;
  }

private:
  // The slot of halfedge h of a face: 4 per face, one per face edge.
  std::size_t slot(halfedge_descriptor h) const
  {
    const auto edges = face_edge_halfedges(face(h, m_pm), m_pm);
    return 4 * std::size_t(get(m_fim, face(h, m_pm))) +
           std::size_t(std::find(edges.begin(), edges.end(), h) - edges.begin());
  }
  bool is_cut(halfedge_descriptor h) const { return m_cut[slot(h)]; }
  void cut(halfedge_descriptor h)
  {
    for(halfedge_descriptor g : {h, opposite(h, m_pm)})
      if(!is_border(g, m_pm))
        m_cut[slot(g)] = true;
  }

  void cut_along_borders_and_triangles()
  {
    for(face_descriptor f : m_face_of)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(f, m_pm), m_pm))
        if(is_border(opposite(h, m_pm), m_pm) || degree(f, m_pm) != 4 ||
           degree(face(opposite(h, m_pm), m_pm), m_pm) != 4)
          cut(h);
  }

  bool is_irregular(vertex_descriptor v) const { return is_irregular_vertex(v, m_pm); }
  bool has_triangle(vertex_descriptor v) const
  {
    for(face_descriptor f : faces_around_target(halfedge(v, m_pm), m_pm))
      if(f != Traits::null_face() && degree(f, m_pm) != 4)
        return true;
    return false;
  }

  // The vertices by first appearance in the faces by index.
  std::vector<vertex_descriptor> ranked_vertices() const
  {
    std::vector<vertex_descriptor> ranked;
    std::map<vertex_descriptor, bool> seen;
    for(face_descriptor f : m_face_of)
      for(vertex_descriptor v : vertices_around_face(halfedge(f, m_pm), m_pm))
        if(seen.emplace(v, true).second)
          ranked.push_back(v);
    return ranked;
  }

  // Every trace is the halfedge it runs along, towards its next vertex.
  void trace_separatrices()
  {
    std::vector<halfedge_descriptor> traces;
    for(vertex_descriptor v : ranked_vertices())
      if(is_irregular(v) || has_triangle(v))
        for(halfedge_descriptor h : halfedges_around_source(v, m_pm))
          if(!is_border_edge(h, m_pm) && !is_cut(h))
            traces.push_back(h);
    std::map<vertex_descriptor, bool> passed;
    while(!traces.empty())
    {
      std::vector<halfedge_descriptor> running;
      for(halfedge_descriptor h : traces)
      {
        cut(h);
        const vertex_descriptor w = target(h, m_pm);
        if(is_border(w, m_pm) || is_irregular(w) || has_triangle(w) || !passed.emplace(w, true).second)
          continue;
        running.push_back(next(opposite(next(h, m_pm), m_pm), m_pm));
      }
      traces.swap(running);
    }
  }

  // The patch of every face: faces joined across edges not cut.
  std::vector<std::size_t> patches() const
  {
    const std::size_t n = m_face_of.size();
    Union_find<> sets(n);
    for(std::size_t f = 0; f < n; ++f)
      for(halfedge_descriptor h : halfedges_around_face(halfedge(m_face_of[f], m_pm), m_pm))
        if(!is_cut(h))
          sets.unite(f, std::size_t(get(m_fim, face(opposite(h, m_pm), m_pm))));
    std::vector<std::size_t> patch(n);
    for(std::size_t f = 0; f < n; ++f)
      patch[f] = sets.find(f);
    relabel_by_first_face(patch);
    return patch;
  }

  // The grid of every patch, its rows along `row_direction` unless it has a
  // single column that way.
  std::vector<Quad_grid> grids(const std::vector<std::vector<std::size_t> >& faces, int row_direction) const
  {
    auto crossable = [this](halfedge_descriptor h) { return !is_cut(h); };
    std::vector<int> flip(m_face_of.size(), -1);
    std::vector<bool> twisted(faces.size(), false);
    for(std::size_t p = 0; p < faces.size(); ++p)
      if(!propagate_strip_flips(m_pm, m_fim, m_face_of, faces[p][0], crossable, flip))
      {
        twisted[p] = true;
        for(std::size_t f : faces[p]) flip[f] = 0;
      }
    const std::array<std::vector<std::size_t>, 2> strips = strips_across(m_pm, m_fim, flip, crossable);
    std::vector<Quad_grid> grids(faces.size());
    for(std::size_t p = 0; p < faces.size(); ++p)
    {
      if(twisted[p] || degree(m_face_of[faces[p][0]], m_pm) != 4)
        continue;
      for(int d : {row_direction, 1 - row_direction})
        if(grids[p].rows == 0)
          grids[p] = region_grid(m_pm, m_fim, m_vpm, m_face_of, faces[p], strips, d, crossable);
    }
    return grids;
  }

  const PolygonMesh& m_pm;
  FaceIndexMap m_fim;
  VertexPointMap m_vpm;
  std::vector<face_descriptor> m_face_of;
  std::vector<bool> m_cut;  // per face edge slot (slot())
};

// The quad layout of `pm` (see above), each grid's rows along the strips of
// direction `row_direction` of its first face, unless it has one column
// that way (then along the other).
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Quad_layout quad_layout(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, int row_direction = 0)
{
  return Quad_layout_builder<PolygonMesh, FaceIndexMap, VertexPointMap>(pm, fim, vpm)(row_direction);
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_LAYOUT_H
