#!/usr/bin/env python3
"""Writes tests/data/gltf/: small glTF 2.0 files written by hand (not by any glTF library), each with
counts and geometry the reader tests check by hand. Standard library only.

    python3 tests/data/make_gltf_samples.py

Every mesh is the unit cube of make_format_samples.py (corners at +-0.5, outward counter-clockwise
winding). "Split" cubes have 24 vertices, 4 per face, as exporters write them (a vertex per face
corner, so each face can carry its own normal); a reader that did not merge equal positions would see
6 separate squares.
"""

import base64
import json
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "gltf")
sys.path.insert(0, HERE)
from make_format_samples import POSITIONS, QUADS, QUAD_NORMALS  # noqa: E402

FLOAT, UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT = 5126, 5121, 5123, 5125
POINTS, LINES, LINE_STRIP, TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN = 0, 1, 3, 4, 5, 6
INDEX_FORMAT = {UNSIGNED_BYTE: "<B", UNSIGNED_SHORT: "<H", UNSIGNED_INT: "<I"}


class Document:
    """A glTF document with one binary buffer, filled by adding accessors."""

    def __init__(self):
        self.json = {"asset": {"version": "2.0", "generator": "make_gltf_samples.py"},
                     "accessors": [], "bufferViews": [], "meshes": [], "nodes": []}
        self.data = b""

    def _view(self, data):
        self.data += b"\0" * (-len(self.data) % 4)  # accessors of 4-byte components stay aligned
        self.json["bufferViews"].append({"buffer": 0, "byteOffset": len(self.data), "byteLength": len(data)})
        self.data += data
        return len(self.json["bufferViews"]) - 1

    def positions(self, points):
        view = self._view(b"".join(struct.pack("<3f", *p) for p in points))
        lows = [min(p[k] for p in points) for k in range(3)]
        highs = [max(p[k] for p in points) for k in range(3)]
        self.json["accessors"].append({"bufferView": view, "componentType": FLOAT, "count": len(points),
                                       "type": "VEC3", "min": lows, "max": highs})
        return len(self.json["accessors"]) - 1

    def normals(self, vectors):
        view = self._view(b"".join(struct.pack("<3f", *v) for v in vectors))
        self.json["accessors"].append({"bufferView": view, "componentType": FLOAT, "count": len(vectors),
                                       "type": "VEC3"})
        return len(self.json["accessors"]) - 1

    def indices(self, values, component_type=UNSIGNED_SHORT):
        view = self._view(b"".join(struct.pack(INDEX_FORMAT[component_type], v) for v in values))
        self.json["accessors"].append({"bufferView": view, "componentType": component_type, "count": len(values),
                                       "type": "SCALAR"})
        return len(self.json["accessors"]) - 1

    def mesh(self, primitives, name):
        self.json["meshes"].append({"name": name, "primitives": primitives})
        return len(self.json["meshes"]) - 1

    def node(self, **fields):
        self.json["nodes"].append(fields)
        return len(self.json["nodes"]) - 1

    def scene(self, roots):
        self.json["scene"] = 0
        self.json["scenes"] = [{"nodes": roots}]

    def gltf(self, bin_name=None):
        """The JSON text, its buffer in bin_name or, without one, embedded as a base64 data URI."""
        buffer = {"byteLength": len(self.data)}
        if bin_name:
            buffer["uri"] = bin_name
        else:
            buffer["uri"] = "data:application/octet-stream;base64," + base64.b64encode(self.data).decode("ascii")
        return json.dumps(dict(self.json, buffers=[buffer]), indent=1) + "\n"

    def glb(self):
        """Binary glTF: 12-byte header, JSON chunk padded with spaces, BIN chunk padded with zeros."""
        text = json.dumps(dict(self.json, buffers=[{"byteLength": len(self.data)}])).encode("ascii")
        text += b" " * (-len(text) % 4)
        data = self.data + b"\0" * (-len(self.data) % 4)
        chunks = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
        return struct.pack("<4sII", b"glTF", 2, 12 + len(chunks)) + chunks


def split_cube(doc, index_type=UNSIGNED_SHORT, name="cube"):
    """The cube as 24 vertices (4 per face, each with the face's normal), 12 indexed triangles; or,
    with index_type None, 36 vertices and no indices."""
    corners = [POSITIONS[i] for quad in QUADS for i in quad]
    normals = [n for n in QUAD_NORMALS for _ in range(4)]
    triangles = [v for k in range(6) for v in (4 * k, 4 * k + 1, 4 * k + 2, 4 * k, 4 * k + 2, 4 * k + 3)]
    if index_type is None:
        points = [corners[v] for v in triangles]
        primitive = {"attributes": {"POSITION": doc.positions(points),
                                    "NORMAL": doc.normals([normals[v] for v in triangles])}, "mode": TRIANGLES}
    else:
        primitive = {"attributes": {"POSITION": doc.positions(corners), "NORMAL": doc.normals(normals)},
                     "indices": doc.indices(triangles, index_type)}  # mode left out: TRIANGLES is the default
    return doc.mesh([primitive], name)


def single_cube(index_type=UNSIGNED_SHORT):
    doc = Document()
    doc.scene([doc.node(mesh=split_cube(doc, index_type))])
    return doc


def strips_and_fans():
    """The cube from strips and fans: the four walls as two triangle strips of 4 triangles (one
    indexed, one not), the two caps as triangle fans of 2 triangles (one indexed, one not). The
    glTF order of strips (odd triangles {v_i, v_i+2, v_i+1}) and fans ({v_i+1, v_i+2, v_0}) makes
    every face outward."""
    doc = Document()
    corners = doc.positions(POSITIONS)
    front_walls = [4, 0, 5, 1, 7, 3]  # -y then +x; first triangle (4, 0, 5) faces -y
    back_walls = [7, 3, 6, 2, 4, 0]   # +y then -x
    bottom_fan = [0, 2, 3, 1]         # -z
    top_fan = [4, 5, 7, 6]            # +z
    primitives = [
        {"attributes": {"POSITION": corners}, "indices": doc.indices(front_walls), "mode": TRIANGLE_STRIP},
        {"attributes": {"POSITION": doc.positions([POSITIONS[i] for i in back_walls])}, "mode": TRIANGLE_STRIP},
        {"attributes": {"POSITION": corners}, "indices": doc.indices(bottom_fan, UNSIGNED_BYTE), "mode": TRIANGLE_FAN},
        {"attributes": {"POSITION": doc.positions([POSITIONS[i] for i in top_fan])}, "mode": TRIANGLE_FAN},
    ]
    doc.scene([doc.node(mesh=doc.mesh(primitives, "cube from strips and fans"))])
    return doc


def instanced():
    """One cube mesh used by two nodes, at x = +2 and x = -2."""
    doc = Document()
    cube = split_cube(doc)
    doc.scene([doc.node(mesh=cube, translation=[2, 0, 0]), doc.node(mesh=cube, translation=[-2, 0, 0])])
    return doc


def transforms():
    """Three instances of the cube: node 0 by translation, rotation and scale; its child node 2 by a
    translation in node 0's frame; node 1 by a column-major matrix."""
    doc = Document()
    cube = split_cube(doc)
    half = 0.5 ** 0.5
    child = doc.node(mesh=cube, translation=[2, 0, 0], name="child of trs")
    trs = doc.node(mesh=cube, translation=[0, 0, 5], rotation=[0, 0, half, half], scale=[2, 1, 1],
                   children=[child], name="trs: scale x by 2, turn 90 degrees about z, move z by 5")
    matrix = doc.node(mesh=cube, matrix=[3, 0, 0, 0, 0, 3, 0, 0, 0, 0, 3, 0, 10, 0, 0, 1],
                      name="matrix: scale by 3, move x by 10")
    doc.scene([trs, matrix])
    return doc


def mirrored():
    """The cube moved to x = 3, then mirrored by scale (-1, 1, 1): it lands at x = -3 with its
    triangles wound clockwise as seen from outside, which glTF makes front faces (det < 0)."""
    doc = Document()
    moved = doc.node(mesh=split_cube(doc), translation=[3, 0, 0])
    doc.scene([doc.node(scale=[-1, 1, 1], children=[moved], name="mirror")])
    return doc


def sparse():
    """The cube whose top corners a sparse accessor lifts from z = 0.5 to z = 1.5: a box twice as
    tall, read through the sparse indices and values that replace 12 of the 24 positions."""
    doc = Document()
    cube = split_cube(doc)
    primitive = doc.json["meshes"][cube]["primitives"][0]
    base = doc.json["accessors"][primitive["attributes"]["POSITION"]]
    corners = [POSITIONS[i] for quad in QUADS for i in quad]
    lifted = [v for v, p in enumerate(corners) if p[2] > 0]
    indices = doc._view(b"".join(struct.pack("<H", v) for v in lifted))
    values = doc._view(b"".join(struct.pack("<3f", corners[v][0], corners[v][1], 1.5) for v in lifted))
    base["sparse"] = {"count": len(lifted), "indices": {"bufferView": indices, "componentType": UNSIGNED_SHORT},
                      "values": {"bufferView": values}}
    base["max"][2] = 1.5
    doc.scene([doc.node(mesh=cube)])
    return doc


def with_lines_and_points():
    """The cube's triangles plus three primitives that are not faces: points, lines, a line strip."""
    doc = Document()
    corners = doc.positions(POSITIONS)
    cube = split_cube(doc)
    triangles = doc.json["meshes"][cube]["primitives"][0]
    doc.json["meshes"].pop()
    primitives = [
        triangles,
        {"attributes": {"POSITION": corners}, "mode": POINTS},
        {"attributes": {"POSITION": corners}, "indices": doc.indices([0, 1, 1, 3]), "mode": LINES},
        {"attributes": {"POSITION": corners}, "indices": doc.indices([4, 5, 7, 6]), "mode": LINE_STRIP},
    ]
    doc.scene([doc.node(mesh=doc.mesh(primitives, "cube with points and lines"))])
    return doc


def write(name, data):
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(OUT, name), mode, **({} if "b" in mode else {"newline": "\n"})) as out:
        out.write(data)


def main():
    os.makedirs(OUT, exist_ok=True)
    cube = single_cube()
    write("cube.gltf", cube.gltf("cube.bin"))
    write("cube.bin", cube.data)
    write("cube-embedded.gltf", cube.gltf())
    write("cube.glb", cube.glb())
    write("cube-u8.gltf", single_cube(UNSIGNED_BYTE).gltf())
    write("cube-u32.gltf", single_cube(UNSIGNED_INT).gltf())
    write("cube-unindexed.gltf", single_cube(None).gltf())
    write("strips-fans.gltf", strips_and_fans().gltf())
    write("instanced.gltf", instanced().gltf())
    write("transforms.gltf", transforms().gltf())
    write("mirrored.gltf", mirrored().gltf())
    write("lines-points.gltf", with_lines_and_points().gltf())
    write("sparse.gltf", sparse().gltf())


if __name__ == "__main__":
    main()
