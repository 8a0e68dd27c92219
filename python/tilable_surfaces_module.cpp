// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `tilable_surfaces`: make_k_set_tilable() on numpy arrays.
//
//   import numpy as np, tilable_surfaces
//   r = tilable_surfaces.make_k_set_tilable(vertices, faces, k=20, seed=7)
//   r["vertices"], r["cluster"], r["orientation"], r["congruence_error"], r["s_quads"], ...
//
// Bad input raises ValueError with the package's Invalid_input message. The
// computation runs without the GIL.

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#endif

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace py = pybind11;
namespace TS = CGAL::Tilable_surfaces;
namespace TSP = CGAL::Tilable_surfaces::parameters;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

namespace {

// The keyword arguments of make_k_set_tilable(). Their defaults are the
// package's (defaults.h), except `iterations` and `fairness_weight`, whose
// default (< 0) leaves the solver's own.
struct Options
{
  int k = 0;
  unsigned int seed = TS::defaults::random_seed;
  std::size_t number_of_candidates = TS::defaults::number_of_candidates;
  double similarity_threshold = TS::defaults::similarity_threshold;
  double flexibility_penalty = TS::defaults::flexibility_penalty;
  std::string orientation_policy = "proper_rigid_motions";
  double distance_weight = TS::defaults::distance_weight;
  double fairness_weight = -1; // negative: the solver's default
  std::string solver = "gauss-newton";
  int iterations = -1;
  double congruence_tolerance = TS::defaults::congruence_tolerance;
  int threads = 0;
  bool planar_tiles = false;
};

[[noreturn]] void invalid(const std::string& message)
{
  throw TS::Invalid_input(message, TS::Invalid_input::PARAMETER);
}

TS::Solver_type solver_type(const std::string& name)
{
  if(name == "gauss-newton") return TS::CONSTRAINED_GAUSS_NEWTON;
  if(name == "paper-cg") return TS::PAPER_CONJUGATE_GRADIENT;
  invalid("unknown solver '" + name + "' (gauss-newton or paper-cg)");
}

TS::Orientation_policy orientation_policy(const std::string& name)
{
  if(name == "proper_rigid_motions") return TS::PROPER_RIGID_MOTIONS;
  if(name == "no_turned_over_panels") return TS::NO_TURNED_OVER_PANELS;
  if(name == "allow_mirrored_panels") return TS::ALLOW_MIRRORED_PANELS;
  invalid("unknown orientation_policy '" + name +
          "' (proper_rigid_motions, no_turned_over_panels or allow_mirrored_panels)");
}

// The mesh of the arrays (or of anything numpy makes arrays of, such as
// nested lists); called with the GIL held.
Mesh mesh_of_arrays(const py::object& vertices_object, const py::object& faces_object)
{
  const py::array vertices = py::array::ensure(vertices_object);
  const py::array faces = py::array::ensure(faces_object);
  if(!vertices || !faces)
    invalid("vertices and faces must be arrays (or nested sequences) of numbers");
  if(vertices.ndim() != 2 || vertices.shape(1) != 3)
    invalid("vertices must be an (n, 3) array of coordinates");
  if(faces.ndim() != 2 || faces.shape(1) != 4)
    invalid("faces must be an (m, 4) array of vertex indices (quads; -1 as the fourth of a triangle)");
  const char kind = faces.dtype().kind();
  if(kind != 'i' && kind != 'u')
    invalid("faces must be an array of integers, not of dtype kind '" + std::string(1, kind) + "'");
  const auto v = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(vertices);
  const auto f = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(faces);
  if(!v || !f)
    invalid("vertices must be numbers and faces integers");

  Mesh mesh;
  const auto vr = v.unchecked<2>();
  for(py::ssize_t i = 0; i < vr.shape(0); ++i)
    mesh.add_vertex(Kernel::Point_3(vr(i, 0), vr(i, 1), vr(i, 2)));
  const auto fr = f.unchecked<2>();
  for(py::ssize_t i = 0; i < fr.shape(0); ++i)
  {
    std::vector<Mesh::Vertex_index> corners;
    for(py::ssize_t j = 0; j < 4; ++j)
    {
      const std::int64_t index = fr(i, j);
      if(j == 3 && index == -1)
        break;  // a triangle
      if(index < 0 || index >= vr.shape(0))
        throw TS::Invalid_input("face " + std::to_string(i) + " refers to vertex " +
                                  std::to_string(index) + ", not in 0.." +
                                  std::to_string(vr.shape(0) - 1),
                                TS::Invalid_input::FACE, std::size_t(i));
      corners.push_back(Mesh::Vertex_index(Mesh::size_type(index)));
    }
    if(mesh.add_face(corners) == Mesh::null_face())
      throw TS::Invalid_input("face " + std::to_string(i) +
                                " cannot be added: a repeated vertex, or the surface is "
                                "non-manifold or inconsistently oriented there",
                              TS::Invalid_input::FACE, std::size_t(i));
  }
  return mesh;
}

// A numpy array of `values`, with the given shape.
template <typename T>
py::array_t<T> numpy_array(const std::vector<T>& values, const std::vector<py::ssize_t>& shape)
{
  py::array_t<T> a(shape);
  std::copy(values.begin(), values.end(), a.mutable_data());
  return a;
}

// The dictionary returned to Python; called with the GIL held.
py::dict result_dict(const Mesh& mesh, const TS::K_set_tilable_result& r)
{
  const TS::Tilability_measure& m = r.optimization.measure;
  // Vertices and faces are indexed as in the input arrays (nothing was removed).
  std::vector<double> points;
  for(Mesh::Vertex_index v : mesh.vertices())
    for(int c = 0; c < 3; ++c) points.push_back(mesh.point(v)[c]);
  std::vector<std::int32_t> cluster;
  std::vector<std::int8_t> orientation;
  const auto cluster_map = mesh.property_map<Mesh::Face_index, std::int32_t>("f:ts_cluster").first;
  const auto orientation_map = mesh.property_map<Mesh::Face_index, std::int8_t>("f:ts_orientation").first;
  for(Mesh::Face_index f : mesh.faces())
  {
    cluster.push_back(cluster_map[f]);
    orientation.push_back(orientation_map[f]);
  }
  // An S-triangle's fourth corner is NaN.
  std::vector<double> s_quads;
  std::vector<std::int64_t> tile_corners;
  for(const TS::Panel& q : m.s_quads)
  {
    tile_corners.push_back(q.size());
    for(int i = 0; i < 4; ++i)
      for(int c = 0; c < 3; ++c)
        s_quads.push_back(i < q.size() ? q[i][c] : std::numeric_limits<double>::quiet_NaN());
  }
  const py::ssize_t n = py::ssize_t(mesh.number_of_vertices()), f = py::ssize_t(cluster.size()),
                    k = py::ssize_t(m.s_quads.size());

  py::dict d;
  d["vertices"] = numpy_array(points, {n, 3});
  d["cluster"] = numpy_array(cluster, {f});
  d["orientation"] = numpy_array(orientation, {f});
  d["number_of_clusters"] = m.number_of_clusters;
  d["degree_of_flexibility"] = m.degree_of_flexibility;
  d["is_tilable"] = r.is_tilable();
  d["congruence_error"] = m.congruence_error;
  d["planarity_error"] = m.planarity_error;
  d["cluster_congruence_errors"] = numpy_array(m.cluster_congruence_errors, {k});
  d["cluster_sizes"] =
    numpy_array(std::vector<std::int64_t>(m.cluster_sizes.begin(), m.cluster_sizes.end()), {k});
  d["s_quads"] = numpy_array(s_quads, {k, 4, 3});
  d["tile_corners"] = numpy_array(tile_corners, {k});
  d["mean_edge_length"] = m.mean_edge_length;
  d["input_bbox_diagonal"] = m.input_bbox_diagonal;
  d["max_approximation_error"] = m.max_approximation_error;
  d["mean_approximation_error"] = m.mean_approximation_error;
  d["max_coverage_error"] = m.max_coverage_error;
  d["mean_coverage_error"] = m.mean_coverage_error;
  d["hausdorff_distance"] = m.hausdorff_distance;
  d["mean_symmetric_distance"] = m.mean_symmetric_distance;
  d["self_intersecting_face_pairs"] = m.self_intersecting_face_pairs;
  d["max_displacement"] = m.max_displacement;
  d["mean_displacement"] = m.mean_displacement;
  const TS::Energy_terms& e = m.normalized_terms;
  d["normalized_terms"] = py::dict(py::arg("distance") = e.distance, py::arg("fairness") = e.fairness,
                                   py::arg("edge_length") = e.edge_length,
                                   py::arg("diagonal") = e.diagonal, py::arg("volume") = e.volume);
  d["iterations"] = r.optimization.iterations;
  d["total_time"] = r.total_time;
  return d;
}

py::dict make_k_set_tilable(const py::object& vertices, const py::object& faces, const Options& o)
{
  if(o.k < 1)
    invalid("k must be at least 1, got " + std::to_string(o.k));
  if(o.threads < 0)
    invalid("threads must be >= 0 (0: all cores), got " + std::to_string(o.threads));
  const TS::Solver_type solver = solver_type(o.solver);
  const TS::Orientation_policy policy = orientation_policy(o.orientation_policy);
  Mesh mesh = mesh_of_arrays(vertices, faces);

  auto cluster = mesh.add_property_map<Mesh::Face_index, std::int32_t>("f:ts_cluster", 0).first;
  auto orientation = mesh.add_property_map<Mesh::Face_index, std::int8_t>("f:ts_orientation", 0).first;
  TS::K_set_tilable_result r;
  {
    py::gil_scoped_release release;
#ifdef CGAL_LINKED_WITH_TBB
    std::unique_ptr<tbb::global_control> threads;
    if(o.threads > 0)
      threads.reset(new tbb::global_control(tbb::global_control::max_allowed_parallelism,
                                            std::size_t(o.threads)));
#endif
    auto np = TSP::number_of_tiles(o.k)
                .face_cluster_map(cluster)
                .face_orientation_map(orientation)
                .random_seed(o.seed)
                .number_of_candidates(o.number_of_candidates)
                .similarity_threshold(o.similarity_threshold)
                .flexibility_penalty(o.flexibility_penalty)
                .orientation_policy(policy)
                .distance_weight(o.distance_weight)
                .fairness_weight(o.fairness_weight < 0 ? TS::default_fairness_weight(solver)
                                                       : o.fairness_weight)
                .solver(solver)
                .congruence_tolerance(o.congruence_tolerance)
                .planar_tiles(o.planar_tiles);
    r = o.iterations >= 0 ? TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(mesh, np.number_of_iterations(o.iterations))
                          : TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(mesh, np);
  }
  return result_dict(mesh, r);
}

} // namespace

PYBIND11_MODULE(tilable_surfaces, module)
{
  module.doc() = "K-set tilable surfaces (Fu, Lai, He, Cohen-Or 2010) on CGAL: the Python "
                 "binding of CGAL::Tilable_surfaces::make_k_set_tilable().";
  py::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const TS::Invalid_input& e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  module.def(
    "make_k_set_tilable",
    [](const py::object& vertices, const py::object& faces, int k, unsigned int seed,
       std::size_t number_of_candidates, double similarity_threshold, double flexibility_penalty,
       const std::string& orientation_policy, double distance_weight, double fairness_weight,
       const std::string& solver, int iterations, double congruence_tolerance, int threads,
       bool planar_tiles) {
      return make_k_set_tilable(vertices, faces,
                                Options{k, seed, number_of_candidates, similarity_threshold,
                                        flexibility_penalty, orientation_policy, distance_weight,
                                        fairness_weight, solver, iterations, congruence_tolerance,
                                        threads, planar_tiles});
    },
    py::arg("vertices"), py::arg("faces"), py::kw_only(), py::arg("k"), py::arg("seed") = Options().seed,
    py::arg("number_of_candidates") = Options().number_of_candidates,
    py::arg("similarity_threshold") = Options().similarity_threshold,
    py::arg("flexibility_penalty") = Options().flexibility_penalty,
    py::arg("orientation_policy") = Options().orientation_policy,
    py::arg("distance_weight") = Options().distance_weight,
    py::arg("fairness_weight") = Options().fairness_weight, py::arg("solver") = Options().solver,
    py::arg("iterations") = Options().iterations,
    py::arg("congruence_tolerance") = Options().congruence_tolerance,
    py::arg("threads") = Options().threads, py::arg("planar_tiles") = Options().planar_tiles,
    R"doc(Makes the quad mesh (vertices, faces) K-set tilable.

vertices: (n, 3) array of float64 coordinates; faces: (m, 4) array of integer vertex
indices, each quad counter-clockwise seen from outside, consistently oriented; a triangle
has -1 as its fourth index (it gets a tile of its own kind).

Keyword arguments (defaults of the C++ named parameters):
  k                     number of distinct tiles (S-quads), required, 1..m
  seed                  random seed of the clustering's k-means and splits (0)
  number_of_candidates  configurations kept while clustering (10)
  similarity_threshold  initial clustering threshold over the mean edge length (0.01)
  flexibility_penalty   weight of lost degrees of flexibility in the clustering score (0.5)
  orientation_policy    'proper_rigid_motions', 'no_turned_over_panels' or 'allow_mirrored_panels'
  distance_weight       mu1, closeness to the input (1e-4)
  fairness_weight       mu2 (< 0: the solver's default, 1e-6 for gauss-newton, 1e-4 for paper-cg)
  solver                'gauss-newton' (exact, default) or 'paper-cg' (the paper's conjugate gradient)
  iterations            maximum solver iterations (< 0: the solver's default, 300 or 5000)
  congruence_tolerance  congruence error below which the result is tilable (1e-6)
  threads               threads of the parallel loops (0: all cores); results do not depend on it
  planar_tiles          every panel planar as well as congruent (gauss-newton only) (False)

Returns a dict: 'vertices' (n, 3) moved positions, 'cluster' (m,) cluster of each face,
'orientation' (m,) orientation 0..7 of each face (template corner i is face vertex
(i + o) % n for o < 4, (o - 4 - i) % n for o >= 4, n = 4 or 3 corners), 's_quads' (K, 4, 3;
an S-triangle's fourth corner is NaN), 'tile_corners' (K,) 4 or 3, 'is_tilable',
'congruence_error', 'cluster_congruence_errors', 'cluster_sizes', 'degree_of_flexibility',
'number_of_clusters', 'mean_edge_length', 'planarity_error' (the largest distance between the
diagonals of a face over the mean edge length), 'input_bbox_diagonal', 'hausdorff_distance' and
'mean_symmetric_distance' (the distance between result and input both ways),
'max_approximation_error', 'mean_approximation_error' (result to input), 'max_coverage_error',
'mean_coverage_error' (input to result), all over the input's bounding-box diagonal,
'self_intersecting_face_pairs' (pairs of faces of the result that cross), 'max_displacement',
'mean_displacement', 'normalized_terms', 'iterations', 'total_time'.

Raises ValueError, with the package's message, for input that cannot be processed.
The computation releases the GIL.)doc");
}
