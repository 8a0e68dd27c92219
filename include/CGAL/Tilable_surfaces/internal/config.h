// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CONFIG_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CONFIG_H

// The package is header-only: a header X.h declares its non-template
// functions with CGAL_TILABLE_SURFACES_INLINE and includes their bodies from
// X_impl.h, as CGAL does with CGAL_HEADER_ONLY.
//
// A project that compiles the package in several translation units can
// instead compile those bodies once: with CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
// defined, the headers leave out the X_impl.h files, and one library whose
// sources include every X_impl.h (with the same definition) provides the
// functions. GCC instantiates the templates (Eigen's decompositions and
// sparse solvers) used by an inline function in every unit that sees its
// body, called or not: this saves tens of seconds of compilation per unit.
// This project's own programs and tests are built that way (CMake target
// Tilable_surfaces_compiled, not installed), which also holds the pipeline
// on a Surface_mesh instantiated once (internal/Search/compiled_pipeline.h).

#ifdef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#  define CGAL_TILABLE_SURFACES_INLINE
#else
#  define CGAL_TILABLE_SURFACES_INLINE inline
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CONFIG_H
