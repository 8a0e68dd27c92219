// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python class KSetTilableSurface (surface.h): the steps of the C++
// class K_set_tilable_surface, under the same names, on numpy arrays.

#include "surface.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace tilable_surfaces_python {
namespace {

typedef py::class_<Surface, std::unique_ptr<Surface> > Surface_class;

std::size_t non_negative(py::ssize_t value, const char* what)
{
  if(value < 0)
    invalid(std::string("no ") + what + " " + std::to_string(value) + " (they are numbered from 0)");
  return std::size_t(value);
}

const char* const class_doc = R"doc(A quad mesh on its way to a K-set tilable surface, one step at a time
(C++: CGAL::Tilable_surfaces::K_set_tilable_surface; user manual, section "Step by step").

    s = KSetTilableSurface(vertices, faces)     # checks the mesh once
    s.cluster(12)                               # the clustering, described
    s.merge_clusters(0, 1), s.split_cluster(3), s.retag_orientations()   # each: the new DOF
    s.optimize_closest()                        # or s.optimize(), s.refine_to(k)
    s.measure(), s.tile_catalog(), s.vertices(), s.face_clusters(), s.face_orientations()

vertices: (n, 3) float64; faces: (m, 4) integer vertex indices (-1 as the fourth of a
triangle). Every step starts from the input positions (input_vertices()); a solve moves
vertices(), restore_input() puts the input back. Edits are judged on the input quads.
Steps take the keyword options of the last cluster() unless given again. Bad input or a
step out of order raises ValueError with the package's message; the steps release the GIL,
and one object runs one step at a time (its progress callable cannot call it: ValueError).)doc";

const char* const clustering_doc =
  "The clustering as a dict: 'path' ('exact' or 'descriptor'), 'number_of_clusters', "
  "'cluster_sizes', 's_quads' (K, 4, 3; centred, the labelling the orientations refer to), "
  "'tile_corners', 'cluster_weights', 'total_weight', 'weights_are_exact', "
  "'degree_of_flexibility', 'number_of_initial_clusters', 'initial_threshold', 'candidates' "
  "(the pool of the last cluster(): dicts with 'origin', 'weight', 'degree_of_flexibility', "
  "'length_deviation', 'score', 'predicted_displacement', 'face_cluster'), 'chosen_candidate', "
  "'choice_reason', 'number_of_edit_rounds'.";

const char* const solve_doc =
  "Returns the optimization as a dict: 'is_tilable', 'ending', 'stopped_by_visitor', 'stalled', "
  "'iterations', 'objective', 'setup_time', 'solve_time', 'measure_time', and every key of "
  "measure().";

void define_clustering(Surface_class& c)
{
  c.def("cluster",
        [](Surface& s, int k, const py::kwargs& keywords) {
          return clustering_dict(s.start_clustering(k, keywords, "cluster", [&](const auto& np) {
            return TS::Clustering_result(s.core().cluster(np));
          }));
        },
        py::arg("k"),
        docstring(std::string("Clusters the faces into k S-quads (forgets the previous clustering and "
                              "result). ") + clustering_doc,
                  CLUSTERING | RUN)
          .c_str());
  c.def("initialize_clusters",
        [](Surface& s, int k, const py::kwargs& keywords) {
          return s.start_clustering(k, keywords, "initialize_clusters",
                                    [&](const auto& np) { return s.core().initialize_clusters(np); });
        },
        py::arg("k"),
        docstring("Stage 1 of cluster(): the threshold clustering; returns its number of clusters. Then "
                  "merge_to_tile_count(), add_other_candidates(), select_candidate().",
                  CLUSTERING | RUN)
          .c_str());
  c.def("merge_to_tile_count", [](Surface& s) { return s.locked([&] { return s.core().merge_to_tile_count(); }); },
        "Stage 2: the beam of merges down to K; returns the size of the candidate pool.");
  c.def("add_other_candidates", [](Surface& s) { return s.locked([&] { return s.core().add_other_candidates(); }); },
        "Stage 3: k-means, quad-strip, grid-segment and sweep candidates; returns the size of the pool.");
  c.def("select_candidate",
        [](Surface& s) { return clustering_dict(s.locked([&] { return s.core().select_candidate(); })); },
        docstring(std::string("Stage 4: the candidate of lowest score becomes the clustering. ") + clustering_doc)
          .c_str());
  c.def("clustering", [](Surface& s) { return clustering_dict(s.locked([&] { return s.core().clustering(); })); },
        docstring(std::string("The current clustering, brought up to date after an edit. ") + clustering_doc)
          .c_str());
}

void define_editing(Surface_class& c)
{
  c.def("merge_clusters",
        [](Surface& s, py::ssize_t a, py::ssize_t b) {
          const std::size_t first = non_negative(a, "cluster"), second = non_negative(b, "cluster");
          return s.locked([&] { return s.core().merge_clusters(first, second); });
        },
        py::arg("a"), py::arg("b"),
        "Merges clusters a and b into min(a, b) (the ids above max(a, b) decrease by one); returns the "
        "new degree of flexibility.");
  c.def("split_cluster",
        [](Surface& s, py::ssize_t id, unsigned int seed) {
          const std::size_t cluster = non_negative(id, "cluster");
          return s.locked([&] { return s.core().split_cluster(cluster, seed); });
        },
        py::arg("c"), py::arg("seed") = TS::defaults::random_seed,
        "Splits cluster c in two (the second part gets the id K); returns the new degree of flexibility.");
  c.def("retag_orientations", [](Surface& s) { return s.locked([&] { return s.core().retag_orientations(); }); },
        "Re-tags every face with the orientation that best matches its S-quad; returns the new degree of "
        "flexibility.");
  c.def("use_candidate",
        [](Surface& s, py::ssize_t i) {
          const std::size_t candidate = non_negative(i, "candidate");
          return s.locked([&] { return s.core().use_candidate(candidate); });
        },
        py::arg("i"),
        "Makes candidate i of clustering()['candidates'] the clustering; returns its degree of flexibility.");
  c.def("set_clustering", &Surface::set_clustering, py::arg("clusters"), py::arg("orientations"),
        py::arg("orientation_policy") = name_of(policy_names(), TS::defaults::orientation_policy),
        "Uses the clustering of the arrays (m,) of cluster ids 0..K-1 (all used) and orientations 0..7; "
        "returns its degree of flexibility.");
  c.def("degree_of_flexibility",
        [](Surface& s) { return s.locked([&] { return s.core().degree_of_flexibility(); }); },
        "The degree of flexibility of the current clustering (its edge-sharing graph's components).");
  c.def_property_readonly("number_of_clusters",
                          [](Surface& s) { return s.locked([&] { return s.core().number_of_clusters(); }); });
  c.def_property_readonly("is_clustered", [](Surface& s) { return s.locked([&] { return s.core().is_clustered(); }); });
  c.def_property_readonly("orientation_policy", [](Surface& s) {
    return name_of(policy_names(), s.locked([&] { return s.core().orientation_policy(); }));
  });
}

void define_optimization(Surface_class& c)
{
  const std::string solve_help = solve_doc;
  c.def("optimize",
        [](Surface& s, const py::kwargs& keywords) {
          const Options o = s.step_options(keywords, OPTIMIZATION | RUN, "optimize");
          return optimization_dict(
            s.run(o, [&](const auto& np) { return TS::Optimization_result(s.core().optimize(np)); }));
        },
        docstring("Moves the vertices from the input until every face fits its S-quad. " + solve_help,
                  OPTIMIZATION | RUN)
          .c_str());
  c.def("optimize_closest",
        [](Surface& s, const py::kwargs& keywords) {
          const Options o = s.step_options(keywords, OPTIMIZATION | SEARCH | RUN, "optimize_closest");
          return optimization_dict(
            s.run(o, [&](const auto& np) { return TS::Optimization_result(s.core().optimize_closest(np)); }));
        },
        docstring("The tilable result closest to the input among the candidate clusterings, then improved by "
         "split-and-merge rounds (what make_k_set_tilable() runs); the clustering becomes the winner's. " +
         solve_help, OPTIMIZATION | SEARCH | RUN)
          .c_str());
  c.def("refine_to",
        [](Surface& s, int k, const py::kwargs& keywords) {
          const Options o = s.step_options(keywords, OPTIMIZATION | RUN, "refine_to");
          const std::size_t tiles = tile_count(k);
          return optimization_dict(
            s.run(o, [&](const auto& np) { return TS::Optimization_result(s.core().refine_to(tiles, np)); }));
        },
        py::arg("k"),
        docstring("Splits the largest clusters until there are k, then optimizes (an exact result stays exact). " +
         solve_help, OPTIMIZATION | RUN)
          .c_str());
  c.def("predict_displacement",
        [](Surface& s, const py::kwargs& keywords) {
          const Options o = s.step_options(keywords, OPTIMIZATION | RUN, "predict_displacement");
          const TS::Displacement_prediction p =
            s.run(o, [&](const auto& np) { return s.core().predict_displacement(np); });
          return py::dict(py::arg("max") = p.max, py::arg("rms") = p.rms, py::arg("max_euclidean") = p.max_euclidean);
        },
        docstring("The displacement the default solver is predicted to need: 'max', 'rms' (closeness metric), "
         "'max_euclidean'.", OPTIMIZATION | RUN)
          .c_str());
  c.def("optimization",
        [](Surface& s) {
          return optimization_dict(s.locked([&] { return TS::Optimization_result(s.core().optimization()); }));
        },
        "The result of the last solve, as optimize() returns it.");
}

void define_results(Surface_class& c)
{
  c.def("measure", [](Surface& s) { return measure_dict(s.locked([&] { return s.core().measure(); })); },
        "Measures the current vertices against the input: congruence_error, hausdorff_distance, "
        "mean_symmetric_distance, self_intersecting_face_pairs, flattened_panels, "
        "number_of_distinct_molds, ... (the keys of make_k_set_tilable()'s measure).");
  c.def("tile_catalog", [](Surface& s) { return catalog_dict(s.locked([&] { return s.core().tile_catalog(); })); },
        "The tile catalog as columns, one row per S-quad: 'id' (cluster), 'mold' (congruent S-quads share "
        "one), 'instance_count', 'mirrored_count', 'worst_deviation' (mesh units), 'corners' (K, 4, 3) in a "
        "canonical frame (t0 at the origin, t1 on +x, t2 in the xy plane), 'tile_corners'.");
  c.def("vertices",
        [](Surface& s) {
          return points_array(s.locked([&] { return point_coordinates(s.mesh(), s.mesh().points()); }));
        },
        "(n, 3) current positions of the vertices.");
  c.def("input_vertices",
        [](Surface& s) {
          return points_array(s.locked([&] { return point_coordinates(s.mesh(), s.core().input_point_map()); }));
        },
        "(n, 3) input positions, against which every result is measured.");
  c.def("face_clusters",
        [](Surface& s) {
          return vector_array(
            s.locked([&] { return face_values<std::int32_t>(s.mesh(), s.core().face_cluster_map()); }));
        },
        "(m,) cluster of each face.");
  c.def("face_orientations",
        [](Surface& s) {
          return vector_array(
            s.locked([&] { return face_values<std::int8_t>(s.mesh(), s.core().face_orientation_map()); }));
        },
        "(m,) orientation 0..7 of each face relative to its cluster's S-quad.");
  c.def("restore_input", [](Surface& s) { s.locked([&] { s.core().restore_input(); }); },
        "Puts the input positions back.");
}

} // namespace

void define_surface(py::module_& module)
{
  Surface_class c(module, "KSetTilableSurface", docstring(class_doc).c_str());
  // Made with the GIL held: the object holds Python objects (its options).
  c.def(py::init([](const py::object& vertices, const py::object& faces) {
          return std::unique_ptr<Surface>(new Surface(mesh_of_arrays(vertices, faces)));
        }),
        py::arg("vertices"), py::arg("faces"));
  define_clustering(c);
  define_editing(c);
  define_optimization(c);
  define_results(c);
}

} // namespace tilable_surfaces_python
