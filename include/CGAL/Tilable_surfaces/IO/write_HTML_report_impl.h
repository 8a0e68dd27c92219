// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_IMPL_H

// The bodies of the non-template functions declared in write_HTML_report.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/write_HTML_report.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::string script_safe(std::string text)
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

CGAL_TILABLE_SURFACES_INLINE
std::string html_escaped(const std::string& text)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<float> distances_to_input(const Viewer_mesh& m)
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

CGAL_TILABLE_SURFACES_INLINE
std::vector<float> coordinates(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<float> c;
  for(const Eigen::Vector3d& p : points)
    for(int a = 0; a < 3; ++a) c.push_back(float(p[a]));
  return c;
}

CGAL_TILABLE_SURFACES_INLINE
nlohmann::json viewer_data_json(const Viewer_mesh& m, double bbox_diagonal)
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

CGAL_TILABLE_SURFACES_INLINE
std::string report_value(const nlohmann::json& report, const std::string& pointer, int digits,
                         double scale, const std::string& unit)
{
  const nlohmann::json::json_pointer p(pointer);
  if(!report.contains(p) || report.at(p).is_null()) return "-";
  const nlohmann::json& v = report.at(p);
  if(v.is_number_float()) return number(scale * v.get<double>(), digits) + unit;
  return html_escaped(v.is_string() ? v.get<std::string>() : v.dump()) + unit;
}

CGAL_TILABLE_SURFACES_INLINE
std::string summary_html(const nlohmann::json& report)
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

CGAL_TILABLE_SURFACES_INLINE
std::string curve_svg(std::vector<Tile_count_trial> trials, double budget)
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

CGAL_TILABLE_SURFACES_INLINE
std::string catalog_html(const std::vector<Tile>& tiles)
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

CGAL_TILABLE_SURFACES_INLINE
std::string viewer_scripts_html(const nlohmann::json& report, const nlohmann::json& viewer_data,
                                const HTML_viewer_scripts& scripts)
{
  return script_element("application/json", "report-data", report.dump()) +
         script_element("application/json", "mesh-data", viewer_data.dump()) +
         script_element("text/plain", "three-module", scripts.three_module) +
         script_element("text/plain", "orbit-controls", scripts.orbit_controls) +
         "<script type=\"module\">" + Tilable_surfaces::internal::html_report_script() + "</script>\n";
}

CGAL_TILABLE_SURFACES_INLINE
std::string report_file(const nlohmann::json& report, const std::string& otherwise)
{
  const nlohmann::json::json_pointer at("/input/file");
  return report.contains(at) && report.at(at).is_string() ? report.at(at).get<std::string>() : otherwise;
}

CGAL_TILABLE_SURFACES_INLINE
std::string trials_table_html(const std::vector<Tile_count_trial>& trials)
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

CGAL_TILABLE_SURFACES_INLINE
std::string viewer_html()
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

CGAL_TILABLE_SURFACES_INLINE
bool write_HTML_curve_report(std::ostream& os, const std::vector<Tile_count_trial>& trials,
                             const nlohmann::json& report)
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

#endif // CGAL_TILABLE_SURFACES_IO_WRITE_HTML_REPORT_IMPL_H
