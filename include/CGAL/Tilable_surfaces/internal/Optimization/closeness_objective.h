// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_H

// What the default solver minimizes subject to the congruence constraints:
// how far the result is from the input *surface*, plus how much the
// displacement distorts the surface locally.
//
//   f(X) = 1/2 sum_v d_v^T M_v d_v + 1/2 r E(X),   d = X - X0.
//
// M_v is the closeness metric of vertex v. Moving off the input surface
// (along the input normal n) costs 1, sliding in it costs `tangential`
// (< 1): sliding changes edge lengths, which is what the constraints ask
// for, without leaving the surface, which is what the Hausdorff distance
// measures. On the boundary, moving inwards or outwards (b = n x t) costs 1
// too, so the result keeps covering the input; sliding along it (t) costs
// `tangential`. At corners and on sharp features every direction costs 1.
//
// E is an as-rigid-as-possible energy of the displacement (Sorkine and
// Alexa 2007) on the mesh edges:
//   E(X) = sum_i sum_{j ~ i} |(x_i - x_j) - R_i (x0_i - x0_j)|^2,
// with R_i the rotation that best fits the edges around i. It is zero for an
// unmoved surface and for any rigid motion of the whole mesh, and it keeps
// the local shape (the details) of the input, unlike a fairness term on the
// positions, which flattens every bump the constraints do not need. With the
// R_i held fixed its Hessian is 4 L (L the graph Laplacian, per coordinate),
// and by optimality of the R_i its gradient is exact:
//   dE/dx_i = sum_{j ~ i} 2 (2 (x_i - x_j) - (R_i + R_j)(x0_i - x0_j)).
// The Gauss-Newton model of f is then the constant metric H = M + 2 r L.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/feature_detection.h>

#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The closeness metric of every vertex of `pm` with positions `points`
// (the input), see above; `pinned` vertices (corners, features) get I.
template <typename PolygonMesh, typename VertexIndexMap>
std::vector<Eigen::Matrix3d> closeness_metrics(const PolygonMesh& pm, const VertexIndexMap& vim,
                                               const Point_matrix& points,
                                               const std::vector<bool>& pinned, double tangential)
{
  const std::size_t n = std::size_t(points.rows());
  std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero()), tangent(n, Eigen::Vector3d::Zero());
  std::vector<int> boundary_neighbours(n, 0);
  for(auto f : faces(pm))
  {
    const Eigen::Vector3d nf = face_normal(f, pm, vim, points);
    if(!nf.allFinite())
      continue;
    for(auto v : CGAL::vertices_around_face(halfedge(f, pm), pm))
      normal[get(vim, v)] += nf;
  }
  for(auto h : halfedges(pm))
  {
    if(!is_border(h, pm))
      continue;
    const std::size_t a = get(vim, source(h, pm)), b = get(vim, target(h, pm));
    const Eigen::Vector3d t = (points.row(b) - points.row(a)).transpose();
    tangent[a] += t;
    tangent[b] += t;
    ++boundary_neighbours[a];
    ++boundary_neighbours[b];
  }
  std::vector<Eigen::Matrix3d> metric(n, Eigen::Matrix3d::Identity());
  for(std::size_t v = 0; v < n; ++v)
  {
    const double length = normal[v].norm();
    if(pinned[v] || !(length > 0))
      continue;
    const Eigen::Vector3d nv = normal[v] / length;
    const Eigen::Matrix3d across = nv * nv.transpose();
    if(boundary_neighbours[v] == 0)
      metric[v] = across + tangential * (Eigen::Matrix3d::Identity() - across);
    else if(boundary_neighbours[v] == 2)
    {
      Eigen::Vector3d t = tangent[v] - tangent[v].dot(nv) * nv;
      if(!(t.norm() > 0))
        continue;
      t.normalize();
      metric[v] = Eigen::Matrix3d::Identity() - (1.0 - tangential) * t * t.transpose();
    }
  }
  return metric;
}

// f and its Gauss-Newton model on the free unknowns (`variable`, see
// number_free_unknowns()).
class Closeness_objective
{
public:
  typedef Eigen::SparseMatrix<double> Matrix;

  Closeness_objective(const Tilable_problem& problem, const Point_matrix& X0,
                      const std::vector<Eigen::Matrix3d>& metric, double rigidity,
                      const std::vector<int>& variable, int number_of_unknowns);

  // The constant Gauss-Newton metric H = M + 2 r L.
  const Matrix& hessian() const { return m_hessian; }

  // I + 2 r L: the metric of the projection phase, where sliding in the
  // surface is no cheaper than leaving it. Cheap slides let the projection
  // shear quads into slivers, and it then stalls short of the tolerance.
  const Matrix& isotropic_hessian() const { return m_isotropic_hessian; }

  double value(const Point_matrix& X) const;

  // The gradient of f with respect to the free unknowns.
  Eigen::VectorXd gradient(const Point_matrix& X) const;

private:
  static Eigen::Vector3d edge(const Point_matrix& X, Eigen::Index v, int w)
  {
    return (X.row(v) - X.row(w)).transpose();
  }

  // The best rotation of each vertex's edges (Kabsch, never a mirror).
  std::vector<Eigen::Matrix3d> rotations(const Point_matrix& X) const;

  const Point_matrix& m_X0;
  const std::vector<Eigen::Matrix3d>& m_metric;
  double m_rigidity;
  const std::vector<int>& m_variable;
  std::vector<std::vector<int> > m_neighbours;
  Matrix m_hessian, m_isotropic_hessian;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_CLOSENESS_OBJECTIVE_H
