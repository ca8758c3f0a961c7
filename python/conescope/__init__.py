"""ConeScope from Python: cluster back-face culling statistics as the command line computes them.

    import conescope
    doc = conescope.stats("datasets/fandisk.off", views=64)      # the `stats` JSON as a dict
    doc["results"][0]["efficiency"]

Settings are keyword arguments named as the command line's options, with underscores or dashes
(``max_tris=64``, ``cone="minimal"``, ``test=["octagon", "apex"]``, ``eye=(0, 0, 5)``,
``fix_winding=True``); the settings schema checks them and a bad one raises ValueError with the
command line's message. Every error raised on purpose is a ``conescope.Error``: a file that cannot
be read raises MeshReadError (also an OSError) with the message ``conescope-cli`` prints, a refused
setting SettingsError (a ValueError), arrays that are not a mesh MeshDataError (a ValueError) or
ArgumentTypeError (a TypeError), naming the row. What the command line warns of on stderr (winding, a missed cluster
budget, what the reader skipped) comes as a Python warning.
"""

import functools as _functools
import inspect as _inspect
import json as _json
import os as _os
import sys as _sys
import warnings as _warnings

try:
    from . import _conescope
except ImportError as _error:
    _built = sorted(name for name in _os.listdir(_os.path.dirname(__file__)) if name.startswith("_conescope"))
    raise ImportError(
        f"conescope's compiled part could not be loaded into Python {_sys.version.split()[0]} "
        f"({_sys.executable}): {_error}. The package holds {_built or 'no compiled module'}; it must be "
        "built for this interpreter: run `python -m pip install --no-build-isolation .` from the "
        "ConeScope repository with this Python (on Debian: a venv made by `/usr/bin/python3 -m venv "
        "--system-site-packages`), or use /usr/bin/python3 with PYTHONPATH=build/python.") from None

from ._conescope import __version__
from ._errors import ArgumentTypeError, BatchError, Error, MeshDataError, MeshReadError, SettingsError
from ._errors import translated as _translated
from ._arrays import mesh_arrays as _mesh_arrays

__all__ = ["stats", "stats_arrays", "clusters", "clusters_arrays", "compare", "compare_arrays", "granularity", "lod", "partition",
           "partition_arrays", "batch",
           "read_results",
           "Error", "MeshReadError", "SettingsError", "MeshDataError", "ArgumentTypeError", "BatchError",
           "extensions", "__version__"]


def extensions():
    """The file extensions the readers take, e.g. ['.off', '.ply', ...]."""
    return _conescope.extensions()


def _setting_text(value):
    """A keyword's value as the command line's text."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if value is None:
        return ""
    if isinstance(value, (list, tuple)) or type(value).__name__ == "ndarray":
        return ",".join(_setting_text(item) for item in value)
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, _os.PathLike):
        return _os.fspath(value)
    return str(value)


def _setting_pairs(settings):
    # None is the default: as if the keyword were not given.
    pairs = [(name, _setting_text(value)) for name, value in settings.items() if value is not None]
    with _translated(SettingsError):
        _conescope.check_settings(pairs)
    return pairs


def _configuration_text(configuration):
    """A comparison side: "K=V,..." as compare's --a takes it, or a dict of settings."""
    if configuration is None:
        return ""
    if isinstance(configuration, dict):
        if not all(isinstance(name, str) for name in configuration):
            raise ArgumentTypeError("a comparison side's settings must be named by texts")
        return ",".join(f"{name.replace('_', '-')}={_setting_text(value)}" for name, value in configuration.items())
    if not isinstance(configuration, str):
        raise ArgumentTypeError(f"a comparison side must be a 'K=V,...' text or a dict, not {type(configuration).__name__}")
    return configuration


def _path(path):
    if not isinstance(path, (str, _os.PathLike)):
        raise ArgumentTypeError(f"path must be a text or a path, not {type(path).__name__}")
    return _os.fspath(path)


# The settings most runs set, as keyword-only arguments of every function that takes settings (None:
# the schema's default); every other setting goes in **settings under its option's name, with
# dashes or underscores (docs/user/command-line.md and what-is-computed.md list them).
_COMMON_SETTINGS = ("builder", "max_verts", "max_tris", "clusters", "cone", "test", "views", "distance")


def _common_settings(function):
    """`function` with the common settings as keyword-only arguments before its **settings."""
    signature = _inspect.signature(function)
    parameters = list(signature.parameters.values())
    common = [_inspect.Parameter(name, _inspect.Parameter.KEYWORD_ONLY, default=None) for name in _COMMON_SETTINGS]

    @_functools.wraps(function)
    def with_common(*arguments, **keywords):
        for name in _COMMON_SETTINGS:
            if name in keywords and keywords[name] is None:
                del keywords[name]
        return function(*arguments, **keywords)
    with_common.__signature__ = signature.replace(parameters=parameters[:-1] + common + parameters[-1:])
    return with_common


def _run(function, *arguments, value_error=SettingsError, result=None):
    """A call of the compiled part: its errors as conescope's, its notes as warnings, its JSON read
    (or the pair (value, notes) given to `result`)."""
    with _translated(value_error):
        return (result or _document)(function(*arguments))


def _flags(per_view, per_cluster):
    for name, value in (("per_view", per_view), ("per_cluster", per_cluster)):
        if not isinstance(value, bool):
            raise ArgumentTypeError(f"{name} must be True or False, not {value!r}")
    return per_view, per_cluster


def _sort_and_top(sort, top):
    if not isinstance(sort, str):
        raise ArgumentTypeError(f"sort must be a text, not {type(sort).__name__}")
    if isinstance(top, bool) or not isinstance(top, int):
        raise ArgumentTypeError(f"top must be an integer, not {top!r}")
    if top < 0:
        raise SettingsError(f"top must be 0 (all clusters) or more, not {top}")
    return sort, top


def _comparison(a, b, pairs):
    """Both sides of a comparison as compare's texts, checked against the shared settings."""
    sides = _configuration_text(a), _configuration_text(b)
    with _translated(SettingsError):
        for side in sides:
            _conescope.check_compare(side, pairs)
    return sides


def _document(result):
    text, notes = result
    for note in notes:
        _warnings.warn(note, stacklevel=4)
    return _json.loads(text)


def _with_cluster_ids(cluster_ids, settings):
    """Per-face cluster ids are the file builder's partition unless a builder is given."""
    if cluster_ids is not None and not any(name.replace("-", "_") == "builder" for name in settings):
        settings = dict(settings, builder="file")
    return settings


@_common_settings
def stats(path, per_view=True, per_cluster=True, **settings):
    """The statistics document `conescope-cli stats PATH` writes, as a dict."""
    return _run(_conescope.stats, _path(path), _setting_pairs(settings), *_flags(per_view, per_cluster))


@_common_settings
def stats_arrays(vertices, faces, cluster_ids=None, name="arrays", per_view=True, per_cluster=True, **settings):
    """The statistics document of a mesh given as arrays.

    vertices: n x 3 numbers; faces: an m x k integer array or a sequence of index sequences (polygons
    of any size); cluster_ids: one id per face, which the file builder uses (the default builder
    then). The mesh is checked and its equal positions merged as a file's are.
    """
    settings = _with_cluster_ids(cluster_ids, settings)
    pairs = _setting_pairs(settings)
    return _run(_conescope.stats_arrays, *_mesh_arrays(vertices, faces, cluster_ids), str(name), pairs,
                *_flags(per_view, per_cluster), value_error=MeshDataError)


@_common_settings
def clusters(path, sort="test-loss", top=20, **settings):
    """The worst clusters, as `conescope-cli clusters PATH --format json` writes them (top=0: all)."""
    return _run(_conescope.clusters, _path(path), _setting_pairs(settings), *_sort_and_top(sort, top))


@_common_settings
def clusters_arrays(vertices, faces, cluster_ids=None, name="arrays", sort="test-loss", top=20, **settings):
    """clusters() of a mesh given as arrays (see stats_arrays)."""
    settings = _with_cluster_ids(cluster_ids, settings)
    pairs = _setting_pairs(settings)
    return _run(_conescope.clusters_arrays, *_mesh_arrays(vertices, faces, cluster_ids), str(name), pairs,
                *_sort_and_top(sort, top), value_error=MeshDataError)


def _ids(result):
    ids, notes = result
    for note in notes:
        _warnings.warn(note, stacklevel=5)
    return ids


@_common_settings
def partition(path, **settings):
    """The partition the settings make: a numpy uint32 array, one cluster id per face of the mesh as
    read (what `conescope-cli partition PATH -o ids.txt` writes)."""
    return _run(_conescope.partition, _path(path), _setting_pairs(settings), result=_ids)


@_common_settings
def partition_arrays(vertices, faces, cluster_ids=None, name="arrays", **settings):
    """partition() of a mesh given as arrays (see stats_arrays): one cluster id per face given."""
    settings = _with_cluster_ids(cluster_ids, settings)
    return _run(_conescope.partition_arrays, *_mesh_arrays(vertices, faces, cluster_ids), str(name), _setting_pairs(settings),
                value_error=MeshDataError, result=_ids)


@_common_settings
def granularity(path, **settings):
    """What each record culls and costs on the mesh's partition, as `conescope-cli granularity PATH
    --format json` writes it: one row per record under "rows" (one cone with each test, 2, 4 and 8
    cones per cluster, per-triangle culling). Without test=..., every test but the oracle."""
    return _run(_conescope.granularity, _path(path), _setting_pairs(settings))


@_common_settings
def lod(path, threshold=1.0, world=False, screen_height=1080.0, fov=60.0, group_size=8, per_view=True, **settings):
    """A cluster LOD hierarchy built from the mesh, culled level by level and as the cut an eye draws,
    as `conescope-cli lod PATH --format json` writes it ("levels", "cut")."""
    if not threshold >= 0:
        raise SettingsError(f"threshold must be 0 or more, not {threshold}")
    if not screen_height > 0:
        raise SettingsError(f"screen_height must be above 0, not {screen_height}")
    if not 0 < fov < 180:
        raise SettingsError(f"fov must be between 0 and 180 degrees, not {fov}")
    if not isinstance(group_size, int) or group_size < 2:
        raise SettingsError(f"group_size must be a whole number of 2 or more, not {group_size!r}")
    return _run(_conescope.lod, _path(path), _setting_pairs(settings), float(threshold), bool(world), float(screen_height),
                float(fov), group_size, bool(per_view))


@_common_settings
def compare(path, a, b=None, per_view=True, per_cluster=True, **settings):
    """A against B, as `conescope-cli compare PATH --a A --b B --format json` writes it.

    a, b: "K=V,..." texts as compare's --a and --b take them, or dicts of settings; the keywords are
    the options both share (b=None: B is those alone).
    """
    pairs = _setting_pairs(settings)
    return _run(_conescope.compare, _path(path), *_comparison(a, b, pairs), pairs, *_flags(per_view, per_cluster))


@_common_settings
def compare_arrays(vertices, faces, a, b=None, cluster_ids=None, name="arrays", per_view=True, per_cluster=True,
                   **settings):
    """compare() of a mesh given as arrays (see stats_arrays)."""
    pairs = _setting_pairs(settings)
    return _run(_conescope.compare_arrays, *_mesh_arrays(vertices, faces, cluster_ids), str(name),
                *_comparison(a, b, pairs), pairs, *_flags(per_view, per_cluster), value_error=MeshDataError)


from ._batch import batch, read_results  # noqa: E402  (uses the helpers above)
batch = _common_settings(batch)
