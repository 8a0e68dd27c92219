// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_MEASURE_H
#define CGAL_TILABLE_SURFACES_MEASURE_H

/// \file measure.h
/// How tilable a surface is and how far it is from the input: congruence by
/// rigid fits, distance to the input surface by an AABB tree, the paper's
/// normalized energy terms (its Table 1), and the S-quad templates.
/// None of it reads a solver's own energy or bookkeeping.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/internal/Measure/approximation.h>
#include <CGAL/Tilable_surfaces/internal/Measure/congruence.h>
#include <CGAL/Tilable_surfaces/internal/Measure/self_intersections.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/fairness_operator.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/panel_tolerance.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Measurements of a (result) surface against the input it was made from.
struct Tilability_measure
{
  /// K, the number of clusters (1 + the largest cluster id).
  std::size_t number_of_clusters = 0;
  /// The degree of flexibility of the clustering (`Edge_sharing_graph`).
  std::size_t degree_of_flexibility = 0;
  /// The congruence error (user manual, section Definitions): the worst
  /// cluster's error.
  double congruence_error = 0;
  /// Per cluster: the largest corner deviation of an instance from the
  /// S-quad after the best proper rigid fit of the S-quad onto it (or the
  /// best improper one if closer, see `allows_mirrored_panels`), divided by
  /// `mean_edge_length`.
  std::vector<double> cluster_congruence_errors;
  /// Per cluster: its number of instances (faces).
  std::vector<std::size_t> cluster_sizes;
  /// The panel tolerance the result was held to (`panel_tolerance`), in
  /// model units; 0 in the exact mode.
  double panel_tolerance = 0;
  /// Per face (by the mesh's own face index, `CGAL::get_initialized_face_index_map(pm)`,
  /// whatever index map the steps used): the largest corner distance, in model units,
  /// between its instance and its cluster's S-quad (its mold) after the best
  /// rigid fit, as in `cluster_congruence_errors` but absolute.
  std::vector<double> panel_deviations;
  /// Per face (by the same index): its cluster.
  std::vector<std::size_t> panel_clusters;
  /// The largest of `panel_deviations`, in model units.
  double worst_panel_deviation = 0;
  /// Whether every panel is within `panel_tolerance` of its mold (with
  /// `requires_planar_tiles`, its diagonals too); false in the exact mode.
  bool within_panel_tolerance() const
  {
    return panel_tolerance > 0 && worst_panel_deviation <= panel_tolerance &&
           (!requires_planar_tiles || planarity_error * mean_edge_length <= panel_tolerance);
  }
  /// Whether instances could be mirror images of their S-quad
  /// (`orientation_policy` `ALLOW_MIRRORED_PANELS`): the fits above are then
  /// proper or improper, whichever is closer.
  bool allows_mirrored_panels = false;
  /// Per cluster: the instances whose best fit is a mirror, made from the
  /// mirror image of the mold; all 0 unless `allows_mirrored_panels`, and 0
  /// for a planar S-quad, whose mold is its own mirror image.
  std::vector<std::size_t> cluster_mirrored_counts;
  /// Per cluster: the S-quad, the generalized Procrustes mean of its
  /// instances (each in the template's labelling) under proper rigid motions,
  /// in mesh units and in a canonical frame: t0 at the origin, t1 on the +x
  /// axis, t2 in the xy plane with y >= 0. Zeros for a cluster without faces.
  std::vector<Panel> s_quads;
  /// The number of molds the result needs: its S-quads (those of clusters
  /// with faces) counted once per group of congruent ones, each corner within
  /// `defaults::congruence_tolerance` times `mean_edge_length` after the best
  /// rigid fit under a correspondence the orientation policy admits (a mirror
  /// fit too with `allows_mirrored_panels`). At most `number_of_clusters`:
  /// the solver may make two clusters' S-quads congruent (De Beers stand-in,
  /// K = 16: 11 molds), and a fabricator cuts one mold for both.
  std::size_t number_of_distinct_molds = 0;
  /// Per cluster: its mold, 0..`number_of_distinct_molds` - 1 numbered in
  /// cluster order (congruent S-quads share one); `number_of_clusters` for a
  /// cluster without faces.
  std::vector<std::size_t> cluster_molds;
  /// The largest distance between the two diagonals of a face of the result,
  /// divided by `mean_edge_length`: 0 when every panel is planar.
  double planarity_error = 0;
  /// Whether planar panels were required (`planar_tiles`); then
  /// `planarity_error` is held to the congruence tolerance as well.
  bool requires_planar_tiles = false;
  /// Mean edge length of the result, the length scale of the congruence error.
  double mean_edge_length = 0;
  /// Bounding-box diagonal of the input, the length scale of the
  /// approximation error.
  double input_bbox_diagonal = 0;
  /// Mean edge length of the input, the second unit of the distances below
  /// (see `in_input_edge_lengths()`).
  double input_mean_edge_length = 0;
  /// Largest distance from a sample of the result to the input surface,
  /// divided by `input_bbox_diagonal`. Every quad is taken as the fan of 4
  /// triangles around its vertex centroid (no preferred diagonal); the samples
  /// are the vertices of the faces and, on each face, the fan's apex, the 4 edge
  /// midpoints and the centroids of the 4 fan triangles. One-sided: it cannot
  /// see a part of the input that the result no longer covers.
  double max_approximation_error = 0;
  /// Mean of the same distances over all samples, divided likewise.
  double mean_approximation_error = 0;
  /// The other direction: largest distance from a sample of the input (the
  /// same samples, on the input) to the result surface, divided by
  /// `input_bbox_diagonal`. Large when the result stopped covering part of
  /// the input.
  double max_coverage_error = 0;
  /// Mean of the same distances, divided likewise.
  double mean_coverage_error = 0;
  /// The symmetric Hausdorff distance between the result and the input, as
  /// sampled: the larger of `max_approximation_error` and
  /// `max_coverage_error` (a fraction of the input's bounding-box diagonal).
  double hausdorff_distance = 0;
  /// The mean of the two directions' mean distances, divided likewise.
  double mean_symmetric_distance = 0;
  /// The number of pairs of faces of the result that cross each other (other
  /// than along the vertices and edges they share), each face taken as the
  /// fan of triangles around its vertex centroid, decided with exact
  /// predicates. A surface that crosses itself cannot be built, however small
  /// its congruence error and its distance to the input: a tube folded flat
  /// stays within two radii of its input.
  std::size_t self_intersecting_face_pairs = 0;
  /// The number of quads the result flattened: twisted in the input (a
  /// `relative_twist()` of magnitude at least `flattening_input_twist`) and
  /// left with at most `flattening_fraction` of that twist. A surface whose
  /// twisted quads became planar to be congruent has changed its shape, even
  /// when it stays near the input.
  std::size_t flattened_panels = 0;
  /// The input twist magnitude from which a quad counts in `flattened_panels`:
  /// a corner 5% of the edge off the plane of the other three, its diagonals
  /// 2.5% apart, 2.5 times what planar-quad meshes are commonly optimized to.
  /// Flattening a quad twisted less moves its corners by about a hundredth of
  /// an edge, which does not change the design.
  static constexpr double flattening_input_twist = 0.05;
  /// The fraction of its input twist below which such a quad is flattened.
  static constexpr double flattening_fraction = 0.1;
  /// `fraction` (of the bounding-box diagonal, as the distances above) in
  /// mean edge lengths of the input.
  double in_input_edge_lengths(double fraction) const
  {
    return input_mean_edge_length > 0 ? fraction * input_bbox_diagonal / input_mean_edge_length : 0.0;
  }
  /// Largest distance between a vertex of the result and the same vertex of
  /// the input, in mesh units.
  double max_displacement = 0;
  /// Mean of the same distances over the vertices, in mesh units.
  double mean_displacement = 0;
  /// The paper's normalized terms (its Table 1): both surfaces scaled by the
  /// same factor so that the input's largest bounding-box side is 1, then
  /// F_d / (number of vertices), F_f / (number of vertices), F_e / (number
  /// of edges), F_a / (number of faces) and F_o / (number of faces), each
  /// term as the paper defines it (cyclic sums, fairness of the result with
  /// the features of the input).
  Energy_terms normalized_terms;
};

/// \ingroup PkgTilableSurfacesRef
/// One S-quad of a tile catalog (`tile_catalog()`), the mold a fabricator
/// cuts its instances from.
struct Tile
{
  /// The cluster id.
  std::size_t id = 0;
  /// The number of faces that are instances of this S-quad.
  std::size_t instance_count = 0;
  /// How many of them are mirror images of it, cut from the mirrored mold
  /// (only with `orientation_policy` `ALLOW_MIRRORED_PANELS`).
  std::size_t mirrored_count = 0;
  /// Corners t0..t3 in a canonical frame (t0 at the origin, t1 on +x, t2 in
  /// the xy plane with y >= 0), in the mesh's units.
  Panel corners;
  /// The largest corner deviation of an instance from the S-quad after its
  /// best rigid fit (proper, or improper for a mirrored instance), in the
  /// mesh's units.
  double worst_deviation = 0;
  /// Its mold (`Tilability_measure::cluster_molds`): tiles whose S-quads are
  /// congruent share one, and a fabricator cuts it once.
  std::size_t mold = 0;
  /// Its instances, by face index, in increasing order.
  std::vector<std::size_t> instance_faces;
  /// The deviation of each of them from the S-quad, as `worst_deviation`.
  std::vector<double> instance_deviations;
  /// The panel tolerance the result was held to, in the mesh's units (0:
  /// exact mode).
  double panel_tolerance = 0;
};

/// \ingroup PkgTilableSurfacesRef
/// What keeps the measured result from being built as the design, one
/// sentence each: not tilable (congruence error above `congruence_tolerance`),
/// crossing itself, a part of its quads flattened (at least
/// `flattened_warning_fraction` of the faces, see
/// `Tilability_measure::flattened_panels`), and fewer distinct molds than
/// half of K (the clusters collapsed onto the same shapes: the surface is
/// made of fewer shapes than it could have). Empty for a result to build.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> buildability_warnings(const Tilability_measure& m,
                                               double congruence_tolerance = defaults::congruence_tolerance,
                                               double flattened_warning_fraction = 0.1);

/// \ingroup PkgTilableSurfacesRef
/// The tile catalog of a measurement: one `Tile` per S-quad, with the
/// measured worst deviation of its instances, in the mesh's units. The IO
/// functions of `IO/tile_catalog.h` write it as CSV or JSON.
CGAL_TILABLE_SURFACES_INLINE
std::vector<Tile> tile_catalog(const Tilability_measure& m);

namespace internal {

// The quads of `result` flattened from `input` (Tilability_measure::flattened_panels).
CGAL_TILABLE_SURFACES_INLINE
std::size_t flattened_panels(const Tilable_problem& problem, const Point_matrix& input,
                             const Point_matrix& result);

// The measurements on arrays; `D` is the fairness operator of the mesh.
CGAL_TILABLE_SURFACES_INLINE
Tilability_measure measure_tilability(const Tilable_problem& problem,
                                      const Eigen::SparseMatrix<double>& D,
                                      const Point_matrix& input, const Point_matrix& result,
                                      double panel_tolerance = defaults::panel_tolerance);

// Per face of the problem of `pm` and `np` (by the index of np's face index
// map), the mesh's own face index: the steps of K_set_tilable_surface index
// the faces in a canonical order, the user by the mesh's.
template <typename PolygonMesh, typename NamedParameters>
std::vector<std::size_t> mesh_face_indices(const PolygonMesh& pm, const NamedParameters& np)
{
  const auto fim = CGAL::get_initialized_face_index_map(pm, np);
  const auto own = CGAL::get_initialized_face_index_map(pm);
  std::vector<std::size_t> index(num_faces(pm));
  for(auto f : faces(pm)) index[std::size_t(get(fim, f))] = std::size_t(get(own, f));
  return index;
}

// The per-face entries of `m`, by problem face, put by the mesh's own face
// index (`mesh_face_indices()`).
CGAL_TILABLE_SURFACES_INLINE
void use_mesh_face_order(Tilability_measure& m, const std::vector<std::size_t>& index);

// measure_tilability() on meshes validate_panel_mesh() accepted, with the
// same numbers of vertices and faces.
template <typename PolygonMesh, typename NamedParameters, typename InputNamedParameters>
Tilability_measure measure_tilability(Validated_mesh, const PolygonMesh& result, const PolygonMesh& input,
                                      const NamedParameters& np, const InputNamedParameters& np_input)
{
  const Tilable_problem problem = make_tilable_problem(result, np);
  const Point_matrix input_points = read_points(
    input,
    internal::const_vertex_point_map(input, np_input),
    CGAL::get_initialized_vertex_index_map(input, np_input));
  const Eigen::SparseMatrix<double> D = fairness_operator(result, input_points, np);
  Tilability_measure m = measure_tilability(problem, D, input_points, problem.points, panel_tolerance_of(np));
  use_mesh_face_order(m, mesh_face_indices(result, np));
  return m;
}

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Measures how tilable `result` is, given the clustering of its faces, and
/// how far it is from `input`, a mesh with the same combinatorics whose
/// vertices correspond to those of `result` by vertex index (e.g. a copy of
/// the mesh taken before `optimize_tilable_surface()`).
///
/// \cgalNamedParamsBegin (for `result`)
///   \cgalParamNBegin{face_cluster_map} (required) cluster of every face of
///     `result`, in 0..K-1 \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} (required) orientation (0..7 or
///     `Panel_orientation`) of every face's S-quad instance \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} points of `result` \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} indices pairing the vertices of the
///     two meshes \cgalParamNEnd
///   \cgalParamNBegin{orientation_policy} with `ALLOW_MIRRORED_PANELS`, an
///     instance may fit its S-quad by an improper motion; default
///     `PROPER_RIGID_MOTIONS` \cgalParamNEnd
///   \cgalParamNBegin{feature_angle} dihedral angle in degrees above which an
///     edge of `input` is a sharp feature, for F_f; default 60 \cgalParamNEnd
///   \cgalParamNBegin{panel_tolerance} recorded in the measure
///     (`Tilability_measure::panel_tolerance`), in model units: the result is
///     certified within it by `Tilability_measure::within_panel_tolerance()`;
///     default 0 \cgalParamNEnd
///   \cgalParamNBegin{edge_is_constrained_map} feature edges, replacing the
///     detection by angle \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \cgalNamedParamsBegin (for `input`, `np_input`)
///   \cgalParamNBegin{vertex_point_map} points of `input` \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map} indices pairing the vertices \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \throws Invalid_input if a mesh is not a valid quad mesh, if the meshes do
/// not have the same numbers of vertices and faces, if a cluster or an
/// orientation is out of range, or if `panel_tolerance` is negative or not finite.
template <typename PolygonMesh, typename NamedParameters, typename InputNamedParameters>
Tilability_measure measure_tilability(const PolygonMesh& result, const PolygonMesh& input,
                                      const NamedParameters& np, const InputNamedParameters& np_input)
{
  internal::panel_tolerance_of(np);
  validate_panel_mesh(result, np);
  validate_panel_mesh(input, np_input);
  if(num_vertices(result) != num_vertices(input) || num_faces(result) != num_faces(input))
    throw Invalid_input("the result and the input do not have the same numbers of vertices and faces");
  return internal::measure_tilability(internal::Validated_mesh(true), result, input,
                                      internal::canonical_parameters(np), internal::canonical_parameters(np_input));
}

/// \ingroup PkgTilableSurfacesRef
/// Same as the function above, the input mesh using its default property
/// maps.
template <typename PolygonMesh, typename NamedParameters>
Tilability_measure measure_tilability(const PolygonMesh& result, const PolygonMesh& input,
                                      const NamedParameters& np)
{
  return measure_tilability(result, input, np, parameters::default_values());
}

} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/measure_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_MEASURE_H
