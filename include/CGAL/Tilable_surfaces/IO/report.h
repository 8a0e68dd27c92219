// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_IO_REPORT_H
#define CGAL_TILABLE_SURFACES_IO_REPORT_H

/// \file report.h
/// A JSON report of everything `make_k_set_tilable()` measured.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/K_set_tilable_result.h>
#include <CGAL/Tilable_surfaces/defaults.h>

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace IO {

/// \ingroup PkgTilableSurfacesRef
/// The normalized terms F̃_d..F̃_o of the paper's Table 1 as a JSON object.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json energy_terms_json(const Energy_terms& t);

/// \ingroup PkgTilableSurfacesRef
/// The K tried by a deviation search (`K_set_tilable_result::trials`), in
/// the order tried, as a JSON array.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tile_count_trials_json(const std::vector<Tile_count_trial>& trials);

namespace internal {

// The "fidelity" entry of tilability_report_json(): the distances between the
// result and the input.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json fidelity_json(const Tilability_measure& m);

// The "panel_deviation" entry of tilability_report_json(): every panel's
// deviation from its mold in model units, the worst, and the panel tolerance
// they are held to (0: exact mode, see "congruence_error").
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json panel_deviation_json(const Tilability_measure& m);

// The "clustering" entry of tilability_report_json().
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json clustering_json(const K_set_tilable_result& r);

// The "time_seconds" entry of tilability_report_json().
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json time_json(const K_set_tilable_result& r);

} // namespace internal

/// \ingroup PkgTilableSurfacesRef
/// The report of a run as JSON: K, degree of flexibility, cluster sizes,
/// the kind of each cluster's tile (`tile_kinds`: `quad` or `triangle`) and
/// how many tiles of each kind,
/// whether planar panels were required and the worst distance between the
/// diagonals of a face, whether mirrored panels were allowed and how many
/// each cluster has,
/// congruence error (worst and per cluster, relative to the mean edge length,
/// and the tolerance it was held to), every panel's deviation from its mold
/// in model units with the worst and the panel tolerance (`panel_deviation`), the distances between the result and
/// the input both ways and the symmetric Hausdorff distance (max and mean,
/// relative to the input's bounding-box diagonal and in its mean edge lengths),
/// displacement (mesh units), the paper's normalized terms, solver
/// iterations and why the solve ended (`Optimization_result::ending()`),
/// whether the result is tilable, the clustering's choice and the rounds
/// of split-and-merge edits after it,
/// the time of each phase in seconds, and the K tried by a deviation search
/// (`tried_K`, empty when K was given). Callers add what only they know
/// (input name, parameters) to the returned object.
CGAL_TILABLE_SURFACES_INLINE
nlohmann::json tilability_report_json(const K_set_tilable_result& r,
                                       double congruence_tolerance = defaults::congruence_tolerance);

} // namespace IO
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/IO/report_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_IO_REPORT_H
