// Test helper: distances between two surfaces by CGAL's
// Polygon_mesh_processing::approximate_Hausdorff_distance (both ways, dense
// grid sampling), on triangulated copies made here: every face of more than
// three vertices becomes the fan of triangles around its vertex centroid, the
// surface the package's measure is defined on. Nothing of measure.h or
// internal/Measure is used: an oracle for the package's sampled distances.
#ifndef TILABLE_SURFACES_TEST_HAUSDORFF_ORACLE_H
#define TILABLE_SURFACES_TEST_HAUSDORFF_ORACLE_H

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace hausdorff_oracle {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Triangle_mesh;

// The triangulated copy of `pm`.
template <typename PolygonMesh>
Triangle_mesh centroid_fans(const PolygonMesh& pm)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  Triangle_mesh t;
  std::map<vertex_descriptor, Triangle_mesh::Vertex_index> copy;
  for(vertex_descriptor v : vertices(pm))
  {
    const auto& p = get(CGAL::vertex_point, pm, v);
    copy[v] = t.add_vertex(Kernel::Point_3(CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                           CGAL::to_double(p.z())));
  }
  for(auto f : faces(pm))
  {
    std::vector<Triangle_mesh::Vertex_index> corner;
    for(vertex_descriptor v : vertices_around_face(halfedge(f, pm), pm))
      corner.push_back(copy[v]);
    if(corner.size() == 3)
    {
      t.add_face(corner[0], corner[1], corner[2]);
      continue;
    }
    double c[3] = {0, 0, 0};
    for(Triangle_mesh::Vertex_index v : corner)
      for(int i = 0; i < 3; ++i)
        c[i] += t.point(v)[i] / double(corner.size());
    const Triangle_mesh::Vertex_index apex = t.add_vertex(Kernel::Point_3(c[0], c[1], c[2]));
    for(std::size_t i = 0; i < corner.size(); ++i)
      t.add_face(corner[i], corner[(i + 1) % corner.size()], apex);
  }
  return t;
}

// The bounding-box diagonal of a mesh.
inline double diagonal(const Triangle_mesh& t)
{
  const CGAL::Bbox_3 box = CGAL::Polygon_mesh_processing::bbox(t);
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

// Both one-sided distances between a result and its input, divided by the
// input's bounding-box diagonal as the package's are.
struct Distances
{
  double result_to_input = 0;  // the package's max_approximation_error
  double input_to_result = 0;  // the package's max_coverage_error
  double hausdorff() const { return (std::max)(result_to_input, input_to_result); }
};

// Sampled on a grid of spacing `spacing` times the input's diagonal (and at
// every vertex): each one-sided value is below the exact one by at most about
// the spacing.
template <typename PolygonMesh>
Distances distances(const PolygonMesh& result, const PolygonMesh& input, double spacing = 1.0 / 400)
{
  namespace PMP = CGAL::Polygon_mesh_processing;
  const Triangle_mesh r = centroid_fans(result), i = centroid_fans(input);
  const double d = diagonal(i);
  const auto sampling = CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing * d);
  Distances out;
  out.result_to_input =
    PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(r, i, sampling, CGAL::parameters::default_values()) / d;
  out.input_to_result =
    PMP::approximate_Hausdorff_distance<CGAL::Sequential_tag>(i, r, sampling, CGAL::parameters::default_values()) / d;
  return out;
}

// How far below the exact distance the package's sampled one may lie, as a
// fraction of the input's diagonal: a tenth of the input's mean edge (the
// package samples each fan triangle at its corners, an edge midpoint and its
// centroid; test_hausdorff_oracle measures at most 0.05 of a mean edge), plus
// the oracle's own grid spacing.
template <typename PolygonMesh>
double sampling_tolerance(const PolygonMesh& input, double spacing = 1.0 / 400)
{
  const Triangle_mesh t = centroid_fans(input);
  double length = 0;
  std::size_t count = 0;
  for(auto e : edges(input))
  {
    const auto& a = get(CGAL::vertex_point, input, source(e, input));
    const auto& b = get(CGAL::vertex_point, input, target(e, input));
    length += std::sqrt(CGAL::to_double(CGAL::squared_distance(a, b)));
    ++count;
  }
  return 0.1 * length / double(count) / diagonal(t) + spacing;
}

// Whether `result` is no farther from `input` than `other` is, by the
// oracle's symmetric Hausdorff distance, up to sampling_tolerance(): what a
// choice made by the package's own sampled distance can promise.
template <typename PolygonMesh>
::testing::AssertionResult no_farther(const PolygonMesh& result, const PolygonMesh& other,
                                      const PolygonMesh& input)
{
  const double a = distances(result, input).hausdorff(), b = distances(other, input).hausdorff();
  const double tolerance = sampling_tolerance(input);
  std::ostringstream what;
  what << "by the oracle: " << a << " against " << b << " (tolerance " << tolerance << ")";
  return a <= b + tolerance ? ::testing::AssertionSuccess() << what.str()
                            : ::testing::AssertionFailure() << what.str();
}

} // namespace hausdorff_oracle

#endif // TILABLE_SURFACES_TEST_HAUSDORFF_ORACLE_H
