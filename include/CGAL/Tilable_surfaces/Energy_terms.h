// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_ENERGY_TERMS_H
#define CGAL_TILABLE_SURFACES_ENERGY_TERMS_H

/// \file Energy_terms.h
/// The five terms of the paper's energy, as measured values or as weights.

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Values of the five terms of the paper's energy (§4): F_d (distance to the
/// input positions), F_f (fairness), F_e (edge lengths), F_a (diagonals) and
/// F_o (signed volumes); or their weights mu1..mu5.
struct Energy_terms
{
  double distance = 0;    ///< F_d, or mu1
  double fairness = 0;    ///< F_f, or mu2
  double edge_length = 0; ///< F_e, or mu3
  double diagonal = 0;    ///< F_a, or mu4
  double volume = 0;      ///< F_o, or mu5

  /// The weighted sum sum_k weights_k * F_k.
  double weighted_sum(const Energy_terms& weights) const
  {
    return weights.distance * distance + weights.fairness * fairness +
           weights.edge_length * edge_length + weights.diagonal * diagonal +
           weights.volume * volume;
  }
};

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_ENERGY_TERMS_H
