"""Helpers of the Python tests: independent recomputations in numpy of what the module
reports, and a measure of whether a call releases the GIL.

Quad meshes only: faces is an (m, 4) integer array. Orientation o puts template
corner i on face corner (i + o) % 4 for o < 4, (o - i) % 4 otherwise.
"""
import importlib.util
import threading
import time

import numpy as np

# The package's default congruence tolerance, in mean edge lengths (the
# module's congruence_tolerance keyword; the tests use the default).
CONGRUENCE_TOLERANCE = 1e-6


def read_mesh(mesh, example):
    """The vertices and quads of the OFF file `mesh`, read by the reader of the example script."""
    spec = importlib.util.spec_from_file_location("make_k_set_tilable_example", example)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.read_off(mesh)


def mean_edge_length(vertices, faces):
    edges = np.concatenate([faces[:, [i, (i + 1) % 4]] for i in range(4)])
    edges = np.unique(np.sort(edges, axis=1), axis=0)
    return np.linalg.norm(vertices[edges[:, 0]] - vertices[edges[:, 1]], axis=1).mean()


def corner_of(i, o):
    """The face corner that template corner i goes to with orientation o."""
    return (i + o) % 4 if o < 4 else (o - i) % 4


def instance(vertices, face, o, corner=corner_of):
    """The corners of a face in the labelling of its S-quad."""
    return vertices[[face[corner(i, o)] for i in range(4)]]


def kabsch_deviation(template, target, mirrored=False):
    """Largest corner distance after the best rigid motion (least squares) of template onto target."""
    a = template - template.mean(axis=0)
    b = target - target.mean(axis=0)
    u, _, vt = np.linalg.svd(a.T @ b)
    d = -1.0 if mirrored else np.sign(np.linalg.det(vt.T @ u.T))
    rotation = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    return np.linalg.norm(a @ rotation.T - b, axis=1).max()


def congruence_error(vertices, faces, cluster, orientation, s_quads, corner=corner_of):
    """The worst face's deviation from its cluster's S-quad, over the mean edge length."""
    worst = 0.0
    for f, face in enumerate(faces):
        q = instance(vertices, face, int(orientation[f]), corner)
        worst = max(worst, kabsch_deviation(s_quads[cluster[f]], q))
    return worst / mean_edge_length(vertices, faces)


def instance_congruence_error(vertices, faces, cluster, orientation):
    """The same without any S-quad of the program: every instance against its cluster's first."""
    worst = 0.0
    for c in np.unique(cluster):
        members = np.flatnonzero(cluster == c)
        first = instance(vertices, faces[members[0]], int(orientation[members[0]]))
        for f in members[1:]:
            worst = max(worst, kabsch_deviation(first, instance(vertices, faces[f], int(orientation[f]))))
    return worst / mean_edge_length(vertices, faces)


def degree_of_flexibility(faces, cluster, orientation):
    """Components of the edge-sharing graph: the 4K S-quad edges, linked through every interior mesh edge."""
    k = int(cluster.max()) + 1
    parent = list(range(4 * k))

    def root(x):
        while parent[x] != x:
            parent[x] = parent[parent[x]]
            x = parent[x]
        return x

    nodes_of_edge = {}
    for f, face in enumerate(faces):
        o = int(orientation[f])
        for j in range(4):
            edge = frozenset((int(face[corner_of(j, o)]), int(face[corner_of((j + 1) % 4, o)])))
            nodes_of_edge.setdefault(edge, []).append(4 * int(cluster[f]) + j)
    for nodes in nodes_of_edge.values():
        for other in nodes[1:]:
            parent[root(other)] = root(nodes[0])
    return len({root(x) for x in range(4 * k)})


def relabelings():
    """The corner correspondences between two quads that a proper rigid motion may realize."""
    return [[corner_of(i, o) for i in range(4)] for o in range(8)]


def distinct_molds(s_quads, tolerance):
    """Mold of each S-quad: the first earlier one congruent to it within tolerance, in order."""
    molds, representatives = [], []
    for q in s_quads:
        for mold, r in enumerate(representatives):
            if min(kabsch_deviation(r, q[p]) for p in relabelings()) <= tolerance:
                molds.append(mold)
                break
        else:
            molds.append(len(representatives))
            representatives.append(q)
    return np.array(molds)


def fan(vertices, faces):
    """The triangles (a, b, c) of every quad's fan around its vertex centroid, and the samples
    the package measures on it: vertices, centroids, edge midpoints, fan-triangle centroids."""
    corners = vertices[faces]                                  # (m, 4, 3)
    apex = corners.mean(axis=1)                                # (m, 3)
    following = np.roll(corners, -1, axis=1)
    a = np.repeat(apex, 4, axis=0)
    b, c = corners.reshape(-1, 3), following.reshape(-1, 3)
    samples = np.concatenate([vertices[np.unique(faces)], apex, (b + c) / 2, (a + b + c) / 3])
    return (a, b, c), samples


def point_triangle_distances(points, a, b, c):
    """(n, m) distances from points (n, 3) to triangles (a, b, c), each (m, 3)."""
    p = points[:, None, :]

    def to_segment(u, v):
        e = v - u
        t = np.clip(np.einsum("nmk,mk->nm", p - u, e) / np.einsum("mk,mk->m", e, e), 0.0, 1.0)
        return np.linalg.norm(p - (u + t[..., None] * e), axis=2)

    normal = np.cross(b - a, c - a)
    normal /= np.linalg.norm(normal, axis=1)[:, None]
    height = np.einsum("nmk,mk->nm", p - a, normal)
    foot = p - height[..., None] * normal
    inside = np.ones(height.shape, dtype=bool)
    for u, v in ((a, b), (b, c), (c, a)):
        inside &= np.einsum("nmk,mk->nm", np.cross(v - u, foot - u), normal) >= 0
    edges = np.minimum(np.minimum(to_segment(a, b), to_segment(b, c)), to_segment(c, a))
    return np.where(inside, np.abs(height), edges)


def hausdorff_distance(result, vertices, faces):
    """The symmetric Hausdorff distance between two positions of the same quads, sampled as the
    package samples it, over the bounding-box diagonal of `vertices` (the input)."""
    triangles_in, samples_in = fan(vertices, faces)
    triangles_out, samples_out = fan(result, faces)
    to_input = point_triangle_distances(samples_out, *triangles_in).min(axis=1).max()
    to_result = point_triangle_distances(samples_in, *triangles_out).min(axis=1).max()
    diagonal = np.linalg.norm(vertices.max(axis=0) - vertices.min(axis=0))
    return max(to_input, to_result) / diagonal


def longest_pause(run):
    """(longest pause this thread saw, duration of run()) while run() ran in another thread: a
    call that releases the GIL lets this thread go on, the pause staying much shorter than it."""
    span = {}

    def work():
        span["start"] = time.perf_counter()
        try:
            run()
        finally:
            span["end"] = time.perf_counter()

    worker = threading.Thread(target=work)
    pause, last = 0.0, time.perf_counter()
    worker.start()
    while worker.is_alive():
        now = time.perf_counter()
        if "start" in span:
            pause = max(pause, now - last)
        last = now
    worker.join()
    return pause, span["end"] - span["start"]
