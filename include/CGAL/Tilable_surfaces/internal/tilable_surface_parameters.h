// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_PARAMETERS_H
#define CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_PARAMETERS_H

// The named parameters through which K_set_tilable_surface and its fidelity
// search call the free functions (clustering, solve, prediction, measure):
// the object's index maps, points and clustering in front of the user's
// parameters; and the concurrency its steps run with.

#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/parallel_for.h>

#include <boost/property_map/property_map.hpp>

#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// Runs f with the parallelism of ConcurrencyTag (the steps that compute)
// and returns what it returns.
template <typename ConcurrencyTag, typename F>
auto with_concurrency(const F& f)
{
  typedef decltype(f()) Result;
  if constexpr(std::is_void<Result>::value)
    run_with_concurrency<ConcurrencyTag>(f);
  else
  {
    std::optional<Result> result;
    run_with_concurrency<ConcurrencyTag>([&] { result.emplace(f()); });
    return std::move(*result);
  }
}

// A clustering as the ints the maps read, in storage of its own: for the
// steps that work on a copy of the current clustering, several at once.
struct Model_maps
{
  std::vector<int> cluster, orientation;
  explicit Model_maps(const Face_clustering& model)
    : cluster(model.label.size()), orientation(model.label.size())
  {
    model.write_ids(cluster, orientation);
  }
};

// The maps and the orientation policy that every step of a
// K_set_tilable_surface passes on, so that edits, solves and measurements
// match instances to S-quads as its clustering did.
template <typename FaceIndexMap, typename VertexIndexMap>
struct Surface_parameters
{
  // The type of the face cluster and orientation maps the object hands out.
  typedef boost::iterator_property_map<std::vector<int>::iterator, FaceIndexMap, int, int&> Face_int_map;

  FaceIndexMap fim;
  VertexIndexMap vim;
  Orientation_policy policy;
  double similarity_threshold;

  // The object's own maps, with its policy and similarity threshold.
  template <typename PointMap>
  auto own_maps(PointMap vpm, Face_int_map cluster, Face_int_map orientation) const
  {
    return parameters::vertex_point_map(vpm)
      .face_index_map(fim)
      .face_cluster_map(cluster)
      .face_orientation_map(orientation)
      .orientation_policy(policy)
      .similarity_threshold(similarity_threshold);
  }

  // The user's parameters with the points in `vpm` and the clustering in
  // `cluster` and `orientation` in front (found first); the user's
  // orientation policy, if given, else `policy`.
  template <typename NP, typename PointMap>
  auto with_maps(const NP& np, PointMap vpm, Face_int_map cluster, Face_int_map orientation) const
  {
    return parameters::extend(np)
      .vertex_point_map(vpm)
      .vertex_index_map(vim)
      .face_index_map(fim)
      .face_cluster_map(cluster)
      .face_orientation_map(orientation)
      .orientation_policy(parameter_or(np, internal_np::orientation_policy, policy));
  }

  // with_maps() with the clustering in `maps`, which must outlive the result.
  template <typename NP, typename PointMap>
  auto with_model_maps(const NP& np, PointMap vpm, Model_maps& maps) const
  {
    return with_maps(np, vpm, Face_int_map(maps.cluster.begin(), fim), Face_int_map(maps.orientation.begin(), fim));
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_TILABLE_SURFACE_PARAMETERS_H
