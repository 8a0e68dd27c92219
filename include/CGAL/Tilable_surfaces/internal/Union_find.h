// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_UNION_FIND_H
#define CGAL_TILABLE_SURFACES_INTERNAL_UNION_FIND_H

// The package's one union-find: Boost's disjoint sets (union by rank, full path
// compression) over the rank and parent arrays `Storage` holds. With a
// std::vector the sets can be reset without reallocating; with a std::array
// they live on the stack, for the few ids a merge or a re-tagging touches.

#include <boost/pending/disjoint_sets.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

template <typename Storage = std::vector<std::size_t> >
class Union_find
{
public:
  explicit Union_find(std::size_t n = 0) { reset(n); }

  // n singletons 0..n-1.
  void reset(std::size_t n)
  {
    resize(m_rank, n);
    resize(m_parent, n);
    for(std::size_t i = 0; i < n; ++i)
      sets().make_set(i);
  }

  void swap(Union_find& other)
  {
    m_rank.swap(other.m_rank);
    m_parent.swap(other.m_parent);
  }

  // Makes x a singleton again (x < the size).
  void make_set(std::size_t x) { sets().make_set(x); }

  std::size_t find(std::size_t x) const { return sets().find_set(x); }

  // Joins the sets of a and b; false when they were one set already.
  bool unite(std::size_t a, std::size_t b)
  {
    a = find(a);
    b = find(b);
    if(a == b)
      return false;
    sets().link(a, b);
    return true;
  }

private:
  static void resize(std::vector<std::size_t>& v, std::size_t n) { v.resize(n); }
  template <std::size_t N>
  static void resize(std::array<std::size_t, N>&, std::size_t) {}

  boost::disjoint_sets<std::size_t*, std::size_t*> sets() const
  {
    return boost::disjoint_sets<std::size_t*, std::size_t*>(m_rank.data(), m_parent.data());
  }

  mutable Storage m_rank, m_parent; // find() compresses paths
};

// For at most N distinct ids: each id gets a slot on first sight.
template <std::size_t N>
class Small_union_find
{
public:
  // The slot of `id`, given on first sight, and whether this was the first.
  std::pair<std::size_t, bool> slot(std::size_t id)
  {
    for(std::size_t i = 0; i < m_size; ++i)
      if(m_id[i] == id)
        return {i, false};
    m_id[m_size] = id;
    m_sets.make_set(m_size);
    return {m_size++, true};
  }

  // The number of ids seen.
  std::size_t size() const { return m_size; }

  Union_find<std::array<std::size_t, N> >& sets() { return m_sets; }

private:
  std::array<std::size_t, N> m_id;
  std::size_t m_size = 0;
  Union_find<std::array<std::size_t, N> > m_sets;
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_INTERNAL_UNION_FIND_H
