#!/usr/bin/env python3
"""The interactive loop of the user manual's section "Step by step", in Python, one test per step.

    PYTHONPATH=build/python python3 test_interactive_loop.py MESH.off EXAMPLE.py

KSetTilableSurface on a small quad mesh: construct, cluster, look, merge, split, re-tag,
optimize, measure, catalog, optimize_closest, refine_to, restore_input; the steps run in
order on one object (LoopTest's tests are numbered). Every reported fact is recomputed in
numpy (numpy_checks.py): the degree of flexibility by a union-find over the S-quad edges,
congruence by Kabsch fits of the instances onto each other, the Hausdorff distance by
point-to-triangle distances, the molds by fits of the S-quads. Then the progress callback,
the deviation budget, the K curve and bad input.
"""
import sys
import unittest

import numpy as np

import numpy_checks as nc
import tilable_surfaces as ts

MESH, EXAMPLE = sys.argv[1], sys.argv[2]
VERTICES, FACES = nc.read_mesh(MESH, EXAMPLE)
K = 7
# A quick search: the tests check what is reported, not how good it is.
FAST = dict(seed=3, number_of_candidates=8, threads=1)
FAST_SEARCH = dict(optimized_candidates=1, improvement_rounds=0)
# Deviation budget (a fraction of the bounding-box diagonal) and the largest K tried for it.
BUDGET, BUDGET_KMAX = 0.32, 8
# Round-off allowed between the program's measures and numpy's: relative, or absolute for
# congruence errors, which are near 0.
ROUND_OFF = 1e-9
PHASES = {"validation", "clustering", "optimization", "threshold clustering", "exact starts", "merges",
          "other candidates", "orientations", "sweep candidate", "displacement prediction",
          "candidate optimization", "improvement round"}


class Recorder:
    """A progress callable that records what it receives and stops when told."""

    def __init__(self, stop_at_iteration=None):
        self.phases, self.iterations, self.stop_at_iteration = [], [], stop_at_iteration

    def __call__(self, kind, *values):
        if kind == "phase":
            self.phases.append(values[0])
            return None
        self.iterations.append(values)
        return self.stop_at_iteration is None or values[0] < self.stop_at_iteration


class Checks(unittest.TestCase):
    def check_clustering_facts(self, s, dof):
        """The DOF an edit returned against the class's own reports and our union-find."""
        clusters, orientations = s.face_clusters(), s.face_orientations()
        k = s.number_of_clusters
        self.assertEqual(sorted(set(clusters.tolist())), list(range(k)))
        self.assertTrue(np.all((orientations >= 0) & (orientations < 8)))
        self.assertEqual(dof, s.degree_of_flexibility())
        self.assertEqual(dof, s.clustering()["degree_of_flexibility"])
        self.assertEqual(dof, nc.degree_of_flexibility(FACES, clusters, orientations))
        self.assertEqual(s.clustering()["cluster_sizes"].tolist(), np.bincount(clusters, minlength=k).tolist())

    def check_tilable(self, s, r):
        """A solve's result: congruent instances by our own fits, and its displacement."""
        vertices, clusters, orientations = s.vertices(), s.face_clusters(), s.face_orientations()
        self.assertTrue(r["is_tilable"], r["ending"])
        self.assertEqual(r["ending"], "tilable")
        self.assertLessEqual(nc.instance_congruence_error(vertices, FACES, clusters, orientations),
                             2 * nc.CONGRUENCE_TOLERANCE)
        ours = nc.congruence_error(vertices, FACES, clusters, orientations, r["s_quads"])
        self.assertLessEqual(ours, nc.CONGRUENCE_TOLERANCE)
        self.assertAlmostEqual(ours, r["congruence_error"], delta=ROUND_OFF)
        moved = np.linalg.norm(vertices - VERTICES, axis=1)
        self.assertAlmostEqual(moved.max(), r["max_displacement"], delta=ROUND_OFF * moved.max())
        self.assertGreater(moved.max(), 0.0)


class LoopTest(Checks):
    """The manual's loop, step by step, on one object."""

    @classmethod
    def setUpClass(cls):
        cls.s = ts.KSetTilableSurface(VERTICES, FACES)

    def test_01_construct(self):
        s = self.s
        self.assertFalse(s.is_clustered)
        np.testing.assert_array_equal(s.input_vertices(), VERTICES)
        np.testing.assert_array_equal(s.vertices(), VERTICES)
        with self.assertRaises(ValueError):
            s.measure()

    def test_02_cluster(self):
        s, progress = self.s, Recorder()
        c = s.cluster(K, progress=progress, **FAST)
        self.assertTrue(s.is_clustered)
        self.assertEqual(c["number_of_clusters"], K)
        self.assertEqual(s.number_of_clusters, K)
        self.assertEqual(c["cluster_sizes"].sum(), len(FACES))
        self.check_clustering_facts(s, c["degree_of_flexibility"])
        self.assertLess(c["chosen_candidate"], len(c["candidates"]))
        self.assertTrue(c["choice_reason"])
        # The chosen candidate is the clustering: the same partition of the faces.
        chosen = c["candidates"][c["chosen_candidate"]]["face_cluster"]
        pairs = set(zip(chosen.tolist(), s.face_clusters().tolist()))
        self.assertEqual(len(pairs), K)
        self.assertIn("threshold clustering", progress.phases)
        self.assertIn("orientations", progress.phases)
        self.assertLessEqual(set(progress.phases), PHASES)
        np.testing.assert_array_equal(s.vertices(), VERTICES)

    def test_03_look(self):
        c = self.s.clustering()
        self.assertEqual(c["s_quads"].shape, (K, 4, 3))
        np.testing.assert_allclose(c["s_quads"].mean(axis=1), 0.0, atol=1e-12)
        for candidate in c["candidates"]:
            self.assertEqual(candidate["face_cluster"].shape, (len(FACES),))
            self.assertTrue(candidate["origin"])

    def test_04_merge(self):
        s = self.s
        before = s.face_clusters()
        a, b = np.argsort(np.bincount(before))[:2]
        kept, removed = min(a, b), max(a, b)
        dof = s.merge_clusters(int(a), int(b))
        after = s.face_clusters()
        self.assertEqual(len(np.unique(after)), len(np.unique(before)) - 1)
        expected = np.where(before == removed, kept, before)
        np.testing.assert_array_equal(after, np.where(expected > removed, expected - 1, expected))
        self.check_clustering_facts(s, dof)

    def test_05_split(self):
        s = self.s
        before = s.face_clusters()
        c = int(np.argmax(np.bincount(before)))
        dof = s.split_cluster(c)
        after = s.face_clusters()
        self.assertEqual(s.number_of_clusters, K)
        new = K - 1
        np.testing.assert_array_equal(after[before != c], before[before != c])
        parts = after[before == c]
        self.assertEqual(set(parts.tolist()), {c, new})
        self.check_clustering_facts(s, dof)

    def test_06_retag(self):
        s = self.s
        before = s.face_clusters()
        dof = s.retag_orientations()
        np.testing.assert_array_equal(s.face_clusters(), before)
        self.check_clustering_facts(s, dof)

    def test_07_optimize(self):
        s, progress = self.s, Recorder()
        r = s.optimize(progress=progress)
        self.check_tilable(s, r)
        numbers = [i[0] for i in progress.iterations]
        self.assertEqual(numbers[0], 0)
        self.assertEqual(numbers[-1], r["iterations"])
        self.assertFalse(r["stopped_by_visitor"])
        self.assertEqual(s.optimization()["congruence_error"], r["congruence_error"])

    def test_08_measure(self):
        s = self.s
        m = s.measure()
        vertices = s.vertices()
        self.assertEqual(m["number_of_clusters"], K)
        self.assertAlmostEqual(nc.hausdorff_distance(vertices, VERTICES, FACES), m["hausdorff_distance"],
                               delta=ROUND_OFF * m["hausdorff_distance"])
        self.assertLessEqual(m["mean_symmetric_distance"], m["hausdorff_distance"])
        molds = nc.distinct_molds(m["s_quads"], nc.CONGRUENCE_TOLERANCE * m["mean_edge_length"])
        self.assertEqual(m["number_of_distinct_molds"], len(set(molds.tolist())))
        np.testing.assert_array_equal(m["cluster_molds"], molds)
        self.assertTrue(0 <= m["flattened_panels"] <= len(FACES))
        self.assertGreaterEqual(m["self_intersecting_face_pairs"], 0)
        self.assertIsInstance(m["buildability_warnings"], list)

    def test_09_catalog(self):
        s = self.s
        catalog, m = s.tile_catalog(), s.measure()
        clusters, orientations, vertices = s.face_clusters(), s.face_orientations(), s.vertices()
        np.testing.assert_array_equal(catalog["instance_count"], np.bincount(clusters, minlength=K))
        np.testing.assert_array_equal(catalog["mold"], m["cluster_molds"])
        np.testing.assert_array_equal(catalog["mirrored_count"], 0)
        corners = catalog["corners"]
        np.testing.assert_allclose(corners[:, 0], 0.0, atol=1e-12)       # t0 at the origin
        np.testing.assert_allclose(corners[:, 1, 1:], 0.0, atol=1e-12)   # t1 on the x axis
        np.testing.assert_allclose(corners[:, 2, 2], 0.0, atol=1e-12)    # t2 in the xy plane
        self.assertTrue(np.all(corners[:, 1, 0] > 0) and np.all(corners[:, 2, 1] >= 0))
        for c in range(K):
            members = np.flatnonzero(clusters == c)
            worst = max(nc.kabsch_deviation(corners[c], nc.instance(vertices, FACES[f], orientations[f]))
                        for f in members)
            self.assertLessEqual(worst, nc.CONGRUENCE_TOLERANCE * m["mean_edge_length"])
            self.assertAlmostEqual(worst, catalog["worst_deviation"][c],
                                   delta=nc.CONGRUENCE_TOLERANCE * m["mean_edge_length"])

    def test_10_optimize_closest(self):
        s, progress = self.s, Recorder()
        r = s.optimize_closest(progress=progress, **FAST_SEARCH)
        self.check_tilable(s, r)
        self.assertLessEqual(set(progress.phases), PHASES)
        self.check_clustering_facts(s, s.degree_of_flexibility())

    def test_11_refine_to(self):
        s = self.s
        r = s.refine_to(K + 2)
        self.assertEqual(s.number_of_clusters, K + 2)
        self.assertEqual(r["number_of_clusters"], K + 2)
        self.check_tilable(s, r)

    def test_12_restore_input(self):
        self.s.restore_input()
        np.testing.assert_array_equal(self.s.vertices(), VERTICES)


class ProgressTest(unittest.TestCase):
    def test_phases_of_the_one_call(self):
        progress = Recorder()
        r = ts.make_k_set_tilable(VERTICES, FACES, k=K, progress=progress, **FAST, **FAST_SEARCH)
        self.assertEqual(progress.phases[0], "validation")
        self.assertIn("clustering", progress.phases)
        self.assertEqual(progress.phases[-1], "optimization")
        self.assertLessEqual(set(progress.phases), PHASES)
        self.assertFalse(r["stopped_by_visitor"])

    def test_false_stops_the_solver(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        s.cluster(K, **FAST)
        progress = Recorder(stop_at_iteration=1)
        r = s.optimize(progress=progress)
        self.assertTrue(r["stopped_by_visitor"])
        self.assertEqual(r["ending"], "stopped by the visitor")
        self.assertEqual(r["iterations"], 1)
        self.assertEqual([i[0] for i in progress.iterations], [0, 1])
        # At iteration 0 no step is made, and the search ends (a sweep may start exact: it is not
        # said whether the result is tilable).
        again = ts.make_k_set_tilable(VERTICES, FACES, k=K, progress=Recorder(stop_at_iteration=0), **FAST)
        self.assertTrue(again["stopped_by_visitor"])

    def test_an_exception_of_the_callable_is_raised_and_the_object_stays_usable(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        s.cluster(K, **FAST)

        def fails(kind, *values):
            raise ZeroDivisionError("from the callback")

        with self.assertRaises(ZeroDivisionError):
            s.optimize(progress=fails)
        self.assertTrue(s.optimize()["is_tilable"])

    def test_the_callable_cannot_use_the_object_of_its_step(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        s.cluster(K, **FAST)
        with self.assertRaises(ValueError) as caught:
            s.optimize(progress=lambda *event: s.vertices())
        self.assertIn("progress callable", str(caught.exception))
        self.assertTrue(s.optimize()["is_tilable"])

    def test_the_gil_is_free_for_other_threads_while_the_callable_is_called(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        s.cluster(K, **FAST)
        calls = []
        pause, duration = nc.longest_pause(
            lambda: s.optimize_closest(progress=lambda *event: calls.append(event), **FAST_SEARCH))
        self.assertTrue(calls)
        self.assertLess(pause, 0.5 * duration)


class DeviationBudgetTest(unittest.TestCase):
    def test_smallest_k_within_the_budget(self):
        r = ts.make_k_set_tilable(VERTICES, FACES, max_deviation=BUDGET, k=BUDGET_KMAX, **FAST, **FAST_SEARCH)
        trials = r["trials"]
        meets = trials["is_tilable"] & (trials["self_intersecting_face_pairs"] == 0) & \
            (trials["hausdorff_distance"] <= BUDGET)
        self.assertTrue(meets.any(), "no K up to BUDGET_KMAX meets the budget: raise BUDGET_KMAX")
        k = r["number_of_clusters"]
        self.assertEqual(k, trials["K"][meets].min())
        # Within the budget by our own distances; the K below was tried and missed it.
        ours = nc.hausdorff_distance(r["vertices"], VERTICES, FACES)
        self.assertLessEqual(ours, BUDGET)
        self.assertAlmostEqual(ours, r["hausdorff_distance"], delta=ROUND_OFF * ours)
        self.assertTrue(r["is_tilable"])
        self.assertLessEqual(nc.instance_congruence_error(r["vertices"], FACES, r["cluster"], r["orientation"]),
                             2 * nc.CONGRUENCE_TOLERANCE)
        if k > 1:
            below = np.flatnonzero(trials["K"] == k - 1)
            self.assertEqual(len(below), 1, "K - 1 was tried")
            self.assertFalse(meets[below[0]])

    def test_curve(self):
        kmin, kmax, step = 4, 8, 2
        c = ts.curve(VERTICES, FACES, kmin, kmax, step, **FAST, **FAST_SEARCH)
        np.testing.assert_array_equal(c["K"], np.arange(kmin, kmax + 1, step))
        self.assertEqual(c["is_tilable"].dtype, np.bool_)
        np.testing.assert_array_equal(c["is_tilable"], c["congruence_error"] <= nc.CONGRUENCE_TOLERANCE)
        # More molds never end farther than fewer, among the results one can build.
        buildable = c["is_tilable"] & (c["self_intersecting_face_pairs"] == 0)
        distances = c["hausdorff_distance"][buildable]
        self.assertTrue(np.all(np.diff(distances) <= ROUND_OFF))
        self.assertTrue(np.all(c["refined_from"][c["refined_from"] > 0] < c["K"][c["refined_from"] > 0]))


class BadInputTest(unittest.TestCase):
    def test_value_errors_with_the_package_message(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        cases = [
            (lambda: s.cluster(0), "k must be at least 1"),
            (lambda: s.merge_clusters(0, 1), "clustering"),
            (lambda: ts.make_k_set_tilable(VERTICES, FACES), "k must be at least 1"),
            (lambda: ts.make_k_set_tilable(VERTICES, FACES, k=K, seed=-1), "seed cannot be -1"),
            (lambda: ts.make_k_set_tilable(VERTICES, FACES, k=K, progress=3), "progress must be callable"),
            (lambda: ts.curve(VERTICES, FACES, 5, 4), "kmin <= kmax"),
            (lambda: ts.KSetTilableSurface(VERTICES[:, :2], FACES), "(n, 3)"),
        ]
        s2 = ts.KSetTilableSurface(VERTICES, FACES)
        s2.cluster(K, **FAST)
        cases += [
            (lambda: s2.merge_clusters(2, 2), "with itself"),
            (lambda: s2.merge_clusters(-1, 2), "no cluster -1"),
            (lambda: s2.split_cluster(K), "cluster"),
            (lambda: s2.use_candidate(10 ** 6), "no clustering candidate"),
            (lambda: s2.refine_to(K - 1), "cannot refine"),
            (lambda: s2.set_clustering(np.zeros(3, int), np.zeros(3, int)), "one per face"),
        ]
        for call, message in cases:
            with self.subTest(message=message):
                with self.assertRaises(ValueError) as caught:
                    call()
                self.assertTrue(str(caught.exception).startswith("Tilable_surfaces: "), str(caught.exception))
                self.assertIn(message, str(caught.exception))
        self.assertEqual(s2.number_of_clusters, K, "a refused edit changes nothing")

    def test_unknown_keyword_is_a_type_error(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        with self.assertRaises(TypeError):
            s.cluster(K, solver="gauss-newton")
        with self.assertRaises(TypeError):
            ts.make_k_set_tilable(VERTICES, FACES, k=K, colour="red")

    def test_set_clustering_from_arrays(self):
        s = ts.KSetTilableSurface(VERTICES, FACES)
        s.cluster(K, **FAST)
        t = ts.KSetTilableSurface(VERTICES.tolist(), FACES.astype(np.int32))
        dof = t.set_clustering(s.face_clusters(), s.face_orientations())
        self.assertEqual(dof, s.degree_of_flexibility())
        np.testing.assert_array_equal(t.face_clusters(), s.face_clusters())
        self.assertEqual(t.orientation_policy, "proper_rigid_motions")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
