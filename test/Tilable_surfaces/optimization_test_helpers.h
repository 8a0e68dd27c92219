// Helpers of test_optimize.cpp and test_measure.cpp: a mesh type, clusterings
// built without the package's clustering (every face alone, all faces in one
// cluster, a greedy k-medoids), and a congruence check computed here with
// Eigen::umeyama, independent of the package's measurement.

#ifndef CGAL_TILABLE_SURFACES_TEST_OPTIMIZATION_TEST_HELPERS_H
#define CGAL_TILABLE_SURFACES_TEST_OPTIMIZATION_TEST_HELPERS_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_helpers {

typedef CGAL::Simple_cartesian<double> Kernel;
typedef Kernel::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Face_index Face;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Property_map<Face, int> Face_int_map;
namespace TS = CGAL::Tilable_surfaces;

inline Mesh load(const std::string& name)
{
  Mesh mesh;
  const std::string path = std::string(CGAL_TILABLE_SURFACES_TEST_DATA) + "/" + name;
  if(!CGAL::IO::read_polygon_mesh(path, mesh))
    throw std::runtime_error("cannot read " + path);
  return mesh;
}

// The clustering maps of a mesh, as Surface_mesh face properties.
struct Clustering
{
  Face_int_map cluster, orientation;
  int K = 0;
};

inline Clustering add_clustering_maps(Mesh& mesh)
{
  Clustering c;
  c.cluster = mesh.add_property_map<Face, int>("f:cluster", 0).first;
  c.orientation = mesh.add_property_map<Face, int>("f:orientation", 0).first;
  return c;
}

// The named parameters of the maps of `c`.
inline auto clustering_parameters(const Clustering& c)
{
  return TS::parameters::face_cluster_map(c.cluster).face_orientation_map(c.orientation);
}

// `m` with its vertices at the rows of `points` (by vertex index).
template <typename Points>
Mesh moved_to(const Mesh& m, const Points& points)
{
  Mesh moved = m;
  for(Vertex v : vertices(moved))
    moved.point(v) = Point(points(int(v), 0), points(int(v), 1), points(int(v), 2));
  return moved;
}

// Clustering maps on `m` holding `label` (by face index) and `orientation`,
// every orientation 0 when it is empty.
inline Clustering clustered(Mesh& m, const std::vector<std::size_t>& label,
                            const std::vector<TS::Panel_orientation>& orientation = {})
{
  Clustering c = add_clustering_maps(m);
  for(Face f : faces(m))
  {
    c.cluster[f] = int(label[std::size_t(f)]);
    if(!orientation.empty())
      c.orientation[f] = orientation[std::size_t(f)].index();
  }
  return c;
}

// Every face its own cluster, orientation 0.
inline Clustering every_face_alone(Mesh& mesh)
{
  Clustering c = add_clustering_maps(mesh);
  for(Face f : faces(mesh))
    c.cluster[f] = c.K++;
  return c;
}

// The faces assigned to the nearest of `seeds` by the paper's dissimilarity,
// each oriented by its best match to the seed.
inline Clustering assign_to_seeds(Mesh& mesh, const std::vector<Face>& seeds)
{
  Clustering c = add_clustering_maps(mesh);
  c.K = int(seeds.size());
  for(Face f : faces(mesh))
  {
    const TS::Panel q = TS::face_panel(f, mesh);
    double best = (std::numeric_limits<double>::max)();
    for(int s = 0; s < c.K; ++s)
    {
      const TS::Quad_match m = TS::best_match(TS::face_panel(seeds[s], mesh), q);
      if(m.dissimilarity < best)
      {
        best = m.dissimilarity;
        c.cluster[f] = s;
        c.orientation[f] = m.orientation.index();
      }
    }
  }
  return c;
}

// All faces in one cluster, oriented against the first face.
inline Clustering single_cluster(Mesh& mesh)
{
  return assign_to_seeds(mesh, {*faces(mesh).begin()});
}

// K seeds by farthest-point sampling in dissimilarity, then assignment: a
// simple stand-in for the package's clustering.
inline Clustering greedy_clustering(Mesh& mesh, int K)
{
  std::vector<Face> all(faces(mesh).begin(), faces(mesh).end());
  std::vector<Face> seeds{all.front()};
  std::vector<double> distance(all.size(), (std::numeric_limits<double>::max)());
  while(int(seeds.size()) < K)
  {
    const TS::Panel s = TS::face_panel(seeds.back(), mesh);
    for(std::size_t i = 0; i < all.size(); ++i)
      distance[i] = (std::min)(distance[i], TS::dissimilarity(s, TS::face_panel(all[i], mesh)));
    seeds.push_back(all[std::max_element(distance.begin(), distance.end()) - distance.begin()]);
  }
  return assign_to_seeds(mesh, seeds);
}

// Worst corner deviation, over the clusters, of an instance from the
// cluster's first instance after the best proper rigid fit (Eigen::umeyama,
// no scaling), divided by the mean edge length. It bounds the package's
// congruence error from above, and is at most twice it.
inline double pairwise_congruence_error(const Mesh& mesh, const Clustering& c)
{
  std::vector<TS::Panel> first(c.K);
  std::vector<bool> seen(c.K, false);
  double worst = 0;
  for(Face f : faces(mesh))
  {
    const TS::Panel q = TS::face_panel(f, mesh, TS::Panel_orientation(c.orientation[f]));
    const int k = c.cluster[f];
    if(!seen[k])
    {
      seen[k] = true;
      first[k] = q;
      continue;
    }
    Eigen::Matrix<double, 3, 4> src, dst;
    for(int i = 0; i < 4; ++i) { src.col(i) = q[i]; dst.col(i) = first[k][i]; }
    const Eigen::Matrix4d T = Eigen::umeyama(src, dst, false);
    const Eigen::Matrix<double, 3, 4> moved =
      (T.topLeftCorner<3, 3>() * src).colwise() + T.topRightCorner<3, 1>();
    worst = (std::max)(worst, (moved - dst).colwise().norm().maxCoeff());
  }
  return worst / TS::mean_edge_length(mesh);
}

inline std::vector<Point> points_of(const Mesh& mesh)
{
  std::vector<Point> p;
  for(Vertex v : vertices(mesh))
    p.push_back(mesh.point(v));
  return p;
}

inline double bbox_diagonal(const Mesh& mesh)
{
  const CGAL::Bbox_3 b = CGAL::bbox_3(mesh.points().begin(), mesh.points().end());
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

} // namespace test_helpers

#endif // CGAL_TILABLE_SURFACES_TEST_OPTIMIZATION_TEST_HELPERS_H
