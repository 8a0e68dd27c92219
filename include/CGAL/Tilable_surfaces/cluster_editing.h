// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H
#define CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H

/// \file cluster_editing.h
/// Interactive editing of a clustering (paper §5): merge two clusters, split
/// one in two, re-tag the orientations. Each function reads and rewrites the
/// `face_cluster_map` and `face_orientation_map` filled by `cluster_quads()`
/// (or by the user), keeps the cluster ids contiguous and returns the new
/// degree of flexibility.
///
/// Common named parameters: `face_cluster_map` and `face_orientation_map`
/// (required, read-write), `orientation_policy` (default
/// `PROPER_RIGID_MOTIONS`), `vertex_point_map`, `face_index_map`.
/// The number of clusters K is the largest id in `face_cluster_map` plus one.

#include <CGAL/Tilable_surfaces/cluster_quads.h>

#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The current labelling, read from the maps and checked.
template <typename PolygonMesh, typename NP>
struct Editable_clustering
{
  typedef typename CGAL::GetInitializedFaceIndexMap<PolygonMesh, NP>::const_type Face_index_map;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NP>::const_type Vertex_point_map;

  Face_index_map fim;
  Vertex_point_map vpm;
  std::vector<Quad> quads;
  std::vector<std::size_t> label;
  std::vector<Quad_orientation> orientation;
  std::size_t k = 0;

  Editable_clustering(const PolygonMesh& pm, const NP& np)
    : fim(CGAL::get_initialized_face_index_map(pm, np))
    , vpm(parameters::choose_parameter(parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                       get_const_property_map(CGAL::vertex_point, pm)))
  {
    namespace TS_np = CGAL::Tilable_surfaces::internal_np;
    require_face_maps<NP>();
    const auto cluster_map = parameters::get_parameter(np, TS_np::face_cluster);
    const auto orientation_map = parameters::get_parameter(np, TS_np::face_orientation);
    validate_quad_mesh(pm, np);
    quads = face_quads(pm, fim, np);
    label.resize(quads.size());
    orientation.resize(quads.size());
    for(auto f : faces(pm))
    {
      const std::size_t i = get(fim, f);
      const long long c = static_cast<long long>(get(cluster_map, f));
      if(c < 0)
        throw Invalid_input("face " + std::to_string(i) + " has a negative cluster id",
                            Invalid_input::FACE, i);
      label[i] = std::size_t(c);
      orientation[i] = Quad_orientation(static_cast<int>(get(orientation_map, f)));
      k = (std::max)(k, label[i] + 1);
    }
    std::vector<bool> used(k, false);
    for(std::size_t c : label) used[c] = true;
    for(std::size_t c = 0; c < k; ++c)
      if(!used[c])
        throw Invalid_input("cluster ids are not contiguous: no face has cluster " +
                            std::to_string(c), Invalid_input::PARAMETER);
  }

  void check_cluster(std::size_t c) const
  {
    if(c >= k)
      throw Invalid_input("no cluster " + std::to_string(c) + " (there are " +
                          std::to_string(k) + ")", Invalid_input::PARAMETER);
  }

  void write(const PolygonMesh& pm, const NP& np) const
  {
    namespace TS_np = CGAL::Tilable_surfaces::internal_np;
    const auto cluster_map = parameters::get_parameter(np, TS_np::face_cluster);
    const auto orientation_map = parameters::get_parameter(np, TS_np::face_orientation);
    typedef typename boost::property_traits<
      typename std::remove_const<decltype(cluster_map)>::type>::value_type Cluster_id;
    for(auto f : faces(pm))
    {
      const std::size_t i = get(fim, f);
      put(cluster_map, f, Cluster_id(label[i]));
      put_orientation(orientation_map, f, orientation[i]);
    }
  }
};

template <typename NP>
Orientation_policy orientation_policy(const NP& np)
{
  return parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::Tilable_surfaces::internal_np::orientation_policy),
    defaults::orientation_policy);
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Merges clusters `a` and `b` of the clustering stored in the maps of `np`.
///
/// The merged cluster takes the id min(a, b); the ids above max(a, b) decrease
/// by one, so the ids stay 0..K-2. The faces of the cluster max(a, b) keep
/// their S-quad instance, re-expressed in the labelling of min(a, b)'s S-quad:
/// their orientation becomes o * c, c the best correspondence between the two
/// S-quads (each the Procrustes mean of its instances in their current
/// orientations). The edge-sharing graph is amended accordingly
/// (`Edge_sharing_graph::merge_clusters()`), and its degree of flexibility is
/// returned. Call `retag_orientations()` afterwards to re-tag the faces
/// against the merged S-quad.
///
/// \throws Invalid_input if `a == b`, a cluster does not exist, or the maps
/// or the mesh are invalid; the maps are not modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t merge_clusters(const PolygonMesh& pm, std::size_t a, std::size_t b,
                           const CGAL_NP_CLASS& np)
{
  internal::Editable_clustering<PolygonMesh, CGAL_NP_CLASS> e(pm, np);
  e.check_cluster(a);
  e.check_cluster(b);
  if(a == b)
    throw Invalid_input("cannot merge cluster " + std::to_string(a) + " with itself",
                        Invalid_input::PARAMETER);
  const Orientation_policy policy = internal::orientation_policy(np);
  const std::size_t kept = (std::min)(a, b), removed = (std::max)(a, b);

  std::vector<std::vector<std::size_t> > members = internal::cluster_members(e.label, e.k);
  auto s_quad = [&](std::size_t c) {
    std::vector<Quad_orientation> o;
    for(std::size_t f : members[c]) o.push_back(e.orientation[f]);
    return internal::procrustes_mean(e.quads, members[c], policy, &o);
  };
  const Quad_orientation correspondence =
    internal::fast_best_match(s_quad(kept), s_quad(removed), policy).orientation;

  Edge_sharing_graph<PolygonMesh> graph =
    internal::edge_sharing_graph(pm, e.fim, e.vpm, e.label, e.orientation, e.k);
  const std::size_t dof = graph.merge_clusters(kept, removed, correspondence);

  for(std::size_t f : members[removed])
  {
    e.orientation[f] = e.orientation[f] * correspondence;
    e.label[f] = kept;
  }
  for(std::size_t& l : e.label)
    if(l > removed) --l;
  e.write(pm, np);
  return dof;
}

/// \ingroup PkgTilableSurfacesRef
/// Splits cluster `c` in two: 2-means on the quad descriptors, then exact
/// refinement (each quad goes to the nearer of the two S-quads, twice); quads
/// with equal descriptors are cut in two halves in face-index order.
///
/// The part with the first face of `c` keeps the id `c`, the other part gets
/// the id K. The faces of both parts are re-tagged with the orientation that
/// best matches their new S-quad; the edge-sharing graph is rebuilt (a union-find
/// cannot undo a union) and its degree of flexibility returned.
/// `random_seed` (default 0) seeds the 2-means.
///
/// \throws Invalid_input if `c` does not exist or has a single face, or the
/// maps or the mesh are invalid; the maps are not modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t split_cluster(const PolygonMesh& pm, std::size_t c, const CGAL_NP_CLASS& np)
{
  internal::Editable_clustering<PolygonMesh, CGAL_NP_CLASS> e(pm, np);
  e.check_cluster(c);
  const std::vector<std::vector<std::size_t> > members = internal::cluster_members(e.label, e.k);
  if(members[c].size() < 2)
    throw Invalid_input("cluster " + std::to_string(c) + " has a single face, it cannot be split",
                        Invalid_input::PARAMETER);
  const Orientation_policy policy = internal::orientation_policy(np);
  CGAL::Random random(parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::internal_np::random_seed), defaults::random_seed));
  std::vector<Quad_descriptor> descriptors(e.quads.size());
  for(std::size_t f : members[c]) descriptors[f] = shape_descriptor(e.quads[f]);

  const std::vector<bool> second =
    internal::split_in_two(e.quads, descriptors, members[c], policy, random);
  std::vector<std::size_t> part[2];
  for(std::size_t i = 0; i < second.size(); ++i)
  {
    part[second[i] ? 1 : 0].push_back(members[c][i]);
    if(second[i]) e.label[members[c][i]] = e.k;
  }
  for(const std::vector<std::size_t>& p : part)
  {
    const Quad s_quad = internal::procrustes_mean(e.quads, p, policy);
    for(std::size_t f : p)
      e.orientation[f] = internal::fast_best_match(s_quad, e.quads[f], policy).orientation;
  }
  e.write(pm, np);
  return internal::edge_sharing_graph(pm, e.fim, e.vpm, e.label, e.orientation, e.k + 1)
           .degree_of_flexibility();
}

/// \ingroup PkgTilableSurfacesRef
/// Recomputes the S-quad of every cluster (Procrustes mean) and re-tags every
/// face with an admissible orientation chosen for flexibility, as
/// `cluster_quads()` does at its end (tau from `similarity_threshold`,
/// default 0.01, times the mean edge length); the ids do not change. Returns
/// the degree of flexibility of the rebuilt edge-sharing graph.
///
/// \throws Invalid_input if the maps or the mesh are invalid; the maps are not
/// modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t retag_orientations(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  internal::Editable_clustering<PolygonMesh, CGAL_NP_CLASS> e(pm, np);
  const Orientation_policy policy = internal::orientation_policy(np);
  const double tau = parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::Tilable_surfaces::internal_np::similarity_threshold),
    defaults::similarity_threshold);
  const internal::Cluster_shapes shapes = internal::cluster_shapes(e.quads, e.label, e.k, policy);
  e.orientation = internal::flexible_orientations(pm, e.fim, e.quads, e.label, shapes.s_quads,
                                                  shapes.orientation, policy,
                                                  tau * mean_edge_length(pm, np));
  e.write(pm, np);
  return internal::edge_sharing_graph(pm, e.fim, e.vpm, e.label, e.orientation, e.k)
           .degree_of_flexibility();
}

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H
