// Test helper: congruence of a tiled mesh, measured without the package's
// own measurement.
#ifndef TILABLE_SURFACES_TEST_CONGRUENCE_CHECK_H
#define TILABLE_SURFACES_TEST_CONGRUENCE_CHECK_H

#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <map>
#include <limits>

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
  typedef Eigen::Matrix<double, 3, Eigen::Dynamic> Corners;  // 4 of a quad, 3 of a triangle
  auto deviation = [](const Corners& from, const Corners& to) {
    const Eigen::Matrix4d T = Eigen::umeyama(from, to, false);
    const Corners fitted = (T.topLeftCorner<3, 3>() * from).colwise() + T.topRightCorner<3, 1>();
    return (fitted - to).colwise().norm().maxCoeff();
  };
  std::map<int, Corners> first;
  double worst = 0;
  for(auto f : faces(m))
  {
    const TS::Panel q = TS::face_panel(f, m, TS::Panel_orientation(int(get(orientation, f))));
    Corners x(3, q.size());
    for(int i = 0; i < q.size(); ++i) x.col(i) = q[i];
    const auto it = first.emplace(int(get(cluster, f)), x).first;
    if(it->second.cols() != x.cols())
      return std::numeric_limits<double>::infinity();  // a cluster of quads and triangles
    double d = deviation(it->second, x);
    if(allow_mirror)
    {
      Corners mirrored = it->second;
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
