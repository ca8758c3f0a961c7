"""conescope.batch: results.csv of many meshes as a pandas DataFrame, on this machine (the command
line's batch: worker processes, crash isolation, resuming) or on a Dask cluster."""

import io
import os
import signal
import subprocess
import tempfile

from . import _conescope
from . import _comparison, _setting_pairs
from ._errors import ArgumentTypeError, BatchError, SettingsError, translated

MESHOPT_PIPELINE = "builder=meshopt,cone=meshopt,test=apex"


def _cli():
    """CONESCOPE_CLI, else the conescope-cli installed in the package, else the one the module was built with."""
    packaged = os.path.join(os.path.dirname(__file__), "conescope-cli")
    return os.environ.get("CONESCOPE_CLI", packaged if os.access(packaged, os.X_OK) else _conescope.cli_path)


# The one table of results.csv's column types (docs/statistics-schema.md): a column keeps its dtype
# whatever the rows hold, so an error row (empty numbers) or an empty text column changes nothing and
# batches concatenate or go to Parquet unchanged. Counts are nullable integers, texts nullable strings.
_COUNTS = ("clusters views clusters_culled triangles_culled back_facing_triangles missed_clusters false_culls "
           "uncullable_clusters open_edges non_manifold_edges inconsistent_edges duplicate_faces double_sided_faces "
           "degenerate_faces components orientable winding_fixed_faces inside_out_components test_loss_triangles "
           "partition_loss_triangles engine_record quantisation_loss_triangles vertices faces triangles "
           "triangles_culled_only_a triangles_culled_only_b triangles_culled_both setting_max_vertices "
           "setting_max_triangles setting_clusters_target setting_views")
_REALS = ("efficiency expected_efficiency ns_per_cluster mean_view_efficiency mean_cluster_triangles "
          "mean_cluster_vertices mean_sphere_radius max_sphere_radius cull_fraction oracle_fraction bytes_per_cluster "
          "uncullable_share seconds setting_normal_weight setting_cone_weight setting_distance culled_share")
_FLAGS = "setting_orthographic setting_fix_winding"
COLUMN_DTYPES = {**{name: "Int64" for name in _COUNTS.split()}, **{name: "float64" for name in _REALS.split()},
                 **{name: "boolean" for name in _FLAGS.split()}}


# The columns of `batch --granularity` (cones_K..., triangle_...) and `--lod` (lod_...): counts by
# their ending, every other one a real number.
_EXTRA_PREFIXES = ("cones_", "triangle_", "lod_")
_EXTRA_COUNTS = ("_bytes_per_cluster", "_levels", "_false_culls", "_triangles")


def column_dtype(name):
    """The dtype of a results.csv column: from the table (A's totals `a_X` as X), else a string."""
    if name in COLUMN_DTYPES:
        return COLUMN_DTYPES[name]
    if name.startswith("a_") and name[2:] in COLUMN_DTYPES:
        return COLUMN_DTYPES[name[2:]]
    if name.startswith(_EXTRA_PREFIXES):
        # The cut's triangles are a mean per view.
        return "Int64" if name.endswith(_EXTRA_COUNTS) and name != "lod_cut_triangles" else "float64"
    return "string"


def with_fixed_dtypes(frame):
    """The frame with every column in its fixed dtype."""
    return frame.astype({name: column_dtype(name) for name in frame.columns})


def read_results(path_or_buffer):
    """A batch's results.csv as the DataFrame conescope.batch returns: exact numbers, fixed dtypes."""
    import pandas as pd
    # round_trip: the shortest texts the CSV holds read back to the very numbers written (pandas's
    # default parser may be one unit in the last place off). Texts are read as text ("1" stays "1").
    frame = pd.read_csv(path_or_buffer, float_precision="round_trip",
                        dtype={name: str for name in _text_columns(path_or_buffer)})
    return with_fixed_dtypes(frame)


def _text_columns(path_or_buffer):
    if hasattr(path_or_buffer, "getvalue"):
        header = path_or_buffer.getvalue().split("\n", 1)[0]
    else:
        with open(path_or_buffer, encoding="utf-8") as file:
            header = file.readline()
    return [name for name in header.strip().split(",") if column_dtype(name) == "string"]


def _local_batch(paths, output_dir, pairs, compare, per_view, per_cluster, jobs, shard, timeout, memory_limit, progress):
    command = [_cli(), "batch", *paths, "-o", output_dir] + ([] if progress else ["--quiet"])
    command += _conescope.setting_arguments(pairs)
    if compare:
        command += ["--compare", compare]
    if not per_view:
        command.append("--no-per-view")
    if not per_cluster:
        command.append("--no-per-cluster")
    for flag, value in (("--jobs", jobs), ("--shard", shard), ("--timeout", timeout), ("--memory-limit", memory_limit)):
        if value is not None:
            command += [flag, str(value)]
    process = subprocess.Popen(command, stderr=subprocess.PIPE, text=True)
    try:
        _, errors = process.communicate()
    except KeyboardInterrupt:
        # The batch stops as on its own Ctrl-C (a notebook's interrupt reaches this process only): it
        # writes the rows it has, the folder stays consistent, and the same call resumes.
        process.send_signal(signal.SIGINT)
        process.wait()
        raise
    # 0: every mesh ok; 3: finished with error rows, which the table holds.
    if process.returncode not in (0, 3):
        raise BatchError(errors.strip() or f"conescope-cli batch ended with exit code {process.returncode}")
    return read_results(os.path.join(output_dir, "results.csv"))


def _row_on_worker(path, folder, pairs, compare, per_view, per_cluster):
    """What a Dask worker runs for one mesh: its results.csv row, as the command line makes it."""
    from conescope import _conescope as worker_module
    return worker_module.batch_row(path, folder, pairs, compare, per_view, per_cluster)


# What each Dask worker is asked before any mesh is sent: the module's version it imports, or why it
# cannot. Defined from source, so that it reaches a worker by value: a worker without the module
# could not unpickle a function of it, and would drop its tasks while the batch waited forever.
_WORKER_CHECK = """
def module_on_worker(folders):
    try:
        import conescope
    except Exception as error:
        return "cannot import conescope (" + type(error).__name__ + ": " + str(error) + ")"
    import os
    unseen = [folder for folder in folders if not os.path.isdir(folder)]
    return conescope.__version__ if not unseen else "does not see " + ", ".join(unseen[:3])
"""


def _check_workers(client, folders):
    """Raise BatchError unless every worker imports this version of the module and sees `folders`
    (the meshes' folders and the output folder: storage every worker must share)."""
    from . import __version__
    namespace = {}
    exec(_WORKER_CHECK, namespace)
    try:
        answers = client.run(namespace["module_on_worker"], folders, on_error="return")
    except Exception as error:
        raise BatchError(f"the Dask cluster did not answer ({type(error).__name__}: {error})") from error
    if not answers:
        raise BatchError("the Dask client has no workers: start some (dask worker SCHEDULER) or use a LocalCluster")
    wrong = {worker: answer for worker, answer in answers.items() if answer != __version__}
    if wrong:
        said = "; ".join(f"{worker}: {answer if isinstance(answer, str) and not answer[:1].isdigit() else f'conescope {answer}'}"
                         for worker, answer in sorted(wrong.items()))
        raise BatchError(f"{len(wrong)} of {len(answers)} Dask workers cannot run this batch (conescope {__version__} here): "
                         f"{said}. Start every worker with the same build on its path "
                         "(PYTHONPATH=/path/to/build/python dask worker SCHEDULER), the meshes and output_dir on "
                         "storage every worker sees.")


def _dask_batch(client, paths, output_dir, pairs, compare, per_view, per_cluster, shard, progress):
    # Absolute paths: the workers may run in another folder.
    with translated(SettingsError):
        meshes = [os.path.abspath(mesh) for mesh in _conescope.find_meshes(paths, shard or "")]
    folder = ""
    if output_dir is not None:
        folder = os.path.abspath(output_dir)  # the workers write here: shared storage on a real cluster
        os.makedirs(os.path.join(folder, "meshes"), exist_ok=True)
    _check_workers(client, sorted({os.path.dirname(mesh) for mesh in meshes} | ({folder} if folder else set())))
    # A second run into the same folder keeps the rows the command line's batch would keep.
    kept = _conescope.kept_rows(meshes, folder, pairs, compare, per_view, per_cluster) if folder else [None] * len(meshes)
    missing = [mesh for mesh, row in zip(meshes, kept) if row is None]
    futures = dict(zip(missing, client.map(_row_on_worker, missing, folder=folder, pairs=pairs, compare=compare,
                                           per_view=per_view, per_cluster=per_cluster, pure=False)))
    if progress and futures:
        from distributed import progress as dask_progress
        dask_progress(list(futures.values()))  # Dask's own bar (a widget in a notebook); returns when all are done
    rows = []
    for mesh, row in zip(meshes, kept):
        if row is not None:
            rows.append(row)
            continue
        try:
            rows.append(futures[mesh].result())
        except Exception as error:  # the worker died on it (KilledWorker) or Dask failed it
            message = f"{mesh}: the Dask task running it failed ({type(error).__name__}: {error})"
            rows.append(_conescope.error_row(mesh, "crash", message, pairs, compare, per_view, per_cluster))
    if folder:
        _conescope.write_results(folder, rows, compare)
    return read_results(io.StringIO(_conescope.results_csv(rows)))


def batch(paths, client=None, output_dir=None, compare=None, compare_meshopt=False, per_view=True, per_cluster=True,
          jobs=None, shard=None, timeout=None, memory_limit=None, progress=False, **settings):
    """results.csv of every mesh in `paths` (files and folders) as a pandas DataFrame: a row per mesh,
    the columns docs/statistics-schema.md lists.

    Without `client`, `conescope-cli batch` runs here (jobs workers, per-mesh timeout and memory
    limit, crash isolation); given `output_dir` it also leaves its files there (meshes/*.json,
    results.csv, report.html) and skips meshes done before. With a dask.distributed Client, each
    mesh's row is computed on a Dask worker with this module; `output_dir` (shared by the workers) then
    gets the JSON files, results.csv and report.html. compare: A's options as "K=V,..." or a dict;
    compare_meshopt: meshoptimizer's pipeline as A. Without output_dir the json columns are empty.
    progress: show it (the command line's progress on stderr, or Dask's own bar).
    """
    if isinstance(paths, (str, os.PathLike)):
        paths = [paths]
    if not all(isinstance(path, (str, os.PathLike)) for path in paths):
        raise ArgumentTypeError("paths must be a path or a list of paths (files or folders)")
    paths = [os.fspath(path) for path in paths]
    pairs = _setting_pairs(settings)
    if compare_meshopt and compare is not None:
        raise SettingsError("compare and compare_meshopt=True both name side A: give one of them")
    if client is not None:
        ignored = [name for name, value in (("jobs", jobs), ("timeout", timeout), ("memory_limit", memory_limit))
                   if value is not None]
        if ignored:
            raise SettingsError(f"{', '.join(ignored)} apply to the local batch only; a Dask client's workers "
                                "set their own processes and limits")
    for name, value in (("jobs", jobs), ("timeout", timeout), ("memory_limit", memory_limit)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, (int, float)) or value <= 0):
            raise SettingsError(f"{name} must be a number above 0, not {value!r}")
    compare = _comparison(MESHOPT_PIPELINE if compare_meshopt else compare, None, pairs)[0]
    if client is not None:
        frame = _dask_batch(client, paths, output_dir, pairs, compare, per_view, per_cluster, shard, progress)
    elif output_dir is not None:
        frame = _local_batch(paths, os.fspath(output_dir), pairs, compare, per_view, per_cluster, jobs, shard, timeout,
                             memory_limit, progress)
    else:
        with tempfile.TemporaryDirectory(prefix="conescope-batch-") as folder:
            frame = _local_batch(paths, folder, pairs, compare, per_view, per_cluster, jobs, shard, timeout, memory_limit,
                                 progress)
    if output_dir is None:
        frame[["json", "compare_json"]] = None
    return with_fixed_dtypes(frame)
