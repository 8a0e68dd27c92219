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
// one (or onto its mirror image z -> -z too, if closer, with `allow_mirror`);
// the largest corner deviation over the mean edge length.
template <typename Mesh, typename ClusterMap, typename OrientationMap>
double congruence_by_umeyama(const Mesh& m, ClusterMap cluster, OrientationMap orientation,
                             bool allow_mirror = false)
{
  auto deviation = [](const Eigen::Matrix<double, 3, 4>& from, const Eigen::Matrix<double, 3, 4>& to) {
    const Eigen::Matrix4d T = Eigen::umeyama(from, to, false);
    const Eigen::Matrix<double, 3, 4> fitted =
      (T.topLeftCorner<3, 3>() * from).colwise() + T.topRightCorner<3, 1>();
    return (fitted - to).colwise().norm().maxCoeff();
  };
  std::map<int, Eigen::Matrix<double, 3, 4> > first;
  double worst = 0;
  for(auto f : faces(m))
  {
    const TS::Quad q = TS::face_quad(f, m, TS::Quad_orientation(int(get(orientation, f))));
    Eigen::Matrix<double, 3, 4> x;
    for(int i = 0; i < 4; ++i) x.col(i) = q[i];
    const auto it = first.emplace(int(get(cluster, f)), x).first;
    double d = deviation(it->second, x);
    if(allow_mirror)
    {
      Eigen::Matrix<double, 3, 4> mirrored = it->second;
      mirrored.row(2) *= -1;
      d = (std::min)(d, deviation(mirrored, x));
    }
    worst = (std::max)(worst, d);
  }
  return worst / TS::mean_edge_length(m);
}

} // namespace congruence_check

using congruence_check::congruence_by_umeyama;

#endif
