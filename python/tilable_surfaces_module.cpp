// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python module `tilable_surfaces`, numpy in and numpy out:
//
//   import numpy as np, tilable_surfaces as ts
//   r = ts.make_k_set_tilable(V, F, k=20, seed=7)       # one call; or max_deviation=0.05 instead of k
//   r["vertices"], r["cluster"], r["orientation"], r["congruence_error"], r["catalog"], r["trials"], ...
//   c = ts.curve(V, F, 4, 24, 4)                        # columns K, hausdorff_distance, ... per K
//
//   s = ts.KSetTilableSurface(V, F)                     # the stateful core, step by step
//   s.cluster(12)                                       # -> the clustering: sizes, DOF, candidates, reason
//   s.merge_clusters(0, 1); s.split_cluster(3); s.retag_orientations()   # -> the new DOF
//   s.optimize_closest(progress=callback)               # or optimize(), refine_to(k)
//   s.measure(); s.tile_catalog(); s.vertices(); s.face_clusters(); s.restore_input()
//
// Keyword arguments are the named parameters of the C++ functions, with the
// package's defaults (options.h). `progress` is a callable that receives
// ('phase', name, seconds) and ('iteration', i, congruence_error, objective)
// and may return False to stop the solvers. Bad input raises ValueError with
// the package's Invalid_input message. The computation runs without the GIL;
// the progress callable is called with it.

#include "surface.h"

#include <CGAL/Tilable_surfaces/k_set_tilable_curve.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tilable_surfaces_python {
namespace {

// What make_k_set_tilable() returns: the result's arrays, its optimization
// and measure (flat), its tile catalog and the K tried.
py::dict pipeline_dict(const Mesh& mesh, const TS::K_set_tilable_result& r)
{
  py::dict d = optimization_dict(r.optimization);
  d["vertices"] = points_array(point_coordinates(mesh, mesh.points()));
  d["cluster"] = vector_array(
    face_values<std::int32_t>(mesh, mesh.property_map<Mesh::Face_index, std::int32_t>("f:ts_cluster").first));
  d["orientation"] = vector_array(
    face_values<std::int8_t>(mesh, mesh.property_map<Mesh::Face_index, std::int8_t>("f:ts_orientation").first));
  d["choice_reason"] = r.clustering.choice_reason;
  d["catalog"] = catalog_dict(r.tiles);
  d["trials"] = trials_dict(r.trials);
  d["validation_time"] = r.validation_time;
  d["clustering_time"] = r.clustering_time;
  d["total_time"] = r.total_time;
  return d;
}

py::dict make_k_set_tilable(const py::object& vertices, const py::object& faces, const py::kwargs& keywords)
{
  Options o;
  read_options(o, keywords, TILE_COUNT | PIPELINE, "make_k_set_tilable");
  const bool budget = o.max_deviation >= 0;
  if(o.k < (budget ? 0 : 1))
    invalid("k must be at least 1 (or 0 with max_deviation), got " + std::to_string(o.k));
  Mesh mesh = mesh_of_arrays(vertices, faces);
  const auto cluster = mesh.add_property_map<Mesh::Face_index, std::int32_t>("f:ts_cluster", 0).first;
  const auto orientation = mesh.add_property_map<Mesh::Face_index, std::int8_t>("f:ts_orientation", 0).first;
  const int largest_k = o.k > 0 ? o.k : int(mesh.number_of_faces());
  const TS::K_set_tilable_result r = run_without_gil(o, mesh.number_of_faces(), nullptr, [&](const auto& np) {
    const auto with_maps = np.face_cluster_map(cluster).face_orientation_map(orientation);
    return budget ? TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(
                      mesh, with_maps.max_deviation(o.max_deviation).number_of_tiles(largest_k))
                  : TS::make_k_set_tilable<CGAL::Parallel_if_available_tag>(mesh, with_maps.number_of_tiles(o.k));
  });
  return pipeline_dict(mesh, r);
}

py::dict curve(const py::object& vertices, const py::object& faces, int kmin, int kmax, int step,
               const py::kwargs& keywords)
{
  Options o;
  read_options(o, keywords, PIPELINE, "curve");
  if(kmin < 1 || kmax < kmin || step < 1)
    invalid("curve needs 1 <= kmin <= kmax and step >= 1, got kmin = " + std::to_string(kmin) +
            ", kmax = " + std::to_string(kmax) + ", step = " + std::to_string(step));
  Mesh mesh = mesh_of_arrays(vertices, faces);
  std::vector<std::size_t> tile_counts;
  for(int k = kmin; k <= kmax; k += step) tile_counts.push_back(std::size_t(k));
  return trials_dict(run_without_gil(o, mesh.number_of_faces(), nullptr, [&](const auto& np) {
    return TS::k_set_tilable_curve<CGAL::Parallel_if_available_tag>(mesh, tile_counts, np);
  }));
}


const char* const pipeline_doc = R"doc(

Arguments: vertices, an (n, 3) array of float64 coordinates; faces, an (m, 4) array of
integer vertex indices, each quad counter-clockwise seen from outside, consistently
oriented; a triangle has -1 as its fourth index (it gets a tile of its own kind).
Orientation o of a face puts template corner i on face vertex (i + o) % c for o < 4,
(o - 4 - i) % c otherwise (c = 4 or 3 corners). Raises ValueError, with the package's
message, for input that cannot be processed. The computation releases the GIL.
)doc";

const char* const measure_doc =
  "'number_of_clusters', 'degree_of_flexibility', 'congruence_error' (over the mean edge length), "
  "'cluster_congruence_errors', 'cluster_sizes', 's_quads' (K, 4, 3; an S-triangle's fourth corner "
  "is NaN), 'tile_corners' (K,) 4 or 3, 'number_of_distinct_molds', 'cluster_molds', "
  "'allows_mirrored_panels', 'cluster_mirrored_counts', 'planarity_error', 'requires_planar_tiles', "
  "'mean_edge_length', 'input_bbox_diagonal', 'input_mean_edge_length', 'hausdorff_distance' and "
  "'mean_symmetric_distance' (both ways), 'max_approximation_error', 'mean_approximation_error' "
  "(result to input), 'max_coverage_error', 'mean_coverage_error' (input to result), all over the "
  "input's bounding-box diagonal, 'self_intersecting_face_pairs', 'flattened_panels', "
  "'max_displacement', 'mean_displacement' (mesh units), 'panel_tolerance', 'panel_deviations' (m,) "
  "(each face's largest corner distance from its mold after the best rigid fit), "
  "'worst_panel_deviation' (mesh units), 'within_panel_tolerance' (False at T = 0), 'normalized_terms', "
  "'buildability_warnings' (list of sentences)";

const char* const optimization_doc =
  "'is_tilable', 'ending' ('tilable', 'stopped by the visitor', 'stalled' or 'iteration limit'), "
  "'stopped_by_visitor', 'stalled', 'iterations', 'objective', 'setup_time', 'solve_time', "
  "'measure_time', and the measure: ";

const char* const trials_doc =
  "columns, one row per K: 'K', 'degree_of_flexibility', 'congruence_error', 'hausdorff_distance' "
  "(over the bounding-box diagonal), 'max_displacement', 'seconds', 'is_tilable', "
  "'self_intersecting_face_pairs', 'refined_from' (the smaller K whose result was refined to this "
  "K, 0 if its own)";

void define_functions(py::module_& module)
{
  const std::string make_doc =
    std::string("Makes the quad mesh (vertices, faces) K-set tilable: at K = k, or at the smallest K "
                "within max_deviation.") +
    pipeline_doc +
    "\nReturns a dict: 'vertices' (n, 3) moved positions, 'cluster' (m,) and 'orientation' (m,) of "
    "each face, 'catalog' (as KSetTilableSurface.tile_catalog()), 'trials' (with max_deviation, every "
    "K tried: " + trials_doc + "), 'choice_reason', 'validation_time', 'clustering_time', 'total_time', " +
    optimization_doc + measure_doc + ".";
  module.def("make_k_set_tilable", &make_k_set_tilable, py::arg("vertices"), py::arg("faces"),
             docstring(make_doc, TILE_COUNT | PIPELINE).c_str());

  const std::string curve_doc =
    std::string("The K / deviation curve: make_k_set_tilable() at K = kmin, kmin + step, ..., kmax; more "
                "molds never end farther than fewer (a better result of a smaller K is refined to K).") +
    pipeline_doc + "\nReturns a dict of " + trials_doc +
    "; a progress callable that stops a solve ends the curve there.";
  module.def("curve", &curve, py::arg("vertices"), py::arg("faces"), py::arg("kmin"), py::arg("kmax"),
             py::arg("step") = 1, docstring(curve_doc, PIPELINE).c_str());
}

} // namespace

void define_surface(py::module_& module);

} // namespace tilable_surfaces_python

PYBIND11_MODULE(tilable_surfaces, module)
{
  namespace tsp = tilable_surfaces_python;
  module.doc() = "K-set tilable surfaces (Fu, Lai, He, Cohen-Or 2010) on CGAL: the Python binding of "
                 "CGAL::Tilable_surfaces: make_k_set_tilable(), curve() and the step-by-step "
                 "KSetTilableSurface.";
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try
    {
      if(p) std::rethrow_exception(p);
    }
    catch(const tsp::TS::Invalid_input& e)
    {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  tsp::define_functions(module);
  tsp::define_surface(module);
}
