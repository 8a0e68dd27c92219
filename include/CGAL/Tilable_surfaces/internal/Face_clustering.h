// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_H
#define CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_H

// The clustered-mesh model every step works on: the cluster and S-quad
// orientation of every face, by face index, and K. The maps a user passes are
// read into it, and checked, in one place: read_face_clustering().

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Per cluster, its faces (increasing indices).
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::vector<std::size_t> >
cluster_members(const std::vector<std::size_t>& label, std::size_t k);

struct Face_clustering
{
  std::vector<std::size_t> label;
  std::vector<Panel_orientation> orientation;
  std::size_t number_of_clusters = 0;

  std::vector<std::size_t> cluster_sizes() const
  {
    std::vector<std::size_t> sizes(number_of_clusters, 0);
    for(std::size_t c : label)
      ++sizes[c];
    return sizes;
  }

  // The clustering as the int ids and orientation indices (0..7) the
  // public maps hold, written in place into `cluster` and `orientation`
  // (one slot per face), so that maps already handed out stay valid.
  void write_ids(std::vector<int>& cluster, std::vector<int>& orientation_index) const
  {
    for(std::size_t f = 0; f < label.size(); ++f)
    {
      cluster[f] = int(label[f]);
      orientation_index[f] = orientation[f].index();
    }
  }

  void check_cluster(std::size_t c) const
  {
    if(c >= number_of_clusters)
      throw Invalid_input("no cluster " + std::to_string(c) + " (there are " +
                          std::to_string(number_of_clusters) + ")", Invalid_input::PARAMETER);
  }
};

// What read_face_clustering() requires of the ids beyond their range.
enum Cluster_ids
{
  ANY_IDS,        // K = 1 + the largest id; some may be unused
  CONTIGUOUS_IDS  // every id in 0..K-1 has a face
};

// K not known beforehand: 1 + the largest id read.
constexpr std::size_t unknown_number_of_clusters = (std::numeric_limits<std::size_t>::max)();

// The number of corners of every cluster's template, 4 or 3 (an empty
// cluster counts as a quad one); throws if a cluster holds quads and triangles.
template <typename PolygonMesh, typename FaceIndexMap>
std::vector<int> cluster_corner_counts(const PolygonMesh& pm, FaceIndexMap fim, const Face_clustering& fc)
{
  std::vector<int> corners(fc.number_of_clusters, 0);
  std::vector<std::size_t> witness(fc.number_of_clusters, 0);
  for(auto f : faces(pm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    const std::size_t c = fc.label[i];
    const int n = face_corner_count(f, pm);
    if(corners[c] == 0)
    {
      corners[c] = n;
      witness[c] = i;
    }
    else if(corners[c] != n)
    {
      const std::size_t triangle = n == 3 ? i : witness[c], quad = n == 3 ? witness[c] : i;
      throw Invalid_input("cluster " + std::to_string(c) + " holds both the triangle " +
                          std::to_string(triangle) + " and the quad " + std::to_string(quad) +
                          ": a cluster holds one kind of face", Invalid_input::FACE, triangle);
    }
  }
  for(int& n : corners)
    if(n == 0) n = 4;
  return corners;
}

// Reads the clustering in `cluster_map` and `orientation_map`, checking every
// id against `number_of_clusters` (if known), every orientation against those
// of its face (0..7, a triangle's 0, 1, 2, 4, 5, 6) and that no cluster mixes
// quads and triangles, and, with CONTIGUOUS_IDS, that no id in 0..K-1 is unused.
template <typename PolygonMesh, typename FaceIndexMap, typename ClusterMap, typename OrientationMap>
Face_clustering read_face_clustering(const PolygonMesh& pm, FaceIndexMap fim, ClusterMap cluster_map,
                                     OrientationMap orientation_map,
                                     std::size_t number_of_clusters = unknown_number_of_clusters,
                                     Cluster_ids ids = ANY_IDS)
{
  Face_clustering fc;
  fc.label.resize(num_faces(pm));
  fc.orientation.resize(num_faces(pm));
  std::size_t largest = 0;
  for(auto f : faces(pm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    const long long c = static_cast<long long>(get(cluster_map, f));
    const long long o = static_cast<long long>(static_cast<int>(get(orientation_map, f)));
    check_face_label(i, c, o, number_of_clusters, face_corner_count(f, pm));
    fc.label[i] = std::size_t(c);
    fc.orientation[i] = Panel_orientation(int(o));
    largest = (std::max)(largest, std::size_t(c));
  }
  fc.number_of_clusters = number_of_clusters != unknown_number_of_clusters
                            ? number_of_clusters
                            : (fc.label.empty() ? 0 : largest + 1);
  cluster_corner_counts(pm, fim, fc);
  if(ids == CONTIGUOUS_IDS)
  {
    const std::vector<std::size_t> sizes = fc.cluster_sizes();
    for(std::size_t c = 0; c < sizes.size(); ++c)
      if(sizes[c] == 0)
        throw Invalid_input("cluster " + std::to_string(c) + " has no face: the ids must be 0..K-1, all used",
                            Invalid_input::PARAMETER);
  }
  return fc;
}

// Writes `fc` into the two maps, whatever their value types.
template <typename PolygonMesh, typename FaceIndexMap, typename ClusterMap, typename OrientationMap>
void write_face_clustering(const PolygonMesh& pm, FaceIndexMap fim, const Face_clustering& fc,
                           ClusterMap cluster_map, OrientationMap orientation_map)
{
  typedef typename boost::property_traits<ClusterMap>::value_type Cluster_id;
  typedef typename boost::property_traits<OrientationMap>::value_type Orientation;
  for(auto f : faces(pm))
  {
    const std::size_t i = std::size_t(get(fim, f));
    put(cluster_map, f, Cluster_id(fc.label[i]));
    put(orientation_map, f, Orientation(fc.orientation[i].index()));
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Face_clustering_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_FACE_CLUSTERING_H
