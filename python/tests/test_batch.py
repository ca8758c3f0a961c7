"""conescope.batch without Dask: the command line's batch, its results.csv as a DataFrame."""

import pandas as pd
import pytest

import conescope
from conftest import cli_error, cli_json, without_timings


def test_batch_rows_are_the_cli_numbers(library, tmp_path):
    out = tmp_path / "out"
    frame = conescope.batch([library], output_dir=out, views=16, jobs=2)
    assert len(frame) == 7
    assert frame.equals(pd.read_csv(out / "results.csv", float_precision="round_trip"))
    broken = frame[frame.file.str.endswith("broken.off")].iloc[0]
    assert broken.status == "error" and broken.error_kind == "read"
    assert broken.error == cli_error("stats", "-q", broken.file)
    for row in frame[frame.status == "ok"].itertuples():
        document = cli_json("stats", "-q", row.file, "--views", "16")
        result = document["results"][0]
        for key in ("efficiency", "triangles_culled", "test_loss_triangles", "partition_loss_triangles", "false_culls",
                    "cull_fraction", "oracle_fraction", "mean_sphere_radius", "max_sphere_radius"):
            assert getattr(row, key) == result[key], (row.file, key)
        assert (row.triangles, row.clusters, row.views) == (document["mesh"]["triangles"], document["clusters"], 16)
        import json
        assert without_timings(json.load(open(out / row.json))) == without_timings(document)


def test_a_second_batch_skips_what_is_done_and_no_folder_leaves_no_files(library, tmp_path):
    first = conescope.batch(library, output_dir=tmp_path / "out", views=8)
    again = conescope.batch(library, output_dir=tmp_path / "out", views=8)
    assert again.equals(first)
    loose = conescope.batch(library, views=8)
    assert loose.json.isna().all()
    keep = ["file", "status", "error", "efficiency", "clusters", "triangles"]
    assert loose[keep].equals(first[keep])


def test_batch_compares_with_meshoptimizers_pipeline(library):
    frame = conescope.batch(library, views=8, compare_meshopt=True)
    ok = frame[frame.status == "ok"]
    assert (ok.a_options == "builder=meshopt,cone=meshopt,test=apex").all()
    assert (ok.a_cone == "meshopt").all() and (ok.a_test == "apex").all()
    assert (ok.triangles_culled_only_b - ok.triangles_culled_only_a == ok.triangles_culled - ok.a_triangles_culled).all()


def test_batch_settings_are_checked_before_any_mesh_runs(library):
    with pytest.raises(ValueError, match="--views: '0' is not a whole number"):
        conescope.batch(library, views=0)
    with pytest.raises(ValueError, match="unknown option 'colour' in a configuration"):
        conescope.batch(library, compare="colour=red")
