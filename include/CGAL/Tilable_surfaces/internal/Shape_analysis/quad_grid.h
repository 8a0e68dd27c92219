// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_H

// Quad strips and quad grids, of a whole mesh or of a region of it.
//
// A quad strip (a polychord) is a sequence of faces, each entered and left
// through two opposite edges. Every quad lies on two strips, one per pair of
// opposite edges. The quads form a grid, rows x columns, when every strip of
// one direction (a row) crosses every strip of the other (a column) exactly
// once: a tube, a shell, a patch. A region is a set of quads joined across
// the edges a predicate `crossable(h)` accepts (h a halfedge of one of its
// faces whose opposite is not a border); for the whole mesh, every edge that
// is not a border (`Across_inner_edges`).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/Union_find.h>

#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <numeric>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Cluster ids renumbered by first face: cluster of face 0 is 0, and so on.
CGAL_TILABLE_SURFACES_INLINE
std::size_t relabel_by_first_face(std::vector<std::size_t>& label);

// Every edge that is not a border joins its two faces.
template <typename PolygonMesh>
struct Across_inner_edges
{
  const PolygonMesh& pm;
  bool operator()(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) const
  {
    return !is_border(opposite(h, pm), pm);
  }
};

// The faces by FaceIndexMap index.
template <typename PolygonMesh, typename FaceIndexMap>
std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> faces_by_index(const PolygonMesh& pm,
                                                                                       FaceIndexMap fim)
{
  std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor> face_of(num_faces(pm));
  for(auto f : faces(pm))
    face_of[std::size_t(get(fim, f))] = f;
  return face_of;
}

// The parity of the place of `h` among the face edges of its face.
template <typename PolygonMesh>
int face_edge_parity(typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h, const PolygonMesh& pm)
{
  const auto face_edges = face_edge_halfedges(face(h, pm), pm);
  return int(std::find(face_edges.begin(), face_edges.end(), h) - face_edges.begin()) % 2;
}

// Sets the flips (strip_direction_flips()) of the faces of the region of
// quad `start`, which gets flip 0; false if two paths disagree (a strip
// that meets itself).
template <typename PolygonMesh, typename FaceIndexMap, typename Crossable>
bool propagate_strip_flips(const PolygonMesh& pm, FaceIndexMap fim,
                           const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                           std::size_t start, Crossable crossable, std::vector<int>& flip)
{
  flip[start] = 0;
  std::deque<std::size_t> queue(1, start);
  while(!queue.empty())
  {
    const std::size_t f = queue.front();
    queue.pop_front();
    for(auto h : face_edge_halfedges(face_of[f], pm))
    {
      if(is_border(opposite(h, pm), pm) || !crossable(h))
        continue;
      const std::size_t g = std::size_t(get(fim, face(opposite(h, pm), pm)));
      const int expected = flip[f] ^ face_edge_parity(h, pm) ^ face_edge_parity(opposite(h, pm), pm);
      if(flip[g] < 0)
      {
        flip[g] = expected;
        queue.push_back(g);
      }
      else if(flip[g] != expected)
        return false;
    }
  }
  return true;
}

// Per face, 1 when its face edges 1 and 3, not 0 and 2, are crossed by the
// strips that face 0's edges 0 and 2 are crossed by, as far as the strips
// can be told apart that way: across an edge, a strip leaves one face
// through a face edge of parity p and enters the next through one of
// parity q, so their flips differ by p xor q. Where a file starts its faces
// at any corner (a CAD export), this is what lets a grid be seen as one;
// on an all-quad mesh whose flips disagree somewhere (a strip that meets
// itself, as around a vertex of odd valence), or with triangles, all 0.
// Face 0 is never flipped: quad_grid() and trimmed_quad_grid() walk from
// face 0 along its own face edges, and direction d must be the same strips
// there (flipping face 0 by a majority rule, when it is in the minority,
// makes a scrambled tunnel no grid).
template <typename PolygonMesh, typename FaceIndexMap>
std::vector<int> strip_direction_flips(const PolygonMesh& pm, FaceIndexMap fim)
{
  const std::size_t n = num_faces(pm);
  for(auto f : faces(pm))
    if(degree(f, pm) != 4)
      return std::vector<int>(n, 0);
  const auto face_of = faces_by_index(pm, fim);
  std::vector<int> flip(n, -1);
  for(std::size_t start = 0; start < n; ++start)
    if(flip[start] < 0 && !propagate_strip_flips(pm, fim, face_of, start, Across_inner_edges<PolygonMesh>{pm}, flip))
      return std::vector<int>(n, 0);
  return flip;
}

// The strip of every face in each direction, joined across the edges where
// `crossable`: strip[d][f] for the strip that crosses face f through its
// face edges d xor flip[f] and d xor flip[f] + 2 (numbered 0..S_d - 1 by
// first face). A face never joined (a triangle) is a strip of its own.
template <typename PolygonMesh, typename FaceIndexMap, typename Crossable>
std::array<std::vector<std::size_t>, 2> strips_across(const PolygonMesh& pm, FaceIndexMap fim,
                                                      const std::vector<int>& flip, Crossable crossable)
{
  const std::size_t n = num_faces(pm);
  Union_find<> sets(2 * n);
  // Node 2 f + (j mod 2): face f's strip through its face edge j.
  auto node = [&](typename boost::graph_traits<PolygonMesh>::halfedge_descriptor h) {
    return 2 * std::size_t(get(fim, face(h, pm))) + std::size_t(face_edge_parity(h, pm));
  };
  for(auto e : edges(pm))
  {
    const auto h = halfedge(e, pm);
    if(is_border_edge(h, pm) || !crossable(h))
      continue;
    sets.unite(node(h), node(opposite(h, pm)));
  }
  std::array<std::vector<std::size_t>, 2> strip{{std::vector<std::size_t>(n), std::vector<std::size_t>(n)}};
  for(int d = 0; d < 2; ++d)
  {
    for(std::size_t f = 0; f < n; ++f)
      strip[d][f] = sets.find(2 * f + std::size_t(d ^ flip[f]));
    relabel_by_first_face(strip[d]);
  }
  return strip;
}

// The strips of the whole mesh (strips_across()), with the flips of
// strip_direction_flips(), or all flips 0 without `carried_directions`.
template <typename PolygonMesh, typename FaceIndexMap>
std::array<std::vector<std::size_t>, 2> quad_strips(const PolygonMesh& pm, FaceIndexMap fim,
                                                    bool carried_directions = true)
{
  const std::vector<int> flip =
    carried_directions ? strip_direction_flips(pm, fim) : std::vector<int>(num_faces(pm), 0);
  return strips_across(pm, fim, flip, Across_inner_edges<PolygonMesh>{pm});
}

// The quads of a grid: face_at[row * columns + column] is a grid face, an
// index into `faces`, the FaceIndexMap indices of the grid's faces.
struct Quad_grid
{
  std::size_t rows = 0, columns = 0;
  std::vector<std::size_t> faces;  // per grid face, increasing; 0..n-1 for a grid of the whole mesh
  std::vector<std::size_t> face_at;
  std::vector<Panel> corners;  // per grid face; corners 3 and 0 on its edge towards the next column
  // Per grid face, corner i is the target of next^(corner_offset + i)(halfedge(f)).
  std::vector<int> corner_offset;
};

// The faces of the strip through `f` that enters and leaves `f` through
// face edges `j` and `j + 2`, in order, starting at `f` when the strip is
// closed and at one of its ends otherwise; the strip ends at an edge that
// is a border or not `crossable`.
template <typename PolygonMesh, typename FaceIndexMap, typename Crossable>
std::vector<std::size_t> ordered_strip(const PolygonMesh& pm, FaceIndexMap fim,
                                       typename boost::graph_traits<PolygonMesh>::face_descriptor f, int j,
                                       Crossable crossable)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  const halfedge_descriptor h = face_edge_halfedges(f, pm)[std::size_t(j)];
  // Walks out of f through `exit`, appending the faces met, until an end
  // (false) or f again (true: a closed strip).
  auto walk = [&](halfedge_descriptor exit, std::vector<std::size_t>& out) {
    for(std::size_t guard = 0; guard < num_faces(pm); ++guard)
    {
      if(is_border(opposite(exit, pm), pm) || !crossable(exit))
        return false;
      const halfedge_descriptor in = opposite(exit, pm);
      if(face(in, pm) == f)
        return true;
      out.push_back(std::size_t(get(fim, face(in, pm))));
      exit = next(next(in, pm), pm);
    }
    return false;
  };
  std::vector<std::size_t> forward, backward;
  if(walk(next(next(h, pm), pm), forward))
  {
    forward.insert(forward.begin(), std::size_t(get(fim, f)));
    return forward;
  }
  walk(h, backward);
  std::reverse(backward.begin(), backward.end());
  backward.push_back(std::size_t(get(fim, f)));
  backward.insert(backward.end(), forward.begin(), forward.end());
  return backward;
}

// The face of each grid place of the region `faces` (increasing FaceIndexMap
// indices), its rows the strips of direction `row_direction` that cross its
// first face, its columns those of the other direction, ordered along them;
// false if the region is not rows x columns with one face per place.
template <typename PolygonMesh, typename FaceIndexMap, typename Crossable>
bool place_region_faces(const PolygonMesh& pm, FaceIndexMap fim,
                        const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                        const std::vector<std::size_t>& faces, const std::array<std::vector<std::size_t>, 2>& strips,
                        int row_direction, Crossable crossable, Quad_grid& grid)
{
  const std::vector<std::size_t> down = ordered_strip(pm, fim, face_of[faces[0]], 1 - row_direction, crossable);
  const std::vector<std::size_t> across = ordered_strip(pm, fim, face_of[faces[0]], row_direction, crossable);
  grid.rows = down.size();
  grid.columns = across.size();
  if(grid.rows * grid.columns != faces.size())
    return false;
  std::map<std::size_t, std::size_t> row_rank, column_rank;
  for(std::size_t r = 0; r < grid.rows; ++r) row_rank.emplace(strips[row_direction][down[r]], r);
  for(std::size_t c = 0; c < grid.columns; ++c) column_rank.emplace(strips[1 - row_direction][across[c]], c);
  grid.face_at.assign(faces.size(), no_index());
  for(std::size_t i = 0; i < faces.size(); ++i)
  {
    const auto r = row_rank.find(strips[row_direction][faces[i]]);
    const auto c = column_rank.find(strips[1 - row_direction][faces[i]]);
    if(r == row_rank.end() || c == column_rank.end() || grid.face_at[r->second * grid.columns + c->second] != no_index())
      return false;
    grid.face_at[r->second * grid.columns + c->second] = i;
  }
  return true;
}

// The grid of the region `faces` (increasing FaceIndexMap indices, joined
// across the edges where `crossable`), its rows the strips of direction
// `row_direction` of `strips` (strips_across() with the same predicate), or
// an empty grid (rows == 0) if the quads do not form one. A region of one
// column and several rows is no grid in this direction (its transpose is).
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap, typename Crossable>
Quad_grid region_grid(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                      const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                      const std::vector<std::size_t>& faces, const std::array<std::vector<std::size_t>, 2>& strips,
                      int row_direction, Crossable crossable)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  Quad_grid grid;
  if(faces.empty() || !place_region_faces(pm, fim, face_of, faces, strips, row_direction, crossable, grid) ||
     (grid.columns == 1 && grid.rows > 1))
    return Quad_grid();
  const std::size_t rows = grid.rows, columns = grid.columns;
  // Corners from the edge shared with the next column (in a closed row the
  // last column's next is the first; in an open row the last column takes
  // the edge opposite to the one it shares with the previous column; a
  // single face its first edge), so that corresponding corners of all faces
  // have the same place in the grid.
  auto shared_halfedge = [&](std::size_t i, std::size_t j, halfedge_descriptor& found) {
    halfedge_descriptor h = halfedge(face_of[faces[i]], pm);
    for(int e = 0; e < 4; ++e, h = next(h, pm))
      if(!is_border(opposite(h, pm), pm) && crossable(h) && std::size_t(get(fim, face(opposite(h, pm), pm))) == faces[j])
      {
        found = h;
        return true;
      }
    return false;
  };
  grid.corners.resize(faces.size());
  grid.corner_offset.assign(faces.size(), 0);
  for(std::size_t r = 0; r < rows; ++r)
    for(std::size_t c = 0; c < columns; ++c)
    {
      const std::size_t i = grid.face_at[r * columns + c];
      halfedge_descriptor h = halfedge(face_of[faces[i]], pm);
      // Two columns are never a closed row: the first is the second's previous.
      const bool has_next = c + 1 < columns || columns > 2;
      if(columns > 1 && !(has_next && shared_halfedge(i, grid.face_at[r * columns + (c + 1) % columns], h)))
      {
        if(c + 1 < columns || !shared_halfedge(i, grid.face_at[r * columns + c - 1], h))
          return Quad_grid();
        h = next(next(h, pm), pm);
      }
      for(halfedge_descriptor g = halfedge(face_of[faces[i]], pm); g != h; g = next(g, pm))
        ++grid.corner_offset[i];
      for(int k = 0; k < 4; ++k, h = next(h, pm))
        grid.corners[i][k] = to_eigen(get(vpm, target(h, pm)));
    }
  grid.faces = faces;
  return grid;
}

// The grid of the whole mesh whose rows are the strips of direction
// `row_direction` (quad_strips()), or an empty grid (rows == 0) if the
// quads do not form one of at least 2 rows and 3 columns.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Quad_grid quad_grid(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                    const std::array<std::vector<std::size_t>, 2>& strips, int row_direction)
{
  std::vector<std::size_t> all(num_faces(pm));
  std::iota(all.begin(), all.end(), std::size_t(0));
  Quad_grid grid = region_grid(pm, fim, vpm, faces_by_index(pm, fim), all, strips, row_direction,
                               Across_inner_edges<PolygonMesh>{pm});
  return grid.rows < 2 || grid.columns < 3 ? Quad_grid() : grid;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SHAPE_ANALYSIS_QUAD_GRID_H
