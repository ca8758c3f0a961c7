"""ConeScope from Python: cluster back-face culling statistics as the command line computes them.

    import conescope
    doc = conescope.stats("datasets/fandisk.off", views=64)      # the `stats` JSON as a dict
    doc["results"][0]["efficiency"]

Settings are keyword arguments named as the command line's options, with underscores or dashes
(``max_tris=64``, ``cone="minimal"``, ``test=["octagon", "apex"]``, ``eye=(0, 0, 5)``,
``fix_winding=True``); the settings schema checks them and a bad one raises ValueError with the
command line's message. A file that cannot be read raises MeshReadError (an OSError) with the
message ``conescope-cli`` prints. What the command line warns of on stderr (winding, a missed cluster
budget, what the reader skipped) comes as a Python warning.
"""

import json as _json
import os as _os
import warnings as _warnings

from . import _conescope
from ._conescope import MeshReadError, __version__

__all__ = ["stats", "stats_arrays", "clusters", "clusters_arrays", "compare", "compare_arrays", "batch",
           "MeshReadError", "extensions", "__version__"]


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
    _conescope.check_settings(pairs)
    return pairs


def _configuration_text(configuration):
    """A comparison side: "K=V,..." as compare's --a takes it, or a dict of settings."""
    if configuration is None:
        return ""
    if isinstance(configuration, dict):
        return ",".join(f"{name.replace('_', '-')}={_setting_text(value)}" for name, value in configuration.items())
    return str(configuration)


def _document(result):
    text, notes = result
    for note in notes:
        _warnings.warn(note, stacklevel=3)
    return _json.loads(text)


def _with_cluster_ids(cluster_ids, settings):
    """Per-face cluster ids are the file builder's partition unless a builder is given."""
    if cluster_ids is not None and not any(name.replace("-", "_") == "builder" for name in settings):
        settings = dict(settings, builder="file")
    return settings


def stats(path, per_view=True, per_cluster=True, **settings):
    """The statistics document `conescope-cli stats PATH` writes, as a dict."""
    return _document(_conescope.stats(_os.fspath(path), _setting_pairs(settings), per_view, per_cluster))


def stats_arrays(vertices, faces, cluster_ids=None, name="arrays", per_view=True, per_cluster=True, **settings):
    """The statistics document of a mesh given as arrays.

    vertices: n x 3 numbers; faces: an m x k integer array or a sequence of index sequences (polygons
    of any size); cluster_ids: one id per face, which the file builder uses (the default builder
    then). The mesh is checked and its equal positions merged as a file's are.
    """
    settings = _with_cluster_ids(cluster_ids, settings)
    return _document(_conescope.stats_arrays(vertices, faces, cluster_ids, name, _setting_pairs(settings),
                                             per_view, per_cluster))


def clusters(path, sort="test-loss", top=20, **settings):
    """The worst clusters, as `conescope-cli clusters PATH --format json` writes them (top=0: all)."""
    return _document(_conescope.clusters(_os.fspath(path), _setting_pairs(settings), sort, top))


def clusters_arrays(vertices, faces, cluster_ids=None, name="arrays", sort="test-loss", top=20, **settings):
    """clusters() of a mesh given as arrays (see stats_arrays)."""
    settings = _with_cluster_ids(cluster_ids, settings)
    return _document(_conescope.clusters_arrays(vertices, faces, cluster_ids, name, _setting_pairs(settings), sort, top))


def compare(path, a, b=None, per_view=True, per_cluster=True, **settings):
    """A against B, as `conescope-cli compare PATH --a A --b B --format json` writes it.

    a, b: "K=V,..." texts as compare's --a and --b take them, or dicts of settings; the keywords are
    the options both share (b=None: B is those alone).
    """
    return _document(_conescope.compare(_os.fspath(path), _configuration_text(a), _configuration_text(b),
                                        _setting_pairs(settings), per_view, per_cluster))


def compare_arrays(vertices, faces, a, b=None, cluster_ids=None, name="arrays", per_view=True, per_cluster=True,
                   **settings):
    """compare() of a mesh given as arrays (see stats_arrays)."""
    return _document(_conescope.compare_arrays(vertices, faces, cluster_ids, name, _configuration_text(a),
                                               _configuration_text(b), _setting_pairs(settings), per_view, per_cluster))


from ._batch import batch  # noqa: E402  (uses the helpers above)
