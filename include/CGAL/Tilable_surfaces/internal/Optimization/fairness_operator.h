// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FAIRNESS_OPERATOR_H
#define CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FAIRNESS_OPERATOR_H

// The fairness term of the paper (§4, after Liu et al. 2006) as a sparse
// linear operator D on vertex positions: F_f(X) = ||D X||^2 (Frobenius, the
// same rows for x, y and z).

#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/feature_detection.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/property_map.h>

#include <Eigen/Sparse>

#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// One or two rows per vertex that is not `excluded`:
// - interior, valence 4: the second differences n0 - 2v + n2 and n1 - 2v + n3
//   through the opposite neighbours (in cyclic order around v);
// - interior, other valences m: the umbrella v - (1/m) sum of neighbours;
// - boundary: the second difference w0 - 2v + w1 along the boundary.
template <typename PolygonMesh, typename VertexIndexMap>
Eigen::SparseMatrix<double> fairness_operator(const PolygonMesh& pm, const VertexIndexMap& vim,
                                              const std::vector<bool>& excluded)
{
  typedef Eigen::Triplet<double> Triplet;
  std::vector<Triplet> triplets;
  int row = 0;
  auto second_difference = [&](int a, int v, int b) {
    triplets.emplace_back(row, a, 1.0);
    triplets.emplace_back(row, v, -2.0);
    triplets.emplace_back(row, b, 1.0);
    ++row;
  };

  for(auto v : vertices(pm))
  {
    const int i = int(get(vim, v));
    if(excluded[i] || halfedge(v, pm) == boost::graph_traits<PolygonMesh>::null_halfedge())
      continue;
    std::vector<int> neighbours, boundary_neighbours;
    bool on_boundary = false;
    for(auto h : CGAL::halfedges_around_target(halfedge(v, pm), pm))
    {
      const int w = int(get(vim, source(h, pm)));
      neighbours.push_back(w);
      if(is_border_edge(h, pm))
      {
        on_boundary = true;
        boundary_neighbours.push_back(w);
      }
    }
    if(on_boundary)
    {
      // A vertex where the boundary pinches has more than 2: no direction.
      if(boundary_neighbours.size() == 2)
        second_difference(boundary_neighbours[0], i, boundary_neighbours[1]);
    }
    else if(neighbours.size() == 4)
    {
      second_difference(neighbours[0], i, neighbours[2]);
      second_difference(neighbours[1], i, neighbours[3]);
    }
    else
    {
      triplets.emplace_back(row, i, 1.0);
      for(int w : neighbours)
        triplets.emplace_back(row, w, -1.0 / double(neighbours.size()));
      ++row;
    }
  }
  Eigen::SparseMatrix<double> D(row, int(num_vertices(pm)));
  D.setFromTriplets(triplets.begin(), triplets.end());
  return D;
}

// The vertices on sharp features and the corners of the boundary of `pm`
// with the geometry `points` (the input surface): `feature_angle` (degrees,
// default 60) or CGAL's `edge_is_constrained_map` when given.
template <typename PolygonMesh, typename NamedParameters>
std::vector<bool> feature_vertices(const PolygonMesh& pm, const Point_matrix& points,
                                   const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef typename boost::graph_traits<PolygonMesh>::edge_descriptor edge_descriptor;
  const double feature_angle =
    parameter_or(np, CGAL::Tilable_surfaces::internal_np::feature_angle, defaults::feature_angle);
  const bool use_edge_map =
    !parameters::is_default_parameter<NamedParameters, CGAL::internal_np::edge_is_constrained_t>::value;
  const auto ecm = choose_parameter(get_parameter(np, CGAL::internal_np::edge_is_constrained),
                                    CGAL::Static_boolean_property_map<edge_descriptor, false>());
  return fairness_exclusions(pm, CGAL::get_initialized_vertex_index_map(pm, np), points,
                             feature_angle, use_edge_map, ecm);
}

// The fairness operator of `pm`, leaving out the feature vertices of the
// geometry `points` (the input surface).
template <typename PolygonMesh, typename NamedParameters>
Eigen::SparseMatrix<double> fairness_operator(const PolygonMesh& pm, const Point_matrix& points,
                                              const NamedParameters& np)
{
  return fairness_operator(pm, CGAL::get_initialized_vertex_index_map(pm, np),
                           feature_vertices(pm, points, np));
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_OPTIMIZATION_FAIRNESS_OPERATOR_H
