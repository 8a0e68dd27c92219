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
inline std::string script_safe(std::string text)
{
  for(std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 1))
  {
    std::string next = text.substr(at + 2, 6);
    for(char& c : next) c = char(std::tolower(static_cast<unsigned char>(c)));
    if(next == "script")
      text.insert(at + 1, "\\");
  }
  return text;
}

// `text` as HTML text or attribute value.
inline std::string html_escaped(const std::string& text)
{
  std::string s;
  for(char c : text)
    switch(c)
    {
      case '&': s += "&amp;"; break;
      case '<': s += "&lt;"; break;
      case '>': s += "&gt;"; break;
      case '"': s += "&quot;"; break;
      default: s += c;
    }
  return s;
}

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
inline std::vector<float> distances_to_input(const Viewer_mesh& m)
{
  typedef CGAL::Simple_cartesian<double> K;
  typedef std::vector<K::Triangle_3>::const_iterator Iterator;
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator> > > Tree;
  auto point = [](const Eigen::Vector3d& p) { return K::Point_3(p.x(), p.y(), p.z()); };
  std::vector<K::Triangle_3> fan;
  for(std::size_t f = 0, first = 0; f < m.face_sizes.size(); first += m.face_sizes[f++])
  {
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for(std::size_t k = 0; k < m.face_sizes[f]; ++k) centre += m.input_points[m.face_vertices[first + k]] / m.face_sizes[f];
    for(std::size_t k = 0; k < m.face_sizes[f]; ++k)
      fan.emplace_back(point(m.input_points[m.face_vertices[first + k]]),
                       point(m.input_points[m.face_vertices[first + (k + 1) % m.face_sizes[f]]]), point(centre));
  }
  std::vector<float> d(m.points.size(), 0.0f);
  if(fan.empty()) return d;
  Tree tree(fan.begin(), fan.end());
  tree.accelerate_distance_queries();
  for(std::size_t v = 0; v < m.points.size(); ++v)
    d[v] = float(std::sqrt(tree.squared_distance(point(m.points[v]))));
  return d;
}

// The coordinates of `points` as floats, x y z per point.
inline std::vector<float> coordinates(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<float> c;
  for(const Eigen::Vector3d& p : points)
    for(int a = 0; a < 3; ++a) c.push_back(float(p[a]));
  return c;
}

// The #mesh-data of the page: the arrays in base64, the colours by tile.
inline nlohmann::json viewer_data_json(const Viewer_mesh& m, double bbox_diagonal)
{
  std::size_t tiles = 0;
  for(std::uint32_t c : m.clusters) tiles = (std::max)(tiles, std::size_t(c) + 1);
  nlohmann::json colors = nlohmann::json::array();
  for(const CGAL::IO::Color& c : cluster_colors(tiles))
  {
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", unsigned(c.red()), unsigned(c.green()), unsigned(c.blue()));
    colors.push_back(hex);
  }
  return {{"positions", base64(coordinates(m.points))},
          {"input_positions", base64(coordinates(m.input_points))},
          {"face_vertices", base64(m.face_vertices)},
          {"face_sizes", base64(m.face_sizes)},
          {"clusters", base64(m.clusters)},
          {"orientations", base64(m.orientations)},
          {"deviation", base64(distances_to_input(m))},
          {"bbox_diagonal", bbox_diagonal},
          {"colors", colors}};
}

// The value at `pointer` of `report` as text: a number with `digits`
// significant digits (times `scale`, followed by `unit`), or "-" if absent.
inline std::string report_value(const nlohmann::json& report, const std::string& pointer, int digits = 4,
                                double scale = 1, const std::string& unit = "")
{
  const nlohmann::json::json_pointer p(pointer);
  if(!report.contains(p) || report.at(p).is_null()) return "-";
  const nlohmann::json& v = report.at(p);
  if(v.is_number_float()) return number(scale * v.get<double>(), digits) + unit;
  return html_escaped(v.is_string() ? v.get<std::string>() : v.dump()) + unit;
}

// The summary table of the report: what a team asks first.
inline std::string summary_html(const nlohmann::json& report)
{
  const std::vector<std::pair<std::string, std::string> > rows{
    {"K (tiles)", report_value(report, "/K")},
    {"distinct molds", report_value(report, "/distinct_molds")},
    {"tilable", report_value(report, "/tilable")},
    {"congruence error (certificate)", report_value(report, "/congruence_error/worst", 3) + " mean edge lengths, tolerance " +
                                         report_value(report, "/congruence_error/tolerance", 3)},
    {"Hausdorff distance to the input, max", report_value(report, "/fidelity/hausdorff/max", 4, 100, "% of the diagonal")},
    {"Hausdorff distance to the input, mean", report_value(report, "/fidelity/hausdorff/mean", 4, 100, "% of the diagonal")},
    {"largest displacement", report_value(report, "/displacement/max") + " model units"},
    {"crossing panel pairs", report_value(report, "/fidelity/self_intersecting_face_pairs")},
    {"flattened panels", report_value(report, "/buildability/flattened_panels")},
    {"mirrored panels allowed", report_value(report, "/mirrored_panels/allowed")},
    {"degree of flexibility", report_value(report, "/degree_of_flexibility")},
    {"clustering", report_value(report, "/clustering/choice")},
    {"solver ending", report_value(report, "/optimization/ending")},
    {"time", report_value(report, "/time_seconds/total", 3, 1, " s")}};
  std::string s = "<table id=\"summary-table\">\n";
  for(const auto& row : rows)
    s += "<tr><th>" + row.first + "</th><td>" + row.second + "</td></tr>\n";
  s += "</table>\n";
  if(report.contains("buildability") && report["buildability"].contains("warnings"))
    for(const nlohmann::json& w : report["buildability"]["warnings"])
      s += "<p class=\"warning\">Warning: " + html_escaped(w.get<std::string>()) + "</p>\n";
  if(report.contains("parameters") && report["parameters"].is_object())
  {
    s += "<h3>Parameters</h3>\n<table id=\"parameters\">\n";
    for(const auto& item : report["parameters"].items())
      s += "<tr><th>" + html_escaped(item.key()) + "</th><td>" + html_escaped(item.value().dump()) + "</td></tr>\n";
    s += "</table>\n";
  }
  return s;
}

// The K tried as an SVG plot: Hausdorff distance (% of the diagonal) against
// K, filled dots where the result is buildable, and the budget if any.
inline std::string curve_svg(std::vector<Tile_count_trial> trials, double budget)
{
  const double width = 600, height = 300, left = 60, bottom = 40, pad = 20;
  std::sort(trials.begin(), trials.end(), [](const Tile_count_trial& a, const Tile_count_trial& b) {
    return a.number_of_tiles < b.number_of_tiles; });
  double k_max = double(trials.back().number_of_tiles), k_min = double(trials.front().number_of_tiles);
  double d_max = budget > 0 ? budget : 0;
  for(const Tile_count_trial& t : trials) d_max = (std::max)(d_max, t.hausdorff_distance);
  if(k_max == k_min) { k_min -= 1; k_max += 1; }
  if(!(d_max > 0)) d_max = 1;
  auto x = [&](double k) { return left + (k - k_min) / (k_max - k_min) * (width - left - pad); };
  auto y = [&](double d) { return height - bottom - d / d_max * (height - bottom - pad); };
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 600 300\" font-size=\"12\">\n"
                  "<path d=\"M60 20 V260 H580\" fill=\"none\" stroke=\"#000\"/>\n";
  s += "<text x=\"320\" y=\"292\" text-anchor=\"middle\">K (tiles): " + number(k_min, 6) + " to " + number(k_max, 6) +
       "</text>\n<text x=\"14\" y=\"150\" transform=\"rotate(-90 14 150)\" text-anchor=\"middle\">Hausdorff distance, "
       "% of the diagonal (0 to " + number(100 * d_max, 3) + ")</text>\n<polyline fill=\"none\" stroke=\"#456\" points=\"";
  for(const Tile_count_trial& t : trials)
    s += number(x(double(t.number_of_tiles)), 6) + "," + number(y(t.hausdorff_distance), 6) + " ";
  s += "\"/>\n";
  if(budget > 0)
    s += "<line x1=\"60\" x2=\"580\" y1=\"" + number(y(budget), 6) + "\" y2=\"" + number(y(budget), 6) +
         "\" stroke=\"#c22\" stroke-dasharray=\"6\"/>\n";
  for(const Tile_count_trial& t : trials)
    s += "<circle class=\"trial\" data-k=\"" + std::to_string(t.number_of_tiles) + "\" cx=\"" +
         number(x(double(t.number_of_tiles)), 6) + "\" cy=\"" + number(y(t.hausdorff_distance), 6) +
         "\" r=\"4\" stroke=\"#123\" fill=\"" + (t.is_tilable && t.self_intersecting_face_pairs == 0 ? "#123" : "#fff") +
         "\"><title>K = " + std::to_string(t.number_of_tiles) + ": " + number(100 * t.hausdorff_distance, 3) + "%" +
         (t.is_tilable ? "" : ", not tilable") + "</title></circle>\n";
  return s + "</svg>\n";
}

// The catalog: per tile with instances its mold sheet, its counts, and a
// button that shows its instances on the surface.
inline std::string catalog_html(const std::vector<Tile>& tiles)
{
  const std::vector<CGAL::IO::Color> colors = cluster_colors(tiles.size());
  std::string s = "<div class=\"molds\">\n";
  for(std::size_t i = 0; i < tiles.size(); ++i)
  {
    const Tile& t = tiles[i];
    if(t.instance_count == 0) continue;
    char swatch[8];
    std::snprintf(swatch, sizeof swatch, "#%02x%02x%02x", unsigned(colors[t.id].red()), unsigned(colors[t.id].green()),
                  unsigned(colors[t.id].blue()));
    const std::string id = std::to_string(t.id);
    s += "<div class=\"mold\" id=\"tile-" + id + "\" data-tile=\"" + id + "\" data-mold=\"" + std::to_string(t.mold) +
         "\" data-instances=\"" + std::to_string(t.instance_count) + "\" data-mirrored=\"" +
         std::to_string(t.mirrored_count) + "\">\n<p><span class=\"swatch\" style=\"background:" + swatch +
         "\"></span> <b>tile " + id + "</b>, mold " + std::to_string(t.mold) + ": " + std::to_string(t.instance_count) +
         " instances, " + std::to_string(t.mirrored_count) + " mirrored <button class=\"show\" data-tile=\"" + id +
         "\">show on the surface</button></p>\n" + mold_sheet_SVG(tiles, i) + "</div>\n";
  }
  return s + "</div>\n";
}

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
inline std::string viewer_scripts_html(const nlohmann::json& report, const nlohmann::json& viewer_data,
                                       const HTML_viewer_scripts& scripts)
{
  return script_element("application/json", "report-data", report.dump()) +
         script_element("application/json", "mesh-data", viewer_data.dump()) +
         script_element("text/plain", "three-module", scripts.three_module) +
         script_element("text/plain", "orbit-controls", scripts.orbit_controls) +
         "<script type=\"module\">" + Tilable_surfaces::internal::html_report_script() + "</script>\n";
}

// The input file the report names (`input/file`), or `otherwise`.
inline std::string report_file(const nlohmann::json& report, const std::string& otherwise)
{
  const nlohmann::json::json_pointer at("/input/file");
  return report.contains(at) && report.at(at).is_string() ? report.at(at).get<std::string>() : otherwise;
}

// The K tried as a plot and its legend.
inline std::string curve_section(const std::vector<Tile_count_trial>& trials, double budget)
{
  return "<section id=\"curve\">\n<h2>K / deviation: the K tried</h2>\n" + curve_svg(trials, budget) +
         "<p>Filled: tilable and not crossing itself; dashed: the deviation budget. A dot's tooltip gives its K "
         "and distance.</p>\n</section>\n";
}

// The K tried as a table, in the order tried.
inline std::string trials_table_html(const std::vector<Tile_count_trial>& trials)
{
  std::string s = "<table id=\"trials\">\n<tr><th>K</th><th>DOF</th><th>congruence error</th><th>Hausdorff, % of the "
                  "diagonal</th><th>largest displacement</th><th>tilable</th><th>crossing pairs</th><th>refined from K"
                  "</th><th>seconds</th></tr>\n";
  for(const Tile_count_trial& t : trials)
    s += "<tr class=\"trial\" data-k=\"" + std::to_string(t.number_of_tiles) + "\"><td>" + std::to_string(t.number_of_tiles) +
         "</td><td>" + std::to_string(t.degree_of_flexibility) + "</td><td>" + number(t.congruence_error, 3) + "</td><td>" +
         number(100 * t.hausdorff_distance, 4) + "</td><td>" + number(t.max_displacement, 4) + "</td><td>" +
         (t.is_tilable ? "yes" : "no") + "</td><td>" + std::to_string(t.self_intersecting_face_pairs) + "</td><td>" +
         (t.refined_from > 0 ? std::to_string(t.refined_from) : "") + "</td><td>" + number(t.seconds, 3) + "</td></tr>\n";
  return s + "</table>\n";
}

// The 3D view and its controls.
inline std::string viewer_html()
{
  return "<section id=\"viewer\">\n<div id=\"view3d\"><canvas id=\"canvas\"></canvas></div>\n<div id=\"side\">\n"
         "<label><input type=\"radio\" name=\"colour\" value=\"mold\" checked> colour by tile</label>\n"
         "<label><input type=\"radio\" name=\"colour\" value=\"deviation\"> colour by deviation (distance of each "
         "vertex to the input surface)</label>\n<div id=\"legend\" hidden><div class=\"bar\"></div><div class=\"ends\">"
         "<span>0</span><span id=\"legend-max\"></span></div></div>\n"
         "<label><input type=\"checkbox\" id=\"ghost\"> the input surface (ghost)</label>\n"
         "<button id=\"show-all\">show every tile</button>\n<div id=\"info\">Drag to orbit, scroll to zoom, click a "
         "panel to see its tile.</div>\n</div>\n</section>\n";
}

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
inline bool write_HTML_curve_report(std::ostream& os, const std::vector<Tile_count_trial>& trials,
                                    const nlohmann::json& report = nlohmann::json::object())
{
  const std::string file = internal::report_file(report, "the surface");
  std::string body = "<header>\n<h1>" + internal::html_escaped(std::filesystem::path(file).filename().string()) +
                     ": " + std::to_string(trials.size()) + " K tried</h1>\n</header>\n";
  if(!trials.empty())
    body += internal::curve_section(trials, 0) + "<section id=\"trials-section\">\n<h2>Every K tried</h2>\n" +
            internal::trials_table_html(trials) + "</section>\n";
  os << internal::html_page(file + ": K / deviation", body,
                            internal::script_element("application/json", "report-data", report.dump()));
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_H
