// The quad layout (internal/Shape_analysis/quad_layout.h) and the mold counts
// (mold_count_bounds.h) on meshes whose patches are counted by hand, and the patch-segment candidates
// (internal/Clustering/patch_candidates.h) on a mesh that is not one grid.

#include "grid_mesh.h"
#include "test_mesh.h"

#include <CGAL/Tilable_surfaces/internal/Clustering/patch_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout.h>
#include <CGAL/Tilable_surfaces/mold_count_bounds.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

// One namespace per file: the testsuite is compiled as unity batches.
namespace test_quad_layout_unit {

namespace TSI = CGAL::Tilable_surfaces::internal;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;

namespace {

TSI::Quad_layout layout_of(const Mesh& m)
{
  return TSI::quad_layout(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m));
}

// Corner i of face f by its grid's corner offset, read from the mesh.
Vertex corner(const Mesh& m, Face f, int offset, int i)
{
  auto h = halfedge(f, m);
  for(int s = 0; s < offset + i; ++s) h = next(h, m);
  return target(h, m);
}

// Every face in one patch; every grid's face_at a permutation of its
// patch's faces, its corners the mesh's points; the shared corners of
// neighbours in a row and in a column are the same vertices, the
// same way throughout the grid.
void expect_consistent(const Mesh& m, const TSI::Quad_layout& layout)
{
  ASSERT_EQ(layout.patch_of_face.size(), num_faces(m));
  const std::vector<std::vector<std::size_t> > faces = TSI::patch_faces(layout.patch_of_face);
  ASSERT_EQ(faces.size(), layout.grids.size());
  for(std::size_t p = 0; p < faces.size(); ++p)
  {
    EXPECT_FALSE(faces[p].empty());
    const TSI::Quad_grid& g = layout.grids[p];
    if(g.rows == 0)
      continue;
    EXPECT_EQ(g.faces, faces[p]);
    std::vector<std::size_t> at = g.face_at;
    std::sort(at.begin(), at.end());
    for(std::size_t i = 0; i < at.size(); ++i) EXPECT_EQ(at[i], i);
    auto vertex = [&](std::size_t r, std::size_t c, int i) {
      const std::size_t local = g.face_at[r * g.columns + c];
      return corner(m, Face(Mesh::size_type(g.faces[local])), g.corner_offset[local], i);
    };
    for(std::size_t local = 0; local < g.faces.size(); ++local)
      for(int i = 0; i < 4; ++i)
      {
        const Point p3 = m.point(corner(m, Face(Mesh::size_type(g.faces[local])), g.corner_offset[local], i));
        EXPECT_EQ(g.corners[local][i], Eigen::Vector3d(p3.x(), p3.y(), p3.z()));
      }
    for(std::size_t r = 0; r < g.rows; ++r)
      for(std::size_t c = 0; c + 1 < g.columns; ++c)
      {
        EXPECT_EQ(vertex(r, c, 0), vertex(r, c + 1, 1));
        EXPECT_EQ(vertex(r, c, 3), vertex(r, c + 1, 2));
      }
    std::set<bool> below;  // whether the next row is across corners 2 and 3
    for(std::size_t r = 0; r + 1 < g.rows; ++r)
      for(std::size_t c = 0; c < g.columns; ++c)
      {
        const bool across_23 = vertex(r, c, 3) == vertex(r + 1, c, 0) && vertex(r, c, 2) == vertex(r + 1, c, 1);
        const bool across_01 = vertex(r, c, 0) == vertex(r + 1, c, 3) && vertex(r, c, 1) == vertex(r + 1, c, 2);
        EXPECT_TRUE(across_23 || across_01);
        below.insert(across_23);
      }
    EXPECT_LE(below.size(), 1u);
  }
}

// The sorted sizes rows x columns (smaller first) of the grids.
std::multiset<std::pair<std::size_t, std::size_t> > grid_sizes(const TSI::Quad_layout& layout)
{
  std::multiset<std::pair<std::size_t, std::size_t> > sizes;
  for(const TSI::Quad_grid& g : layout.grids)
    sizes.insert(std::make_pair((std::min)(g.rows, g.columns), (std::max)(g.rows, g.columns)));
  return sizes;
}

// `count` grids of `rows` x `columns`, as grid_sizes() lists them.
std::multiset<std::pair<std::size_t, std::size_t> > copies(std::size_t count, std::size_t rows, std::size_t columns)
{
  std::multiset<std::pair<std::size_t, std::size_t> > sizes;
  for(std::size_t i = 0; i < count; ++i)
    sizes.insert(std::make_pair((std::min)(rows, columns), (std::max)(rows, columns)));
  return sizes;
}

// The cube [0, n]^3 meshed with n x n squares per side, projected on the
// unit sphere about its centre: 8 vertices of valence 3.
Mesh quad_ball(int n)
{
  Mesh m;
  std::map<std::array<int, 3>, Vertex> vertex;
  auto at = [&](std::array<int, 3> x) {
    auto found = vertex.find(x);
    if(found != vertex.end())
      return found->second;
    const double a = x[0] - n / 2.0, b = x[1] - n / 2.0, c = x[2] - n / 2.0, r = std::sqrt(a * a + b * b + c * c);
    return vertex[x] = m.add_vertex(Point(a / r, b / r, c / r));
  };
  for(int axis = 0; axis < 3; ++axis)
    for(int side : {0, n})
      for(int u = 0; u < n; ++u)
        for(int v = 0; v < n; ++v)
        {
          std::array<Vertex, 4> q;
          const int du[4] = {0, 1, 1, 0}, dv[4] = {0, 0, 1, 1};
          for(int i = 0; i < 4; ++i)
          {
            std::array<int, 3> x;
            x[axis] = side;
            x[(axis + 1) % 3] = u + du[i];
            x[(axis + 2) % 3] = v + dv[i];
            q[i] = at(x);
          }
          if(side == 0) std::reverse(q.begin(), q.end());
          m.add_face(q[0], q[1], q[2], q[3]);
        }
  return m;
}

// Five n x n sectors around a vertex of valence 5 in the plane, sector s
// spanned by the unit vectors at angles 2 pi s / 5 and 2 pi (s + 1) / 5.
Mesh five_sectors(int n)
{
  Mesh m;
  std::map<std::array<int, 3>, Vertex> vertex;
  auto at = [&](int s, int i, int j) {
    std::array<int, 3> key = {{s % 5, i, j}};
    if(i == 0 && j == 0) key = {{0, 0, 0}};
    else if(i == 0) key = {{(s + 1) % 5, j, 0}};
    auto found = vertex.find(key);
    if(found != vertex.end())
      return found->second;
    const double a = 2 * CGAL_PI * key[0] / 5, b = 2 * CGAL_PI * (key[0] + 1) / 5;
    return vertex[key] = m.add_vertex(Point(key[1] * std::cos(a) + key[2] * std::cos(b),
                                            key[1] * std::sin(a) + key[2] * std::sin(b), 0));
  };
  for(int s = 0; s < 5; ++s)
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j)
        m.add_face(at(s, i, j), at(s, i + 1, j), at(s, i + 1, j + 1), at(s, i, j + 1));
  return m;
}

// A torus of `around` x `along` quads: no irregular vertex, no border.
Mesh torus(int around, int along)
{
  Mesh m;
  std::vector<Vertex> v;
  for(int i = 0; i < along; ++i)
    for(int j = 0; j < around; ++j)
    {
      const double u = 2 * CGAL_PI * i / along, w = 2 * CGAL_PI * j / around;
      v.push_back(m.add_vertex(Point((3 + std::cos(w)) * std::cos(u), (3 + std::cos(w)) * std::sin(u), std::sin(w))));
    }
  auto id = [&](int i, int j) { return v[std::size_t((i % along) * around + j % around)]; };
  for(int i = 0; i < along; ++i)
    for(int j = 0; j < around; ++j)
      m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  return m;
}

} // namespace

TEST(QuadLayout, SingleGridIsOnePatch)
{
  const Mesh m = grid<Mesh>(5, 3);
  const TSI::Quad_layout layout = layout_of(m);
  EXPECT_EQ(layout.grids.size(), 1u);
  EXPECT_EQ(grid_sizes(layout), copies(1, 3, 5));
  expect_consistent(m, layout);
}

TEST(QuadLayout, QuadBallHasSixSquarePatches)
{
  const int n = 4;
  const Mesh m = quad_ball(n);
  ASSERT_EQ(num_faces(m), std::size_t(6 * n * n));
  const TSI::Quad_layout layout = layout_of(m);
  EXPECT_EQ(grid_sizes(layout), copies(6, n, n));
  expect_consistent(m, layout);
}

// The cells (i, j) of [0, 2n)^2 but [n, 2n)^2: the concave corner (n, n) is
// a border vertex of valence 4, whose two inner edges are traced to the
// border along x = n and y = n: three n x n squares.
TEST(QuadLayout, LShapeSplitsIntoThreeSquares)
{
  const int n = 3;
  const Mesh m = grid_of_kept_cells<Mesh>(2 * n, 2 * n, [](int i, int j) { return Point(i, j, 0); },
                                          [&](int i, int j) { return i < n || j < n; });
  const TSI::Quad_layout layout = layout_of(m);
  EXPECT_EQ(grid_sizes(layout), copies(3, n, n));
  expect_consistent(m, layout);
  // Faces in one square share its patch: cell (i, j) is face i + 2n j minus the cells left out before it.
  std::vector<std::size_t> square_patch(3, TSI::no_index());
  std::size_t f = 0;
  for(int j = 0; j < 2 * n; ++j)
    for(int i = 0; i < 2 * n; ++i)
      if(i < n || j < n)
      {
        const std::size_t square = j >= n ? 2 : (i >= n ? 1 : 0);
        if(square_patch[square] == TSI::no_index()) square_patch[square] = layout.patch_of_face[f];
        EXPECT_EQ(layout.patch_of_face[f++], square_patch[square]);
      }
  EXPECT_EQ(std::set<std::size_t>(square_patch.begin(), square_patch.end()).size(), 3u);
}

// The valence-5 vertex's five traces run along the sectors' sides to the
// border (whose vertices have valence 3, but the sectors' outer corners,
// of valence 2): one patch per sector.
TEST(QuadLayout, ValenceFiveVertexCutsFiveSectors)
{
  const int n = 3;
  const Mesh m = five_sectors(n);
  const TSI::Quad_layout layout = layout_of(m);
  EXPECT_EQ(grid_sizes(layout), copies(5, n, n));
  expect_consistent(m, layout);
  for(std::size_t f = 0; f < num_faces(m); ++f)  // sector s holds faces s n^2 .. (s + 1) n^2 - 1
    EXPECT_EQ(layout.patch_of_face[f], layout.patch_of_face[f - f % (n * n)]);
}

TEST(QuadLayout, TorusIsOneClosedGrid)
{
  const Mesh m = torus(6, 9);
  const TSI::Quad_layout layout = layout_of(m);
  EXPECT_EQ(grid_sizes(layout), copies(1, 6, 9));
  expect_consistent(m, layout);
}

// Cell (1, 1) of a 4 x 4 grid split into two triangles: each is a patch of
// its own and no grid; every quad patch is a grid.
TEST(QuadLayout, TriangleIsItsOwnPatch)
{
  Mesh m;
  std::vector<Vertex> v;
  for(int j = 0; j <= 4; ++j)
    for(int i = 0; i <= 4; ++i) v.push_back(m.add_vertex(Point(i, j, 0)));
  auto id = [&](int i, int j) { return v[std::size_t(i + 5 * j)]; };
  for(int j = 0; j < 4; ++j)
    for(int i = 0; i < 4; ++i)
      if(i == 1 && j == 1)
      {
        m.add_face(id(1, 1), id(2, 1), id(2, 2));
        m.add_face(id(1, 1), id(2, 2), id(1, 2));
      }
      else
        m.add_face(id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
  const TSI::Quad_layout layout = layout_of(m);
  expect_consistent(m, layout);
  const std::vector<std::vector<std::size_t> > faces = TSI::patch_faces(layout.patch_of_face);
  for(std::size_t p = 0; p < faces.size(); ++p)
  {
    const bool triangle = degree(Face(Mesh::size_type(faces[p][0])), m) == 3;
    EXPECT_EQ(layout.grids[p].rows == 0, triangle);
    if(triangle)
    {
      EXPECT_EQ(faces[p].size(), 1u);
    }
  }
  EXPECT_NE(layout.patch_of_face[5], layout.patch_of_face[6]);  // the two triangles
}

// On the quad ball (6 patches), K = 4 and K = 9: every candidate has
// exactly K clusters, and no cluster holds quads twisted both ways in the
// labelling of its S-quad (each quad's best match on it, as the optimization
// pairs corners), beyond 5% of its largest twist and beyond a flat quad's.
TEST(PatchSegments, KClustersWithoutMixedTwists)
{
  const Mesh m = quad_ball(4);
  std::vector<TS::Panel> panels;
  std::vector<TS::Quad_descriptor> descriptors;
  for(Face f : faces(m))
  {
    panels.push_back(TS::face_panel(f, m));
    descriptors.push_back(TS::shape_descriptor(panels.back()));
  }
  for(std::size_t k : {4u, 9u})
  {
    const auto labels = TSI::patch_segment_clusterings(m, get(CGAL::face_index, m), get(CGAL::vertex_point, m),
                                                       panels, descriptors, k, TS::PROPER_RIGID_MOTIONS, 1u);
    ASSERT_FALSE(labels.empty());
    for(const std::vector<std::size_t>& label : labels)
    {
      EXPECT_EQ(std::set<std::size_t>(label.begin(), label.end()).size(), k);
      EXPECT_EQ(*std::max_element(label.begin(), label.end()), k - 1);
      const TSI::Cluster_shapes shapes = TSI::cluster_shapes(panels, label, k, TS::PROPER_RIGID_MOTIONS);
      std::vector<double> positive(k, 0), negative(k, 0);
      for(std::size_t f = 0; f < label.size(); ++f)
      {
        const TS::Panel q = TS::reoriented(panels[f], shapes.orientation[f]);
        const double twist = (q[1] - q[0]).dot((q[2] - q[0]).cross(q[3] - q[0]));
        (twist > 0 ? positive : negative)[label[f]] =
          (std::max)((twist > 0 ? positive : negative)[label[f]], std::abs(twist));
      }
      for(std::size_t c = 0; c < k; ++c)
      {
        // A quad flat to 0.1% of its edge has no sign (its edges are longer than 0.2 here).
        const double significant = (std::max)(0.05 * (std::max)(positive[c], negative[c]), 1e-3 * 0.008);
        EXPECT_FALSE(positive[c] > significant && negative[c] > significant) << "cluster " << c;
      }
    }
  }
}

// The mold counts by hand. Unstructured: the first K with 6 (quads - K) +
// 3 triangles <= 3 V - 6, molds going to quads first (6 equations each),
// then to triangles (3 each). Patch sweeps: min(rows, columns) per grid patch.
TEST(MoldCountBounds, CountedByHandOnAGridABallAndAnOctahedron)
{
  // 5 x 3 quads, 24 vertices: 90 equations against 66 coordinates, 4 molds; one patch, 3 columns.
  const TS::Mold_count_bounds grid_bounds = TS::mold_count_bounds(grid<Mesh>(5, 3));
  EXPECT_EQ(grid_bounds.unstructured_molds, 4u);
  EXPECT_EQ(grid_bounds.grid_patches, 1u);
  EXPECT_EQ(grid_bounds.patch_sweep_molds, 3u);
  // 96 quads, 98 vertices (closed, genus 0): 576 against 288, 48 molds, half the quads; 6 patches of 4 x 4.
  const TS::Mold_count_bounds ball_bounds = TS::mold_count_bounds(quad_ball(4));
  EXPECT_EQ(ball_bounds.unstructured_molds, 48u);
  EXPECT_EQ(ball_bounds.grid_patches, 6u);
  EXPECT_EQ(ball_bounds.patch_sweep_molds, 24u);
  // 8 triangles, 6 vertices: 24 against 12, 4 triangle molds; no grid, one mold per face.
  Mesh octahedron;
  std::vector<Vertex> v;
  for(int axis = 0; axis < 3; ++axis)
    for(int sign : {1, -1})
    {
      double x[3] = {0, 0, 0};
      x[axis] = sign;
      v.push_back(octahedron.add_vertex(Point(x[0], x[1], x[2])));
    }
  for(int a : {0, 1})
    for(int b : {2, 3})
      for(int c : {4, 5})
      {
        const bool positive = (a == 0) == (b == 2) ? c == 4 : c == 5;  // outward, right-handed
        if(positive) octahedron.add_face(v[a], v[b], v[c]);
        else octahedron.add_face(v[a], v[c], v[b]);
      }
  ASSERT_EQ(num_faces(octahedron), 8u);
  const TS::Mold_count_bounds octahedron_bounds = TS::mold_count_bounds(octahedron);
  EXPECT_EQ(octahedron_bounds.unstructured_molds, 4u);
  EXPECT_EQ(octahedron_bounds.grid_patches, 0u);
  EXPECT_EQ(octahedron_bounds.patch_sweep_molds, 8u);
}

} // namespace test_quad_layout_unit
