// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

// The package's non-template functions, compiled once for this project's
// programs and tests (CMake target Tilable_surfaces_compiled, built with
// CGAL_TILABLE_SURFACES_COMPILED_LIBRARY: see internal/config.h). The library
// has two sources, so that two cores build it in parallel; this one:
// the rest: optimization, measure, searches, shape analysis, input and output.

#include <CGAL/Tilable_surfaces/IO/cluster_colors_impl.h>
#include <CGAL/Tilable_surfaces/IO/mold_sheet_impl.h>
#include <CGAL/Tilable_surfaces/IO/read_polygon_mesh_impl.h>
#include <CGAL/Tilable_surfaces/IO/report_impl.h>
#include <CGAL/Tilable_surfaces/IO/tile_catalog_impl.h>
#include <CGAL/Tilable_surfaces/IO/write_HTML_report_impl.h>
#include <CGAL/Tilable_surfaces/IO/write_tile_count_curve_impl.h>
#include <CGAL/Tilable_surfaces/cluster_editing_impl.h>
#include <CGAL/Tilable_surfaces/internal/Face_clustering_impl.h>
#include <CGAL/Tilable_surfaces/internal/IO/html_report_viewer_impl.h>
#include <CGAL/Tilable_surfaces/internal/Measure/approximation_impl.h>
#include <CGAL/Tilable_surfaces/internal/Measure/congruence_impl.h>
#include <CGAL/Tilable_surfaces/internal/Measure/self_intersections_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/Solver_settings_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/closeness_objective_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_constraints_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/congruence_quantities_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/conjugate_gradient_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/constrained_gauss_newton_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/displacement_estimate_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/quantity_hessian_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sparse_solver_impl.h>
#include <CGAL/Tilable_surfaces/internal/Optimization/sweep_start_impl.h>
#include <CGAL/Tilable_surfaces/internal/Search/multilevel_start_impl.h>
#include <CGAL/Tilable_surfaces/internal/Search/refinement_impl.h>
#include <CGAL/Tilable_surfaces/internal/Search/tile_count_search_impl.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_coarsening_impl.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_grid_impl.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout_impl.h>
#include <CGAL/Tilable_surfaces/internal/Tilable_problem_impl.h>
#include <CGAL/Tilable_surfaces/measure_impl.h>
#include <CGAL/Tilable_surfaces/optimize_tilable_surface_impl.h>
#include <CGAL/Tilable_surfaces/quad_shape_impl.h>
#include <CGAL/Tilable_surfaces/validation_impl.h>
