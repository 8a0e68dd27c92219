#!/usr/bin/env python3
"""Makes a quad mesh K-set tilable with the Python module tilable_surfaces.

    PYTHONPATH=build/python python3 examples/Tilable_surfaces/python/make_k_set_tilable.py \
        examples/Tilable_surfaces/data/monkey_saddle.off 7 [OUTPUT.off]

Reads an OFF quad mesh, makes it 7-set tilable, prints what was measured and
optionally writes the moved mesh as OFF.
"""
import sys

import numpy as np

import tilable_surfaces


def read_off(path):
    """The vertices (n, 3) and quad faces (m, 4) of an OFF file."""
    with open(path) as f:
        tokens = [t for line in f for t in line.split("#", 1)[0].split()]
    if not tokens or tokens[0] != "OFF":
        raise ValueError(f"{path}: not an OFF file")
    n, m = int(tokens[1]), int(tokens[2])
    vertices = np.array(tokens[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    faces, i = [], 4 + 3 * n
    for _ in range(m):
        size = int(tokens[i])
        faces.append([int(t) for t in tokens[i + 1:i + 1 + size]])
        i += 1 + size
    if any(len(face) != 4 for face in faces):
        raise ValueError(f"{path}: not a quad mesh")
    return vertices, np.array(faces, dtype=np.int64).reshape(m, 4)


def write_off(path, vertices, faces):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        for p in vertices:
            f.write(" ".join(repr(float(x)) for x in p) + "\n")
        for q in faces:
            f.write("4 " + " ".join(str(int(v)) for v in q) + "\n")


def main(argv):
    if len(argv) not in (3, 4):
        print(__doc__, file=sys.stderr)
        return 2
    vertices, faces = read_off(argv[1])
    k = int(argv[2])
    r = tilable_surfaces.make_k_set_tilable(vertices, faces, k=k, seed=0)

    print(f"{len(vertices)} vertices, {len(faces)} quads, K = {r['number_of_clusters']}, "
          f"DOF = {r['degree_of_flexibility']}")
    print(f"congruence error {r['congruence_error']:.2e} of the mean edge length "
          f"({'tilable' if r['is_tilable'] else 'NOT tilable'})")
    print(f"approximation error max {r['max_approximation_error']:.2e}, "
          f"mean {r['mean_approximation_error']:.2e} of the bounding-box diagonal")
    print("panels per tile:", np.bincount(r["cluster"], minlength=k).tolist())
    print("tile 0 (S-quad corners):\n", r["s_quads"][0])
    if len(argv) == 4:
        write_off(argv[3], r["vertices"], faces)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
