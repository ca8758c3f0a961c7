"""Arrays into conescope.stats_arrays: a torus of 1,000,000 triangles given as numpy arrays, the
checks of conescope._arrays and the whole call timed (median of 3), against the same mesh read from
an OFF file by conescope.stats. Run from the repository root after scripts/build.sh:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_arrays.py
"""
import os
import statistics
import sys
import tempfile
import time

import numpy as np

import conescope
from conescope import _arrays


def torus(around=1000, across=500):
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, around, endpoint=False), np.linspace(0, 2 * np.pi, across, endpoint=False),
                       indexing="ij")
    vertices = np.c_[((1 + 0.35 * np.cos(v)) * np.cos(u)).ravel(), ((1 + 0.35 * np.cos(v)) * np.sin(u)).ravel(),
                     (0.35 * np.sin(v)).ravel()]
    i, j = np.meshgrid(np.arange(around), np.arange(across), indexing="ij")
    a, b = (i * across + j).ravel(), (((i + 1) % around) * across + j).ravel()
    c, d = (((i + 1) % around) * across + (j + 1) % across).ravel(), (i * across + (j + 1) % across).ravel()
    return vertices, np.r_[np.c_[a, b, c], np.c_[a, c, d]].astype(np.int64)


def median_seconds(work, repeat=3):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


vertices, faces = torus()
options = dict(views=1, per_view=False, per_cluster=False)
checks = median_seconds(lambda: _arrays.mesh_faces(faces, len(_arrays.mesh_vertices(vertices))))
arrays = median_seconds(lambda: conescope.stats_arrays(vertices, faces, **options))
with tempfile.TemporaryDirectory() as folder:
    path = os.path.join(folder, "torus.off")
    with open(path, "w") as out:
        out.write(f"OFF\n{len(vertices)} {len(faces)} 0\n")
        np.savetxt(out, vertices, fmt="%.17g")
        np.savetxt(out, np.c_[np.full(len(faces), 3), faces], fmt="%d")
    from_file = median_seconds(lambda: conescope.stats(path, **options))
print(f"{len(faces):,} triangles: checks {checks:.3f} s, stats_arrays {arrays:.3f} s, stats of the same mesh as OFF {from_file:.3f} s",
      file=sys.stdout)
