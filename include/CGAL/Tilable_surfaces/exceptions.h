// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_EXCEPTIONS_H
#define CGAL_TILABLE_SURFACES_EXCEPTIONS_H

/// \file exceptions.h
/// The exception types thrown by the package.

#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Tilable_surfaces {

/// \ingroup PkgTilableSurfacesRef
/// Thrown when the input (mesh, property maps or parameter values) cannot be
/// processed. The message names the first offending element; `element()` and
/// `index()` give it in a form a program can use. The functions that throw it
/// do so before they modify anything the user passed in.
class Invalid_input : public std::invalid_argument
{
public:
  /// The kind of element the error is about.
  enum Element { MESH, VERTEX, FACE, EDGE, PARAMETER };

  /// An error about `element` number `index`, explained by `message`.
  Invalid_input(const std::string& message,
                Element element = MESH,
                std::size_t index = (std::numeric_limits<std::size_t>::max)())
    : std::invalid_argument("Tilable_surfaces: " + message)
    , m_element(element)
    , m_index(index)
  {}

  /// The kind of the offending element.
  Element element() const { return m_element; }
  /// Its index (the vertex, face or edge index map value), or
  /// `std::numeric_limits<std::size_t>::max()` for the mesh or a parameter.
  std::size_t index() const { return m_index; }

private:
  Element m_element;
  std::size_t m_index;
};

} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_EXCEPTIONS_H
