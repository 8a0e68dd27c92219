// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The package's non-template functions, compiled once for this project's
// programs and tests (CMake target Tilable_surfaces_compiled, built with
// CGAL_TILABLE_SURFACES_COMPILED_LIBRARY: see internal/config.h). The library
// has two sources, so that two cores build it in parallel; this one:
// the clustering.

#include <CGAL/Tilable_surfaces/internal/Clustering/cluster_analysis_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/fast_match_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/flexible_orientations_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/initial_clustering_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/kmeans_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/merge_costs_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/panel_kinds_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/patch_candidates_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/pole_fans_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/s_quad_template_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/strip_candidates_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/sweep_candidates_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/tolerance_candidates_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/trimmed_grid_impl.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/twist_separation_impl.h>
