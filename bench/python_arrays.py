"""Arrays into conescope.stats_arrays against conescope.stats of the same mesh as a binary PLY file:
tori of 1 and 5 million triangles given as numpy arrays (one view, no per-view or per-cluster
tables; median of 3), the checks of conescope._arrays, and the longest time the call held the GIL
(the largest gap a Python thread waking every millisecond saw). Run from the repository root after
scripts/build.sh:

    PYTHONPATH=build/python /usr/bin/python3 bench/python_arrays.py
"""
import os
import statistics
import tempfile
import threading
import time

import numpy as np

import conescope
from conescope import _arrays


def torus(around, across):
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, around, endpoint=False), np.linspace(0, 2 * np.pi, across, endpoint=False),
                       indexing="ij")
    vertices = np.c_[((1 + 0.35 * np.cos(v)) * np.cos(u)).ravel(), ((1 + 0.35 * np.cos(v)) * np.sin(u)).ravel(),
                     (0.35 * np.sin(v)).ravel()]
    i, j = np.meshgrid(np.arange(around), np.arange(across), indexing="ij")
    a, b = (i * across + j).ravel(), (((i + 1) % around) * across + j).ravel()
    c, d = (((i + 1) % around) * across + (j + 1) % across).ravel(), (i * across + (j + 1) % across).ravel()
    return vertices, np.r_[np.c_[a, b, c], np.c_[a, c, d]].astype(np.int64)


def write_binary_ply(path, vertices, faces):
    with open(path, "wb") as out:
        out.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(vertices)}\nproperty float x\nproperty float y\n"
                  f"property float z\nelement face {len(faces)}\nproperty list uchar int vertex_indices\nend_header\n".encode())
        out.write(vertices.astype("<f4").tobytes())
        record = np.zeros(len(faces), dtype=[("n", "u1"), ("v", "<i4", (3,))])
        record["n"], record["v"] = 3, faces
        out.write(record.tobytes())


def longest_gil_hold(work):
    """Seconds: the call's time, and the largest gap between a watching thread's wake-ups."""
    gaps, running = [0.0], [True]

    def watch():
        last = time.perf_counter()
        while running[0]:
            time.sleep(0.001)
            now = time.perf_counter()
            gaps.append(now - last)
            last = now
    watcher = threading.Thread(target=watch)
    watcher.start()
    start = time.perf_counter()
    work()
    seconds = time.perf_counter() - start
    running[0] = False
    watcher.join()
    return seconds, max(gaps)


options = dict(views=1, per_view=False, per_cluster=False)
print("| triangles | checks (s) | stats_arrays (s) | longest GIL hold (s) | stats of the binary PLY (s) |")
print("|---:|---:|---:|---:|---:|")
for around, across in ((1000, 500), (2500, 1000)):
    vertices, faces = torus(around, across)
    checks = statistics.median(longest_gil_hold(lambda: _arrays.mesh_faces(faces, len(_arrays.mesh_vertices(vertices))))[0]
                               for _ in range(3))
    runs = [longest_gil_hold(lambda: conescope.stats_arrays(vertices, faces, **options)) for _ in range(3)]
    with tempfile.TemporaryDirectory() as folder:
        path = os.path.join(folder, "torus.ply")
        write_binary_ply(path, vertices, faces)
        from_file = statistics.median(longest_gil_hold(lambda: conescope.stats(path, **options))[0] for _ in range(3))
    print(f"| {len(faces):,} | {checks:.3f} | {statistics.median(r[0] for r in runs):.3f} | {max(r[1] for r in runs):.3f} | "
          f"{from_file:.3f} |", flush=True)
