// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_IMPL_H

// The bodies of the non-template functions declared in mold_sheet.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/mold_sheet.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
std::string number(double x, int digits)
{
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s << std::setprecision(digits) << x;
  return s.str();
}

CGAL_TILABLE_SURFACES_INLINE
std::array<double, 4> corner_angles(const Panel& p)
{
  std::array<double, 4> a{{0, 0, 0, 0}};
  const int n = p.size();
  for(int i = 0; i < n; ++i)
  {
    const Eigen::Vector3d u = p[(i + 1) % n] - p[i], v = p[(i + n - 1) % n] - p[i];
    a[std::size_t(i)] = std::atan2(u.cross(v).norm(), u.dot(v)) * 180.0 / 3.14159265358979323846;
  }
  return a;
}

CGAL_TILABLE_SURFACES_INLINE
double round_length(double x)
{
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  for(double m : {5.0, 2.0})
    if(m * power <= x) return m * power;
  return power;
}

CGAL_TILABLE_SURFACES_INLINE
std::string tiles_sharing_mold(const std::vector<Tile>& tiles, std::size_t i)
{
  std::string list;
  for(const Tile& t : tiles)
    if(t.id != tiles[i].id && t.mold == tiles[i].mold && t.instance_count > 0)
      list += (list.empty() ? "" : ", ") + std::to_string(t.id);
  return list;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<Eigen::Vector2d> plan_view(const Panel& p)
{
  std::vector<Eigen::Vector2d> v;
  for(int i = 0; i < p.size(); ++i) v.emplace_back(p[i].x(), 0.0 - p[i].y());
  return v;
}

CGAL_TILABLE_SURFACES_INLINE
std::string svg_text(const Eigen::Vector2d& at, const std::string& text, double font,
                     const char* anchor, double relative)
{
  const double k = font / Mold_sheet_layout::nominal_font;
  return "<text transform=\"scale(" + number(k, 9) + ")\" x=\"" + number(at.x() / k, 9) + "\" y=\"" +
         number(at.y() / k, 9) + "\" font-size=\"" + number(Mold_sheet_layout::nominal_font * relative, 6) +
         "\" text-anchor=\"" + anchor + "\">" + text + "</text>\n";
}

CGAL_TILABLE_SURFACES_INLINE
std::string svg_drawing(const Panel& p, const Tile_row& row, double font)
{
  typedef Mold_sheet_layout L;
  const std::vector<Eigen::Vector2d> v = plan_view(p);
  const int n = p.size();
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  for(const Eigen::Vector2d& c : v) centre += c / double(n);
  std::string s = "<polygon class=\"outline\" points=\"";
  for(const Eigen::Vector2d& c : v) s += number(c.x(), 9) + "," + number(c.y(), 9) + " ";
  s += "\" fill=\"#eef3f8\" stroke=\"#123\" stroke-width=\"" + number(font / 8, 6) + "\"/>\n";
  const std::array<double, 4> angles = corner_angles(p);
  auto outwards = [&](const Eigen::Vector2d& at, double by) {
    const Eigen::Vector2d d = at - centre;
    return Eigen::Vector2d(at + (d.norm() > 0 ? d.normalized() : Eigen::Vector2d(0, 1)) * by * font);
  };
  for(int i = 0; i < n; ++i)
  {
    const Eigen::Vector2d mid = (v[std::size_t(i)] + v[std::size_t((i + 1) % n)]) / 2;
    s += svg_text(outwards(v[std::size_t(i)], L::corner_label), "t" + std::to_string(i), font, "middle", 1.2);
    s += svg_text(outwards(mid, L::edge_label), number(row.edges[std::size_t(i)], L::shown_digits), font);
    s += svg_text(outwards(v[std::size_t(i)], -L::angle_label),
                  number(angles[std::size_t(i)], 5) + "&#176;", font, "middle", 0.85);
  }
  for(int d = 0; n == 4 && d < 2; ++d)
  {
    const Eigen::Vector2d a = v[std::size_t(d)], b = v[std::size_t(d + 2)];
    s += "<line x1=\"" + number(a.x(), 9) + "\" y1=\"" + number(a.y(), 9) + "\" x2=\"" +
         number(b.x(), 9) + "\" y2=\"" + number(b.y(), 9) + "\" stroke=\"#678\" stroke-dasharray=\"" +
         number(font / 2, 6) + "\" stroke-width=\"" + number(font / 14, 6) + "\"/>\n";
    s += svg_text(a + (b - a) * L::diagonal_label, number(row.diagonals[std::size_t(d)], L::shown_digits),
                  font, "middle", 0.85);
  }
  return s;
}

CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> sheet_lines(const std::vector<Tile>& tiles, std::size_t i, const Tile_row& row)
{
  typedef Mold_sheet_layout L;
  const Tile& t = tiles[i];
  const int n = t.corners.size();
  const std::string shared = tiles_sharing_mold(tiles, i);
  std::vector<std::string> lines{
    "Tile " + std::to_string(t.id) + ", mold " + std::to_string(t.mold) +
      (shared.empty() ? "" : " (shared with tile" + std::string(shared.find(',') == std::string::npos ? " " : "s ") +
                               shared + ")") + ": " +
      std::to_string(t.instance_count) + " instances, " + std::to_string(t.mirrored_count) + " mirrored"};
  std::string edges = "edges", angles = "angles";
  const std::array<double, 4> a = corner_angles(t.corners);
  for(int k = 0; k < n; ++k)
  {
    edges += " t" + std::to_string(k) + "t" + std::to_string((k + 1) % n) + " " +
             number(row.edges[std::size_t(k)], L::shown_digits);
    angles += " t" + std::to_string(k) + " " + number(a[std::size_t(k)], 5) + "&#176;";
  }
  lines.push_back(edges);
  if(n == 4)
    lines.push_back("diagonals t0t2 " + number(row.diagonals[0], L::shown_digits) + " t1t3 " +
                    number(row.diagonals[1], L::shown_digits));
  lines.push_back(angles);
  const char* const flat = t.panel_tolerance > 0 && n == 4 ? "planar within the panel tolerance" : "planar";
  lines.push_back(n == 3 || row.is_planar ? std::string(flat)
                  : "twist 6V/e&#179; " + number(relative_twist(t.corners), 4) + ": t3 is " +
                      number(row.planarity, L::shown_digits) + " off the plane t0 t1 t2 (drawn from above)");
  lines.push_back("worst instance deviation " + number(t.worst_deviation, 3) + " (model units)");
  const std::string mod = " mod " + std::to_string(n);
  lines.push_back("corner ti is the vertex (i + o)" + mod + " of a PLY face of orientation o &lt; 4,");
  lines.push_back("(o - 4 - i)" + mod + " of one of orientation o &gt;= 4");
  return lines;
}

} // namespace internal

CGAL_TILABLE_SURFACES_INLINE
std::string mold_sheet_SVG(const std::vector<Tile>& tiles, std::size_t i)
{
  typedef internal::Mold_sheet_layout L;
  const Tile& t = tiles[i];
  const internal::Tile_row row = internal::tile_row(t);
  const std::vector<Eigen::Vector2d> v = internal::plan_view(t.corners);
  Eigen::Vector2d low = v[0], high = v[0];
  for(const Eigen::Vector2d& c : v) { low = low.cwiseMin(c); high = high.cwiseMax(c); }
  const double extent = (std::max)((high - low).maxCoeff(), std::numeric_limits<double>::min());
  const double font = extent * L::font_per_extent, m = L::margin * font;
  const double width = (std::max)(high.x() - low.x() + 2 * m, L::min_width * font);
  const double text_top = high.y() + m, height = text_top - (low.y() - m) + L::text_lines * L::line * font;
  const std::size_t n = std::size_t(t.corners.size());
  std::string s = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"mold-sheet\" viewBox=\"" +
    internal::number(low.x() - m, 9) + " " + internal::number(low.y() - m, 9) + " " + internal::number(width, 9) +
    " " + internal::number(height, 9) + "\" font-family=\"sans-serif\" data-tile=\"" + std::to_string(t.id) +
    "\" data-mold=\"" + std::to_string(t.mold) + "\" data-instances=\"" + std::to_string(t.instance_count) +
    "\" data-mirrored=\"" + std::to_string(t.mirrored_count) + "\" data-edges=\"" +
    internal::number_list(row.edges, n) + "\" data-diagonals=\"" + internal::number_list(row.diagonals, n == 4 ? 2 : 0) +
    "\" data-angles=\"" + internal::number_list(internal::corner_angles(t.corners), n) + "\">\n";
  s += internal::svg_drawing(t.corners, row, font);
  double y = text_top + L::line * font;
  for(const std::string& line : internal::sheet_lines(tiles, i, row))
  {
    s += internal::svg_text(Eigen::Vector2d(low.x() - m + font, y), line, font, "start", 0.8);
    y += L::line * font;
  }
  const double bar = internal::round_length(extent * L::scale_bar_fraction), x0 = low.x() - m + font;
  s += "<path class=\"scale-bar\" d=\"M" + internal::number(x0, 9) + " " + internal::number(y - font / 2, 9) +
       " v" + internal::number(font / 2, 9) + " h" + internal::number(bar, 9) + " v" +
       internal::number(-font / 2, 9) + "\" fill=\"none\" stroke=\"#000\" stroke-width=\"" +
       internal::number(font / 10, 6) + "\"/>\n";
  s += internal::svg_text(Eigen::Vector2d(x0 + bar + font / 2, y), internal::number(bar, 6) + " model units",
                          font, "start", 0.8);
  return s + "</svg>\n";
}

CGAL_TILABLE_SURFACES_INLINE
std::string mold_sheet_file_name(const Tile& tile)
{
  std::ostringstream s;
  s << "tile_" << std::setw(3) << std::setfill('0') << tile.id << ".svg";
  return s.str();
}

CGAL_TILABLE_SURFACES_INLINE
bool write_mold_sheet_SVG(std::ostream& os, const std::vector<Tile>& tiles, std::size_t i)
{
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << mold_sheet_SVG(tiles, i);
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_IMPL_H
