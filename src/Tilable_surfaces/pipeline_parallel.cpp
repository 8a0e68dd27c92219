// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The pipeline on a Surface_mesh, compiled once for this project's programs
// and tests (internal/Search/compiled_pipeline.h), with the concurrency tag
// CGAL::Parallel_tag (when TBB is linked); one source per tag, so that two
// cores build them in parallel.

#include <CGAL/Tilable_surfaces/internal/Search/compiled_pipeline.h>
#include <CGAL/Tilable_surfaces/k_set_tilable_curve.h>
#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#ifdef CGAL_LINKED_WITH_TBB
CGAL_TILABLE_SURFACES_PIPELINE_INSTANTIATIONS(, CGAL::Parallel_tag)
#endif
