// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H
#define CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H

/// \file mold_sheet.h
/// The mold sheet of a tile, what a fabricator cuts from: an SVG drawing in
/// model units (its `viewBox`), with a scale bar, the corners labelled as the
/// tiled PLY's orientations number them, the true edge and diagonal lengths,
/// the corner angles, the twist and the instance count.

#include <CGAL/Tilable_surfaces/internal/config.h>
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
CGAL_TILABLE_SURFACES_INLINE
std::string number(double x, int digits = std::numeric_limits<double>::max_digits10);

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
CGAL_TILABLE_SURFACES_INLINE
std::array<double, 4> corner_angles(const Panel& p);

// A round length near `x`: 1, 2 or 5 times a power of ten, at most `x`.
CGAL_TILABLE_SURFACES_INLINE
double round_length(double x);

// The tiles other than `tiles[i]` cut from its mold, as "tiles 3, 7".
CGAL_TILABLE_SURFACES_INLINE
std::string tiles_sharing_mold(const std::vector<Tile>& tiles, std::size_t i);

// The drawing in the sheet's frame: the corners seen from +z (the tile's
// canonical frame has t0, t1, t2 in the xy plane), y pointing down as SVG's does.
CGAL_TILABLE_SURFACES_INLINE
std::vector<Eigen::Vector2d> plan_view(const Panel& p);

// `text` at `at` in font size `font` (scaled by `relative`). The text is set
// at a nominal size in a scaled frame: renderers that lay text out in whole
// fractions of a point garble the tiny font sizes of model units.
CGAL_TILABLE_SURFACES_INLINE
std::string svg_text(const Eigen::Vector2d& at, const std::string& text, double font,
                     const char* anchor = "middle", double relative = 1.0);

// The outline, the diagonals and the labels on them.
CGAL_TILABLE_SURFACES_INLINE
std::string svg_drawing(const Panel& p, const Tile_row& row, double font);

// The lines of text under the drawing: what the drawing shows, in full.
CGAL_TILABLE_SURFACES_INLINE
std::vector<std::string> sheet_lines(const std::vector<Tile>& tiles, std::size_t i, const Tile_row& row);

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
CGAL_TILABLE_SURFACES_INLINE
std::string mold_sheet_SVG(const std::vector<Tile>& tiles, std::size_t i);

/// \ingroup PkgTilableSurfacesRef
/// The file name of the mold sheet of `tile`: `tile_` and its id on at least
/// three digits, `.svg`, so that a directory lists the sheets in order.
CGAL_TILABLE_SURFACES_INLINE
std::string mold_sheet_file_name(const Tile& tile);

/// \ingroup PkgTilableSurfacesRef
/// Writes `mold_sheet_SVG(tiles, i)` as a standalone SVG file.
/// \returns whether the stream is good after writing.
CGAL_TILABLE_SURFACES_INLINE
bool write_mold_sheet_SVG(std::ostream& os, const std::vector<Tile>& tiles, std::size_t i);

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/mold_sheet_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_MOLD_SHEET_H
