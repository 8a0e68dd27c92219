// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_VISITOR_H
#define CGAL_TILABLE_SURFACES_VISITOR_H

/// \file visitor.h
/// The package's visitor: one object follows (and may stop) every stage of a
/// call.

#include <CGAL/Tilable_surfaces/named_parameters.h>

#include <functional>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// The visitor of the package, and the model that does nothing: derive from
/// it and override what you need, then pass it with the named parameter
/// `visitor`. Given by value it is copied once, by the function called;
/// given as `std::ref(v)` it is `v` itself. Either way every stage of that
/// call (clustering, each optimization, the fidelity search, the deviation
/// search) calls that one object.
struct Default_visitor
{
  /// Called after iteration `iteration` (from 1) of a solver with the
  /// congruence error (user manual, section Definitions) and the solver's
  /// objective (on the normalized input), and once before its first
  /// iteration with `iteration` 0 and the values at its starting point.
  /// Returning `false` stops the solver, and the search around it; at
  /// iteration 0 the solver then makes no step at all. The default solver
  /// measures the congruence error only when it may meet the tolerance and
  /// every 10 iterations; in between it passes its estimate, the largest
  /// constraint residual in mean edge lengths.
  /// `Optimization_result::converged` is always decided on the measured
  /// value.
  bool iteration(int /*iteration*/, double /*congruence_error*/, double /*objective*/)
  {
    return true;
  }

  /// Called when a phase ends, with its duration in seconds:
  /// `cluster_panels()`: "threshold clustering", "exact starts" (the sweeps,
  /// and in `K_set_tilable_surface::cluster()` the multilevel start, whose
  /// coarse solve calls `iteration()` but not `phase()`), "merges",
  /// "other candidates", "orientations" (no "merges" and "other candidates"
  /// when an exact start ends the search);
  /// `K_set_tilable_surface::optimize_closest()`: "sweep candidate",
  /// "multilevel start" (above 5,000 faces, on a 2 x 2 refinement without an
  /// exact sweep, when the coarse result is exact), "displacement prediction",
  /// "candidate optimization", "improvement round" (the last three only when
  /// the search goes beyond the exact starts, the first of them only up to
  /// 5,000 faces);
  /// `make_k_set_tilable()` and `k_set_tilable_curve()`: "validation",
  /// "clustering", "optimization".
  void phase(const char* /*name*/, double /*seconds*/) {}
};

namespace internal {

// A visitor of any type behind one type: what make_k_set_tilable() and
// k_set_tilable_curve() hand to the pipeline, so that it is compiled once
// whatever the user's visitor (and the multilevel start's coarse solve
// shares that instantiation). `visitor` must outlive it.
class Visitor_ref
{
public:
  template <typename Visitor>
  explicit Visitor_ref(Visitor& visitor)
    : m_object(&visitor),
      m_iteration([](void* v, int i, double error, double objective) {
        return static_cast<Visitor*>(v)->iteration(i, error, objective);
      }),
      m_phase([](void* v, const char* name, double seconds) { static_cast<Visitor*>(v)->phase(name, seconds); })
  {}

  bool iteration(int i, double congruence_error, double objective)
  {
    return m_iteration(m_object, i, congruence_error, objective);
  }
  void phase(const char* name, double seconds) { m_phase(m_object, name, seconds); }

private:
  void* m_object;
  bool (*m_iteration)(void*, int, double, double);
  void (*m_phase)(void*, const char*, double);
};

// A visitor that lets every solve run and hears no phase.
inline Visitor_ref silent_visitor()
{
  static Default_visitor silent;  // stateless
  return Visitor_ref(silent);
}

// The visitor of `np`: the user's object if given as std::ref, else a copy of
// it, or a Default_visitor.
template <typename NamedParameters>
decltype(auto) visitor_of(const NamedParameters& np)
{
  if constexpr(parameters::is_default_parameter<NamedParameters, CGAL::internal_np::visitor_t>::value)
    return Default_visitor();
  else
    return parameters::get_parameter_reference(np, CGAL::internal_np::visitor);
}

// `np` with `visitor` passed on by reference, for the stages below a call.
template <typename NamedParameters, typename Visitor>
auto with_visitor(const NamedParameters& np, Visitor& visitor)
{
  return parameters::extend(np).visitor(std::ref(visitor));
}

} // namespace internal

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_VISITOR_H
