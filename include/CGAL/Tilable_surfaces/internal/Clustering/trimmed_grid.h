// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_H

// Quad grids with missing cells: a facade or a roof is a grid trimmed by its
// outline, so its strips are rows of different lengths and quad_grid()
// refuses it. Walking from face to face gives every face its cell (x, y) in
// one lattice, and every vertex its lattice point; the mesh is a trimmed
// grid when no walk disagrees (no vertex of valence other than 4 inside, no
// strip that closes), and every lattice point is one vertex.
// The grid is the cells' bounding box, with `face_at` = no_index() where a
// cell is missing. Its corners follow the conventions of Quad_grid, so that
// the sweeps (sweep_candidates.h) see rings of rows + 1 lattice points, some
// missing.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <numeric>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Per lattice point (ring r, position c: entry r * (columns + 1) + c)
// of a trimmed grid, a cell that has it and its corner there, or no cell.
struct Trimmed_grid_points
{
  std::vector<std::size_t> cell;
  std::vector<int> corner;
};

// Corner i of the cell of row r and column c lies at ring
// r + grid_corner_ring[i], position c + grid_corner_position[i] (Quad_grid:
// corners 0, 1 on the far ring, 3 and 0 on the edge towards the next column).
constexpr int grid_corner_ring[4] = {1, 1, 0, 0};
constexpr int grid_corner_position[4] = {1, 0, 0, 1};

// The cell of every face on the square lattice and its face edge on the
// cell's -y side, running towards +x (side m of a face, 0: -y, 1: +x, 2: +y,
// 3: -x, is face edge bottom + m): a breadth-first search from face 0 at
// cell (0, 0). False when the faces do not fit the lattice (two cells for a
// face, or a face not reached). `face_of` maps indices to faces.
template <typename PolygonMesh, typename FaceIndexMap>
bool lattice_cells(const PolygonMesh& pm, FaceIndexMap fim,
                   const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                   std::vector<std::array<long, 2> >& cell, std::vector<int>& bottom)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t n = face_of.size();
  const long unset = (std::numeric_limits<long>::max)();
  cell.assign(n, {unset, unset});
  bottom.assign(n, 0);
  const long step[4][2] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  std::deque<std::size_t> queue(1, 0);
  cell[0] = {0, 0};
  std::size_t reached = 1;
  while(!queue.empty())
  {
    const std::size_t f = queue.front();
    queue.pop_front();
    const auto h = face_edge_halfedges(face_of[f], pm);
    for(int m = 0; m < 4; ++m)
    {
      const halfedge_descriptor across = opposite(h[std::size_t((bottom[f] + m) % 4)], pm);
      if(is_border(across, pm))
        continue;
      const std::size_t g = std::size_t(get(fim, face(across, pm)));
      const auto hg = face_edge_halfedges(face_of[g], pm);
      int j = 0;
      while(j < 4 && hg[std::size_t(j)] != across) ++j;
      const int bottom_g = (j - (m + 2) + 8) % 4;
      const std::array<long, 2> at = {cell[f][0] + step[m][0], cell[f][1] + step[m][1]};
      if(cell[g][0] == unset)
      {
        cell[g] = at;
        bottom[g] = bottom_g;
        queue.push_back(g);
        ++reached;
      }
      else if(cell[g] != at || bottom[g] != bottom_g)
        return false;
    }
  }
  return reached == n;
}

// The bounding box of the cells: `low` and `high` corners per lattice axis.
CGAL_TILABLE_SURFACES_INLINE
void lattice_bounds(const std::vector<std::array<long, 2> >& cell, long low[2], long high[2]);

// Fills `trimmed` (its rows and columns already set, its rows left at 0
// by the caller until every check has passed) and `lattice` from the cells:
// every face at its row and column, its corners in grid order, and each
// lattice point's first cell and corner. Rows along x: row y, column x. Rows
// along y: row x, column -y, so that the corners keep the faces' cyclic
// order. False when two faces share a cell or two vertices a lattice point
// (a slit).
template <typename PolygonMesh, typename VertexPointMap>
bool place_trimmed_cells(const PolygonMesh& pm, VertexPointMap vpm,
                         const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                         const std::vector<std::array<long, 2> >& cell, const std::vector<int>& bottom,
                         const long low[2], const long high[2], int row_direction, std::size_t columns,
                         Quad_grid& trimmed, Trimmed_grid_points& lattice,
                         std::vector<typename boost::graph_traits<PolygonMesh>::vertex_descriptor>& vertex_at)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t n = face_of.size();
  for(std::size_t f = 0; f < n; ++f)
  {
    const std::size_t r = std::size_t(row_direction == 0 ? cell[f][1] - low[1] : cell[f][0] - low[0]),
                      c = std::size_t(row_direction == 0 ? cell[f][0] - low[0] : high[1] - cell[f][1]);
    if(trimmed.face_at[r * columns + c] != no_index())
      return false;
    trimmed.face_at[r * columns + c] = f;
    // Corner 0 is the +x,+y vertex of the face (rows along x), or its +x,-y
    // vertex (rows along y); face vertex bottom + 2, resp. bottom + 1.
    trimmed.corner_offset[f] = (bottom[f] + (row_direction == 0 ? 2 : 1)) % 4;
    auto h = halfedge(face_of[f], pm);
    for(int j = 0; j < trimmed.corner_offset[f]; ++j) h = next(h, pm);
    for(int i = 0; i < 4; ++i, h = next(h, pm))
    {
      const vertex_descriptor v = target(h, pm);
      trimmed.corners[f][i] = to_eigen(get(vpm, v));
      const std::size_t p = (r + std::size_t(grid_corner_ring[i])) * (columns + 1) + c + std::size_t(grid_corner_position[i]);
      if(lattice.cell[p] == no_index())
      {
        lattice.cell[p] = r * columns + c;
        lattice.corner[p] = i;
        vertex_at[p] = v;
      }
      else if(vertex_at[p] != v)  // a slit: two vertices at one lattice point
        return false;
    }
  }
  return true;
}

// Whether every vertex has one lattice point: a surface that meets itself at
// a vertex would put that vertex at two.
template <typename VertexDescriptor>
bool one_lattice_point_per_vertex(const Trimmed_grid_points& lattice, const std::vector<VertexDescriptor>& vertex_at)
{
  std::vector<VertexDescriptor> seen;
  seen.reserve(lattice.cell.size());
  for(std::size_t p = 0; p < lattice.cell.size(); ++p)
    if(lattice.cell[p] != no_index())
      seen.push_back(vertex_at[p]);
  std::sort(seen.begin(), seen.end());
  return std::adjacent_find(seen.begin(), seen.end()) == seen.end();
}

// The trimmed grid of `pm` whose rows run along lattice direction
// `row_direction`, and its lattice points; an empty grid (rows == 0) when
// the quads do not form one, or form a grid without a missing cell (which
// quad_grid() takes), or a grid of fewer than 2 rows or 3 columns, or one
// whose bounding box holds more than tuning::trimmed_grid_max_cells_per_face
// cells per face.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
Quad_grid trimmed_quad_grid(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm, int row_direction,
                            Trimmed_grid_points& points)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const std::size_t n = num_faces(pm);
  const Quad_grid none;
  points = Trimmed_grid_points();
  if(n < 3)
    return none;
  std::vector<face_descriptor> face_of(n);
  for(face_descriptor f : faces(pm))
  {
    if(degree(f, pm) != 4)
      return none;
    face_of[get(fim, f)] = f;
  }
  std::vector<std::array<long, 2> > cell;
  std::vector<int> bottom;
  if(!lattice_cells(pm, fim, face_of, cell, bottom))
    return none;
  long low[2], high[2];
  lattice_bounds(cell, low, high);
  const std::size_t rows = std::size_t(high[1 - row_direction] - low[1 - row_direction] + 1),
                    columns = std::size_t(high[row_direction] - low[row_direction] + 1);
  if(rows < 2 || columns < 3 || rows * columns == n ||
     double(rows) * double(columns) > tuning::trimmed_grid_max_cells_per_face * double(n))
    return none;
  // Filled in place; rows stays 0 (no grid) until every check has passed.
  Quad_grid trimmed;
  trimmed.face_at.assign(rows * columns, no_index());
  trimmed.corners.resize(n);
  trimmed.corner_offset.assign(n, 0);
  Trimmed_grid_points lattice;
  lattice.cell.assign((rows + 1) * (columns + 1), no_index());
  lattice.corner.assign(lattice.cell.size(), 0);
  std::vector<vertex_descriptor> vertex_at(lattice.cell.size());
  if(!place_trimmed_cells(pm, vpm, face_of, cell, bottom, low, high, row_direction, columns, trimmed, lattice,
                          vertex_at) ||
     !one_lattice_point_per_vertex(lattice, vertex_at))
    return none;
  trimmed.rows = rows;
  trimmed.faces.resize(n);
  std::iota(trimmed.faces.begin(), trimmed.faces.end(), std::size_t(0));
  trimmed.columns = columns;
  points = std::move(lattice);
  return trimmed;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/trimmed_grid_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_TRIMMED_GRID_H
