// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_IMPL_H
#define CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_IMPL_H

// The bodies of the non-template functions declared in cluster_colors.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/IO/cluster_colors.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

CGAL_TILABLE_SURFACES_INLINE
std::vector<CGAL::IO::Color> cluster_colors(std::size_t number_of_colors)
{
  std::vector<CGAL::IO::Color> colors;
  colors.reserve(number_of_colors);
  std::set<std::array<int, 3> > used;
  const double golden_angle = 0.38196601125010515; // (3 - sqrt(5)) / 2 turns
  namespace T = Tilable_surfaces::internal::tuning;
  for(std::size_t i = 0; i < number_of_colors; ++i)
  {
    const double h = std::fmod(double(i) * golden_angle, 1.0) * 6.0;
    const std::size_t saturation_level = (i / T::palette_saturation_period) % T::palette_levels,
                      value_level = (i / T::palette_value_period) % T::palette_levels;
    const double s = T::palette_saturation - T::palette_saturation_step * double(saturation_level);
    const double v = T::palette_value - T::palette_value_step * double(value_level);
    const int sector = int(h) % 6;
    const double f = h - std::floor(h);
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    const double rgb[6][3] = {{v, t, p}, {q, v, p}, {p, v, t}, {p, q, v}, {t, p, v}, {v, p, q}};
    std::array<int, 3> c{{int(std::lround(255 * rgb[sector][0])),
                          int(std::lround(255 * rgb[sector][1])),
                          int(std::lround(255 * rgb[sector][2]))}};
    while(used.count(c))
    {
      // Next triple in lexicographic order: count in base 256.
      int k = 2;
      while(k >= 0 && c[k] == 255) c[k--] = 0;
      if(k >= 0) ++c[k];
    }
    used.insert(c);
    colors.emplace_back((unsigned char)c[0], (unsigned char)c[1], (unsigned char)c[2]);
  }
  return colors;
}

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_IO_CLUSTER_COLORS_IMPL_H
