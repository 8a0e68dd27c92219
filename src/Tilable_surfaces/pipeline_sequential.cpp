// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The pipeline on a Surface_mesh, compiled once for this project's programs
// and tests (internal/Search/compiled_pipeline.h), with the concurrency tag
// CGAL::Sequential_tag; one source per tag, so that two cores build them in
// parallel.

#include <CGAL/Tilable_surfaces/internal/Search/compiled_pipeline.h>
#include <CGAL/Tilable_surfaces/k_set_tilable_curve.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

CGAL_TILABLE_SURFACES_PIPELINE_INSTANTIATIONS(, CGAL::Sequential_tag)
