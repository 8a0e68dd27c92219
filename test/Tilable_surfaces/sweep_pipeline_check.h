// Test helper: the pipeline ends tilable through a sweep clustering where
// nothing else is exact without solver iterations.
#ifndef TILABLE_SURFACES_TEST_SWEEP_PIPELINE_CHECK_H
#define TILABLE_SURFACES_TEST_SWEEP_PIPELINE_CHECK_H

#include "congruence_check.h"
#include "optimization_test_helpers.h"

#include <CGAL/Tilable_surfaces/make_k_set_tilable.h>

#include <gtest/gtest.h>

// make_k_set_tilable() at K = k with no solver iteration on make_mesh()
// ends tilable, checked independently, with a sweep clustering chosen; with
// no grid candidates (use_segment_candidates false) it is not tilable.
template <typename MakeMesh>
void expect_tilable_only_through_a_sweep(MakeMesh make_mesh, int k)
{
  using namespace test_helpers;
  test_helpers::Mesh m = make_mesh();
  Clustering c = add_clustering_maps(m);
  const TS::K_set_tilable_result r = TS::make_k_set_tilable(
    m, TS::parameters::number_of_tiles(k).number_of_iterations(0)
         .face_cluster_map(c.cluster).face_orientation_map(c.orientation));
  EXPECT_TRUE(r.is_tilable());
  EXPECT_EQ(r.clustering.candidates[r.clustering.chosen_candidate].origin, TS::Clustering_candidate::GRID_SWEEPS);
  EXPECT_LE(congruence_by_umeyama(m, c.cluster, c.orientation), 1e-6);

  test_helpers::Mesh without = make_mesh();
  EXPECT_FALSE(TS::make_k_set_tilable(without, TS::parameters::number_of_tiles(k).number_of_iterations(0)
                                                 .use_segment_candidates(false)).is_tilable());
}

#endif
