// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module's conversions: numpy arrays to a mesh, and the package's
// result structures to dicts of numpy arrays. Every function here is called
// with the GIL held.

#ifndef TILABLE_SURFACES_PYTHON_ARRAYS_H
#define TILABLE_SURFACES_PYTHON_ARRAYS_H

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/candidate_generator.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tilable_surfaces_python {

namespace py = pybind11;
namespace TS = CGAL::Tilable_surfaces;
typedef CGAL::Simple_cartesian<double> Kernel;
typedef CGAL::Surface_mesh<Kernel::Point_3> Mesh;

[[noreturn]] inline void invalid(const std::string& message)
{
  throw TS::Invalid_input(message, TS::Invalid_input::PARAMETER);
}

// Corner `j` of face `i` of `faces` as a vertex of a mesh of `n` vertices;
// -1 as the fourth corner is a triangle (null vertex).
inline Mesh::Vertex_index face_corner(std::int64_t index, py::ssize_t i, py::ssize_t j, py::ssize_t n)
{
  if(j == 3 && index == -1)
    return Mesh::null_vertex();
  if(index < 0 || index >= n)
    throw TS::Invalid_input("face " + std::to_string(i) + " refers to vertex " + std::to_string(index) +
                              ", not in 0.." + std::to_string(n - 1),
                            TS::Invalid_input::FACE, std::size_t(i));
  return Mesh::Vertex_index(Mesh::size_type(index));
}

// The mesh of the arrays (or of anything numpy makes arrays of, such as
// nested lists).
inline Mesh mesh_of_arrays(const py::object& vertices_object, const py::object& faces_object)
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
      const Mesh::Vertex_index corner = face_corner(fr(i, j), i, j, vr.shape(0));
      if(corner != Mesh::null_vertex())
        corners.push_back(corner);
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

template <typename T>
py::array_t<T> vector_array(const std::vector<T>& values)
{
  return numpy_array(values, {py::ssize_t(values.size())});
}

// One field of every row, as a numpy array of T.
template <typename T, typename Row, typename Field>
py::array_t<T> column(const std::vector<Row>& rows, const Field& field)
{
  std::vector<T> values;
  for(const Row& r : rows) values.push_back(T(field(r)));
  return vector_array(values);
}

template <typename T>
py::array_t<std::int64_t> int64_array(const std::vector<T>& values)
{
  return column<std::int64_t>(values, [](T v) { return v; });
}

// d[key]: the (K, 4, 3) corners of the panels, the fourth corner of a
// triangle NaN; d["tile_corners"]: (K,) 4 or 3.
inline void add_panels(py::dict& d, const char* key, const std::vector<TS::Panel>& panels)
{
  std::vector<double> corners;
  for(const TS::Panel& q : panels)
    for(int i = 0; i < 4; ++i)
      for(int c = 0; c < 3; ++c)
        corners.push_back(i < q.size() ? q[i][c] : std::numeric_limits<double>::quiet_NaN());
  d[key] = numpy_array(corners, {py::ssize_t(panels.size()), 4, 3});
  d["tile_corners"] = column<std::int64_t>(panels, [](const TS::Panel& q) { return q.size(); });
}

// The coordinates of the vertices, in the order of the input arrays: an
// (n, 3) array once given to numpy_array().
template <typename PointMap>
std::vector<double> point_coordinates(const Mesh& mesh, const PointMap& points)
{
  std::vector<double> xyz;
  for(Mesh::Vertex_index v : mesh.vertices())
    for(int c = 0; c < 3; ++c) xyz.push_back(get(points, v)[c]);
  return xyz;
}

inline py::array_t<double> points_array(const std::vector<double>& xyz)
{
  return numpy_array(xyz, {py::ssize_t(xyz.size() / 3), 3});
}

// The values of a face map, in the order of the input arrays.
template <typename T, typename FaceMap>
std::vector<T> face_values(const Mesh& mesh, const FaceMap& map)
{
  std::vector<T> values;
  for(Mesh::Face_index f : mesh.faces()) values.push_back(T(get(map, f)));
  return values;
}

// Everything Tilability_measure holds, flat.
inline void add_measure(py::dict& d, const TS::Tilability_measure& m)
{
  d["number_of_clusters"] = m.number_of_clusters;
  d["degree_of_flexibility"] = m.degree_of_flexibility;
  d["congruence_error"] = m.congruence_error;
  d["cluster_congruence_errors"] = vector_array(m.cluster_congruence_errors);
  d["cluster_sizes"] = int64_array(m.cluster_sizes);
  d["allows_mirrored_panels"] = m.allows_mirrored_panels;
  d["cluster_mirrored_counts"] = int64_array(m.cluster_mirrored_counts);
  add_panels(d, "s_quads", m.s_quads);
  d["number_of_distinct_molds"] = m.number_of_distinct_molds;
  d["cluster_molds"] = int64_array(m.cluster_molds);
  d["planarity_error"] = m.planarity_error;
  d["requires_planar_tiles"] = m.requires_planar_tiles;
  d["mean_edge_length"] = m.mean_edge_length;
  d["input_bbox_diagonal"] = m.input_bbox_diagonal;
  d["input_mean_edge_length"] = m.input_mean_edge_length;
  d["max_approximation_error"] = m.max_approximation_error;
  d["mean_approximation_error"] = m.mean_approximation_error;
  d["max_coverage_error"] = m.max_coverage_error;
  d["mean_coverage_error"] = m.mean_coverage_error;
  d["hausdorff_distance"] = m.hausdorff_distance;
  d["mean_symmetric_distance"] = m.mean_symmetric_distance;
  d["self_intersecting_face_pairs"] = m.self_intersecting_face_pairs;
  d["flattened_panels"] = m.flattened_panels;
  d["max_displacement"] = m.max_displacement;
  d["mean_displacement"] = m.mean_displacement;
  d["panel_tolerance"] = m.panel_tolerance;
  d["panel_deviations"] = vector_array(m.panel_deviations);
  d["worst_panel_deviation"] = m.worst_panel_deviation;
  d["within_panel_tolerance"] = m.within_panel_tolerance();
  const TS::Energy_terms& e = m.normalized_terms;
  d["normalized_terms"] = py::dict(py::arg("distance") = e.distance, py::arg("fairness") = e.fairness,
                                   py::arg("edge_length") = e.edge_length,
                                   py::arg("diagonal") = e.diagonal, py::arg("volume") = e.volume);
  d["buildability_warnings"] = TS::buildability_warnings(m);
}

inline py::dict measure_dict(const TS::Tilability_measure& m)
{
  py::dict d;
  add_measure(d, m);
  return d;
}

// How a solve ended, and the measure of its result, flat.
inline py::dict optimization_dict(const TS::Optimization_result& r)
{
  py::dict d = measure_dict(r.measure);
  d["is_tilable"] = r.converged;
  d["ending"] = r.ending();
  d["stopped_by_visitor"] = r.stopped_by_visitor;
  d["stalled"] = r.stalled;
  d["iterations"] = r.iterations;
  d["objective"] = r.objective;
  d["setup_time"] = r.setup_time;
  d["solve_time"] = r.solve_time;
  d["measure_time"] = r.measure_time;
  return d;
}

inline py::dict candidate_dict(const TS::Clustering_candidate& c)
{
  py::dict d;
  d["origin"] = TS::internal::origin_traits(c.origin).name;
  d["weight"] = c.weight;
  d["degree_of_flexibility"] = c.degree_of_flexibility;
  d["length_deviation"] = c.length_deviation;
  d["score"] = c.score;
  d["predicted_displacement"] = c.predicted_displacement;
  d["face_cluster"] = int64_array(c.face_cluster);
  return d;
}

inline py::dict clustering_dict(const TS::Clustering_result& r)
{
  py::dict d;
  d["path"] = r.path == TS::DESCRIPTOR_PATH ? "descriptor" : "exact";
  d["number_of_clusters"] = r.cluster_sizes.size();
  d["cluster_sizes"] = int64_array(r.cluster_sizes);
  add_panels(d, "s_quads", r.s_quads);
  d["cluster_weights"] = vector_array(r.cluster_weights);
  d["total_weight"] = r.total_weight;
  d["weights_are_exact"] = r.weights_are_exact;
  d["degree_of_flexibility"] = r.degree_of_flexibility;
  d["number_of_initial_clusters"] = r.number_of_initial_clusters;
  d["initial_threshold"] = r.initial_threshold;
  py::list candidates;
  for(const TS::Clustering_candidate& c : r.candidates) candidates.append(candidate_dict(c));
  d["candidates"] = candidates;
  d["chosen_candidate"] = r.chosen_candidate;
  d["choice_reason"] = r.choice_reason;
  d["number_of_edit_rounds"] = r.number_of_edit_rounds;
  return d;
}

// The tile catalog, one row per S-quad, as columns.
inline py::dict catalog_dict(const std::vector<TS::Tile>& tiles)
{
  std::vector<TS::Panel> corners;
  for(const TS::Tile& t : tiles) corners.push_back(t.corners);
  py::dict d;
  d["id"] = column<std::int64_t>(tiles, [](const TS::Tile& t) { return t.id; });
  d["mold"] = column<std::int64_t>(tiles, [](const TS::Tile& t) { return t.mold; });
  d["instance_count"] = column<std::int64_t>(tiles, [](const TS::Tile& t) { return t.instance_count; });
  d["mirrored_count"] = column<std::int64_t>(tiles, [](const TS::Tile& t) { return t.mirrored_count; });
  d["worst_deviation"] = column<double>(tiles, [](const TS::Tile& t) { return t.worst_deviation; });
  add_panels(d, "corners", corners);
  return d;
}

// The K tried (deviation search or curve), one row per K, as columns.
inline py::dict trials_dict(const std::vector<TS::Tile_count_trial>& trials)
{
  typedef TS::Tile_count_trial T;
  py::dict d;
  d["K"] = column<std::int64_t>(trials, [](const T& t) { return t.number_of_tiles; });
  d["degree_of_flexibility"] = column<std::int64_t>(trials, [](const T& t) { return t.degree_of_flexibility; });
  d["congruence_error"] = column<double>(trials, [](const T& t) { return t.congruence_error; });
  d["hausdorff_distance"] = column<double>(trials, [](const T& t) { return t.hausdorff_distance; });
  d["max_displacement"] = column<double>(trials, [](const T& t) { return t.max_displacement; });
  d["seconds"] = column<double>(trials, [](const T& t) { return t.seconds; });
  d["is_tilable"] = column<bool>(trials, [](const T& t) { return t.is_tilable; });
  d["self_intersecting_face_pairs"] =
    column<std::int64_t>(trials, [](const T& t) { return t.self_intersecting_face_pairs; });
  d["refined_from"] = column<std::int64_t>(trials, [](const T& t) { return t.refined_from; });
  return d;
}

} // namespace tilable_surfaces_python

#endif // TILABLE_SURFACES_PYTHON_ARRAYS_H
