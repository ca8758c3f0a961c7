"""conescope.batch on a Dask cluster: each mesh's row computed on a worker with the module, the same
rows and columns as the command line's batch."""

import json

import pandas as pd
import pytest
from dask.distributed import Client, LocalCluster

import conescope
from conftest import cli_json, without_timings

TIMINGS = ["seconds", "ns_per_cluster", "a_ns_per_cluster"]


@pytest.fixture(scope="module")
def client():
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    with Client(cluster) as client:
        yield client
    cluster.close()


def test_dask_rows_are_the_command_lines(library, client, tmp_path):
    out = tmp_path / "out"
    frame = conescope.batch([library], client=client, output_dir=out, views=16, compare_meshopt=True)
    local = conescope.batch([library], views=16, compare_meshopt=True)
    assert list(frame.columns) == list(local.columns) == conescope._conescope.batch_columns()
    assert len(frame) == 7
    assert frame.drop(columns=TIMINGS + ["json", "compare_json"]).equals(local.drop(columns=TIMINGS + ["json", "compare_json"]))
    for row in frame[frame.status == "ok"].itertuples():
        document = cli_json("stats", "-q", row.file, "--views", "16")
        assert row.efficiency == document["results"][0]["efficiency"]
        assert row.clusters == document["clusters"]
        assert without_timings(json.load(open(out / row.json))) == without_timings(document)
    assert conescope.read_results(out / "results.csv").drop(columns=TIMINGS).equals(frame.drop(columns=TIMINGS))
    report = (out / "report.html").read_text()
    assert all(file in report for file in frame.file)


def test_a_broken_mesh_on_dask_is_an_error_row(library, client):
    frame = conescope.batch([library / "broken.off", library / "torus.off"], client=client, views=4)
    assert list(frame.status) == ["error", "ok"]
    assert frame.error[0].endswith("header declares 3 vertices but only 12 bytes follow (truncated file or wrong count)")


def test_workers_without_this_build_stop_the_batch_before_any_mesh(library, client):
    """A worker that imports another version (or none) is named in a BatchError, not waited for."""
    def set_version(version):
        import conescope as worker_conescope
        worker_conescope.__version__ = version
    workers = sorted(client.scheduler_info()["workers"])
    client.run(set_version, "0.0-other", workers=workers[:1])
    try:
        with pytest.raises(conescope.BatchError, match=r"1 of 2 Dask workers cannot run this batch .*conescope 0\.0-other"):
            conescope.batch([library / "torus.off"], client=client, views=4)
    finally:
        client.run(set_version, conescope.__version__, workers=workers[:1])
    assert list(conescope.batch([library / "torus.off"], client=client, views=4).status) == ["ok"]


def test_a_second_dask_batch_into_the_same_folder_runs_only_what_changed(library, client, tmp_path):
    """The command line's resume rule: kept rows come back as they were, a changed mesh runs again."""
    out = tmp_path / "out"
    first = conescope.batch([library], client=client, output_dir=out, views=8)
    (library / "torus.off").write_text((library / "torus.off").read_text() + "\n")  # new bytes, same mesh
    second = conescope.batch([library], client=client, output_dir=out, views=8)
    assert list(second.file) == list(first.file)
    changed = second.file.str.endswith("torus.off")
    # Kept rows are the first run's, seconds included; the changed mesh was run again (new hash).
    assert second[~changed].equals(first[~changed])
    assert (second[changed].content_hash != first[changed].content_hash).all()
    assert (second[changed].status == "ok").all()
    again = conescope.batch([library], client=client, output_dir=out, views=16)  # other settings: all again
    assert (again.settings_hash != second.settings_hash).all()



def test_a_worker_killed_on_a_mesh_leaves_every_row(library, tmp_path, monkeypatch):
    """A mesh that kills the worker process computing it (SIGSEGV, the test hook of the batch workers)
    becomes a crash row once Dask gives up on it; every other mesh still has its row."""
    monkeypatch.setenv("CONESCOPE_BATCH_TEST_FAULT", "crash:elephant.off")  # the workers start with it
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=":0")
    try:
        with Client(cluster) as crashing:
            frame = conescope.batch([library], client=crashing, views=4)
    finally:
        cluster.close()
    assert len(frame) == 7
    elephant = frame[frame.file.str.endswith("elephant.off")].iloc[0]
    assert elephant.status == "error" and elephant.error_kind == "crash"
    assert "KilledWorker" in elephant.error
    assert (frame[~frame.file.str.endswith("elephant.off") & ~frame.file.str.endswith("broken.off")].status == "ok").all()


def test_relative_paths_reach_the_workers_as_absolute_ones(library, client, monkeypatch):
    monkeypatch.chdir(library)
    frame = conescope.batch(["torus.off", "polygons"], client=client, views=4)
    assert list(frame.status) == ["ok", "ok", "ok"]
    assert all(file.startswith("/") for file in frame.file)


def test_progress_and_folders_the_workers_cannot_see(library, client, capsys):
    """progress=True shows Dask's bar; a folder the workers do not see stops the batch, named (on a
    LocalCluster the workers share the client's files, so the check is asked of a folder none has)."""
    frame = conescope.batch([library / "torus.off"], client=client, views=4, progress=True)
    assert list(frame.status) == ["ok"]
    assert "100%" in capsys.readouterr().out
    from conescope._batch import _check_workers
    with pytest.raises(conescope.BatchError, match=r"2 of 2 Dask workers .*does not see /no/such/storage"):
        _check_workers(client, [str(library), "/no/such/storage"])
    _check_workers(client, [str(library)])


def test_a_worker_without_the_module_is_named_not_waited_for(library, tmp_path):
    """A real worker process that cannot import conescope (started without the build on its path)
    joins the cluster: the batch stops at once with a BatchError naming it."""
    import os
    import subprocess
    import sys
    cluster = LocalCluster(n_workers=0, processes=True, dashboard_address=":0")
    environment = {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}
    worker = subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", cluster.scheduler_address, "--nworkers", "1",
                               "--nthreads", "1", "--dashboard-address", ":0", "--no-nanny"],
                              cwd=tmp_path, env=environment, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        with Client(cluster) as bare:
            bare.wait_for_workers(1, timeout=60)
            with pytest.raises(conescope.BatchError, match=r"1 of 1 Dask workers .*cannot import conescope \(ModuleNotFoundError"):
                conescope.batch([library / "torus.off"], client=bare, views=4)
    finally:
        worker.terminate()
        worker.wait(timeout=30)
        cluster.close()
