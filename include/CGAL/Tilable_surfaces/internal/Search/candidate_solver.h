// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_CANDIDATE_SOLVER_H
#define CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_CANDIDATE_SOLVER_H

// The solves of the fidelity search and of K_set_tilable_surface::refine_to()
// on copies: a clustering of the candidate pool, or any clustering model,
// optimized from the input positions without touching the object, so that
// several may run at once.

#include <CGAL/Tilable_surfaces/Edge_sharing_graph.h>
#include <CGAL/Tilable_surfaces/cluster_editing.h>
#include <CGAL/Tilable_surfaces/cluster_panels.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface.h>
#include <CGAL/Tilable_surfaces/visitor.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start.h>
#include <CGAL/Tilable_surfaces/internal/canonical_face_order.h>
#include <CGAL/Tilable_surfaces/internal/tilable_surface_parameters.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// A solved clustering: the positions (by vertex index), the clustering, its
// edge-sharing graph when built (a copy costs O(K)) and the optimization
// result. What the fidelity search keeps of its best result so far.
template <typename PolygonMesh, typename Point>
struct Solution
{
  std::vector<Point> points;
  Face_clustering clustering;
  std::optional<Edge_sharing_graph<PolygonMesh> > graph;
  Optimization_result optimization;
};

// Forwards to a visitor under a lock: two solves may call it at once. The
// solves see it through a Visitor_ref, the visitor type of every other
// solve, so that they share one instantiation.
class Locked_visitor
{
public:
  template <typename Visitor>
  Locked_visitor(Visitor& visitor, std::mutex& mutex) : m_visitor(visitor), m_mutex(&mutex)
  {}

  bool iteration(int iteration, double congruence_error, double objective)
  {
    std::lock_guard<std::mutex> lock(*m_mutex);
    return m_visitor.iteration(iteration, congruence_error, objective);
  }
  void phase(const char* name, double seconds)
  {
    std::lock_guard<std::mutex> lock(*m_mutex);
    m_visitor.phase(name, seconds);
  }

private:
  Visitor_ref m_visitor;
  std::mutex* m_mutex;
};

// The solves and predictions of clusterings of the input of a
// K_set_tilable_surface (its internal::Tilable_surface_state `State`), each
// on copies of its own (clustering, maps, points). Every member is const and
// safe to call from several threads; the predictions read the mesh's points,
// which must hold the input (restore_input()).
template <typename State>
class Candidate_solver
{
public:
  typedef typename State::Solution Solution;

  explicit Candidate_solver(const State& state) : m_state(state) {}

  std::size_t number_of_faces() const { return num_faces(m_state.mesh); }

  // The clusters of candidate `i` of the pool (by face index), by canonical index.
  std::vector<std::size_t> candidate_labels(std::size_t i) const
  {
    return internal::by_canonical_index(m_state.clustering.candidates[i].face_cluster, m_state.input_faces.rank);
  }

  // Candidate `i` with S-quads and flexible orientations as
  // K_set_tilable_surface::use_candidate() makes it current; reads the input quads only.
  Face_clustering candidate_model(std::size_t i, std::size_t& degree_of_flexibility) const
  {
    const std::vector<std::size_t> label = candidate_labels(i);
    const std::size_t k = m_state.clustering.cluster_sizes.size();
    const Cluster_shapes shapes =
      internal::finished_clustering(m_state.mesh, m_state.fim, m_state.input_point_map(), m_state.input_faces.quads,
                                    label, k, m_state.policy, m_state.similarity_threshold * m_state.mean_length);
    degree_of_flexibility = shapes.degree_of_flexibility;
    return Face_clustering{label, shapes.orientation, k};
  }

  // Candidate `i` optimized from the input: what use_candidate(i) then
  // optimize() give. A candidate its origin solves from an exact start
  // (origin_traits()) starts from the swept surface when it has one, or
  // from the multilevel start with its own orientations.
  template <typename NP>
  Solution solved_candidate(std::size_t i, const NP& np) const
  {
    if(m_state.clustering.candidates[i].origin == Clustering_candidate::MULTILEVEL && m_state.multilevel_start)
    {
      const auto& multilevel = *m_state.multilevel_start;
      const Point_matrix start = internal::read_points(
        m_state.mesh, typename State::Input_point_map(multilevel.points.cbegin(), m_state.vim), m_state.vim);
      return solved_model(multilevel.clustering, np, &start);
    }
    std::size_t unused_dof;
    Face_clustering model = candidate_model(i, unused_dof);
    Point_matrix start;
    if(origin_traits(m_state.clustering.candidates[i].origin).solved_first_from_start)
      start = swept_start(model);
    return solved_model(std::move(model), np, start.rows() > 0 ? &start : nullptr);
  }

  // The solve of clustering `model` from the input on a copy of the points,
  // from `start` when it is not null and `model` is exact there.
  template <typename NP>
  Solution solved_model(Face_clustering model, const NP& np, const Point_matrix* start) const
  {
    Solution solved;
    solved.clustering = std::move(model);
    Model_maps maps(solved.clustering);
    solved.points = m_state.input_points;
    const Point_storage_map points(solved.points.begin(), m_state.vim);
    solved.optimization = internal::optimize_tilable_surface(
      Validated_mesh(true), m_state.mesh, m_state.step_parameters().with_model_maps(np, points, maps), start);
    return solved;
  }

  // The positions at which the sweep clustering `model` is exact
  // (sweep_start()), with its orientations re-tagged there: the ones chosen
  // on the input for flexibility need not be those of the sweep, whose
  // quads correspond in grid order. Empty when there is none.
  Point_matrix swept_start(Face_clustering& model) const
  {
    std::vector<Panel_orientation> orientation(model.orientation.size());
    const Point_matrix start = internal::sweep_start(
      m_state.mesh, m_state.fim, m_state.vim, m_state.input_point_map(),
      internal::read_points(m_state.mesh, m_state.input_point_map(), m_state.vim), model.label, &orientation);
    if(start.rows() > 0)
      model.orientation.swap(orientation);
    return start;
  }

  // The predicted displacement (`Displacement_prediction::max`) of the
  // clustering `model`, from the mesh's points.
  template <typename NP>
  double predicted_displacement(const Face_clustering& model, const NP& np) const
  {
    Model_maps maps(model);
    return internal::predict_displacement(Validated_mesh(true), m_state.mesh,
                                          m_state.step_parameters().with_model_maps(np, m_state.vpm, maps))
      .max;
  }

  // The same for `model` with clusters `a` and `b` merged, judged on the input quads.
  template <typename NP>
  double predicted_displacement_after_merge(Face_clustering model, std::size_t a, std::size_t b, const NP& np) const
  {
    internal::merge_clusters(model, m_state.input_faces.quads, a, b, m_state.policy);
    return predicted_displacement(model, np);
  }

  // Per cluster of `model`, the summed distances of its faces' corners from
  // their input positions (the mesh's points), and the number of its faces.
  void corner_displacements(const Face_clustering& model, std::vector<double>& moved,
                            std::vector<std::size_t>& size) const
  {
    moved.assign(model.number_of_clusters, 0.0);
    size.assign(model.number_of_clusters, 0);
    for(auto f : faces(m_state.mesh))
    {
      double sum = 0;
      for(auto v : CGAL::vertices_around_face(halfedge(f, m_state.mesh), m_state.mesh))
        sum += internal::distance(get(m_state.vpm, v), m_state.input_points[get(m_state.vim, v)]);
      moved[model.label[get(m_state.fim, f)]] += sum;
      ++size[model.label[get(m_state.fim, f)]];
    }
  }

  // The mesh's points now.
  Point_matrix current_points() const { return internal::read_points(m_state.mesh, m_state.vpm, m_state.vim); }

  // The clustering `model` split at its largest cluster (the first such), as
  // split_cluster() does, until it has `k` clusters.
  Face_clustering split_to(Face_clustering model, std::size_t k) const
  {
    while(model.number_of_clusters < k)
    {
      const std::vector<std::size_t> size = model.cluster_sizes();
      CGAL::Random random(defaults::random_seed);
      internal::split_cluster(model, m_state.input_faces.quads,
                              std::size_t(std::max_element(size.begin(), size.end()) - size.begin()), m_state.policy,
                              random);
    }
    return model;
  }

private:
  typedef typename State::Point Point;
  // Points stored by vertex index: the positions of a solve on a copy.
  typedef boost::iterator_property_map<typename std::vector<Point>::iterator, typename State::Vertex_index_map, Point,
                                       Point&>
    Point_storage_map;

  const State& m_state;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_SEARCH_CANDIDATE_SOLVER_H
