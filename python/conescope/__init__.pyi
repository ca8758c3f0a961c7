# Types of conescope's public functions (checked against the module by python/tests/test_stubs.py).
import os
from typing import Any, Mapping, Sequence, Union

import numpy.typing as npt
import pandas as pd

__version__: str
__all__: list[str]

PathLike = Union[str, os.PathLike[str]]
# builder ... distance: the common settings, keyword-only in every function that takes settings.
Settings = Any  # a keyword's value: number, text, bool or a list of texts (the README's Python section lists the keys)
Side = Union[str, Mapping[str, Any]]  # a comparison side: "K=V,..." or a dict of settings
Vertices = npt.ArrayLike  # (n, 3) float32/float64
Faces = Union[npt.ArrayLike, Sequence[Sequence[int]]]  # (m, k) integers, or one list of indices per face
ClusterIds = npt.ArrayLike | None  # one integer cluster id per face

class Error(Exception): ...
class MeshReadError(Error, OSError): ...
class SettingsError(Error, ValueError): ...
class MeshDataError(Error, ValueError): ...
class ArgumentTypeError(Error, TypeError): ...
class BatchError(Error, RuntimeError): ...

def extensions() -> list[str]: ...
def stats(path: PathLike, per_view: bool = True, per_cluster: bool = True, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def stats_arrays(vertices: Vertices, faces: Faces, cluster_ids: ClusterIds = None, name: str = "arrays",
                 per_view: bool = True, per_cluster: bool = True, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def clusters(path: PathLike, sort: str = "test-loss", top: int = 20, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def clusters_arrays(vertices: Vertices, faces: Faces, cluster_ids: ClusterIds = None, name: str = "arrays",
                    sort: str = "test-loss", top: int = 20, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def partition(path: PathLike, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> npt.NDArray[Any]: ...
def partition_arrays(vertices: Vertices, faces: Faces, cluster_ids: ClusterIds = None, name: str = "arrays",
                     *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> npt.NDArray[Any]: ...
def granularity(path: PathLike, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def lod(path: PathLike, threshold: float = 1.0, world: bool = False, screen_height: float = 1080.0, fov: float = 60.0,
        group_size: int = 8, per_view: bool = True, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def compare(path: PathLike, a: Side, b: Side | None = None, per_view: bool = True, per_cluster: bool = True,
            *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def compare_arrays(vertices: Vertices, faces: Faces, a: Side, b: Side | None = None, cluster_ids: ClusterIds = None,
                   name: str = "arrays", per_view: bool = True, per_cluster: bool = True,
                   *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> dict[str, Any]: ...
def batch(paths: PathLike | Sequence[PathLike], client: Any = None, output_dir: PathLike | None = None,
          compare: Side | None = None, compare_meshopt: bool = False, per_view: bool = True, per_cluster: bool = True,
          jobs: int | None = None, shard: str | None = None, timeout: float | None = None,
          memory_limit: float | None = None, progress: bool = False, *,
        builder: str | None = None, max_verts: int | None = None, max_tris: int | None = None, clusters: int | None = None,
        cone: str | Sequence[str] | None = None, test: str | Sequence[str] | None = None, views: int | None = None,
        distance: float | None = None, **settings: Settings) -> pd.DataFrame: ...
def read_results(path_or_buffer: Any) -> pd.DataFrame: ...
