"""The one place arrays given as a mesh are checked: shapes, dtypes, finite positions, indices in
range; each refusal names the row. What passes goes to the compiled part as contiguous buffers."""

import numpy as np

from ._errors import ArgumentTypeError, MeshDataError


def _first_row(mask):
    return int(np.flatnonzero(mask.reshape(mask.shape[0], -1).any(axis=1))[0])


def mesh_vertices(vertices):
    """(n, 3) float32/float64 (or integer) positions as C-contiguous float64."""
    try:
        array = np.asarray(vertices)
    except (ValueError, TypeError) as error:
        raise MeshDataError(f"vertices must be an n x 3 array of numbers ({error})") from None
    if array.dtype == object or not (np.issubdtype(array.dtype, np.floating) or np.issubdtype(array.dtype, np.integer)):
        raise ArgumentTypeError(f"vertices must hold numbers, not {array.dtype}")
    if array.ndim != 2 or array.shape[1] != 3:
        raise MeshDataError(f"vertices must be an n x 3 array, not of shape {array.shape}")
    array = np.ascontiguousarray(array, dtype=np.float64)
    bad = ~np.isfinite(array)
    if bad.any():
        row = _first_row(bad)
        raise MeshDataError(f"vertices[{row}] is not finite: {array[row].tolist()}")
    return array


def _check_indices(array, vertex_count, what):
    if array.size and (array.min() < 0 or array.max() >= vertex_count):
        bad = (array < 0) | (array >= vertex_count)
        row = _first_row(bad)
        raise MeshDataError(f"{what}[{row}] = {array[row].tolist()} has a vertex index outside [0, {vertex_count})")


def mesh_faces(faces, vertex_count):
    """(m, k) integer faces as C-contiguous uint32, k >= 3; or a list of index lists (polygons of
    any size), each checked the same way."""
    try:
        array = np.asarray(faces)
    except ValueError:  # ragged: polygons of different sizes
        array = None
    if array is not None and array.dtype != object:
        if not np.issubdtype(array.dtype, np.integer):
            raise ArgumentTypeError(f"faces must hold integer vertex indices, not {array.dtype}")
        if array.ndim != 2 or array.shape[1] < 3:
            raise MeshDataError(f"faces must be an m x k array with k >= 3, not of shape {array.shape}")
        _check_indices(array, vertex_count, "faces")
        return np.ascontiguousarray(array, dtype=np.uint32)
    polygons = []
    for row, face in enumerate(faces):
        try:
            polygon = np.asarray(face)
        except ValueError:
            raise MeshDataError(f"faces[{row}] is not a sequence of vertex indices") from None
        if polygon.dtype == object or not np.issubdtype(polygon.dtype, np.integer):
            raise ArgumentTypeError(f"faces[{row}] must hold integer vertex indices, not {polygon.dtype}")
        if polygon.ndim != 1 or polygon.size < 3:
            raise MeshDataError(f"faces[{row}] must list at least 3 vertex indices, not {polygon.tolist()}")
        if polygon.min() < 0 or polygon.max() >= vertex_count:
            raise MeshDataError(f"faces[{row}] = {polygon.tolist()} has a vertex index outside [0, {vertex_count})")
        polygons.append(polygon.astype(np.uint32).tolist())
    return polygons


def face_cluster_ids(cluster_ids, face_count):
    """One integer cluster id per face, or None."""
    if cluster_ids is None:
        return None
    array = np.asarray(cluster_ids)
    if array.dtype == object or not np.issubdtype(array.dtype, np.integer):
        raise ArgumentTypeError(f"cluster_ids must hold integers, not {array.dtype}")
    if array.ndim != 1 or array.shape[0] != face_count:
        raise MeshDataError(f"cluster_ids must hold one id per face ({face_count}), not an array of shape {array.shape}")
    if array.size and array.min() < 0:
        row = int(np.flatnonzero(array < 0)[0])
        raise MeshDataError(f"cluster_ids[{row}] = {int(array[row])} is negative")
    return np.ascontiguousarray(array, dtype=np.float64)


def mesh_arrays(vertices, faces, cluster_ids):
    vertices = mesh_vertices(vertices)
    faces = mesh_faces(faces, vertices.shape[0])
    return vertices, faces, face_cluster_ids(cluster_ids, len(faces))
