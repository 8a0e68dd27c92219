// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_H

// The coarse mesh of a quad mesh that is one 2 x 2 refinement of another (a
// Catmull-Clark step, a midpoint split), and the bilinear prolongation of
// positions and clusterings from it.
//
// The vertices of such a mesh are of three classes: coarse vertices (C),
// edge vertices (E, one per coarse edge) and face vertices (F, one per
// coarse face), and every quad has its corners C, E, F, E in cyclic order.
// The classes are found by propagation over the quads: a quad with one
// corner of class C or F known has all four known, and two quads sharing an
// edge share a C or an F. Vertices that only a coarse vertex can be (inner
// ones of valence other than 4, border ones of valence other than 3) seed
// it; a component without one is tried with each corner of its first quad
// as C, in turn. The coarse mesh has the C vertices and one quad per F
// vertex, whose corners are the C vertices of the 4 quads around it.
//
// Prolongation: a C vertex where the coarse vertex is, an E vertex at the
// midpoint of its coarse edge, an F vertex at the mean of its coarse quad's
// corners. The sub-quad at corner i of a coarse quad is then its corner, the
// two midpoints next to it and its centre; a rigid motion or a mirror that
// maps one coarse quad onto another maps these points onto theirs. So the
// sub-quads at corresponding corners of congruent coarse quads are
// congruent, and a clustering exact on the coarse mesh gives one exact on
// the fine mesh with four clusters per coarse cluster.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/number_utils.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The fine-to-coarse relation of a quad mesh that is a 2 x 2 refinement.
struct Quad_coarsening
{
  static constexpr std::size_t none = std::size_t(-1);

  // Per fine vertex (by vertex index): the coarse vertices whose mean is
  // its prolongated position, `parent_count` of them: itself (C), the ends
  // of its coarse edge (E), the corners of its coarse quad (F).
  std::vector<std::array<std::size_t, 4> > parents;
  std::vector<unsigned char> parent_count;
  // Per coarse vertex, its fine vertex (by vertex index).
  std::vector<std::size_t> fine_vertex;
  // Per coarse quad, its corners (coarse vertices) in the fine quads' cyclic direction.
  std::vector<std::array<std::size_t, 4> > coarse_faces;
  // Per fine face (by face index): its coarse quad, the corner (0..3) of
  // that quad it holds, and where that corner is among the fine face's own
  // vertices (0..3, as vertices_around_face(halfedge(f)) lists them).
  std::vector<std::size_t> coarse_face;
  std::vector<int> coarse_corner, own_corner;

  std::size_t number_of_coarse_vertices() const { return fine_vertex.size(); }
  std::size_t number_of_coarse_faces() const { return coarse_faces.size(); }
};

// Finds the C, E, F classes of the vertices of a quad mesh and the coarse
// mesh they define; see the top of this file.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap>
class Quad_coarsener
{
  typedef boost::graph_traits<PolygonMesh> Traits;
  typedef typename Traits::vertex_descriptor vertex_descriptor;
  typedef typename Traits::face_descriptor face_descriptor;
  enum Vertex_class : unsigned char { UNKNOWN, COARSE, EDGE, FACE };

public:
  Quad_coarsener(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim)
    : m_pm(pm), m_fim(fim), m_vim(vim), m_class(num_vertices(pm), UNKNOWN), m_visited(num_faces(pm), false)
  {
    m_result.own_corner.assign(num_faces(pm), -1);
  }

  // The coarsening, or nothing when the mesh has a face that is no quad or
  // is not a 2 x 2 refinement.
  std::optional<Quad_coarsening> run()
  {
    for(face_descriptor f : faces(m_pm))
      if(degree(f, m_pm) != 4)
        return std::nullopt;
    if(num_faces(m_pm) == 0 || !label_seeded_components() || !label_other_components() || !classes_fit())
      return std::nullopt;
    if(!build_coarse_faces())
      return std::nullopt;
    return std::move(m_result);
  }

private:
  std::array<vertex_descriptor, 4> corners(face_descriptor f) const
  {
    std::array<vertex_descriptor, 4> v;
    std::size_t i = 0;
    for(vertex_descriptor u : CGAL::vertices_around_face(halfedge(f, m_pm), m_pm))
      v[i++] = u;
    return v;
  }

  // Gives `v` class `c`; false if it has another.
  bool set_class(vertex_descriptor v, Vertex_class c)
  {
    Vertex_class& current = m_class[get(m_vim, v)];
    if(current == UNKNOWN)
    {
      current = c;
      m_touched.push_back(get(m_vim, v));
    }
    return current == c;
  }

  // Classes the corners of `f` from one corner of class C or F; false when
  // it has none or a corner already has another class.
  bool label_face(face_descriptor f)
  {
    const std::array<vertex_descriptor, 4> v = corners(f);
    for(int k = 0; k < 4; ++k)
    {
      const Vertex_class c = m_class[get(m_vim, v[k])];
      if(c != COARSE && c != FACE)
        continue;
      const int coarse = c == COARSE ? k : (k + 2) % 4;
      m_result.own_corner[get(m_fim, f)] = coarse;
      return set_class(v[coarse], COARSE) && set_class(v[(coarse + 1) % 4], EDGE) &&
             set_class(v[(coarse + 2) % 4], FACE) && set_class(v[(coarse + 3) % 4], EDGE);
    }
    return false;
  }

  // Classes every face reachable from `queue` across inner edges.
  bool propagate(std::deque<face_descriptor> queue)
  {
    for(face_descriptor f : queue)
      mark_visited(f);
    while(!queue.empty())
    {
      const face_descriptor f = queue.front();
      queue.pop_front();
      if(!label_face(f))
        return false;
      for(auto h : CGAL::halfedges_around_face(halfedge(f, m_pm), m_pm))
      {
        const face_descriptor g = face(opposite(h, m_pm), m_pm);
        if(g != Traits::null_face() && !m_visited[get(m_fim, g)])
        {
          mark_visited(g);
          queue.push_back(g);
        }
      }
    }
    return true;
  }

  void mark_visited(face_descriptor f)
  {
    m_visited[get(m_fim, f)] = true;
    m_visited_faces.push_back(get(m_fim, f));
  }

  // The components that have a vertex only a coarse vertex can be.
  bool label_seeded_components()
  {
    std::deque<face_descriptor> seeds;
    for(vertex_descriptor v : vertices(m_pm))
      if(is_irregular_vertex(v, m_pm)) // only a coarse vertex can be irregular
      {
        if(!set_class(v, COARSE))
          return false;
        for(face_descriptor f : CGAL::faces_around_target(halfedge(v, m_pm), m_pm))
          if(f != Traits::null_face() && !m_visited[get(m_fim, f)])
          {
            m_visited[get(m_fim, f)] = true;
            seeds.push_back(f);
          }
      }
    for(face_descriptor f : seeds)
      m_visited[get(m_fim, f)] = false;
    return propagate(seeds);
  }

  // The other components: each corner of their first face as C in turn,
  // until one classes the whole component.
  bool label_other_components()
  {
    for(face_descriptor f : faces(m_pm))
    {
      if(m_visited[get(m_fim, f)])
        continue;
      bool labelled = false;
      for(int k = 0; k < 4 && !labelled; ++k)
      {
        m_touched.clear();
        m_visited_faces.clear();
        labelled = set_class(corners(f)[std::size_t(k)], COARSE) && propagate({f});
        if(!labelled)
          undo_trial();
      }
      if(!labelled)
        return false;
    }
    return true;
  }

  void undo_trial()
  {
    for(std::size_t v : m_touched) m_class[v] = UNKNOWN;
    for(std::size_t f : m_visited_faces) m_visited[f] = false;
  }

  // F vertices are inner of valence 4; every E vertex has two C
  // neighbours, its parents; every vertex is classed.
  bool classes_fit()
  {
    m_result.parents.assign(num_vertices(m_pm), {});
    m_result.parent_count.assign(num_vertices(m_pm), 0);
    std::vector<std::size_t> coarse_id(num_vertices(m_pm), Quad_coarsening::none);
    for(vertex_descriptor v : vertices(m_pm))
      if(m_class[get(m_vim, v)] == COARSE)
      {
        coarse_id[get(m_vim, v)] = m_result.fine_vertex.size();
        m_result.parents[get(m_vim, v)][0] = m_result.fine_vertex.size();
        m_result.parent_count[get(m_vim, v)] = 1;
        m_result.fine_vertex.push_back(get(m_vim, v));
      }
    for(vertex_descriptor v : vertices(m_pm))
    {
      const std::size_t i = get(m_vim, v);
      if(m_class[i] == UNKNOWN || (m_class[i] == FACE && (bool(is_border(v, m_pm)) || degree(v, m_pm) != 4)))
        return false;
      if(m_class[i] != EDGE)
        continue;
      for(vertex_descriptor u : CGAL::vertices_around_target(halfedge(v, m_pm), m_pm))
        if(m_class[get(m_vim, u)] == COARSE && m_result.parent_count[i] < 4)
          m_result.parents[i][m_result.parent_count[i]++] = coarse_id[get(m_vim, u)];
      if(m_result.parent_count[i] != 2)
        return false;
    }
    return true;
  }

  // One coarse quad per F vertex, from the first fine face around it (in
  // face order): its corner m is the C vertex of the m-th fine face met
  // turning around the F vertex in the faces' direction.
  bool build_coarse_faces()
  {
    const std::size_t n = num_faces(m_pm);
    m_result.coarse_face.assign(n, Quad_coarsening::none);
    m_result.coarse_corner.assign(n, -1);
    for(face_descriptor f : faces(m_pm))
      if(m_result.coarse_face[get(m_fim, f)] == Quad_coarsening::none && !build_coarse_face(f))
        return false;
    return true;
  }

  bool build_coarse_face(face_descriptor first)
  {
    const std::size_t q = m_result.coarse_faces.size();
    std::array<std::size_t, 4> corner;
    face_descriptor g = first;
    for(int m = 0; m < 4; ++m)
    {
      const std::size_t gi = get(m_fim, g);
      if(m_result.coarse_face[gi] != Quad_coarsening::none)
        return false;
      const int own = m_result.own_corner[gi];
      corner[std::size_t(m)] = m_result.parents[get(m_vim, corners(g)[std::size_t(own)])][0];
      m_result.coarse_face[gi] = q;
      m_result.coarse_corner[gi] = m;
      // Across the edge from the E vertex after the C vertex to the F vertex.
      g = face(opposite(face_edge_halfedges(g, m_pm)[std::size_t((own + 1) % 4)], m_pm), m_pm);
      if(g == Traits::null_face())
        return false;
    }
    if(g != first)
      return false;
    const vertex_descriptor centre = corners(first)[std::size_t((m_result.own_corner[get(m_fim, first)] + 2) % 4)];
    m_result.parents[get(m_vim, centre)] = corner;
    m_result.parent_count[get(m_vim, centre)] = 4;
    m_result.coarse_faces.push_back(corner);
    return true;
  }

  const PolygonMesh& m_pm;
  FaceIndexMap m_fim;
  VertexIndexMap m_vim;
  std::vector<Vertex_class> m_class;  // by vertex index
  std::vector<bool> m_visited;        // by face index
  std::vector<std::size_t> m_touched, m_visited_faces;  // of the current trial, to undo it
  Quad_coarsening m_result;
};

// The coarsening of the quad mesh `pm`, or nothing if it is no 2 x 2 refinement.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap>
std::optional<Quad_coarsening> quad_coarsening(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim)
{
  return Quad_coarsener<PolygonMesh, FaceIndexMap, VertexIndexMap>(pm, fim, vim).run();
}

// The coarse mesh of `coarsening`, its vertices at the points of their fine
// vertices (`fine_points`, by fine vertex index); false if its quads do not
// form a manifold mesh.
template <typename Point>
bool make_coarse_mesh(const Quad_coarsening& coarsening, const std::vector<Point>& fine_points,
                      CGAL::Surface_mesh<Point>& coarse)
{
  typedef typename CGAL::Surface_mesh<Point>::Vertex_index Vertex_index;
  coarse.clear();
  for(std::size_t v : coarsening.fine_vertex)
    coarse.add_vertex(fine_points[v]);
  for(const std::array<std::size_t, 4>& q : coarsening.coarse_faces)
    if(coarse.add_face(Vertex_index(q[0]), Vertex_index(q[1]), Vertex_index(q[2]), Vertex_index(q[3])) ==
       CGAL::Surface_mesh<Point>::null_face())
      return false;
  return true;
}

// The fine positions (by fine vertex index) prolongated from the coarse
// ones (by coarse vertex index): each the mean of its parents.
template <typename Point>
std::vector<Point> prolongated_points(const Quad_coarsening& coarsening, const std::vector<Point>& coarse_points)
{
  std::vector<Point> fine;
  fine.reserve(coarsening.parents.size());
  for(std::size_t v = 0; v < coarsening.parents.size(); ++v)
  {
    const std::size_t count = coarsening.parent_count[v];
    double x = 0, y = 0, z = 0;
    for(std::size_t j = 0; j < count; ++j)
    {
      const Point& p = coarse_points[coarsening.parents[v][j]];
      x += CGAL::to_double(p.x());
      y += CGAL::to_double(p.y());
      z += CGAL::to_double(p.z());
    }
    fine.emplace_back(x / double(count), y / double(count), z / double(count));
  }
  return fine;
}

// The fine clustering (by fine face index) prolongated from the coarse one
// (by coarse face index): the sub-quad at template corner t of a coarse
// quad of cluster c is in cluster 4c + t. Its template is the S-quad's
// corner t, the midpoint towards corner t + 1, the centre and the midpoint
// towards corner t - 1; its orientation starts at its C vertex and turns
// the way the coarse orientation turns.
CGAL_TILABLE_SURFACES_INLINE
Face_clustering prolongated_clustering(const Quad_coarsening& coarsening, const Face_clustering& coarse);

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_coarsening_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_COARSENING_H
