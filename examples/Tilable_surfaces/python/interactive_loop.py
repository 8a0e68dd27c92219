#!/usr/bin/env python3
"""The interactive loop of the user manual (section "Step by step"), in Python, cell by cell.

    PYTHONPATH=build/python python3 examples/Tilable_surfaces/python/interactive_loop.py \
        examples/Tilable_surfaces/data/monkey_saddle.off [K] [OUTPUT.off]

Cluster, look at the clustering, edit it (merge, split, re-tag), optimize, measure, read
the tile catalog, then the K curve around K. Each "# %%" cell can be run on its own in an
editor that knows cells (VS Code, Spyder, Jupyter's py:percent).
"""
# %% Read the mesh and make the stateful object (it checks the mesh once).
import sys

import numpy as np

import tilable_surfaces as ts
from make_k_set_tilable import read_off, write_off

if len(sys.argv) not in (2, 3, 4):
    print(__doc__, file=sys.stderr)
    sys.exit(2)
vertices, faces = read_off(sys.argv[1])
k = int(sys.argv[2]) if len(sys.argv) > 2 else 8
surface = ts.KSetTilableSurface(vertices, faces)
print(f"{len(vertices)} vertices, {len(faces)} quads")


def progress(kind, *values):
    """One line per phase; of the solver's iterations, one in 100."""
    if kind == "phase":
        print(f"  {values[0]} done in {values[1]:.2f} s")
    elif values[0] % 100 == 0:
        print(f"  iteration {values[0]:3d}: congruence error {values[1]:.2e}")
    return True  # False would stop the solvers


# %% Cluster the quads into K S-quads.
clustering = surface.cluster(k, seed=0, progress=progress)
print(f"K = {clustering['number_of_clusters']}, DOF = {clustering['degree_of_flexibility']}: "
      f"{clustering['choice_reason']}")

# %% Look: the cluster sizes, and the candidates the clustering chose from.
print("faces per cluster:", clustering["cluster_sizes"].tolist())
for i, c in enumerate(clustering["candidates"][:5]):
    print(f"  candidate {i} ({c['origin']}): score {c['score']:.3f}, DOF {c['degree_of_flexibility']}")

# %% Edit: merge the two smallest clusters, split the largest, re-tag; each says the new DOF.
sizes = np.bincount(surface.face_clusters())
a, b = (int(c) for c in np.argsort(sizes)[:2])
print(f"merge clusters {a} and {b}: DOF {surface.merge_clusters(a, b)}")
largest = int(np.argmax(np.bincount(surface.face_clusters())))
print(f"split cluster {largest}: DOF {surface.split_cluster(largest)}")
print(f"re-tag the orientations: DOF {surface.retag_orientations()}")

# %% Optimize the edited clustering, then look for a closer result among the candidates.
edited = surface.optimize(progress=progress)
print(f"edited clustering: {edited['ending']}, Hausdorff {100 * edited['hausdorff_distance']:.2f}% "
      "of the diagonal")
closest = surface.optimize_closest(progress=progress)
print(f"closest: {closest['ending']}, Hausdorff {100 * closest['hausdorff_distance']:.2f}%")

# %% Measure the result against the input.
m = surface.measure()
print(f"congruence error {m['congruence_error']:.1e} of the mean edge length, "
      f"Hausdorff max {100 * m['hausdorff_distance']:.2f}% mean {100 * m['mean_symmetric_distance']:.2f}%, "
      f"{m['self_intersecting_face_pairs']} crossing pairs, {m['flattened_panels']} flattened panels, "
      f"{m['number_of_distinct_molds']} distinct molds")
for warning in m["buildability_warnings"]:
    print("  warning:", warning)

# %% The tile catalog: one row per S-quad, the mold it is cut from, its edge lengths.
catalog = surface.tile_catalog()
for c in range(len(catalog["id"])):
    corners = catalog["corners"][c]
    edges = np.linalg.norm(corners - np.roll(corners, -1, axis=0), axis=1)
    print(f"  tile {catalog['id'][c]}: mold {catalog['mold'][c]}, {catalog['instance_count'][c]} panels, "
          f"edges {np.array2string(edges, precision=3)}")

# %% The K curve around K: what each extra mold buys.
curve = ts.curve(vertices, faces, max(1, k - 2), k + 2, 2, optimized_candidates=1, improvement_rounds=0)
for row in zip(curve["K"], curve["hausdorff_distance"], curve["is_tilable"]):
    print(f"  K = {row[0]:3d}: Hausdorff {100 * row[1]:.2f}%{'' if row[2] else ' (not tilable)'}")

# %% Keep the result, or go back to the input and start another loop.
if len(sys.argv) == 4:
    write_off(sys.argv[3], surface.vertices(), faces)
surface.restore_input()
