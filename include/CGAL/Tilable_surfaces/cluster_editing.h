// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H
#define CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H

/// \file cluster_editing.h
/// Interactive editing of a clustering (paper §5): merge two clusters, split
/// one in two, re-tag the orientations. Each function reads and rewrites the
/// `face_cluster_map` and `face_orientation_map` filled by `cluster_panels()`
/// (or by the user), keeps the cluster ids contiguous and returns the new
/// degree of flexibility.
///
/// Common named parameters: `face_cluster_map` and `face_orientation_map`
/// (required, read-write), `orientation_policy` (default
/// `PROPER_RIGID_MOTIONS`), `vertex_point_map`, `face_index_map`.
/// The number of clusters K is the largest id in `face_cluster_map` plus one.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>

#include <string>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename NP>
Orientation_policy orientation_policy(const NP& np)
{
  return parameter_or(np, CGAL::Tilable_surfaces::internal_np::orientation_policy, defaults::orientation_policy);
}

// The three edits on the clustered-mesh model, given the quads of the faces
// they are judged on; the free functions below and K_set_tilable_surface
// share them. Each keeps the ids 0..K-1.

// Merges cluster max(a, b) into min(a, b); returns the correspondence between
// their S-quads, which the edge-sharing graph needs.
CGAL_TILABLE_SURFACES_INLINE
Panel_orientation merge_clusters(Face_clustering& fc, const std::vector<Panel>& quads, std::size_t a,
                                std::size_t b, Orientation_policy policy);

// Splits cluster `c` in two; the second part gets the id K.
CGAL_TILABLE_SURFACES_INLINE
void split_cluster(Face_clustering& fc, const std::vector<Panel>& quads, std::size_t c,
                   Orientation_policy policy, CGAL::Random& random);

// Re-tags every face against its cluster's Procrustes mean, near-ties within
// `tolerance` chosen for flexibility.
template <typename PolygonMesh, typename FaceIndexMap>
void retag_orientations(Face_clustering& fc, const PolygonMesh& pm, FaceIndexMap fim,
                        const std::vector<Panel>& quads, Orientation_policy policy, double tolerance)
{
  fc.orientation =
    flexible_cluster_shapes(pm, fim, quads, fc.label, fc.number_of_clusters, policy, tolerance).orientation;
}

// The clustering in the maps of `np`, read and checked once, with the quads
// of `pm`, both by canonical index (as K_set_tilable_surface keeps them):
// what the free edit functions work on.
template <typename PolygonMesh, typename NP>
struct Editable_clustering
{
  typedef typename CGAL::GetInitializedFaceIndexMap<PolygonMesh, NP>::const_type Original_face_index_map;
  typedef typename CGAL::GetVertexPointMap<PolygonMesh, NP>::const_type Vertex_point_map;

  Canonical_faces<Original_face_index_map> faces;
  Canonical_face_index_map<Original_face_index_map> fim;
  Vertex_point_map vpm;
  Face_clustering fc;

  Editable_clustering(const PolygonMesh& pm, const NP& np) : vpm(internal::const_vertex_point_map(pm, np))
  {
    namespace TS_np = CGAL::Tilable_surfaces::internal_np;
    require_face_maps<NP>();
    validate_panel_mesh(pm, np);
    const Original_face_index_map original_index = CGAL::get_initialized_face_index_map(pm, np);
    const Face_clustering read =
      read_face_clustering(pm, original_index, parameters::get_parameter(np, TS_np::face_cluster),
                           parameters::get_parameter(np, TS_np::face_orientation),
                           unknown_number_of_clusters, CONTIGUOUS_IDS);
    faces = Canonical_faces<Original_face_index_map>(pm, original_index, face_quads(pm, original_index, np));
    fim = faces.index_map();
    fc = in_canonical_order(read, faces.rank);
  }

  void write(const PolygonMesh& pm, const NP& np) const
  {
    namespace TS_np = CGAL::Tilable_surfaces::internal_np;
    write_face_clustering(pm, fim, fc, parameters::get_parameter(np, TS_np::face_cluster),
                          parameters::get_parameter(np, TS_np::face_orientation));
  }

  std::size_t degree_of_flexibility(const PolygonMesh& pm) const
  {
    return Edge_sharing_graph<PolygonMesh>(Validated_mesh(true), pm, fim, vpm, fc).degree_of_flexibility();
  }
};

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
  Edge_sharing_graph<PolygonMesh> graph(internal::Validated_mesh(true), pm, e.fim, e.vpm, e.fc);
  const Panel_orientation correspondence =
    internal::merge_clusters(e.fc, e.faces.quads, a, b, internal::orientation_policy(np));
  const std::size_t dof = graph.merge_clusters((std::min)(a, b), (std::max)(a, b), correspondence);
  e.write(pm, np);
  return dof;
}

/// \ingroup PkgTilableSurfacesRef
/// Splits cluster `c` in two: 2-means on the quad descriptors, then exact
/// refinement (each quad goes to the nearer of the two S-quads, twice); quads
/// with equal descriptors are cut in two halves in the canonical face order
/// (`cluster_panels()`).
///
/// The part with the first face of `c` (in that order) keeps the id `c`, the other part gets
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
  CGAL::Random random(internal::parameter_or(np, CGAL::internal_np::random_seed, defaults::random_seed));
  internal::split_cluster(e.fc, e.faces.quads, c, internal::orientation_policy(np), random);
  e.write(pm, np);
  return e.degree_of_flexibility(pm);
}

/// \ingroup PkgTilableSurfacesRef
/// Recomputes the S-quad of every cluster (Procrustes mean) and re-tags every
/// face with an admissible orientation chosen for flexibility, as
/// `cluster_panels()` does at its end (tau from `similarity_threshold`,
/// default 0.01, times the mean edge length); the ids do not change. Returns
/// the degree of flexibility of the rebuilt edge-sharing graph.
///
/// \throws Invalid_input if the maps or the mesh are invalid; the maps are not
/// modified then.
template <class PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
std::size_t retag_orientations(const PolygonMesh& pm, const CGAL_NP_CLASS& np)
{
  internal::Editable_clustering<PolygonMesh, CGAL_NP_CLASS> e(pm, np);
  const double tau = internal::parameter_or(np, CGAL::Tilable_surfaces::internal_np::similarity_threshold,
                                            defaults::similarity_threshold);
  internal::retag_orientations(e.fc, pm, e.fim, e.faces.quads, internal::orientation_policy(np),
                               tau * mean_edge_length(pm, np));
  e.write(pm, np);
  return e.degree_of_flexibility(pm);
}

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/cluster_editing_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_CLUSTER_EDITING_H
