// Copyright (c) 2026 Tilable_surfaces contributors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_H
#define CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_H

// Segment clusterings of quad meshes that are not one grid, for the final
// pool of cluster_panels(): the grid segments of segment_candidates.h per
// patch of the quad layout (Shape_analysis/quad_layout.h), with molds shared
// across patches.
//
// 1. Per patch, in both directions of its grid, the runs of rows with m
//    molds of least spread (Run_partitions), for every m.
// 2. M molds in all are spread over the patches by that spread: one each,
//    then each further mold where it lowers the spread most per mold.
// 3. A cluster whose quads are twisted both ways (signed volumes in the
//    labelling of its S-quad, the one the optimization pairs corners by, of
//    opposite signs, both significant: twist_sign.h) is split by sign:
//    such quads can only become congruent by flattening.
// 4. The clusters are merged across patches, least increase of the spread
//    of their six corner distances first (Ward's criterion, each pair in its
//    best corner correspondence), never mixing twist signs, down to K;
//    steps 3 and 4 repeat until no cluster mixes twists.
// The candidates differ by M (tuning::patch_mold_factors times K, at least
// one mold per patch): more molds per patch keep more of each patch's
// structure and share more across patches.

#include <CGAL/Tilable_surfaces/internal/config.h>
#include <CGAL/Tilable_surfaces/internal/Clustering/segment_candidates.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/quad_layout.h>
#include <CGAL/Tilable_surfaces/internal/Shape_analysis/twist_sign.h>
#include <CGAL/Tilable_surfaces/internal/tuning.h>

#include <CGAL/Random.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <memory>
#include <vector>

namespace CGAL {
namespace Tilable_surfaces {
namespace internal {

// The sign of the permutation i -> o(i) of the corners: the factor of the
// signed volume of a quad relabelled by o.
inline int orientation_sign(Panel_orientation o)
{
  return ((o.index() & 1) != 0) != o.is_reversed() ? -1 : 1;
}

// A cluster of quads in a common corner labelling: the sum of their corner
// distances and their largest twists of each sign.
struct Mold_sum
{
  std::size_t count = 0;
  Eigen::Matrix<double, 6, 1> distances = Eigen::Matrix<double, 6, 1>::Zero();
  double positive_twist = 0, negative_twist = 0;  // largest 6 x signed volume of each sign, as magnitudes

  void add(const Panel& q);
  // The twist of a quad of the mean edge planar as far as its mold is concerned.
  double planar_twist() const
  {
    const double edge = distances.head<4>().sum() / double(4 * count);
    return tuning::planar_twist * edge * edge * edge;
  }
  double significant_twist() const
  {
    return internal::significant_twist((std::max)(positive_twist, negative_twist), planar_twist());
  }
  // Both signs significant (twists_oppose()): a mix that only flattening
  // makes congruent.
  bool mixes_twists() const { return twists_oppose(positive_twist, -negative_twist, planar_twist()); }
  // With `other` in this labelling, `other` matched with orientation o.
  Mold_sum merged(const Mold_sum& other, Panel_orientation o) const;
  // Ward's increase of the spread when merged with `other` matched by o.
  double merge_cost(const Mold_sum& other, Panel_orientation o) const;
};

// The runs of rows of one grid patch, in both directions of its grid and
// every set of run options, for up to `max_molds` molds.
struct Patch_runs
{
  std::vector<std::unique_ptr<Segment_options> > grids;
  std::vector<std::unique_ptr<Run_partitions> > partitions;

  Patch_runs(const std::array<const Quad_grid*, 2>& grid, std::size_t max_molds, Orientation_policy policy);

  // The partition of least cost with exactly m molds, or none.
  const Run_partitions* best(std::size_t m) const
  {
    const Run_partitions* found = nullptr;
    for(const std::unique_ptr<Run_partitions>& p : partitions)
      if(p->cost(m) < (std::numeric_limits<double>::max)() && (found == nullptr || p->cost(m) < found->cost(m)))
        found = p.get();
    return found;
  }
  double cost(std::size_t m) const
  {
    const Run_partitions* p = best(m);
    return p == nullptr ? (std::numeric_limits<double>::max)() : p->cost(m);
  }
};

// The quad layout of a mesh with the runs of rows of each patch (both
// layouts, rows along either direction of each patch's grid), and the
// clusterings made from them (steps 2 to 4 above).
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
class Patch_segment_clusterer
{
public:
  Patch_segment_clusterer(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                          const std::vector<Panel>& panels, std::size_t k, Orientation_policy policy)
    : m_panels(panels), m_k(k), m_policy(policy)
  {
    const Quad_layout rows_first = quad_layout(pm, fim, vpm, 0), columns_first = quad_layout(pm, fim, vpm, 1);
    m_faces = patch_faces(rows_first.patch_of_face);
    const std::size_t most =
      (std::min)(panels.size(), k * *std::max_element(std::begin(tuning::patch_mold_factors),
                                                      std::end(tuning::patch_mold_factors)));
    const bool grids = applies(rows_first);
    for(std::size_t p = 0; p < m_faces.size() && grids; ++p)
      m_runs.emplace_back(new Patch_runs({&rows_first.grids[p], &columns_first.grids[p]},
                                         (std::min)(m_faces[p].size(), most), policy));
  }

  std::size_t number_of_patches() const { return m_runs.size(); }

  // The clustering with k clusters from `molds` molds spread over the
  // patches (at least one each), or an empty vector when the layout has a
  // patch that is not a grid, or fewer than 2 patches, or when the twists
  // of its clusters still mix after tuning::patch_twist_passes passes.
  std::vector<std::size_t> clustering(std::size_t molds) const
  {
    if(m_runs.size() < 2)
      return std::vector<std::size_t>();
    std::vector<std::size_t> label = patch_labels(spread(molds));
    for(int round = 0; round < tuning::patch_twist_passes; ++round)
    {
      bool split = false;
      for(int pass = 0; pass < tuning::patch_twist_passes && split_twists(label, labelled_panels(label)); ++pass)
        split = true;
      if(!split && relabel_by_first_face(label) <= m_k)
        return label;
      merge_to_k(label);
    }
    return std::vector<std::size_t>();
  }

private:
  static bool applies(const Quad_layout& layout)
  {
    for(const Quad_grid& g : layout.grids)
      if(g.rows == 0)
        return false;
    return layout.grids.size() >= 2;
  }

  // The molds of every patch: one each, then each further mold (or run of
  // molds, where some counts cannot be reached) where it lowers the spread
  // most per mold.
  std::vector<std::size_t> spread(std::size_t molds) const
  {
    std::vector<std::size_t> m(m_runs.size(), 1);
    for(std::size_t left = molds > m.size() ? molds - m.size() : 0; left > 0;)
    {
      double best_gain = -1;
      std::size_t best_patch = 0, best_molds = 0;
      for(std::size_t p = 0; p < m_runs.size(); ++p)
      {
        const double now = m_runs[p]->cost(m[p]);
        for(std::size_t to = m[p] + 1; to <= m[p] + left && to <= m_faces[p].size(); ++to)
        {
          const double cost = m_runs[p]->cost(to);
          if(cost == (std::numeric_limits<double>::max)())
            continue;
          const double gain = (now - cost) / double(to - m[p]);
          if(gain > best_gain)
          {
            best_gain = gain;
            best_patch = p;
            best_molds = to;
          }
        }
      }
      if(best_gain < 0)
        break;
      left -= best_molds - m[best_patch];
      m[best_patch] = best_molds;
    }
    return m;
  }

  // Every face's cluster: the runs of its patch with the molds of `m`,
  // numbered apart from the other patches'.
  std::vector<std::size_t> patch_labels(const std::vector<std::size_t>& m) const
  {
    std::vector<std::size_t> label(m_panels.size(), 0);
    std::size_t first = 0;
    for(std::size_t p = 0; p < m_runs.size(); ++p)
    {
      const Run_partitions* runs = m_runs[p]->best(m[p]);
      const std::vector<std::size_t> local = runs != nullptr ? runs->label(m[p])
                                                             : std::vector<std::size_t>(m_faces[p].size(), 0);
      for(std::size_t i = 0; i < local.size(); ++i)
        label[m_faces[p][i]] = first + local[i];
      first += m[p];
    }
    relabel_by_first_face(label);
    return label;
  }

  // Each face in the labelling of its cluster's S-quad (cluster_shapes()),
  // the one the optimization pairs its corners by.
  std::vector<Panel> labelled_panels(std::vector<std::size_t>& label) const
  {
    const std::size_t clusters = relabel_by_first_face(label);
    const Cluster_shapes shapes = cluster_shapes(m_panels, label, clusters, m_policy);
    std::vector<Panel> labelled(label.size());
    for(std::size_t f = 0; f < label.size(); ++f)
      labelled[f] = reoriented(m_panels[f], shapes.orientation[f]);
    return labelled;
  }

  // The sums of the clusters of `label`, numbered from 0, with each face
  // as in `labelled`.
  static std::vector<Mold_sum> mold_sums(const std::vector<std::size_t>& label, const std::vector<Panel>& labelled)
  {
    std::vector<Mold_sum> sum(*std::max_element(label.begin(), label.end()) + 1);
    for(std::size_t f = 0; f < label.size(); ++f)
      sum[label[f]].add(labelled[f]);
    return sum;
  }

  // Clusters that mix twist signs (Mold_sum::mixes_twists()) split by sign:
  // the quads twisted against the larger sign, beyond
  // tuning::twist_split_margin times the significance, form a cluster of
  // their own.
  // Whether any was split.
  static bool split_twists(std::vector<std::size_t>& label, const std::vector<Panel>& labelled)
  {
    const std::vector<Mold_sum> sum = mold_sums(label, labelled);
    std::vector<std::size_t> opposite(sum.size(), no_index());
    std::size_t next = sum.size();
    for(std::size_t f = 0; f < label.size(); ++f)
    {
      const Mold_sum& s = sum[label[f]];
      if(!s.mixes_twists())
        continue;
      const double larger = s.positive_twist >= s.negative_twist ? 1 : -1;
      if(6 * signed_volume(labelled[f]) * larger < -tuning::twist_split_margin * s.significant_twist())
      {
        if(opposite[label[f]] == no_index())
          opposite[label[f]] = next++;
        label[f] = opposite[label[f]];
      }
    }
    return next > sum.size();
  }

  // The sum of the quads `members`, each in the labelling of their S-quad.
  Mold_sum shape_sum(const std::vector<std::size_t>& members) const
  {
    const Panel s_quad = procrustes_mean(m_panels, members, m_policy);
    Mold_sum sum;
    for(std::size_t f : members)
      sum.add(reoriented(m_panels[f], fast_best_match(s_quad, m_panels[f], m_policy).orientation));
    return sum;
  }

  // The clusters merged, least Ward increase first, down to k (or as far as
  // twists allow). A merge is kept when the merged quads, in the labelling
  // of their S-quad, do not mix twists.
  void merge_to_k(std::vector<std::size_t>& label) const
  {
    const std::size_t clusters = relabel_by_first_face(label);
    std::vector<std::vector<std::size_t> > members = cluster_members(label, clusters);
    std::vector<Mold_sum> sum(clusters);
    parallel_for(clusters, [&](std::size_t c) { sum[c] = shape_sum(members[c]); });
    std::vector<std::size_t> parent(clusters);
    for(std::size_t c = 0; c < clusters; ++c) parent[c] = c;
    std::vector<std::pair<double, Panel_orientation> > pair(clusters * clusters);
    parallel_for(clusters, [&](std::size_t a) {
      for(std::size_t b = a + 1; b < clusters; ++b) pair[a * clusters + b] = best_merge(sum[a], sum[b]);
    });
    for(std::size_t count = clusters; count > m_k;)
    {
      std::size_t kept = 0, removed = 0;
      double least = (std::numeric_limits<double>::max)();
      for(std::size_t a = 0; a < clusters; ++a)
        for(std::size_t b = a + 1; parent[a] == a && b < clusters; ++b)
          if(parent[b] == b && pair[a * clusters + b].first < least)
          {
            least = pair[a * clusters + b].first;
            kept = a;
            removed = b;
          }
      if(least == (std::numeric_limits<double>::max)())
        break;
      std::vector<std::size_t> both = members[kept];
      both.insert(both.end(), members[removed].begin(), members[removed].end());
      const Mold_sum merged = shape_sum(both);
      pair[kept * clusters + removed].first = (std::numeric_limits<double>::max)();
      if(merged.mixes_twists())
        continue;
      sum[kept] = merged;
      members[kept].swap(both);
      parent[removed] = kept;
      --count;
      for(std::size_t c = 0; c < clusters; ++c)
        if(parent[c] == c && c != kept)
          pair[(std::min)(c, kept) * clusters + (std::max)(c, kept)] =
            c < kept ? best_merge(sum[c], sum[kept]) : best_merge(sum[kept], sum[c]);
    }
    for(std::size_t& l : label)
      while(parent[l] != l) l = parent[l];
  }

  // The least Ward increase over the correspondences that keep twists
  // apart, with its correspondence; infinite when none does.
  std::pair<double, Panel_orientation> best_merge(const Mold_sum& a, const Mold_sum& b) const
  {
    std::pair<double, Panel_orientation> best((std::numeric_limits<double>::max)(), Panel_orientation());
    for(Panel_orientation o : admissible_orientations(4, m_policy))
    {
      const double cost = a.merge_cost(b, o);
      if(cost < best.first && !a.merged(b, o).mixes_twists())
        best = std::make_pair(cost, o);
    }
    return best;
  }

  const std::vector<Panel>& m_panels;
  std::size_t m_k;
  Orientation_policy m_policy;
  std::vector<std::vector<std::size_t> > m_faces;
  std::vector<std::unique_ptr<Patch_runs> > m_runs;
};

// The patch segment clusterings with k clusters, one per factor of
// tuning::patch_mold_factors (distinct ones), brought to k by shape splits
// (bring_to(), drawing from a generator seeded by `seed`) where the patches
// hold fewer molds, left out where twists keep more than k apart; none when
// the quads form one grid, or the layout has fewer than 2 patches or a patch
// that is not a grid.
template <typename PolygonMesh, typename FaceIndexMap, typename VertexPointMap>
std::vector<std::vector<std::size_t> >
patch_segment_clusterings(const PolygonMesh& pm, FaceIndexMap fim, VertexPointMap vpm,
                          const std::vector<Panel>& panels, const std::vector<Quad_descriptor>& descriptors,
                          std::size_t k, Orientation_policy policy, unsigned int seed)
{
  std::vector<std::vector<std::size_t> > result;
  const std::array<std::vector<std::size_t>, 2> strips = quad_strips(pm, fim);
  if(quad_grid(pm, fim, vpm, strips, 0).rows > 0 || quad_grid(pm, fim, vpm, strips, 1).rows > 0)
    return result;
  const Patch_segment_clusterer<PolygonMesh, FaceIndexMap, VertexPointMap> clusterer(pm, fim, vpm, panels, k, policy);
  for(std::size_t factor : tuning::patch_mold_factors)
  {
    const std::size_t molds = (std::max)(clusterer.number_of_patches(), (std::min)(panels.size(), factor * k));
    std::vector<std::size_t> label = clusterer.clustering(molds);
    if(label.empty())
      return result;
    const std::size_t count = *std::max_element(label.begin(), label.end()) + 1;
    if(count > k)
      continue;
    CGAL::Random random(seed);
    bring_to(k, pm, fim, vpm, panels, descriptors, policy, random, label, count);
    if(std::find(result.begin(), result.end(), label) == result.end())
      result.push_back(std::move(label));
  }
  return result;
}

// The patch-segment candidate generator (CandidateGenerator, origin
// PATCH_SEGMENTS): with `use_segment_candidates`, K > 1 and no triangle,
// when the quads are not one grid and split into at least 2 grid patches,
// the patch segment clusterings (patch_segment_clusterings()).
struct Patch_segment_generator
{
  template <typename Context>
  std::vector<typename Context::Candidate> operator()(const Context& context) const
  {
    if(!context.settings.use_segments || context.k <= 1 || context.has_triangles)
      return std::vector<typename Context::Candidate>();
    return best_match_candidates<typename Context::Candidate>(
      patch_segment_clusterings(context.mesh, context.face_index, context.vertex_point, context.panels,
                                context.descriptors, context.k, context.policy, context.seed),
      Context::PATCH_SEGMENTS);
  }
};

} // namespace internal
} // namespace Tilable_surfaces
} // namespace CGAL

#ifndef CGAL_TILABLE_SURFACES_COMPILED_LIBRARY
#include <CGAL/Tilable_surfaces/internal/Clustering/patch_candidates_impl.h>
#endif

#endif // CGAL_TILABLE_SURFACES_INTERNAL_CLUSTERING_PATCH_CANDIDATES_H
