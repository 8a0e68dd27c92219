// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_NAMED_PARAMETERS_H
#define CGAL_TILABLE_SURFACES_NAMED_PARAMETERS_H

/// \file named_parameters.h
/// Named parameters of the package, chaining with CGAL's own ones.
///
/// CGAL 5.5 generates the chaining member functions of
/// `CGAL::Named_function_parameters` from its own fixed list, so a package
/// outside CGAL cannot add `.number_of_tiles(60)` to that class. This header
/// defines a thin wrapper, `CGAL::Tilable_surfaces::Named_function_parameters`,
/// which *is* a CGAL parameter pack (it derives from CGAL's class, so
/// `get_parameter()`, `choose_parameter()`, `GetVertexPointMap` ... accept it)
/// and whose chaining functions cover both CGAL's list and this package's list.
/// A package name that clashes with a CGAL name declares two members that
/// differ only by their return type, which does not compile.
///
/// \code
/// namespace TSP = CGAL::Tilable_surfaces::parameters;
/// auto np = TSP::number_of_tiles(60).vertex_point_map(vpm).random_seed(7);
/// \endcode

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace Tilable_surfaces {

/// Tag types of the package's named parameters (one enum per parameter, as in
/// `CGAL::internal_np`).
namespace internal_np {
#define CGAL_TS_add_named_parameter(X, Y, Z) enum X { Y };
#include <CGAL/Tilable_surfaces/internal/parameters_interface.h>
#undef CGAL_TS_add_named_parameter
} // namespace internal_np

namespace internal {
// Declaring every parameter name of CGAL and of this package as the same
// member function makes a clash (or a duplicate in our list) a compile error
// where it is introduced, not at the first ambiguous call.
struct Name_clash_probe {};
struct Parameter_names_are_unique
{
#define CGAL_add_named_parameter(X, Y, Z) static void Z(Name_clash_probe);
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define CGAL_TS_add_named_parameter(X, Y, Z) static void Z(Name_clash_probe);
#include <CGAL/Tilable_surfaces/internal/parameters_interface.h>
#undef CGAL_TS_add_named_parameter
};
} // namespace internal

/// \ingroup PkgTilableSurfacesNamedParameters
/// A CGAL named-parameter pack whose chaining functions know the parameters of
/// CGAL and those of this package.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters
  : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// The CGAL pack this wrapper is.
  typedef CGAL::Named_function_parameters<T, Tag, Base> CGAL_parameters;
  /// This type, the base of the packs its chaining functions return.
  typedef Named_function_parameters<T, Tag, Base> self;

  /// The pack of one default-constructed value.
  Named_function_parameters() : CGAL_parameters() {}
  /// The pack of one value `v` under `Tag`.
  Named_function_parameters(const T& v) : CGAL_parameters(v) {}
  /// The pack `b` extended by the value `v` under `Tag`.
  Named_function_parameters(const T& v, const Base& b) : CGAL_parameters(v, b) {}

#define CGAL_TS_chain_member(TAG_NAMESPACE, X, Z)                         \
  template <typename K>                                                   \
  Named_function_parameters<K, TAG_NAMESPACE::X, self> Z(const K& k) const \
  {                                                                       \
    return Named_function_parameters<K, TAG_NAMESPACE::X, self>(k, *this);\
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_TS_chain_member(CGAL::internal_np, X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define CGAL_TS_add_named_parameter(X, Y, Z) \
  CGAL_TS_chain_member(CGAL::Tilable_surfaces::internal_np, X, Z)
#include <CGAL/Tilable_surfaces/internal/parameters_interface.h>
#undef CGAL_TS_add_named_parameter
#undef CGAL_TS_chain_member
};

/// Starters of named-parameter chains: every CGAL parameter and every
/// parameter of this package, plus `default_values()` and `extend()`.
namespace parameters {

/// The empty pack.
inline Named_function_parameters<bool, CGAL::internal_np::all_default_t>
default_values()
{
  return Named_function_parameters<bool, CGAL::internal_np::all_default_t>();
}

/// Wraps a chain started with `CGAL::parameters::...` so that it can be
/// continued with this package's parameters.
template <typename T, typename Tag>
Named_function_parameters<T, Tag>
extend(const CGAL::Named_function_parameters<T, Tag, CGAL::internal_np::No_property>& np)
{
  return Named_function_parameters<T, Tag>(np.v);
}

/// \copydoc extend()
template <typename T, typename Tag, typename Base>
Named_function_parameters<T, Tag, Base>
extend(const CGAL::Named_function_parameters<T, Tag, Base>& np)
{
  return Named_function_parameters<T, Tag, Base>(np.v, static_cast<const Base&>(np));
}

#define CGAL_TS_chain_start(TAG_NAMESPACE, X, Z)              \
  template <typename K>                                       \
  Named_function_parameters<K, TAG_NAMESPACE::X> Z(const K& k) \
  {                                                           \
    return Named_function_parameters<K, TAG_NAMESPACE::X>(k);  \
  }
#define CGAL_add_named_parameter(X, Y, Z) CGAL_TS_chain_start(CGAL::internal_np, X, Z)
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define CGAL_TS_add_named_parameter(X, Y, Z) \
  CGAL_TS_chain_start(CGAL::Tilable_surfaces::internal_np, X, Z)
#include <CGAL/Tilable_surfaces/internal/parameters_interface.h>
#undef CGAL_TS_add_named_parameter
#undef CGAL_TS_chain_start

using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::get_parameter_reference;
using CGAL::parameters::is_default_parameter;

} // namespace parameters

namespace internal {

// The two maps of a clustered mesh, which the functions that read or write a
// clustering require: a compile error, naming them, when they are missing.
template <typename NamedParameters>
constexpr void require_face_maps()
{
  static_assert(!parameters::is_default_parameter<NamedParameters, internal_np::face_cluster_t>::value,
                "the named parameter face_cluster_map is required");
  static_assert(!parameters::is_default_parameter<NamedParameters, internal_np::face_orientation_t>::value,
                "the named parameter face_orientation_map is required");
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_NAMED_PARAMETERS_H
