// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_CLUSTER_EDITING_IMPL_H
#define CGAL_TILABLE_SURFACES_CLUSTER_EDITING_IMPL_H

// The bodies of the non-template functions declared in cluster_editing.h: inline when the package
// is used header-only, else compiled once into the package's library (internal/config.h).

#include <CGAL/Tilable_surfaces/cluster_editing.h>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

CGAL_TILABLE_SURFACES_INLINE
Panel_orientation merge_clusters(Face_clustering& fc, const std::vector<Panel>& quads, std::size_t a,
                                std::size_t b, Orientation_policy policy)
{
  fc.check_cluster(a);
  fc.check_cluster(b);
  if(a == b)
    throw Invalid_input("cannot merge cluster " + std::to_string(a) + " with itself",
                        Invalid_input::PARAMETER);
  const std::size_t kept = (std::min)(a, b), removed = (std::max)(a, b);
  const std::vector<std::vector<std::size_t> > members = cluster_members(fc.label, fc.number_of_clusters);
  const int n = members[kept].empty() ? 4 : quads[members[kept].front()].size();
  if(!members[removed].empty() && quads[members[removed].front()].size() != n)
    throw Invalid_input("cannot merge cluster " + std::to_string(removed) + " into cluster " +
                        std::to_string(kept) + ": a quad cluster and a triangle cluster",
                        Invalid_input::PARAMETER);
  auto s_quad = [&](std::size_t c) {
    std::vector<Panel_orientation> o;
    for(std::size_t f : members[c]) o.push_back(fc.orientation[f]);
    return procrustes_mean(quads, members[c], policy, &o);
  };
  const Panel_orientation correspondence = fast_best_match(s_quad(kept), s_quad(removed), policy).orientation;
  for(std::size_t f : members[removed])
  {
    fc.orientation[f] = compose(fc.orientation[f], correspondence, n);
    fc.label[f] = kept;
  }
  for(std::size_t& l : fc.label)
    if(l > removed) --l;
  --fc.number_of_clusters;
  return correspondence;
}

CGAL_TILABLE_SURFACES_INLINE
void split_cluster(Face_clustering& fc, const std::vector<Panel>& quads, std::size_t c,
                   Orientation_policy policy, CGAL::Random& random)
{
  fc.check_cluster(c);
  const std::vector<std::size_t> members = cluster_members(fc.label, fc.number_of_clusters)[c];
  if(members.size() < 2)
    throw Invalid_input("cluster " + std::to_string(c) + " has a single face, it cannot be split",
                        Invalid_input::PARAMETER);
  std::vector<Quad_descriptor> descriptors(quads.size());
  for(std::size_t f : members) descriptors[f] = shape_descriptor(quads[f]);
  const std::vector<bool> second = split_in_two(quads, descriptors, members, policy, random);
  std::vector<std::size_t> part[2];
  for(std::size_t i = 0; i < second.size(); ++i)
  {
    part[second[i] ? 1 : 0].push_back(members[i]);
    if(second[i]) fc.label[members[i]] = fc.number_of_clusters;
  }
  ++fc.number_of_clusters;
  for(const std::vector<std::size_t>& p : part)
  {
    const Panel s_quad = procrustes_mean(quads, p, policy);
    for(std::size_t f : p)
      fc.orientation[f] = fast_best_match(s_quad, quads[f], policy).orientation;
  }
}

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#endif // CGAL_TILABLE_SURFACES_CLUSTER_EDITING_IMPL_H
