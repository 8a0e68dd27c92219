// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_H

// A kd-tree (CGAL spatial searching) on the 6 length components of the quad
// descriptors: sorted edge lengths and sorted diagonal lengths.
//
// Why it is an exact prefilter: if s(p, q) = sum_i |q_o(i) - T(p_i)| then each
// edge or diagonal length of p differs from the matching one of q by at most
// the two corner distances, hence by at most s(p, q); sorting keeps that bound
// (sorting is 1-Lipschitz for the max norm). So every q with s(p, q) < tau lies
// in the box of half-width tau around p's lengths. The volume component is not
// Lipschitz in the corners and is left out.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/quad_shape.h>

#include <CGAL/Fuzzy_iso_box.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

struct Length_point
{
  std::array<double, 6> c;
  std::size_t index;
  bool operator==(const Length_point& o) const { return index == o.index; }
  bool operator!=(const Length_point& o) const { return index != o.index; }
};

struct Construct_length_iterator
{
  typedef const double* result_type;
  const double* operator()(const Length_point& p) const { return p.c.data(); }
  const double* operator()(const Length_point& p, int) const { return p.c.data() + 6; }
};

// The search traits, with the box types that `Fuzzy_iso_box` asks for.
struct Length_traits
  : CGAL::Search_traits<double, Length_point, const double*, Construct_length_iterator,
                        CGAL::Dimension_tag<6> >
{
  struct Iso_box_d { Length_point min, max; };
  struct Construct_iso_box_d
  {
    Iso_box_d operator()(const Length_point& p, const Length_point& q) const { return {p, q}; }
  };
  struct Construct_min_vertex_d
  {
    typedef Length_point result_type;
    Length_point operator()(const Iso_box_d& b) const { return b.min; }
  };
  struct Construct_max_vertex_d
  {
    typedef Length_point result_type;
    Length_point operator()(const Iso_box_d& b) const { return b.max; }
  };
};

class Descriptor_index
{
  typedef Length_traits Traits;
  typedef CGAL::Kd_tree<Traits> Tree;
  typedef CGAL::Fuzzy_iso_box<Traits> Box;

public:
  explicit Descriptor_index(const std::vector<Quad_descriptor>& descriptors);

  // Indices, increasing, of the descriptors within max-norm distance
  // `half_width` of `d` on the 6 length components.
  std::vector<std::size_t> in_box(const Quad_descriptor& d, double half_width) const;

private:
  Tree m_tree;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/descriptor_index_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_DESCRIPTOR_INDEX_H
