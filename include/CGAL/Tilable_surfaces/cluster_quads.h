// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

/// \file cluster_quads.h
/// \deprecated The name of `cluster_panels.h` until 1.0.0; includes it.

/// \cond
#define CGAL_DEPRECATED_HEADER "<CGAL/Tilable_surfaces/cluster_quads.h>"
#define CGAL_REPLACEMENT_HEADER "<CGAL/Tilable_surfaces/cluster_panels.h>"
#include <CGAL/Installation/internal/deprecation_warning.h>
/// \endcond

#include <CGAL/Tilable_surfaces/cluster_panels.h>
