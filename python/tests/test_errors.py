"""A table of bad inputs: each raises the documented conescope exception (also the standard type a
caller catches) with a message of its own, never a binding library's text, never a crash."""

import numpy as np
import pytest

import conescope
from conftest import DATASETS

V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=np.float64)
F = np.array([[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]], dtype=np.int32)
MESH = DATASETS / "cube.off"


def stats_arrays(vertices=V, faces=F, **keywords):
    return lambda: conescope.stats_arrays(vertices, faces, **keywords)


def with_row(array, row, value):
    array = array.copy()
    array[row] = value
    return array


# (name, call, the exception, the base it is also, a piece of the message)
CASES = [
    # vertices: shapes, dtypes, values
    ("vertices 1-d", stats_arrays(vertices=np.zeros(12)), conescope.MeshDataError, ValueError, "n x 3"),
    ("vertices n x 2", stats_arrays(vertices=np.zeros((4, 2))), conescope.MeshDataError, ValueError, "(4, 2)"),
    ("vertices n x 4", stats_arrays(vertices=np.zeros((4, 4))), conescope.MeshDataError, ValueError, "n x 3"),
    ("vertices 3-d", stats_arrays(vertices=np.zeros((4, 3, 1))), conescope.MeshDataError, ValueError, "n x 3"),
    ("vertices strings", stats_arrays(vertices=np.array([["a", "b", "c"]] * 4)), conescope.ArgumentTypeError,
     TypeError, "numbers"),
    ("vertices objects", stats_arrays(vertices=[[0, 0, None]] * 4), conescope.ArgumentTypeError, TypeError, "numbers"),
    ("vertices complex", stats_arrays(vertices=V.astype(complex)), conescope.ArgumentTypeError, TypeError, "complex"),
    ("vertices ragged", stats_arrays(vertices=[[0, 0, 0], [1, 0]]), conescope.MeshDataError, ValueError, "n x 3"),
    ("vertex NaN", stats_arrays(vertices=with_row(V, 2, np.nan)), conescope.MeshDataError, ValueError, "vertices[2]"),
    ("vertex inf", stats_arrays(vertices=with_row(V, 3, np.inf)), conescope.MeshDataError, ValueError, "vertices[3]"),
    ("vertex -inf float32", stats_arrays(vertices=with_row(V.astype(np.float32), 1, -np.inf)), conescope.MeshDataError,
     ValueError, "vertices[1]"),
    # faces: shapes, dtypes, indices
    ("faces float", stats_arrays(faces=F.astype(float)), conescope.ArgumentTypeError, TypeError, "integer"),
    ("faces strings", stats_arrays(faces=[["0", "1", "2"]]), conescope.ArgumentTypeError, TypeError, "integer"),
    ("faces 1-d", stats_arrays(faces=np.arange(12)), conescope.MeshDataError, ValueError, "m x k"),
    ("faces m x 2", stats_arrays(faces=F[:, :2]), conescope.MeshDataError, ValueError, "k >= 3"),
    ("face index negative", stats_arrays(faces=with_row(F, 1, [0, -1, 3])), conescope.MeshDataError, ValueError,
     "faces[1]"),
    ("face index = n", stats_arrays(faces=with_row(F, 2, [0, 4, 2])), conescope.MeshDataError, ValueError, "faces[2]"),
    ("face index huge", stats_arrays(faces=with_row(F.astype(np.int64), 3, [0, 2**40, 2])), conescope.MeshDataError,
     ValueError, "faces[3]"),
    ("face index 2**32 wraps", stats_arrays(faces=with_row(F.astype(np.int64), 0, [2**32, 1, 2])),
     conescope.MeshDataError, ValueError, "faces[0]"),
    ("polygon too short", stats_arrays(faces=[[0, 1, 2, 3], [0, 1]]), conescope.MeshDataError, ValueError, "faces[1]"),
    ("polygon index out of range", stats_arrays(faces=[[0, 1, 2], [0, 1, 2, 9]]), conescope.MeshDataError, ValueError,
     "faces[1]"),
    ("polygon of floats", stats_arrays(faces=[[0, 1, 2], [0.5, 1, 2, 3]]), conescope.ArgumentTypeError, TypeError,
     "faces[1]"),
    ("polygon nested", stats_arrays(faces=[[0, 1, 2], [[0, 1], [2, 3]]]), conescope.MeshDataError, ValueError,
     "faces[1]"),
    # cluster ids
    ("cluster ids too few", stats_arrays(cluster_ids=[0, 1]), conescope.MeshDataError, ValueError, "one id per face"),
    ("cluster ids float", stats_arrays(cluster_ids=[0.5, 1, 1, 0]), conescope.ArgumentTypeError, TypeError,
     "integers"),
    ("cluster id negative", stats_arrays(cluster_ids=[0, 1, -3, 0]), conescope.MeshDataError, ValueError,
     "cluster_ids[2]"),
    ("cluster ids 2-d", stats_arrays(cluster_ids=[[0, 1, 1, 0]]), conescope.MeshDataError, ValueError,
     "one id per face"),
    # settings and arguments
    ("views 0", lambda: conescope.stats(MESH, views=0), conescope.SettingsError, ValueError, "--views"),
    ("views text", lambda: conescope.stats(MESH, views="many"), conescope.SettingsError, ValueError, "--views"),
    ("unknown setting", lambda: conescope.stats(MESH, colour="red"), conescope.SettingsError, ValueError, "colour"),
    ("unknown builder", stats_arrays(builder="best"), conescope.SettingsError, ValueError, "--builder"),
    ("eye and views", lambda: conescope.stats(MESH, eye=(0, 0, 5), views=4), conescope.SettingsError, ValueError,
     "excludes"),
    ("path a number", lambda: conescope.stats(42), conescope.ArgumentTypeError, TypeError, "path"),
    ("per_view text", lambda: conescope.stats(MESH, per_view="no"), conescope.ArgumentTypeError, TypeError,
     "per_view"),
    ("top negative", lambda: conescope.clusters(MESH, top=-1), conescope.SettingsError, ValueError, "top"),
    ("top a float", lambda: conescope.clusters(MESH, top=2.5), conescope.ArgumentTypeError, TypeError, "top"),
    ("sort unknown", lambda: conescope.clusters(MESH, sort="colour"), conescope.SettingsError, ValueError, "colour"),
    ("compare side unknown", lambda: conescope.compare(MESH, a="cone=wobbly"), conescope.SettingsError, ValueError,
     "wobbly"),
    ("compare side a number", lambda: conescope.compare(MESH, a=3), conescope.ArgumentTypeError, TypeError,
     "comparison side"),
    ("missing file", lambda: conescope.stats(DATASETS / "no-such.off"), conescope.MeshReadError, OSError,
     "no-such.off"),
    ("unknown extension", lambda: conescope.stats(DATASETS / "README.md"), conescope.MeshReadError, OSError, "README"),
    ("batch compare twice", lambda: conescope.batch(MESH, compare="cone=minimal", compare_meshopt=True),
     conescope.SettingsError, ValueError, "compare_meshopt"),
    ("batch jobs 0", lambda: conescope.batch(MESH, jobs=0), conescope.SettingsError, ValueError, "jobs"),
    ("batch timeout text", lambda: conescope.batch(MESH, timeout="soon"), conescope.SettingsError, ValueError,
     "timeout"),
    ("batch paths numbers", lambda: conescope.batch([1, 2]), conescope.ArgumentTypeError, TypeError, "paths"),
    ("batch client with jobs", lambda: conescope.batch(MESH, client=object(), jobs=2), conescope.SettingsError,
     ValueError, "jobs"),
]


def test_the_table_is_large_enough():
    assert len(CASES) >= 30


@pytest.mark.parametrize("name,call,error,base,fragment", CASES, ids=[case[0] for case in CASES])
def test_bad_input_raises_the_documented_error(name, call, error, base, fragment):
    with pytest.raises(error) as raised:
        call()
    assert isinstance(raised.value, conescope.Error) and isinstance(raised.value, base)
    message = str(raised.value)
    assert fragment in message
    for leak in ("Unable to cast", "incompatible function arguments", "pybind11", "1.79769"):
        assert leak not in message


def test_a_good_mesh_passes_the_same_checks():
    for faces in (F, F.astype(np.uint64), F.tolist(), [list(face) + [] for face in F]):
        document = conescope.stats_arrays(V.astype(np.float32), faces, views=4)
        assert document["mesh"]["triangles"] == 4
