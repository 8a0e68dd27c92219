// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H

// An exact starting point for the sweep clusterings of a quad grid
// (sweep_clusterings() in sweep_candidates.h, which says why they are
// exact). The Gauss-Newton solver, started at the input, does not find
// such surfaces on large grids (10k seashell, K = 100: stalls near 3e-3,
// user manual, section Optimization): the section must stop growing, a
// large and coherent move. Built directly it costs O(F):
// - M_i of a run: the rigid motion that best maps its rings onto the next
//   ones (Umeyama, no scale), stacked;
// - the section: the mean of the input rings pulled back to the middle ring
//   by the composed motions, its column runs put on their helices;
// - the rings: the section pushed forward again, the whole then rigidly
//   aligned with the input.
// A row that is a run of its own has a mold per quad: the groups of runs it
// separates are each built so, from a section of their own
// (grouped_sweep_start()). A row that is one mold on a tube of round section
// joins groups swept from regular polygons on one axis
// (coaxial_sweep_start()).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The label of the cell of row r and column c of `grid`, no_index() at a
// missing cell of a trimmed grid.
inline std::size_t grid_cell_label(const Quad_grid& grid, const std::vector<std::size_t>& label, std::size_t r,
                                   std::size_t c)
{
  const std::size_t f = grid.face_at[r * grid.columns + c];
  return f == no_index() ? no_index() : label[f];
}

// The run of rows of every row: rows r and r + 1 share a motion when a
// cluster holds a quad of both. With `one_run` (a trimmed grid, or one
// closed across its rows, swept as one run by sweep_clusterings(), whose
// columns may be cut into pieces), every row is in run 0.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::size_t> grid_row_runs(const Quad_grid& grid, const std::vector<std::size_t>& label,
                                       bool one_run);

// How the clusters of `label` lie in the runs `run_of` of the grid.
enum class Sweep_layout { NONE, COLUMNS_OF_RUNS, COLUMN_RUNS };

// COLUMNS_OF_RUNS when every cluster lies in one column and one run,
// COLUMN_RUNS when the grid is one run whose clusters are runs of columns
// (screw_column_runs()), NONE otherwise. `run_of_column` receives the label
// of the first quad of every column.
CGAL_TILABLE_SURFACES_INLINE
Sweep_layout sweep_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
                          const std::vector<std::size_t>& run_of, std::vector<std::size_t>& run_of_column);

// Moves the points present of the rings in `points` (by vertex index) to the
// swept `surface` (rings side by side), rigidly aligned with the input
// (Umeyama, no scale). `ring`: the input rings, `rings`: their vertex
// indices, `present`: per ring, 1 or 0 per point. A closed grid's last ring
// is its first, and is not placed twice.
CGAL_TILABLE_SURFACES_INLINE
void place_sweep(Point_matrix& points, const Eigen::Matrix3Xd& surface,
                 const std::vector<Eigen::Matrix3Xd>& ring,
                 const std::vector<std::vector<std::size_t> >& rings,
                 const std::vector<Eigen::ArrayXd>& present, bool closed);

// The rows [first, end) of the groups of runs of `run_of` that share one
// section: maximal sequences of runs of two rows or more. A run of a single
// row has a mold per quad, so the section may change across it: the rings
// on its two sides belong to different groups (a transition row).
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::pair<std::size_t, std::size_t> > section_groups(const std::vector<std::size_t>& run_of);

// The sweep start of an open full grid whose runs `run_of` may include
// transition rows (section_groups()): every group swept from its own
// section and rigidly aligned with its input rings; the rings of a group
// start where the rows between two groups are all transitions stay as
// input. Arguments as place_sweep() takes them.
CGAL_TILABLE_SURFACES_INLINE
Point_matrix grouped_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
                                 const std::vector<std::vector<std::size_t> >& rings,
                                 const std::vector<Eigen::ArrayXd>& present,
                                 const std::vector<std::size_t>& run_of);

// Whether the clusters of `label` on a full grid with the runs `run_of` lie
// as coaxial_transition_sweep() makes them: every cluster in one run, and in
// one column or a whole row, at least one a whole row.
CGAL_TILABLE_SURFACES_INLINE
bool coaxial_transition_layout(const Quad_grid& grid, const std::vector<std::size_t>& label,
                               const std::vector<std::size_t>& run_of);

// The rigid motion that puts the regular polygon `next` on the axis of
// `previous`, `gap` farther along its normal, in a parallel plane and with
// the same phase (the coaxial transition row, sweep_candidates.h).
CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix4d coaxial_motion(const Regular_polygon& previous, const Regular_polygon& next, double gap);

// The screw motion with the axis direction and the step along it of `m`
// that turns `f` times as far per row, about an axis moved so that `center`
// keeps its distance per row and its path's tangent: that path bent `f`
// times as much. `m` when it hardly turns.
CGAL_TILABLE_SURFACES_INLINE
Eigen::Matrix4d bent_motion(const Eigen::Matrix4d& m, const Eigen::Vector3d& center, double f);

// The one-run sweep `swept` of `rows` rows with its motion bent `f` times
// as much about its middle ring's centre (bent_motion()), its frames
// composed again from the middle ring.
CGAL_TILABLE_SURFACES_INLINE
void bend_sweep(Swept_section& swept, std::size_t rows, double f);

// The sweep start of a full grid closed around its round rings whose runs
// `run_of` are groups separated by coaxial transition rows
// (coaxial_transition_layout()): every group swept from its own section made
// a regular polygon (fit_regular_polygon()), the first group rigidly aligned
// with its input rings, every next one put coaxially after the one before,
// as far along the axis as their input rings' centres are apart; the whole
// then rigidly aligned with the input. Empty when a ring lies in no group or
// two transition rows meet. Arguments as place_sweep() takes them.
CGAL_TILABLE_SURFACES_INLINE
Point_matrix coaxial_sweep_start(const Point_matrix& points, const std::vector<Eigen::Matrix3Xd>& ring,
                                 const std::vector<std::vector<std::size_t> >& rings,
                                 const std::vector<Eigen::ArrayXd>& present,
                                 const std::vector<std::size_t>& run_of);

// The start of quad_grid_sweep_start() on the grid `grid` of `pm` (its
// lattice points `points_of_grid` when trimmed); empty when the clusters do
// not lie as a sweep of it.
template <typename PolygonMesh, typename VertexIndexMap>
Point_matrix grid_sweep_start(const PolygonMesh& pm, VertexIndexMap vim,
                              const std::vector<typename boost::graph_traits<PolygonMesh>::face_descriptor>& face_of,
                              const Quad_grid& grid, const Trimmed_grid_points& points_of_grid,
                              const Point_matrix& points, const std::vector<std::size_t>& label, bool closed)
{
  typedef typename boost::graph_traits<PolygonMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t rows = grid.rows, columns = grid.columns;
  const bool one_run = closed || !points_of_grid.cell.empty();
  const std::vector<std::size_t> run_of = grid_row_runs(grid, label, one_run);
  std::vector<std::size_t> run_of_column;
  const Sweep_layout layout = sweep_layout(grid, label, run_of, run_of_column);
  if(layout == Sweep_layout::NONE && one_run)
    return Point_matrix();
  const bool column_runs = layout == Sweep_layout::COLUMN_RUNS;
  auto vertex = [&](std::size_t r, std::size_t c, int i) {
    const std::size_t f = grid.face_at[r * columns + c];
    halfedge_descriptor h = halfedge(face_of[f], pm);
    for(int j = 0; j < grid.corner_offset[f] + i; ++j)
      h = next(h, pm);
    return std::size_t(get(vim, target(h, pm)));
  };
  std::vector<Eigen::ArrayXd> present;
  const std::vector<std::vector<std::size_t> > rings = present_grid_rings(grid, points_of_grid, vertex, present);
  if(rings.empty())
    return Point_matrix();
  const Eigen::Index width = Eigen::Index(rings[0].size());
  const bool coaxial = layout == Sweep_layout::NONE && !one_run && std::size_t(width) == columns &&
                       coaxial_transition_layout(grid, label, run_of);
  if(layout == Sweep_layout::NONE && !coaxial)
    return Point_matrix();
  std::vector<Eigen::Matrix3Xd> ring(rows + 1, Eigen::Matrix3Xd::Zero(3, width));
  for(std::size_t i = 0; i <= rows; ++i)
    for(Eigen::Index j = 0; j < width; ++j)
      if(present[i](j) > 0)
        ring[i].col(j) = points.row(Eigen::Index(rings[i][std::size_t(j)])).transpose();
  if(coaxial)
    return coaxial_sweep_start(points, ring, rings, present, run_of);
  if(!one_run && !column_runs)
    return grouped_sweep_start(points, ring, rings, present, run_of);
  Swept_section swept = swept_section(ring, run_of, column_runs, present, closed);
  if(!swept.valid || (column_runs && !fit_screw_column_runs(swept.section, swept.motion[0], run_of_column)))
    return Point_matrix();
  Point_matrix start = points;
  place_sweep(start, swept.swept(), ring, rings, present, closed);
  return start;
}

// Positions, by vertex index, at which the clustering `label` (by face
// index) is exact, as described above; an empty matrix when the quads do
// not form a grid, full or trimmed (trimmed_grid.h: only the points
// present are fitted and placed), whose every cluster lies in one column
// and one run of rows, or in one run of columns of a single run of rows
// (the only run of a trimmed grid or one closed across its rows: its
// clusters may then be pieces of columns). `points` are the
// input positions by vertex index. `orientation`, if given, receives the
// orientation of every face (by face index) at which the clusters' quads
// correspond corner by corner there, in grid order: exact, where a best
// match on the swept shapes would pick among the symmetries of a
// symmetric quad by round-off. With `closed_only`, only a grid closed
// across its rows.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Point_matrix quad_grid_sweep_start(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                                   const Point_matrix& points, const std::vector<std::size_t>& label,
                                   std::vector<Panel_orientation>* orientation, bool closed_only)
{
  typedef typename boost::graph_traits<PolygonMesh>::face_descriptor face_descriptor;
  std::vector<face_descriptor> face_of(num_faces(pm));
  for(face_descriptor f : faces(pm))
    face_of[get(fim, f)] = f;
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  for(int row_direction = 0; row_direction < 2; ++row_direction)
  {
    Trimmed_grid_points points_of_grid;
    const Quad_grid grid = full_or_trimmed_grid(pm, fim, vpm, strips, row_direction, points_of_grid);
    if(grid.rows == 0)
      continue;
    const bool closed = closed_across_rows(grid, points_of_grid);
    if(closed_only && !closed)
      continue;
    Point_matrix start = grid_sweep_start(pm, vim, face_of, grid, points_of_grid, points, label, closed);
    if(start.rows() == 0)
      continue;
    // Corner i in grid order is the face's vertex corner_offset + i.
    if(orientation != nullptr)
      for(std::size_t f = 0; f < grid.corner_offset.size(); ++f)
        (*orientation)[f] = Panel_orientation(grid.corner_offset[f] % 4);
    return start;
  }
  return Point_matrix();
}

// The positions at which the sweep clustering `label` (by face index) of a
// quad grid, or of one capped by pole fans, is exact: quad_grid_sweep_start()
// of the grid, or of the capped grid's quads, which must then be closed
// across its rows, with the poles put on the axes (pole_fans.h). Empty
// when there is none; `orientation` as quad_grid_sweep_start() says, each
// triangle's from its pole.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexIndexMap, typename VertexPointMap>
Point_matrix sweep_start(const PolygonMesh& pm, FaceIndexMap fim, VertexIndexMap vim, VertexPointMap vpm,
                         const Point_matrix& points, const std::vector<std::size_t>& label,
                         std::vector<Panel_orientation>* orientation = nullptr)
{
  Pole_fans fans;
  const Triangle_layout layout = pole_fans(pm, fim, vim, vpm, fans);
  if(layout == Triangle_layout::NONE)
    return quad_grid_sweep_start(pm, fim, vim, vpm, points, label, orientation, false);
  const std::vector<std::size_t> quad_label =
    layout == Triangle_layout::POLE_FANS ? quad_part_label(fans, label) : std::vector<std::size_t>();
  if(quad_label.empty())
    return Point_matrix();
  const Pole_fans::Quad_part& quads = fans.quads;
  Point_matrix quad_points(Eigen::Index(fans.vertex_of.size()), 3);
  for(std::size_t v = 0; v < fans.vertex_of.size(); ++v)
    quad_points.row(Eigen::Index(v)) = points.row(Eigen::Index(fans.vertex_of[v]));
  std::vector<Panel_orientation> quad_orientation(quad_label.size());
  const Point_matrix quad_start =
    quad_grid_sweep_start(quads, get(CGAL::face_index, quads), get(CGAL::vertex_index, quads),
                          get(CGAL::vertex_point, quads), quad_points, quad_label, &quad_orientation, true);
  if(quad_start.rows() == 0)
    return quad_start;
  Point_matrix start = points;
  for(std::size_t v = 0; v < fans.vertex_of.size(); ++v)
    start.row(Eigen::Index(fans.vertex_of[v])) = quad_start.row(Eigen::Index(v));
  if(!put_poles_on_axes(fans, start, points, Tilable_surfaces::mean_edge_length(quads)))
    return Point_matrix();
  if(orientation != nullptr)
  {
    // A quad's corner 0 in grid order, found in its face in the mesh.
    for(std::size_t f = 0; f < quad_label.size(); ++f)
    {
      auto h = halfedge(Pole_fans::Quad_part::Face_index(std::uint32_t(f)), quads);
      for(int i = 0; i < quad_orientation[f].index(); ++i)
        h = next(h, quads);
      const std::array<std::size_t, 4>& corners = fans.quad_corners[f];
      const std::size_t first = fans.vertex_of[std::size_t(target(h, quads))];
      (*orientation)[fans.face_of[f]] =
        Panel_orientation(int(std::find(corners.begin(), corners.end(), first) - corners.begin()));
    }
    for(std::size_t fan = 0; fan < fans.triangles.size(); ++fan)
      for(std::size_t t = 0; t < fans.triangles[fan].size(); ++t)
        (*orientation)[fans.triangles[fan][t]] = Panel_orientation(fans.pole_corner[fan][t]);
  }
  return start;
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_SWEEP_START_H
