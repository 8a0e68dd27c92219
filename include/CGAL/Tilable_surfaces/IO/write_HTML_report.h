// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_H

/// \file write_HTML_report.h
/// One self-contained HTML file that a design team opens in a browser,
/// offline: the result in 3D (by tile or by deviation, the input as a ghost,
/// a click on a panel tells its tile, mold, instances and deviation), the
/// mold sheets (`mold_sheet.h`) with a button that shows each tile's
/// instances on the surface, the summary and parameters of the JSON report,
/// and the K / deviation curve of a deviation search; and the page of a
/// curve alone (`k_set_tilable_curve()`).

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/IO/cluster_colors.h>
#include <CGAL/Tilable_surfaces/IO/mold_sheet.h>
#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/internal/IO/html_report_viewer.h>
#include <CGAL/Tilable_surfaces/named_parameters.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>
#include <CGAL/Tilable_surfaces/validation.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/iterator.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <ostream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// The JavaScript that the HTML report embeds for its 3D view: three.js's
/// ES module (`build/three.module.min.js` of the npm package `three`) and
/// its `examples/jsm/controls/OrbitControls.js`. Empty texts give a report
/// without the 3D view (the catalog, summary and curve stay).
struct HTML_viewer_scripts
{
  std::string three_module;   ///< the text of three.module.min.js
  std::string orbit_controls; ///< the text of OrbitControls.js
};

namespace internal {

// `text` with every "</script" written "<\/script", so that it cannot end the
// <script> element it is embedded in (the same text in JSON strings and in
// JavaScript strings, comments and regular expressions).
CGAL_TILABLE_SURFACES_INLINE
std::string script_safe(std::string text);

// `text` as HTML text or attribute value.
CGAL_TILABLE_SURFACES_INLINE
std::string html_escaped(const std::string& text);

// The bytes of `values` in base64 (host byte order, little-endian on the
// platforms whose browsers read them: JavaScript's typed arrays use it too).
template <typename T>
std::string base64(const std::vector<T>& values)
{
  static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  if(!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  std::string s;
  s.reserve((bytes.size() + 2) / 3 * 4);
  for(std::size_t i = 0; i < bytes.size(); i += 3)
  {
    const std::size_t left = bytes.size() - i;
    const std::uint32_t word = std::uint32_t(bytes[i]) << 16 | (left > 1 ? std::uint32_t(bytes[i + 1]) << 8 : 0u) |
                               (left > 2 ? std::uint32_t(bytes[i + 2]) : 0u);
    for(int k = 0; k < 4; ++k)
      s += k <= int(left) ? alphabet[(word >> (18 - 6 * k)) & 63] : '=';
  }
  return s;
}

// The result and the input as the viewer draws them: the points of both
// (same vertices, same faces), the faces' corners in their own order, and
// per face its cluster and orientation.
struct Viewer_mesh
{
  std::vector<Eigen::Vector3d> points, input_points;
  std::vector<std::uint32_t> face_vertices, clusters;
  std::vector<std::uint8_t> face_sizes, orientations;
};

template <typename PolygonMesh, typename ResultPoints, typename InputPoints, typename ClusterMap,
          typename OrientationMap>
Viewer_mesh viewer_mesh(const PolygonMesh& result, const PolygonMesh& input, const ResultPoints& result_points,
                        const InputPoints& input_points, const ClusterMap& clusters,
                        const OrientationMap& orientations)
{
  typedef typename boost::graph_traits<PolygonMesh>::vertex_descriptor vertex_descriptor;
  if(num_vertices(result) != num_vertices(input) || num_faces(result) != num_faces(input))
    throw Invalid_input("the input mesh of the HTML report does not have the result's vertices and faces");
  Viewer_mesh m;
  std::unordered_map<vertex_descriptor, std::uint32_t> index, input_index;
  for(vertex_descriptor v : vertices(result))
  {
    index.emplace(v, std::uint32_t(m.points.size()));
    m.points.push_back(Tilable_surfaces::internal::to_eigen(get(result_points, v)));
  }
  for(vertex_descriptor v : vertices(input))
  {
    input_index.emplace(v, std::uint32_t(m.input_points.size()));
    m.input_points.push_back(Tilable_surfaces::internal::to_eigen(get(input_points, v)));
  }
  auto input_face = faces(input).begin();
  for(auto f : faces(result))
  {
    auto w = CGAL::vertices_around_face(halfedge(*input_face++, input), input).begin();
    m.face_sizes.push_back(std::uint8_t(CGAL::vertices_around_face(halfedge(f, result), result).size()));
    for(vertex_descriptor v : CGAL::vertices_around_face(halfedge(f, result), result))
    {
      if(input_index.at(*w++) != index.at(v))
        throw Invalid_input("the input mesh of the HTML report does not have the result's faces", Invalid_input::FACE);
      m.face_vertices.push_back(index.at(v));
    }
    m.clusters.push_back(std::uint32_t(cluster_index(get(clusters, f))));
    m.orientations.push_back(std::uint8_t(int(get(orientations, f))));
  }
  return m;
}

// Per vertex of the result, its distance to the input surface (each face the
// fan of triangles around its vertex centroid, as the measurement takes it).
CGAL_TILABLE_SURFACES_INLINE
std::vector<float> distances_to_input(const Viewer_mesh& m);

// The coordinates of `points` as floats, x y z per point.
CGAL_TILABLE_SURFACES_INLINE
std::vector<float> coordinates(const std::vector<Eigen::Vector3d>& points);

// The #mesh-data of the page: the arrays in base64, the colours by tile.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json viewer_data_json(const Viewer_mesh& m, double bbox_diagonal);

// The value at `pointer` of `report` as text: a number with `digits`
// significant digits (times `scale`, followed by `unit`), or "-" if absent.
CGAL_TILABLE_SURFACES_INLINE
std::string report_value(const nlohmann::json& report, const std::string& pointer, int digits = 4,
                         double scale = 1, const std::string& unit = "");

// The summary table of the report: what a team asks first.
CGAL_TILABLE_SURFACES_INLINE
std::string summary_html(const nlohmann::json& report);

// The K tried as an SVG plot: Hausdorff distance (% of the diagonal) against
// K, filled dots where the result is buildable, and the budget if any.
CGAL_TILABLE_SURFACES_INLINE
std::string curve_svg(std::vector<Tile_count_trial> trials, double budget);

// The catalog: per tile with instances its mold sheet, its counts, and a
// button that shows its instances on the surface.
CGAL_TILABLE_SURFACES_INLINE
std::string catalog_html(const std::vector<Tile>& tiles);

// `value` as a <script> element of type `type` with id `id`.
inline std::string script_element(const char* type, const char* id, const std::string& value)
{
  return std::string("<script type=\"") + type + "\" id=\"" + id + "\">" + script_safe(value) + "</script>\n";
}

// The page around the sections and the scripts after them.
inline std::string html_page(const std::string& title, const std::string& body, const std::string& scripts)
{
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + html_escaped(title) +
         "</title>\n<style>" + Tilable_surfaces::internal::html_report_style() + "</style>\n</head>\n<body>\n" + body +
         scripts + "</body>\n</html>\n";
}

// The embedded data and scripts of the report with the 3D view.
CGAL_TILABLE_SURFACES_INLINE
std::string viewer_scripts_html(const nlohmann::json& report, const nlohmann::json& viewer_data,
                                const HTML_viewer_scripts& scripts);

// The input file the report names (`input/file`), or `otherwise`.
CGAL_TILABLE_SURFACES_INLINE
std::string report_file(const nlohmann::json& report, const std::string& otherwise);

// The K tried as a plot and its legend.
inline std::string curve_section(const std::vector<Tile_count_trial>& trials, double budget)
{
  return "<section id=\"curve\">\n<h2>K / deviation: the K tried</h2>\n" + curve_svg(trials, budget) +
         "<p>Filled: tilable and not crossing itself; dashed: the deviation budget. A dot's tooltip gives its K "
         "and distance.</p>\n</section>\n";
}

// The K tried as a table, in the order tried.
CGAL_TILABLE_SURFACES_INLINE
std::string trials_table_html(const std::vector<Tile_count_trial>& trials);

// The 3D view and its controls.
CGAL_TILABLE_SURFACES_INLINE
std::string viewer_html();

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// Writes the HTML report of the result `pm` of `r`, made from `input` (the
/// mesh before `make_k_set_tilable()` moved it: the same vertices and faces,
/// in the same order). `report` is the JSON report
/// (`tilability_report_json()` and what the caller added, such as
/// `parameters`); it is embedded whole and its summary shown. The tiles and
/// the curve (`K_set_tilable_result::trials`, with the budget
/// `report["parameters"]["max_deviation"]` if it is a number) come from `r`.
/// The page needs no network: the data are embedded (coordinates as base64
/// float32), and so is `scripts`. The same arguments give the same bytes.
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{face_cluster_map} cluster ids 0..K-1 of the faces of `pm` (required) \cgalParamNEnd
///   \cgalParamNBegin{face_orientation_map} orientations 0..7 (required) \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map} the points of `pm` \cgalParamNEnd
/// \cgalNamedParamsEnd
/// \returns whether the stream is good after writing.
/// \throws Invalid_input if `input` does not have the vertices and faces of
/// `pm`, or a face has a negative cluster; nothing is written then.
template <typename PolygonMesh, typename CGAL_NP_TEMPLATE_PARAMETERS>
bool write_HTML_report(std::ostream& os, const PolygonMesh& pm, const PolygonMesh& input,
                       const K_set_tilable_result& r, const nlohmann::json& report,
                       const HTML_viewer_scripts& scripts, const CGAL_NP_CLASS& np = parameters::default_values())
{
  using parameters::get_parameter;
  const internal::Viewer_mesh mesh = internal::viewer_mesh(
    pm, input, Tilable_surfaces::internal::const_vertex_point_map(pm, np), get_const_property_map(CGAL::vertex_point, input),
    get_parameter(np, internal_np::face_cluster), get_parameter(np, internal_np::face_orientation));
  const Tilability_measure& m = r.optimization.measure;
  const nlohmann::json::json_pointer budget_at("/parameters/max_deviation");
  const double budget = report.contains(budget_at) && report.at(budget_at).is_number() ? report.at(budget_at).get<double>() : 0;
  const std::string file = internal::report_file(report, "the result");
  std::string body = "<header>\n<h1>" + internal::html_escaped(std::filesystem::path(file).filename().string()) + ": " + std::to_string(m.number_of_clusters) +
                     "-set tilable, " + std::to_string(m.number_of_distinct_molds) + " distinct molds</h1>\n<p>" +
                     std::to_string(mesh.face_sizes.size()) + " panels. <a href=\"#summary\">Summary</a> &middot; " +
                     (r.trials.empty() ? "" : "<a href=\"#curve\">K / deviation</a> &middot; ") +
                     "<a href=\"#catalog\">Molds</a></p>\n</header>\n" + internal::viewer_html();
  body += "<section id=\"summary\">\n<h2>Summary</h2>\n" + internal::summary_html(report) + "</section>\n";
  if(!r.trials.empty())
    body += internal::curve_section(r.trials, budget);
  body += "<section id=\"catalog\">\n<h2>Molds: " + std::to_string(m.number_of_clusters) + " tiles</h2>\n" +
          internal::catalog_html(r.tiles) + "</section>\n";
  os << internal::html_page(file + ", K = " + std::to_string(m.number_of_clusters), body,
                            internal::viewer_scripts_html(report, internal::viewer_data_json(mesh, m.input_bbox_diagonal),
                                                          scripts));
  return bool(os);
}

/// \ingroup PkgTilableSurfacesRef
/// Writes the HTML page of a K / deviation curve (`k_set_tilable_curve()`,
/// or the K tried by a deviation search): the plot, the table of every K
/// tried in the given order, and `report` embedded (`id="report-data"`; its
/// `input/file`, if any, names the page). Self-contained, without a 3D view
/// and so without three.js. The same arguments give the same bytes.
/// \returns whether the stream is good after writing.
CGAL_TILABLE_SURFACES_INLINE
bool write_HTML_curve_report(std::ostream& os, const std::vector<Tile_count_trial>& trials,
                             const nlohmann::json& report = nlohmann::json::object());

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/write_HTML_report_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_H
