"""What the module's tests share: the CLI they compare with, the bundled meshes, and a small library
of meshes (polygon OBJ files among them) made in a temporary folder."""

import json
import math
import os
import shutil
import subprocess
from pathlib import Path

import pytest

DATASETS = Path(os.environ.get("CONESCOPE_DATASETS_DIR", Path(__file__).resolve().parents[2] / "datasets"))
CLI = os.environ.get("CONESCOPE_CLI", "conescope-cli")
BROKEN_OFF = "OFF\n3 1 0\n0 0 0\n1 0 0\n"


def run_cli(*arguments, check=True):
    result = subprocess.run([CLI, *map(str, arguments)], capture_output=True, text=True)
    if check:
        assert result.returncode == 0, result.stderr
    return result


def cli_json(*arguments):
    return json.loads(run_cli(*arguments).stdout)


def cli_error(*arguments):
    """The message after "conescope-cli: error: " of a run that fails."""
    result = run_cli(*arguments, check=False)
    assert result.returncode != 0
    line = next(line for line in result.stderr.splitlines() if line.startswith("conescope-cli: error: "))
    return line[len("conescope-cli: error: "):]


def without_timings(document):
    if isinstance(document, dict):
        return {key: without_timings(value) for key, value in document.items() if key != "ns_per_cluster"}
    if isinstance(document, list):
        return [without_timings(value) for value in document]
    return document


def quad_sphere(rings=8, segments=10):
    """A UV sphere as arrays: float32-exact positions, quads between rings and an n-gon at each pole."""
    import numpy as np
    vertices = []
    for r in range(1, rings):
        for s in range(segments):
            theta, phi = math.pi * r / rings, 2 * math.pi * s / segments
            vertices.append((math.sin(theta) * math.cos(phi), math.cos(theta), math.sin(theta) * math.sin(phi)))
    index = lambda r, s: (r - 1) * segments + s % segments
    faces = [[index(1, s) for s in reversed(range(segments))], [index(rings - 1, s) for s in range(segments)]]
    for r in range(1, rings - 1):
        for s in range(segments):
            faces.append([index(r, s), index(r, s + 1), index(r + 1, s + 1), index(r + 1, s)])
    return np.asarray(vertices, dtype=np.float32), faces


def write_obj(path, vertices, faces):
    """An OBJ holding exactly these float32 positions (9 digits read back to the same float)."""
    with open(path, "w") as out:
        for x, y, z in vertices:
            out.write(f"v {float(x):.9g} {float(y):.9g} {float(z):.9g}\n")
        for face in faces:
            out.write("f " + " ".join(str(corner + 1) for corner in face) + "\n")


def read_off(path):
    """Positions and faces of a plain ASCII OFF file (the bundled ones)."""
    import numpy as np
    words = [line.split("#")[0].split() for line in open(path)]
    words = [w for w in words if w]
    counts = list(map(int, words[1][:2])) if words[0] == ["OFF"] else list(map(int, words[0][1:3]))
    start = 2 if words[0] == ["OFF"] else 1
    vertices = np.asarray([list(map(float, w[:3])) for w in words[start:start + counts[0]]], dtype=np.float32)
    faces = [list(map(int, w[1:1 + int(w[0])])) for w in words[start + counts[0]:start + counts[0] + counts[1]]]
    return vertices, faces


@pytest.fixture
def library(tmp_path):
    """Four bundled meshes, two polygon OBJ files in polygons/, and broken.off: seven files."""
    folder = tmp_path / "library"
    (folder / "polygons").mkdir(parents=True)
    for name in ("cube-quads.off", "elephant.off", "icosphere-clusters.vtp", "torus.off"):
        shutil.copy(DATASETS / name, folder / name)
    write_obj(folder / "polygons" / "sphere.obj", *quad_sphere())
    write_obj(folder / "polygons" / "coarse-sphere.obj", *quad_sphere(5, 7))
    (folder / "broken.off").write_text(BROKEN_OFF)
    return folder
