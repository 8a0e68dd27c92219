#!/usr/bin/env python3
"""The Python module tilable_surfaces, checked with numpy only.

    PYTHONPATH=build/python python3 test_python_module.py MESH.off EXAMPLE.py

Runs make_k_set_tilable on a small quad mesh (read with the example's OFF
reader) and checks its result independently: each face's corners, read in its
orientation, against its cluster's S-quad by a Kabsch rigid fit of our own;
the displacement; the cluster sizes; with a panel tolerance T, every face
within T of its S-quad by the same fit. Then that bad input raises ValueError
with the package's message, and that the GIL is released during the run.
"""
import sys
import unittest

import numpy as np

import numpy_checks
import tilable_surfaces
from numpy_checks import corner_of, mean_edge_length

MESH, EXAMPLE = sys.argv[1], sys.argv[2]
K = 7


def congruence_error(result, faces, corner=corner_of):
    return numpy_checks.congruence_error(result["vertices"], faces, result["cluster"], result["orientation"],
                                         result["s_quads"], corner)


class MakeKSetTilable(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.vertices, cls.faces = numpy_checks.read_mesh(MESH, EXAMPLE)
        cls.result = tilable_surfaces.make_k_set_tilable(cls.vertices, cls.faces, k=K, seed=3,
                                                         number_of_candidates=8, threads=1)

    def test_arrays(self):
        r, n, m = self.result, len(self.vertices), len(self.faces)
        self.assertEqual(r["vertices"].shape, (n, 3))
        self.assertEqual(r["vertices"].dtype, np.float64)
        self.assertEqual(r["cluster"].shape, (m,))
        self.assertEqual(r["orientation"].shape, (m,))
        self.assertEqual(r["s_quads"].shape, (K, 4, 3))
        self.assertEqual(r["number_of_clusters"], K)
        self.assertEqual(set(r["cluster"].tolist()), set(range(K)))
        self.assertTrue(np.all((r["orientation"] >= 0) & (r["orientation"] < 8)))
        self.assertEqual(np.bincount(r["cluster"], minlength=K).tolist(), r["cluster_sizes"].tolist())
        self.assertGreater(r["degree_of_flexibility"], 0)
        self.assertIsInstance(r["self_intersecting_face_pairs"], int)

    def test_congruence_by_our_own_rigid_fits(self):
        r = self.result
        self.assertTrue(r["is_tilable"])
        ours = congruence_error(r, self.faces)
        self.assertLessEqual(ours, 1e-6)
        self.assertAlmostEqual(ours, r["congruence_error"], delta=1e-9)
        # The check has teeth: the surface was moved, and another corner
        # convention (the reversed direction) does not fit.
        self.assertGreater(congruence_error(dict(r, vertices=self.vertices), self.faces), 1e-4)
        self.assertGreater(congruence_error(r, self.faces, lambda i, o: corner_of((4 - i) % 4, o)), 1e-4)

    def test_distances(self):
        r = self.result
        displacement = np.linalg.norm(r["vertices"] - self.vertices, axis=1)
        self.assertAlmostEqual(displacement.max(), r["max_displacement"], delta=1e-12)
        self.assertAlmostEqual(displacement.mean(), r["mean_displacement"], delta=1e-12)
        diagonal = np.linalg.norm(self.vertices.max(axis=0) - self.vertices.min(axis=0))
        self.assertAlmostEqual(diagonal, r["input_bbox_diagonal"], delta=1e-12)
        # Every vertex of the result is a sample of the approximation error.
        self.assertLessEqual(r["mean_approximation_error"], r["max_approximation_error"])
        self.assertLessEqual(r["max_approximation_error"] * diagonal, displacement.max() + 1e-12)

    def test_planar_tiles_by_our_own_diagonal_distances(self):
        r = tilable_surfaces.make_k_set_tilable(self.vertices, self.faces, k=K, planar_tiles=True)
        self.assertTrue(r["is_tilable"])
        self.assertLessEqual(congruence_error(r, self.faces), 1e-6)
        v = r["vertices"]
        p0, p1, p2, p3 = (v[self.faces[:, i]] for i in range(4))
        n = np.cross(p2 - p0, p3 - p1)
        gaps = np.abs(np.einsum("ij,ij->i", p1 - p0, n)) / np.linalg.norm(n, axis=1)
        self.assertLessEqual(gaps.max() / mean_edge_length(v, self.faces), 1e-6)
        self.assertAlmostEqual(gaps.max() / mean_edge_length(v, self.faces), r["planarity_error"], delta=1e-9)
        self.assertGreater(self.result["planarity_error"], 1e-4, "without it the panels are not planar")

    def test_same_result_with_other_threads_and_arguments_by_keyword(self):
        again = tilable_surfaces.make_k_set_tilable(self.vertices.tolist(), self.faces.astype(np.int32),
                                                    k=K, seed=3, number_of_candidates=8, threads=2)
        np.testing.assert_array_equal(again["cluster"], self.result["cluster"])
        np.testing.assert_array_equal(again["vertices"], self.result["vertices"])

    def test_bad_input_raises_value_error_with_the_package_message(self):
        v, f = self.vertices, self.faces
        bad_vertex = v.copy()
        bad_vertex[5, 1] = np.nan
        out_of_range = f.copy()
        out_of_range[3, 2] = len(v) + 4
        cases = [
            (dict(vertices=v, faces=f, k=0), "k must be at least 1"),
            (dict(vertices=v, faces=f, k=len(f) + 1), "number_of_tiles"),
            (dict(vertices=v, faces=f[:, :3], k=K), "(m, 4)"),
            (dict(vertices=v[:, :2], faces=f, k=K), "(n, 3)"),
            (dict(vertices=v, faces=f.astype(np.float64), k=K), "integers"),
            (dict(vertices=v, faces=out_of_range, k=K), "face 3 refers to vertex"),
            (dict(vertices=bad_vertex, faces=f, k=K), "vertex 5"),
            (dict(vertices=v, faces=f, k=K, solver="magic"), "unknown solver"),
            (dict(vertices=v, faces=f, k=K, distance_weight=-1.0), "weights"),
            (dict(vertices=v, faces=f, k=K, panel_tolerance=-0.1), "panel_tolerance is -0.1"),
            (dict(vertices=v, faces=f, k=K, panel_tolerance="wide"), "panel_tolerance cannot be 'wide'"),
        ]
        for arguments, message in cases:
            with self.subTest(message=message):
                with self.assertRaises(ValueError) as caught:
                    tilable_surfaces.make_k_set_tilable(**arguments)
                self.assertTrue(str(caught.exception).startswith("Tilable_surfaces: "), str(caught.exception))
                self.assertIn(message, str(caught.exception))

    def test_the_gil_is_released_during_the_run(self):
        # While the run goes on in another thread, this thread keeps running
        # Python code: the longest pause it sees is much shorter than the run.
        pause, duration = numpy_checks.longest_pause(
            lambda: tilable_surfaces.make_k_set_tilable(self.vertices, self.faces, k=K, seed=3, threads=1))
        self.assertGreater(duration, 0.05)
        self.assertLess(pause, 0.5 * duration)


class PanelToleranceTest(unittest.TestCase):
    """With panel_tolerance T every face lies within T of its cluster's S-quad (its mold), by a Kabsch
    fit of our own; on one clustering, the slack is used: the result is closer to the input than the
    exact one."""

    RELATIVE_TOLERANCE = 0.02  # of the input's mean edge: far above the exact mode's 1e-6

    @classmethod
    def setUpClass(cls):
        cls.vertices, cls.faces = numpy_checks.read_mesh(MESH, EXAMPLE)
        cls.tolerance = cls.RELATIVE_TOLERANCE * mean_edge_length(cls.vertices, cls.faces)
        arguments = dict(k=K, seed=3, number_of_candidates=8, threads=1)
        cls.exact = tilable_surfaces.make_k_set_tilable(cls.vertices, cls.faces, **arguments)
        cls.result = tilable_surfaces.make_k_set_tilable(cls.vertices, cls.faces, panel_tolerance=cls.tolerance,
                                                         **arguments)

    def deviations(self, result):
        v, c, o, molds = result["vertices"], result["cluster"], result["orientation"], result["s_quads"]
        return np.array([numpy_checks.kabsch_deviation(molds[c[f]], numpy_checks.instance(v, face, int(o[f])))
                         for f, face in enumerate(self.faces)])

    def test_every_instance_is_within_t_of_its_mold_by_our_own_rigid_fits(self):
        r, ours = self.result, self.deviations(self.result)
        self.assertTrue(r["is_tilable"])
        self.assertTrue(r["within_panel_tolerance"])
        self.assertEqual(r["panel_tolerance"], self.tolerance)
        self.assertEqual(r["number_of_clusters"], K)
        self.assertLessEqual(ours.max(), self.tolerance * (1 + 1e-9))
        np.testing.assert_allclose(ours, r["panel_deviations"], rtol=0, atol=1e-9 * self.tolerance)
        self.assertAlmostEqual(ours.max(), r["worst_panel_deviation"], delta=1e-9 * self.tolerance)

    def test_on_the_same_clustering_the_tolerance_is_used_to_stay_closer_to_the_input(self):
        exact = self.exact
        exact_edge = numpy_checks.CONGRUENCE_TOLERANCE * mean_edge_length(exact["vertices"], self.faces)
        self.assertLessEqual(self.deviations(exact).max(), exact_edge)
        self.assertFalse(exact["within_panel_tolerance"])
        surface = tilable_surfaces.KSetTilableSurface(self.vertices, self.faces)
        surface.set_clustering(exact["cluster"], exact["orientation"])
        r = surface.optimize(panel_tolerance=self.tolerance, threads=1)
        r.update(vertices=surface.vertices(), cluster=exact["cluster"], orientation=exact["orientation"])
        ours = self.deviations(r)
        self.assertTrue(r["within_panel_tolerance"])
        self.assertLessEqual(ours.max(), self.tolerance * (1 + 1e-9))
        self.assertGreater(ours.max(), 100 * exact_edge)
        displacement = np.linalg.norm(r["vertices"] - self.vertices, axis=1)
        exact_displacement = np.linalg.norm(exact["vertices"] - self.vertices, axis=1)
        self.assertLess(displacement.max(), exact_displacement.max())
        self.assertLess(displacement.mean(), exact_displacement.mean())


class TrianglesTest(unittest.TestCase):
    # Two unit squares and two right isosceles triangles on top, the apex
    # moved so that the two triangles differ.
    vertices = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0],
                         [1.15, 1.9, 0.2]], dtype=np.float64)
    faces = np.array([[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 6, -1], [4, 5, 6, -1]])

    def test_a_fourth_index_of_minus_one_is_a_triangle_with_a_tile_of_its_own(self):
        r = tilable_surfaces.make_k_set_tilable(self.vertices, self.faces, k=2)
        self.assertTrue(r["is_tilable"])
        self.assertEqual(sorted(r["tile_corners"].tolist()), [3, 4])
        self.assertNotEqual(r["cluster"][0], r["cluster"][2])
        self.assertEqual(r["cluster"][2], r["cluster"][3])
        triangle = int(r["cluster"][2])
        self.assertTrue(np.isnan(r["s_quads"][triangle, 3]).all())
        self.assertFalse(np.isnan(r["s_quads"][triangle, :3]).any())
        # The two triangles are congruent: the same sorted edge lengths.
        v = r["vertices"]
        lengths = [sorted(np.linalg.norm(v[f[[1, 2, 0]]] - v[f[:3]], axis=1)) for f in self.faces[2:]]
        np.testing.assert_allclose(lengths[0], lengths[1], atol=1e-6)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
