// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_H
#define CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_H

// The style sheet and the script of the HTML report (IO/write_HTML_report.h).
// The script reads the embedded data (#mesh-data), loads the embedded three.js
// module and OrbitControls from Blob URLs (no network, also from file://),
// and exposes window.tilableReport for the headless-browser test.

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
const char* html_report_style();

CGAL_TILABLE_SURFACES_INLINE
const char* html_report_script();

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/IO/html_report_viewer_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_IO_HTML_REPORT_VIEWER_H#include <CGAL/Tilable_surfaces/internal/config.h>

