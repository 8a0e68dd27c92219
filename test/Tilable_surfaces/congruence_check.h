// Test helper: congruence of a tiled mesh, measured without the package's
// own measurement.
#ifndef TILABLE_SURFACES_TEST_CONGRUENCE_CHECK_H
#define TILABLE_SURFACES_TEST_CONGRUENCE_CHECK_H

#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>

namespace congruence_check {

namespace TS = CGAL::Tilable_surfaces;

// Congruence measured here, independently of the package's measurement: for
// each cluster, Eigen::umeyama (no scaling) of every instance onto the first
// one; the largest corner deviation over the mean edge length.
template <typename Mesh, typename ClusterMap, typename OrientationMap>
double congruence_by_umeyama(const Mesh& m, ClusterMap cluster, OrientationMap orientation)
{
  std::map<int, Eigen::Matrix<double, 3, 4> > first;
  double worst = 0;
  for(auto f : faces(m))
  {
    const TS::Quad q = TS::face_quad(f, m, TS::Quad_orientation(int(get(orientation, f))));
    Eigen::Matrix<double, 3, 4> x;
    for(int i = 0; i < 4; ++i) x.col(i) = q[i];
    const auto it = first.emplace(int(get(cluster, f)), x).first;
    const Eigen::Matrix4d T = Eigen::umeyama(it->second, x, false);
    const Eigen::Matrix<double, 3, 4> fitted =
      (T.topLeftCorner<3, 3>() * it->second).colwise() + T.topRightCorner<3, 1>();
    worst = (std::max)(worst, (fitted - x).colwise().norm().maxCoeff());
  }
  return worst / TS::mean_edge_length(m);
}

} // namespace congruence_check

using congruence_check::congruence_by_umeyama;

#endif
