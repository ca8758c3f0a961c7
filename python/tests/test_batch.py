"""conescope.batch without Dask: the command line's batch, its results.csv as a DataFrame."""

import io

import pandas as pd
import pytest

import conescope
from conftest import DATASETS, cli_error, cli_json, run_cli, without_timings


def test_batch_rows_are_the_cli_numbers(library, tmp_path):
    out = tmp_path / "out"
    frame = conescope.batch([library], output_dir=out, views=16, jobs=2)
    assert len(frame) == 7
    assert frame.equals(conescope.read_results(out / "results.csv"))
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


def test_dtypes_do_not_change_with_error_rows_and_survive_concatenation(library, tmp_path):
    clean = [str(path) for path in sorted(library.glob("*.off")) if path.name != "broken.off"][:1]
    with_error = clean + [str(library / "broken.off")]
    good = conescope.batch(clean, views=8)
    mixed = conescope.batch(with_error, views=8)
    errors_only = conescope.batch([str(library / "broken.off")], views=8)
    assert (mixed.status == "error").sum() == 1 and (good.status == "ok").all()
    assert good.dtypes.equals(mixed.dtypes) and good.dtypes.equals(errors_only.dtypes)
    assert str(good.dtypes["triangles"]) == "Int64" and str(good.dtypes["efficiency"]) == "float64"
    assert str(good.dtypes["error"]) == "string" and pd.isna(good.error.iloc[0])
    assert str(good.dtypes["setting_orthographic"]) == "boolean"
    assert pd.isna(errors_only.triangles.iloc[0])  # <NA>, not a float NaN turning the column into floats
    joined = pd.concat([good, mixed, errors_only], ignore_index=True)
    assert joined.dtypes.equals(good.dtypes) and len(joined) == 4
    assert conescope.read_results(io.StringIO(joined.to_csv(index=False))).equals(joined)


def test_granularity_and_lod_columns_read_as_numbers(tmp_path):
    """The columns `batch --granularity --lod` adds are numbers in the frame, counts as Int64."""
    out = tmp_path / "out"
    run_cli("batch", DATASETS / "torus.off", DATASETS / "cube.off", "-o", out, "--views", "4", "--granularity", "--lod", "--quiet")
    frame = conescope.read_results(out / "results.csv")
    extra = [name for name in frame.columns if name.startswith(("cones_", "triangle_", "lod_")) or name == "culled_share"]
    assert len(extra) > 40
    for name in extra:
        assert str(frame[name].dtype) in ("Int64", "float64"), name
        assert frame[name].notna().all() or name.startswith("lod_level_"), name
    assert str(frame["cones_4_compact_bytes_per_cluster"].dtype) == "Int64"
    assert str(frame["lod_cut_triangles"].dtype) == "float64"
    torus = frame[frame["file"].str.endswith("torus.off")].iloc[0]
    assert torus["lod_level_0_efficiency"] == torus["efficiency"]

