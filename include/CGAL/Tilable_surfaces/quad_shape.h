// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_QUAD_SHAPE_H
#define CGAL_TILABLE_SURFACES_QUAD_SHAPE_H

/// \file quad_shape.h
/// Shape analysis of quads: orientations (vertex correspondences), edge and
/// diagonal lengths, signed volume, a rotation-invariant descriptor, the best
/// proper rigid fit, the dissimilarity of the paper (§3) and the congruence
/// error of instances against an S-quad (user manual, section Definitions).
///
/// All computations are done in double precision with Eigen, whatever the
/// kernel of the mesh: the quantities are measurements, not predicates.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <boost/graph/graph_traits.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace CGAL {
namespace Tilable_surfaces {

namespace internal {
// Measurements are done in double whatever the kernel's number type.
template <typename Point_3>
Eigen::Vector3d to_eigen(const Point_3& p)
{
  return Eigen::Vector3d(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// No index: an unset entry of an index table.
inline std::size_t no_index() { return (std::numeric_limits<std::size_t>::max)(); }

// At most N values kept in place (the edges of a face, the correspondences
// of a panel), with what range-for loops and indexing need.
template <typename T, std::size_t N>
class Bounded_list
{
public:
  void push_back(const T& x) { m_values[m_size++] = x; }
  std::size_t size() const { return m_size; }
  const T& operator[](std::size_t i) const { return m_values[i]; }
  const T* begin() const { return m_values.data(); }
  const T* end() const { return m_values.data() + m_size; }

private:
  std::array<T, N> m_values{};
  std::size_t m_size = 0;
};
} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The corners t0, t1, ... of a panel in double precision: four for a quad,
/// three for a triangle. Edge `k` joins corners `k` and `(k+1) mod size()`;
/// the diagonals of a quad are t0t2 and t1t3.
class Panel
{
public:
  /// A quad whose corners are left uninitialized.
  Panel() : m_size(4) {}

  /// The quad with corners `q[0..3]`.
  Panel(const std::array<Eigen::Vector3d, 4>& q) : m_corners(q), m_size(4) {}

  /// The triangle with corners `a`, `b`, `c`.
  Panel(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
    : m_corners{{a, b, c, Eigen::Vector3d::Zero()}}, m_size(3)
  {}

  /// A panel of `corners` (3 or 4) corners at the origin.
  static Panel zero(int corners)
  {
    const Eigen::Vector3d o = Eigen::Vector3d::Zero();
    return corners == 3 ? Panel(o, o, o) : Panel{{o, o, o, o}};
  }

  /// The number of corners, 3 or 4.
  int size() const { return m_size; }
  /// Whether the panel is a triangle.
  bool is_triangle() const { return m_size == 3; }

  /// Corner `i`, in 0..size()-1.
  Eigen::Vector3d& operator[](int i) { return m_corners[std::size_t(i)]; }
  /// Corner `i`, in 0..size()-1.
  const Eigen::Vector3d& operator[](int i) const { return m_corners[std::size_t(i)]; }

  /// The corners, for range-for loops.
  Eigen::Vector3d* begin() { return m_corners.data(); }
  /// Past the last corner.
  Eigen::Vector3d* end() { return m_corners.data() + m_size; }
  /// The corners, for range-for loops.
  const Eigen::Vector3d* begin() const { return m_corners.data(); }
  /// Past the last corner.
  const Eigen::Vector3d* end() const { return m_corners.data() + m_size; }

  /// The centroid of the corners.
  Eigen::Vector3d centroid() const
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for(const Eigen::Vector3d& p : *this) c += p;
    return c / double(m_size);
  }

  /// Twice the vector area: (t2 - t0) x (t3 - t1) for a quad, which does not
  /// depend on the diagonal that would split a non-planar quad, and
  /// (t1 - t0) x (t2 - t0) for a triangle.
  Eigen::Vector3d doubled_vector_area() const
  {
    const std::array<Eigen::Vector3d, 4>& t = m_corners;
    return is_triangle() ? Eigen::Vector3d((t[1] - t[0]).cross(t[2] - t[0]))
                         : Eigen::Vector3d((t[2] - t[0]).cross(t[3] - t[1]));
  }

private:
  std::array<Eigen::Vector3d, 4> m_corners;
  int m_size;
};

/// \ingroup PkgTilableSurfacesRef
/// One of the correspondences between the corners of an S-quad (or
/// S-triangle) and the vertices (v0, v1, ...) of a face of `n` corners, in
/// the face's order: template corner `i` goes to face vertex `(*this)(i, n)`,
/// with `(i + o) mod n` for `o < 4` (same direction) and `(o - 4 - i) mod n`
/// for `o >= 4` (reversed: the panel is turned over). A quad has the 8
/// correspondences 0..7, a triangle the 6 correspondences 0, 1, 2, 4, 5, 6
/// (`is_valid_for()`). Every member takes the number of corners `n`, 4 by default.
class Panel_orientation
{
public:
  /// The identity correspondence (o = 0).
  Panel_orientation() : m_index(0) {}

  /// The correspondence number `index`, in 0..7.
  /// \throws Invalid_input if `index` is out of range.
  explicit Panel_orientation(int index) : m_index(static_cast<unsigned char>(index))
  {
    if(index < 0 || index > 7)
      throw Invalid_input("quad orientation " + std::to_string(index) + " is not in 0..7",
                          Invalid_input::PARAMETER);
  }

  /// The number o in 0..7 of the correspondence.
  int index() const { return m_index; }

  /// The number o, for property maps that store orientations as integers.
  explicit operator int() const { return m_index; }

  /// Whether the correspondence reverses the cyclic order (o >= 4).
  bool is_reversed() const { return m_index >= 4; }

  /// Whether this is one of the correspondences of a face of `n` corners.
  bool is_valid_for(int n) const { return (m_index & 3) < n; }

  /// The face vertex (0..n-1) that template corner `i` (0..n-1) goes to.
  int operator()(int i, int n = 4) const
  {
    return m_index < 4 ? modulo(i + m_index, n) : modulo(m_index - 4 - i, n);
  }

  /// The correspondence that undoes this one: `inverse(n)((*this)(i, n), n) == i`.
  Panel_orientation inverse(int n = 4) const
  {
    return m_index < 4 ? Panel_orientation(modulo(n - m_index, n)) : *this;
  }


  /// The face edge (0..n-1, edge j joins v_j and v_{j+1}) that template edge
  /// `k` (joining t_k and t_{k+1}) goes to.
  int face_edge(int k, int n = 4) const
  {
    return m_index < 4 ? modulo(k + m_index, n) : modulo(m_index - 4 - k - 1, n);
  }

  /// The template edge that goes to face edge `j`; inverse of `face_edge()`.
  int template_edge(int j, int n = 4) const
  {
    return m_index < 4 ? modulo(j - m_index, n) : modulo(m_index - 4 - j - 1, n);
  }

  /// Equality of correspondences.
  friend bool operator==(const Panel_orientation& a, const Panel_orientation& b)
  { return a.m_index == b.m_index; }
  /// Inequality of correspondences.
  friend bool operator!=(const Panel_orientation& a, const Panel_orientation& b)
  { return a.m_index != b.m_index; }

private:
  // `a & 3` is the quads' hot path; works for negative `a` too.
  static int modulo(int a, int n) { return n == 4 ? (a & 3) : ((a % n) + n) % n; }

  unsigned char m_index;
};


/// \ingroup PkgTilableSurfacesRef
/// The composition of two correspondences between panels of `n` corners:
/// `compose(a, b, n)(i, n) == a(b(i, n), n)`.
CGAL_TILABLE_SURFACES_INLINE
Panel_orientation compose(const Panel_orientation& a, const Panel_orientation& b, int n = 4);

/// \ingroup PkgTilableSurfacesRef
/// The composition of two quad correspondences, `compose(a, b, 4)`.
inline Panel_orientation operator*(const Panel_orientation& a, const Panel_orientation& b)
{
  return compose(a, b, 4);
}

/// \ingroup PkgTilableSurfacesRef
/// Returns the panel `r` with `r[i] = q[o(i)]`: the corners of `q` listed in
/// the labelling of a template matched to `q` with orientation `o`.
inline Panel reoriented(const Panel& q, Panel_orientation o)
{
  if(q.is_triangle())
    return Panel(q[o(0, 3)], q[o(1, 3)], q[o(2, 3)]);
  return Panel{{q[o(0)], q[o(1)], q[o(2)], q[o(3)]}};
}

/// \ingroup PkgTilableSurfacesRef
/// Lengths of the edges t0t1, t1t2, t2t3, t3t0 of a quad; of a triangle, of
/// t0t1, t1t2, t2t0, then 0.
CGAL_TILABLE_SURFACES_INLINE
std::array<double, 4> edge_lengths(const Panel& q);

/// \ingroup PkgTilableSurfacesRef
/// Lengths of the diagonals t0t2 and t1t3 of a quad; 0 and 0 for a triangle.
inline std::array<double, 2> diagonal_lengths(const Panel& q)
{
  if(q.is_triangle())
    return {{0, 0}};
  return {{(q[2] - q[0]).norm(), (q[3] - q[1]).norm()}};
}

/// \ingroup PkgTilableSurfacesRef
/// Signed volume det[t1 - t0, t2 - t0, t3 - t0] / 6 of the tetrahedron of the
/// four corners of a quad (0 for a triangle). It changes sign under a mirror,
/// under reversal of the labels and under an odd cyclic shift; evaluate it in
/// the template's labelling.
inline double signed_volume(const Panel& q)
{
  if(q.is_triangle())
    return 0;
  return (q[1] - q[0]).dot((q[2] - q[0]).cross(q[3] - q[0])) / 6.0;
}

/// \ingroup PkgTilableSurfacesRef
/// The twist of a quad without its scale: 6 x `signed_volume()` over the cube
/// of its mean edge length (0 for a planar quad and for a triangle). Its sign
/// depends on the labelling as the signed volume's does; congruence under a
/// proper rigid motion keeps it, so quads twisted opposite ways in their
/// S-quad's labelling become congruent only by flattening.
CGAL_TILABLE_SURFACES_INLINE
double relative_twist(const Panel& q);

/// \ingroup PkgTilableSurfacesRef
/// Distance of t3 to the plane through t0, t1, t2: 0 for a planar quad and
/// for a triangle. When t0, t1, t2 are (nearly) collinear, the largest of the
/// four corner triangles is taken as the base instead, so the value stays
/// meaningful.
CGAL_TILABLE_SURFACES_INLINE
double planarity_defect(const Panel& q);

/// \ingroup PkgTilableSurfacesRef
/// Distance between the lines of the diagonals t0t2 and t1t3 of a quad: 0
/// exactly when the quad is planar (or its diagonals are parallel); 0 for a
/// triangle. The planarity measure of `planar_tiles`.
CGAL_TILABLE_SURFACES_INLINE
double diagonal_distance(const Panel& q);

/// \ingroup PkgTilableSurfacesRef
/// A rotation-invariant and relabelling-invariant shape descriptor, all in
/// length units: the 4 edge lengths sorted, the 2 diagonal lengths sorted and
/// the cube root of 6|V|. Congruent panels have equal descriptors (mirror
/// images too: the descriptor prefilters, the dissimilarity decides). A
/// triangle's lists a zero edge, zero diagonals and a zero volume.
typedef std::array<double, 7> Quad_descriptor;

/// \ingroup PkgTilableSurfacesRef
/// Computes the descriptor of `q`; see `Quad_descriptor`.
CGAL_TILABLE_SURFACES_INLINE
Quad_descriptor shape_descriptor(const Panel& q);

/// \ingroup PkgTilableSurfacesRef
/// A rigid motion `x -> rotation * x + translation`; `rotation` has
/// determinant +1 unless `is_mirrored` (only with `ALLOW_MIRRORED_PANELS`).
struct Rigid_fit
{
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< the linear part
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();   ///< the translation
  bool is_mirrored = false;                                ///< whether det(rotation) = -1

  /// The image of `p`.
  Eigen::Vector3d operator()(const Eigen::Vector3d& p) const { return rotation * p + translation; }
  /// The image of every corner of `q`.
  Panel operator()(Panel q) const
  {
    for(Eigen::Vector3d& p : q) p = (*this)(p);
    return q;
  }
};

namespace internal {

// best_rigid_fit() for panels of N corners: fixed sizes, so that Eigen
// rounds a quad's fit as it always did.
template <int N>
Rigid_fit best_rigid_fit(const Panel& source, const Panel& target, bool allow_mirror)
{
  typedef Eigen::Matrix<double, 3, N> Corners;
  const int n = N;
  Corners src, dst;
  for(int i = 0; i < n; ++i) { src.col(i) = source[i]; dst.col(i) = target[i]; }
  const Eigen::Matrix4d proper = Eigen::umeyama(src, dst, false);
  Rigid_fit fit;
  fit.rotation = proper.topLeftCorner<3, 3>();
  fit.translation = proper.topRightCorner<3, 1>();
  if(!allow_mirror)
    return fit;

  // An improper motion is a proper one applied after the mirror z -> -z.
  Corners mirrored = src;
  mirrored.row(2) *= -1;
  const Eigen::Matrix4d improper = Eigen::umeyama(mirrored, dst, false);
  Rigid_fit mirror_fit;
  mirror_fit.rotation = improper.topLeftCorner<3, 3>() * Eigen::Vector3d(1, 1, -1).asDiagonal();
  mirror_fit.translation = improper.topRightCorner<3, 1>();
  mirror_fit.is_mirrored = true;

  auto squared_residual = [&](const Rigid_fit& f) {
    double r = 0;
    for(int i = 0; i < n; ++i) r += (target[i] - f(source[i])).squaredNorm();
    return r;
  };
  return squared_residual(mirror_fit) < squared_residual(fit) ? mirror_fit : fit;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The proper rigid motion T minimising sum_i |target[i] - T(source[i])|^2
/// (Umeyama's closed form, never a mirror). With `allow_mirror`, the better of
/// that motion and the best improper one. `source` and `target` have the same
/// number of corners.
CGAL_TILABLE_SURFACES_INLINE
Rigid_fit best_rigid_fit(const Panel& source, const Panel& target, bool allow_mirror = false);

/// \ingroup PkgTilableSurfacesRef
/// max_i |target[i] - T(source[i])| for the best rigid fit T of `source`
/// onto `target` (labels already in correspondence).
CGAL_TILABLE_SURFACES_INLINE
double rigid_fit_deviation(const Panel& source, const Panel& target, bool allow_mirror = false);

/// \ingroup PkgTilableSurfacesRef
/// Whether correspondence `o` may match panels of `n` corners under `policy`:
/// one of their correspondences (`Panel_orientation::is_valid_for()`), and not
/// reversed under `NO_TURNED_OVER_PANELS`.
inline bool is_admissible(Panel_orientation o, int n, Orientation_policy policy)
{
  return o.is_valid_for(n) && !(policy == NO_TURNED_OVER_PANELS && o.is_reversed());
}

/// \ingroup PkgTilableSurfacesRef
/// The outcome of matching a template panel to a face: the dissimilarity
/// s(p, q) of the paper, the correspondence that achieves it and the motion.
/// Panels of different kinds (a quad and a triangle) never match: their
/// dissimilarity is infinite.
struct Quad_match
{
  double dissimilarity = std::numeric_limits<double>::infinity();  ///< s(p, q)
  Panel_orientation orientation;  ///< the correspondence that achieves it
  Rigid_fit fit;                 ///< the motion of p onto q relabelled by `orientation`
};

/// \ingroup PkgTilableSurfacesRef
/// Matches template `p` (corners t_i) to panel `q` (vertices v_j in the
/// face's order): the minimum over the correspondences allowed by `policy`
/// (`is_admissible()`) of sum_i |v_{o(i)} - T(t_i)|, T the best rigid fit of
/// `p` onto `q` relabelled by `o`. Symmetric in value: `best_match(q, p)` has
/// the same dissimilarity, with the inverse orientation. Ties are broken by
/// the smallest orientation index, so the result is deterministic.
CGAL_TILABLE_SURFACES_INLINE
Quad_match best_match(const Panel& p, const Panel& q,
                      Orientation_policy policy = PROPER_RIGID_MOTIONS);

/// \ingroup PkgTilableSurfacesRef
/// The dissimilarity s(p, q) of the paper (§3); see `best_match()`.
inline double dissimilarity(const Panel& p, const Panel& q,
                            Orientation_policy policy = PROPER_RIGID_MOTIONS)
{
  return best_match(p, q, policy).dissimilarity;
}

/// \ingroup PkgTilableSurfacesRef
/// The congruence error of a set of instances against an S-quad: the worst
/// instance's largest corner deviation after its best rigid fit, divided by
/// `length_scale` (the package's congruence error uses the mean edge length
/// of the mesh: user manual, section Definitions).
/// Each instance must already be in the template's labelling (see
/// `reoriented()`). Returns 0 for an empty range.
template <typename QuadRange>
double congruence_error(const QuadRange& instances, const Panel& s_quad,
                        double length_scale = 1.0, bool allow_mirror = false)
{
  double worst = 0;
  for(const Panel& instance : instances)
    worst = (std::max)(worst, rigid_fit_deviation(s_quad, instance, allow_mirror));
  return worst / length_scale;
}

/// \ingroup PkgTilableSurfacesRef
/// The halfedges of the edges of face `f` (a quad or a triangle): entry `j`
/// is face edge j, from the face's vertex v_j to v_{j+1} (the vertices as
/// `face_panel()` lists them), that is next^(j+1)(halfedge(f, pm)), since
/// `vertices_around_face()` starts at the target of `halfedge(f, pm)`.
/// `Panel_orientation::face_edge()` and the edge-sharing graph number a face's
/// edges this way. Faces of more than 4 edges give their first 4. The result
/// has `size()`, `operator[]` and `begin()` / `end()`.
template <typename PolygonMesh>
internal::Bounded_list<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor, 4>
face_edge_halfedges(typename boost::graph_traits<PolygonMesh>::face_descriptor f, const PolygonMesh& pm)
{
  internal::Bounded_list<typename boost::graph_traits<PolygonMesh>::halfedge_descriptor, 4> h;
  const auto first = halfedge(f, pm);
  auto current = first;
  do
  {
    current = next(current, pm);
    h.push_back(current);
  } while(current != first && h.size() < 4);
  return h;
}

namespace internal {

// The vertex point map of `np`, else the mesh's own, read only.
template <typename PolygonMesh, typename NamedParameters>
auto const_vertex_point_map(const PolygonMesh& pm, const NamedParameters& np)
{
  return parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                      get_const_property_map(CGAL::vertex_point, pm));
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The corners of face `f` of `pm` (a quad or a triangle) in the labelling of
/// a template matched with orientation `o`: corner `i` is the face's vertex
/// `o(i, n)`, the face's n vertices (v0, v1, ...) being listed as
/// `vertices_around_face(halfedge(f, pm), pm)` does (for a `Surface_mesh`, the
/// order in which they were given to `add_face()` or in the file).
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{vertex_point_map} the property map with the points
///     associated to the vertices of `pm` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \throws Invalid_input if `f` is neither a quad nor a triangle, or if `o`
/// is not one of its correspondences.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
Panel face_panel(typename boost::graph_traits<PolygonMesh>::face_descriptor f,
                 const PolygonMesh& pm,
                 Panel_orientation o = Panel_orientation(),
                 const CGAL_NP_CLASS& np = parameters::default_values())
{
  const auto vpm = internal::const_vertex_point_map(pm, np);
  std::array<Eigen::Vector3d, 4> face_order;
  int n = 0;
  for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
  {
    if(n == 4) { n = 5; break; }
    face_order[std::size_t(n++)] = internal::to_eigen(get(vpm, v));
  }
  if(n != 3 && n != 4)
    throw Invalid_input("a face that is neither a quad nor a triangle was given where a panel is needed",
                        Invalid_input::FACE);
  if(!o.is_valid_for(n))
    throw Invalid_input("orientation " + std::to_string(o.index()) + " is not one of a triangle's",
                        Invalid_input::PARAMETER);
  const Panel panel = n == 3 ? Panel(face_order[0], face_order[1], face_order[2]) : Panel(face_order);
  return reoriented(panel, o);
}

/// \ingroup PkgTilableSurfacesRef
/// The mean length of the edges of `pm`, the length scale of the congruence
/// error. Returns 0 for a mesh without edges.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
double mean_edge_length(const PolygonMesh& pm,
                        const CGAL_NP_CLASS& np = parameters::default_values())
{
  const auto vpm = internal::const_vertex_point_map(pm, np);
  double sum = 0;
  std::size_t count = 0;
  for(auto e : edges(pm))
  {
    sum += (internal::to_eigen(get(vpm, source(e, pm))) -
            internal::to_eigen(get(vpm, target(e, pm)))).norm();
    ++count;
  }
  return count == 0 ? 0.0 : sum / double(count);
}

#ifndef CGAL_NO_DEPRECATED_CODE
/// \ingroup PkgTilableSurfacesRef
/// \deprecated The name of `Panel_orientation` until 1.0.0.
#ifdef DOXYGEN_RUNNING
typedef Panel_orientation Quad_orientation;
#else
using Quad_orientation CGAL_DEPRECATED_MSG("use Panel_orientation") = Panel_orientation;
#endif
#endif

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/quad_shape_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_QUAD_SHAPE_H
