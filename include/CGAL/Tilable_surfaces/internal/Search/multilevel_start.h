// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_H

// The multilevel exact start (user manual, section TS_Multilevel): above
// large_mesh_faces a solve from the input costs 1 to 3 s per iteration and
// stalls, so a mesh that is a 2 x 2 refinement
// (quad_coarsening.h) is coarsened, level by level, until it has at most
// tuning::multilevel_coarsest_faces faces (not tried if it cannot be
// coarsened that far, or K / 4 per level would be 0 before: the whole
// search on a larger coarse mesh takes minutes, spot_quadrangulated's 2,928
// quads 968 s, and does not end exact there). The coarsest mesh goes through the
// pipeline (cluster(), optimize_closest()) at K / 4 per level; when that
// result is exact, its positions and clustering are prolongated back to the
// input mesh, where they are exact with four clusters per coarse one. The
// largest clusters are then split in halves, orientations kept, up to K.
// K_set_tilable_surface::cluster() makes it through the clusterer's
// Multilevel_generator, where it is a MULTILEVEL candidate treated as the
// sweeps are: when it ends the search, the clusterer makes no other
// candidate (the beam of merges alone costs O(K^2) a step); otherwise it
// is a fallback the final result must beat.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/defaults.h>
#include <CGAL/Tilable_surfaces/exceptions.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_coarsening.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid.h>
#include <CGAL/Tilable_surfaces/internal/canonical_parameters.h>
#include <CGAL/Tilable_surfaces/internal/panel_tolerance.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Surface_mesh.h>
#include <CGAL/property_map.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <algorithm>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {

template <typename ConcurrencyTag, typename PolygonMesh, typename VertexPointMap>
class K_set_tilable_surface;

namespace internal {

// The user's visitor for the coarse solve: its iterations (a budget may
// stop them), not its phases, which name the steps on the user's mesh.
template <typename Visitor>
struct Coarse_solve_visitor
{
  Visitor* visitor;

  bool iteration(int iteration, double congruence_error, double objective)
  {
    return visitor->iteration(iteration, congruence_error, objective);
  }
  void phase(const char*, double) {}
};

// The levels from the input mesh of `state` down to the mesh that is solved.
template <typename Point>
struct Coarsening_levels
{
  std::vector<Quad_coarsening> levels;  // the input's first
  CGAL::Surface_mesh<Point> coarsest;
  std::size_t k = 0;                    // K / 4 per level
};

// The input mesh of `state` coarsened while it has more than
// tuning::multilevel_coarsest_faces faces, it can be, and `k` / 4 is at
// least 1; no level if it cannot be coarsened once.
template <typename State>
Coarsening_levels<typename State::Point> coarsening_levels(const State& state, std::size_t k)
{
  typedef typename State::Point Point;
  typedef CGAL::Surface_mesh<Point> Mesh;
  Coarsening_levels<Point> result;
  result.k = k;
  std::optional<Quad_coarsening> level = quad_coarsening(state.mesh, state.fim, state.vim);
  std::vector<Point> points = state.input_points;
  Mesh coarse;
  while(level && result.k / 4 >= 1 && make_coarse_mesh(*level, points, coarse))
  {
    result.levels.push_back(std::move(*level));
    result.k /= 4;
    result.coarsest = coarse;
    if(num_faces(coarse) <= tuning::multilevel_coarsest_faces)
      break;
    points.assign(coarse.points().begin(), coarse.points().end());
    level = quad_coarsening(coarse, get(CGAL::face_index, coarse), get(CGAL::vertex_index, coarse));
  }
  return result;
}

// The coarsest mesh of `levels` through the pipeline at `levels.k` with the
// parameters `np` (K replaced): its positions (by vertex index) and its
// clustering (by face index), if the result is exact.
template <typename ConcurrencyTag, typename Point, typename NP, typename Visitor>
std::optional<std::pair<std::vector<Point>, Face_clustering> >
coarse_solution(Coarsening_levels<Point>& levels, const NP& np, Visitor& visitor)
{
  typedef CGAL::Surface_mesh<Point> Mesh;
  Mesh& coarse = levels.coarsest;
  Coarse_solve_visitor<Visitor> coarse_visitor{&visitor};
  Visitor_ref coarse_ref(coarse_visitor);  // the type of make_k_set_tilable()'s: one instantiation for both
  // The user's values; the user's maps are of the fine mesh, not of the coarse one.
  const auto coarse_np = with_visitor(canonical_values(np).number_of_tiles(int(levels.k)), coarse_ref);
  try
  {
    K_set_tilable_surface<ConcurrencyTag, Mesh, typename CGAL::GetVertexPointMap<Mesh>::type> surface(
      coarse, get(CGAL::vertex_point, coarse));
    surface.cluster(coarse_np);
    if(!surface.optimize_closest(coarse_np).converged)
      return std::nullopt;
    Face_clustering clustering{std::vector<std::size_t>(num_faces(coarse)),
                               std::vector<Panel_orientation>(num_faces(coarse)), levels.k};
    for(auto f : faces(coarse))
    {
      clustering.label[f.idx()] = std::size_t(get(surface.face_cluster_map(), f));
      clustering.orientation[f.idx()] = Panel_orientation(get(surface.face_orientation_map(), f));
    }
    return std::make_pair(std::vector<Point>(coarse.points().begin(), coarse.points().end()), clustering);
  }
  catch(const Invalid_input&)
  {
    return std::nullopt; // a coarse mesh the pipeline refuses: no start
  }
}

// Splits the cluster of `fc` with most faces (the first such) in two halves
// by face index until it has `k` clusters or none has two faces. Each half
// keeps its orientations: both stay instances of the one S-quad, so an
// exact clustering stays exact.
CGAL_TILABLE_SURFACES_INLINE
void split_in_halves_to(Face_clustering& fc, std::size_t k);

// Whether the multilevel start is tried on `pm` with the parameters `np`:
// the default solver (the only one that starts from an exact start), no
// planar panels, no panel tolerance and no vertex held (the coarse mesh
// would not hold it).
template <typename PolygonMesh, typename NP>
bool multilevel_start_applies(const PolygonMesh& pm, const NP& np)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  const auto held = parameters::choose_parameter(
    parameters::get_parameter(np, CGAL::internal_np::vertex_is_constrained),
    CGAL::Static_boolean_property_map<vertex_descriptor, false>());
  for(vertex_descriptor v : vertices(pm))
    if(get(held, v))
      return false;
  return parameter_or(np, internal_np::solver, defaults::solver) == CONSTRAINED_GAUSS_NEWTON &&
         !parameter_or(np, internal_np::planar_tiles, defaults::planar_tiles) && panel_tolerance_of(np) == 0;
}

// The exact start the multilevel start makes: its clustering (by canonical
// index) and the positions where it is exact (by vertex index).
template <typename Point>
struct Multilevel_start
{
  Face_clustering clustering;
  std::vector<Point> points;
};

// The multilevel candidate of the input of `state` at `k` clusters, solved
// on the coarse mesh with the values of `np`, its iterations reported to
// `visitor`; its start is kept in `state.multilevel_start`. Nothing when
// the mesh is no 2 x 2 refinement down to multilevel_coarsest_faces or the
// coarse result is not exact.
template <typename ConcurrencyTag, typename State, typename NP>
std::optional<Generated_candidate> multilevel_candidate(State& state, std::size_t k, const NP& np,
                                                        Visitor_ref visitor)
{
  Coarsening_levels<typename State::Point> levels = coarsening_levels(state, k);
  if(levels.levels.empty() || num_faces(levels.coarsest) > tuning::multilevel_coarsest_faces)
    return std::nullopt;
  auto coarse = coarse_solution<ConcurrencyTag>(levels, np, visitor);
  if(!coarse)
    return std::nullopt;
  for(auto level = levels.levels.rbegin(); level != levels.levels.rend(); ++level)
  {
    coarse->first = prolongated_points(*level, coarse->first);
    coarse->second = prolongated_clustering(*level, coarse->second);
  }
  Face_clustering& fc = coarse->second;
  split_in_halves_to(fc, k);
  relabel_by_first_face(fc.label);
  Generated_candidate candidate;
  candidate.origin = Candidate_origins::MULTILEVEL;
  candidate.label = fc.label;
  candidate.orientation = fc.orientation;
  candidate.has_exact_start = candidate.start_is_exact = true;
  state.multilevel_start = Multilevel_start<typename State::Point>{std::move(fc), std::move(coarse->first)};
  return candidate;
}

// The hook Clustering_settings::multilevel_start for the input of `state`
// clustered with the parameters `np`; none (an empty function) when the
// start does not apply. The coarse solve (at most multilevel_coarsest_faces
// faces) is below large_mesh_faces, so it makes no multilevel start of its own.
template <typename ConcurrencyTag, typename State, typename NP>
Multilevel_start_hook multilevel_start_hook(State& state, const NP& np)
{
  static_assert(tuning::multilevel_coarsest_faces <= large_mesh_faces, "a coarse solve must not recurse");
  if(num_faces(state.mesh) <= large_mesh_faces || !multilevel_start_applies(state.mesh, np))
    return {};
  return [&state, values = canonical_values(np)](std::size_t k, Visitor_ref visitor) {
    return multilevel_candidate<ConcurrencyTag>(state, k, values, visitor);
  };
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Search/multilevel_start_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_MULTILEVEL_START_H
