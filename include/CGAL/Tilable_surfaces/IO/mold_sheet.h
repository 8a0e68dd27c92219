// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H
#define CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H

/// \file mold_sheet.h
/// The mold sheet of a tile, what a fabricator cuts from: an SVG drawing in
/// model units (its `viewBox`), with a scale bar, the corners labelled as the
/// tiled PLY's orientations number them, the true edge and diagonal lengths,
/// the corner angles, the twist and the instance count.

#include <CGAL/Tilable_surfaces/IO/tile_catalog.h>
#include <CGAL/Tilable_surfaces/measure.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

namespace internal {

// The sheet's layout, in units of its font size, itself a fraction of the
// tile's extent so that every sheet reads alike whatever the model's units.
struct Mold_sheet_layout
{
  static constexpr double font_per_extent = 1.0 / 22;
  static constexpr double margin = 3.5;          // around the drawing: room for the labels
  static constexpr double line = 1.45;           // text line height
  static constexpr double min_width = 36;        // so that the text block fits
  static constexpr double corner_label = 1.3;    // corner label offset, outwards
  static constexpr double edge_label = 0.9;      // edge length offset, outwards
  static constexpr double angle_label = 2.6;     // corner angle offset, inwards
  static constexpr double diagonal_label = 0.3;  // where along a diagonal its length is written
  static constexpr double scale_bar_fraction = 0.3; // of the extent, before rounding
  static constexpr int text_lines = 10;          // lines of the text block and the scale bar
  static constexpr int shown_digits = 6;         // significant digits of the printed lengths
  static constexpr double nominal_font = 12;     // font size of the text's own frame
};

// `x` with `digits` significant digits, or with every digit (max_digits10)
// by default, in the classic locale.
inline std::string number(double x, int digits = std::numeric_limits<double>::max_digits10)
{
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s << std::setprecision(digits) << x;
  return s.str();
}

// The numbers of `values` separated by spaces, every digit.
template <typename Values>
std::string number_list(const Values& values, std::size_t count)
{
  std::string s;
  for(std::size_t i = 0; i < count; ++i)
    s += (i ? " " : "") + number(values[i]);
  return s;
}

// The angle in degrees at every corner of `p` between its two edges.
inline std::array<double, 4> corner_angles(const Panel& p)
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

// A round length near `x`: 1, 2 or 5 times a power of ten, at most `x`.
inline double round_length(double x)
{
  const double power = std::pow(10.0, std::floor(std::log10(x)));
  for(double m : {5.0, 2.0})
    if(m * power <= x) return m * power;
  return power;
}

// The tiles other than `tiles[i]` cut from its mold, as "tiles 3, 7".
inline std::string tiles_sharing_mold(const std::vector<Tile>& tiles, std::size_t i)
{
  std::string list;
  for(const Tile& t : tiles)
    if(t.id != tiles[i].id && t.mold == tiles[i].mold && t.instance_count > 0)
      list += (list.empty() ? "" : ", ") + std::to_string(t.id);
  return list;
}

// The drawing in the sheet's frame: the corners seen from +z (the tile's
// canonical frame has t0, t1, t2 in the xy plane), y pointing down as SVG's does.
inline std::vector<Eigen::Vector2d> plan_view(const Panel& p)
{
  std::vector<Eigen::Vector2d> v;
  for(int i = 0; i < p.size(); ++i) v.emplace_back(p[i].x(), 0.0 - p[i].y());
  return v;
}

// `text` at `at` in font size `font` (scaled by `relative`). The text is set
// at a nominal size in a scaled frame: renderers that lay text out in whole
// fractions of a point garble the tiny font sizes of model units.
inline std::string svg_text(const Eigen::Vector2d& at, const std::string& text, double font,
                            const char* anchor = "middle", double relative = 1.0)
{
  const double k = font / Mold_sheet_layout::nominal_font;
  return "<text transform=\"scale(" + number(k, 9) + ")\" x=\"" + number(at.x() / k, 9) + "\" y=\"" +
         number(at.y() / k, 9) + "\" font-size=\"" + number(Mold_sheet_layout::nominal_font * relative, 6) +
         "\" text-anchor=\"" + anchor + "\">" + text + "</text>\n";
}

// The outline, the diagonals and the labels on them.
inline std::string svg_drawing(const Panel& p, const Tile_row& row, double font)
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

// The lines of text under the drawing: what the drawing shows, in full.
inline std::vector<std::string> sheet_lines(const std::vector<Tile>& tiles, std::size_t i, const Tile_row& row)
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

/// \ingroup PkgTilableSurfacesRef
/// The mold sheet of `tiles[i]` as an `<svg>` element: the tile seen from
/// above in its canonical frame (`Tile::corners`), the `viewBox` in model
/// units so that the drawing scales 1:1 to the model, with a scale bar;
/// corners labelled t0..t3 as `Panel_orientation` numbers them (corner ti of
/// a face with PLY `orientation` o is its vertex (i + o) mod 4 for o < 4,
/// (o - 4 - i) mod 4 otherwise); the true (3D) edge and diagonal lengths, the
/// corner angles, the twist, the instance and mirrored counts, and the tiles
/// cut from the same mold. The exact numbers are in the attributes
/// `data-tile`, `data-mold`, `data-instances`, `data-mirrored`, `data-edges`
/// (t0t1, t1t2, ...), `data-diagonals` (t0t2, t1t3) and `data-angles`
/// (degrees), with every digit.
inline std::string mold_sheet_SVG(const std::vector<Tile>& tiles, std::size_t i)
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

/// \ingroup PkgTilableSurfacesRef
/// The file name of the mold sheet of `tile`: `tile_` and its id on at least
/// three digits, `.svg`, so that a directory lists the sheets in order.
inline std::string mold_sheet_file_name(const Tile& tile)
{
  std::ostringstream s;
  s << "tile_" << std::setw(3) << std::setfill('0') << tile.id << ".svg";
  return s.str();
}

/// \ingroup PkgTilableSurfacesRef
/// Writes `mold_sheet_SVG(tiles, i)` as a standalone SVG file.
/// \returns whether the stream is good after writing.
inline bool write_mold_sheet_SVG(std::ostream& os, const std::vector<Tile>& tiles, std::size_t i)
{
  os << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" << mold_sheet_SVG(tiles, i);
  return bool(os);
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H
