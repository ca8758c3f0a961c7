"""conescope.stats, stats_arrays, clusters and compare give the documents `conescope-cli` writes."""

import re

import numpy as np
import pytest

import conescope
from conftest import (BROKEN_OFF, DATASETS, cli_error, cli_json, quad_sphere, read_off, run_cli, without_timings,
                      write_obj)


@pytest.mark.parametrize("name", ["fandisk.off", "icosphere-clusters.vtp", "cube-quads.off"])
def test_stats_is_the_cli_document(name):
    document = conescope.stats(DATASETS / name, views=16)
    assert without_timings(document) == without_timings(cli_json("stats", "-q", DATASETS / name, "--views", "16"))


def test_settings_are_the_cli_options_with_underscores_or_dashes():
    mesh = DATASETS / "elephant.off"
    document = conescope.stats(mesh, views=8, max_tris=64, **{"max-verts": 48}, cone=["minimal", "average"],
                               test="octagon,apex", eye=None, fix_winding=False)
    expected = cli_json("stats", "-q", mesh, "--views", "8", "--max-tris", "64", "--max-verts", "48",
                        "--cone", "minimal,average", "--test", "octagon,apex")
    assert without_timings(document) == without_timings(expected)
    assert len(document["results"]) == 4
    one_eye = conescope.stats(mesh, eye=(0.5, 2, 3), per_cluster=False)
    assert without_timings(one_eye) == without_timings(
        cli_json("stats", "-q", mesh, "--eye", "0.5,2,3", "--no-per-cluster"))


def test_bad_settings_raise_the_schema_messages():
    mesh = DATASETS / "cube.off"
    with pytest.raises(ValueError, match=re.escape("--views: '0' is not a whole number in [1, ")):
        conescope.stats(mesh, views=0)
    with pytest.raises(ValueError, match=re.escape("--builder: unknown name 'best' (expected one of: ")):
        conescope.stats(mesh, builder="best")
    with pytest.raises(ValueError, match="unknown setting 'colour' \\(expected one of: builder, max_verts"):
        conescope.stats(mesh, colour="red")
    with pytest.raises(ValueError, match="--eye excludes --views"):
        conescope.stats(mesh, eye=(0, 0, 5), views=4)
    with pytest.raises(ValueError, match="--max-tris is given twice"):
        conescope.stats(mesh, max_tris=64, max_triangles=32)


def test_a_file_that_cannot_be_read_raises_the_cli_message(tmp_path):
    broken = tmp_path / "broken.off"
    broken.write_text(BROKEN_OFF)
    with pytest.raises(conescope.MeshReadError) as error:
        conescope.stats(broken)
    assert str(error.value) == cli_error("stats", "-q", broken)
    assert isinstance(error.value, OSError)
    with pytest.raises(conescope.MeshReadError, match="file does not exist"):
        conescope.stats(tmp_path / "missing.off")


def test_arrays_of_polygons_give_the_numbers_of_the_same_mesh_as_a_file(tmp_path):
    vertices, faces = quad_sphere()
    write_obj(tmp_path / "sphere.obj", vertices, faces)
    expected = cli_json("stats", "-q", tmp_path / "sphere.obj", "--views", "16")
    document = conescope.stats_arrays(vertices, faces, name="sphere.obj", views=16)
    assert without_timings(document) == without_timings(expected)
    assert document["mesh"]["faces"] < document["mesh"]["triangles"]


def test_triangle_arrays_give_the_numbers_of_the_file_they_came_from():
    vertices, faces = read_off(DATASETS / "icosphere.off")
    document = conescope.stats_arrays(vertices.astype(np.float64), np.asarray(faces, dtype=np.int64),
                                      name="icosphere.off", views=16)
    assert without_timings(document) == without_timings(cli_json("stats", "-q", DATASETS / "icosphere.off", "--views", "16"))


def test_cluster_ids_are_the_file_builders_partition(tmp_path):
    vertices, faces = read_off(DATASETS / "icosphere.off")
    ids = np.arange(len(faces)) // 40
    (tmp_path / "ids.txt").write_text("".join(f"{i}\n" for i in ids))
    expected = cli_json("stats", "-q", DATASETS / "icosphere.off", "--views", "16", "--builder", "file",
                        "--cluster-file", tmp_path / "ids.txt")
    document = conescope.stats_arrays(vertices, faces, cluster_ids=ids, name="icosphere.off", views=16)
    assert document["clusters"] == 32
    expected["settings"]["cluster_file"] = None  # the ids came as an array, not a file
    assert without_timings(document) == without_timings(expected)


def test_bad_arrays_raise():
    vertices, faces = quad_sphere()
    with pytest.raises(ValueError, match="vertices must be an n x 3 array"):
        conescope.stats_arrays(vertices[:, :2], faces)
    # Any index out of range is the same error, whatever its value.
    with pytest.raises(conescope.MeshDataError, match=re.escape("faces[1] = [0, 1, -1] has a vertex index outside")):
        conescope.stats_arrays(vertices, [faces[0], [0, 1, -1]])
    with pytest.raises(conescope.MeshDataError, match=re.escape("faces[0] = [0, 1, 9999] has a vertex index outside")):
        conescope.stats_arrays(vertices, [[0, 1, 9999]])
    with pytest.raises(ValueError, match="cluster_ids must hold one id per face"):
        conescope.stats_arrays(vertices, faces, cluster_ids=[0, 1])


def test_clusters_and_compare_are_the_cli_documents():
    mesh = DATASETS / "elephant.off"
    table = conescope.clusters(mesh, sort="lost", top=5, views=16)
    assert without_timings(table) == without_timings(
        cli_json("clusters", "-q", mesh, "--sort", "lost", "--top", "5", "--views", "16", "--format", "json"))
    assert len(table["rows"]) == 5
    pipeline = "builder=meshopt,cone=meshopt,test=apex"
    expected = cli_json("compare", "-q", mesh, "--a", pipeline, "--views", "16", "--format", "json")
    assert without_timings(conescope.compare(mesh, a=pipeline, views=16)) == without_timings(expected)
    as_dict = conescope.compare(mesh, a={"builder": "meshopt", "cone": "meshopt", "test": "apex"}, views=16)
    assert without_timings(as_dict) == without_timings(expected)
    vertices, faces = read_off(mesh)
    arrays = conescope.compare_arrays(vertices, faces, a=pipeline, name="elephant.off", views=16)
    assert without_timings(arrays) == without_timings(expected)
    with pytest.raises(ValueError, match="unknown option 'colour' in a configuration"):
        conescope.compare(mesh, a="colour=red")


def test_what_the_cli_warns_of_is_a_python_warning(tmp_path):
    vertices, faces = quad_sphere()
    faces[5] = list(reversed(faces[5]))  # one face wound the other way
    with pytest.warns(UserWarning, match="repair with --fix-winding"):
        conescope.stats_arrays(vertices, faces, views=4)


def test_float64_positions_that_float32_merges_are_a_warning(tmp_path):
    # fandisk moved by 1e6: float32 (the core's) has steps of 0.0625 there and merges 5,877 positions.
    vertices, faces = read_off(DATASETS / "fandisk.off")
    far = vertices.astype(np.float64) + 1e6
    with pytest.warns(UserWarning, match=r"6475 vertices read, 598 kept: float32, which ConeScope computes in, merged 5877 positions the file holds apart"):
        document = conescope.stats_arrays(far, faces, name="far.off", views=4)
    assert document["mesh"]["vertices"] == 598
    path = tmp_path / "far.off"
    path.write_text(f"OFF\n{len(far)} {len(faces)} 0\n" + "".join(f"{float(x)!r} {float(y)!r} {float(z)!r}\n" for x, y, z in far)
                    + "".join(f"3 {a} {b} {c}\n" for a, b, c in faces))
    with pytest.warns(UserWarning, match="merged 5877 positions the file holds apart"):
        conescope.stats(path, views=4)


def test_granularity_is_the_cli_document():
    """Every record's row as `conescope-cli granularity` gives it, all tests without test=..."""
    document = conescope.granularity(DATASETS / "elephant.off", views=16)
    assert document == cli_json("granularity", DATASETS / "elephant.off", "--views", "16", "--format", "json", "--quiet")
    records = [row["record"] for row in document["rows"]]
    assert records[0] == "chosen/octagon" and "cones-4-compact" in records and records[-1] == "triangle"
    only_apex = conescope.granularity(DATASETS / "elephant.off", views=16, test="apex")
    assert [row["record"] for row in only_apex["rows"]][0] == "chosen/apex"
    assert len(only_apex["rows"]) == 1 + 6 + 1


def test_lod_is_the_cli_document():
    """Levels and cut as `conescope-cli lod` gives them; bad thresholds raise SettingsError."""
    document = conescope.lod(DATASETS / "elephant.off", threshold=2, views=16, per_view=False)
    expected = cli_json("lod", DATASETS / "elephant.off", "--threshold", "2", "--views", "16", "--no-per-view", "--format", "json",
                        "--quiet")
    for side in (document, expected):
        side.pop("build_seconds")
    assert document == expected
    assert document["levels"][0]["efficiency"] == conescope.stats(DATASETS / "elephant.off", views=16)["results"][0]["efficiency"]
    with pytest.raises(conescope.SettingsError, match="threshold"):
        conescope.lod(DATASETS / "elephant.off", threshold=-1)
    with pytest.raises(conescope.SettingsError, match="group_size"):
        conescope.lod(DATASETS / "elephant.off", group_size=1)


def test_partition_is_the_cli_partitions_ids(tmp_path):
    """One uint32 cluster id per face, the ids `conescope-cli partition -o ids.txt` writes, for a file
    and for arrays of the same mesh."""
    ids_file = tmp_path / "ids.txt"
    run_cli("partition", DATASETS / "fandisk.off", "-o", ids_file, "--quiet")
    expected = np.array([int(line) for line in ids_file.read_text().splitlines() if not line.startswith("#")], dtype=np.uint32)
    ids = conescope.partition(DATASETS / "fandisk.off")
    assert ids.dtype == np.uint32 and ids.shape == expected.shape
    assert (ids == expected).all()
    vertices, faces = read_off(DATASETS / "fandisk.off")
    assert (conescope.partition_arrays(vertices, faces) == expected).all()
    assert len(np.unique(conescope.partition(DATASETS / "fandisk.off", builder="meshopt"))) > 1



def test_common_settings_are_keyword_only_arguments_and_none_is_the_default():
    import inspect
    for function in (conescope.stats, conescope.compare_arrays, conescope.granularity, conescope.batch):
        parameters = inspect.signature(function).parameters
        for name in ("builder", "max_verts", "max_tris", "clusters", "cone", "test", "views", "distance"):
            assert parameters[name].kind is inspect.Parameter.KEYWORD_ONLY and parameters[name].default is None, name
    with_none = conescope.stats(DATASETS / "torus.off", views=None, test=None, per_view=False, per_cluster=False)
    default = conescope.stats(DATASETS / "torus.off", per_view=False, per_cluster=False)
    assert without_timings(with_none) == without_timings(default)
    assert conescope.stats(DATASETS / "torus.off", views=8, max_tris=64)["settings"]["max_triangles"] == 64
