#!/usr/bin/env python3
"""Writes tests/data/formats/: the same unit cube (centred on the origin, outward counter-clockwise
winding) in every format readMesh supports, written by hand rather than by VTK so the reader tests
do not just test VTK against itself. Standard library only.

    python3 tests/data/make_format_samples.py

Faces carry "cluster_id" = face index // 2 where the format can hold per-face data (.vtp, .vtk).
"""

import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
OUT = os.path.join(HERE, "formats")

# Vertex i: x = bit 0, y = bit 1, z = bit 2, each -0.5 or +0.5.
POSITIONS = [(float(i & 1) - 0.5, float((i >> 1) & 1) - 0.5, float((i >> 2) & 1) - 0.5) for i in range(8)]
QUADS = [
    (0, 2, 3, 1),  # -z
    (4, 5, 7, 6),  # +z
    (0, 1, 5, 4),  # -y
    (2, 6, 7, 3),  # +y
    (0, 4, 6, 2),  # -x
    (1, 3, 7, 5),  # +x
]
TRIANGLES = [tri for a, b, c, d in QUADS for tri in ((a, b, c), (a, c, d))]
QUAD_NORMALS = [(0, 0, -1), (0, 0, 1), (0, -1, 0), (0, 1, 0), (-1, 0, 0), (1, 0, 0)]


def number(value):
    return f"{value:g}"


def point_line(p):
    return " ".join(number(c) for c in p)


def write(name, data, mode="w"):
    with open(os.path.join(OUT, name), mode, **({} if "b" in mode else {"newline": "\n"})) as out:
        out.write(data)


def ascii_ply():
    lines = ["ply", "format ascii 1.0", "comment unit cube, 6 quads", "element vertex 8",
             "property float x", "property float y", "property float z",
             "element face 6", "property list uchar int vertex_indices", "end_header"]
    lines += [point_line(p) for p in POSITIONS]
    lines += ["4 " + " ".join(str(i) for i in q) for q in QUADS]
    return "\n".join(lines) + "\n"


def binary_ply():
    header = "\n".join(["ply", "format binary_little_endian 1.0", "comment unit cube, 12 triangles",
                        "element vertex 8", "property float x", "property float y", "property float z",
                        "element face 12", "property list uchar int vertex_indices", "end_header"]) + "\n"
    body = b"".join(struct.pack("<3f", *p) for p in POSITIONS)
    body += b"".join(struct.pack("<B3i", 3, *t) for t in TRIANGLES)
    return header.encode("ascii") + body


def obj():
    lines = ["# unit cube, 6 quads (OBJ indices start at 1)", "o cube"]
    lines += ["v " + point_line(p) for p in POSITIONS]
    lines += ["f " + " ".join(str(i + 1) for i in q) for q in QUADS]
    return "\n".join(lines) + "\n"


def textured_obj():
    """The cube with a texture coordinate and a normal at every corner, in all four corner forms and
    with negative indices, among groups, materials (one usemtl empty), smoothing groups, a trailing
    comment, a line and points: 8 positions, 6 quads; the line and the 3 points are not faces."""
    lines = ["# unit cube: 8 positions, 4 texture coordinates, 6 normals, 6 quads", "mtllib cube.mtl", "o cube"]
    lines += ["v " + point_line(p) for p in POSITIONS]
    lines += ["vt 0 0", "vt 1 0", "vt 1 1", "vt 0 1"]
    lines += ["vn " + point_line(n) for n in QUAD_NORMALS]
    forms = ["{v}/{t}/{n}", "{v}/{t}/{n}", "{v}//{n}", "{v}/{t}", "{v}", "{rv}/{rt}/{rn}"]
    groups = ["g bottom", "usemtl red", "s 1", "g top", "usemtl", "s off"]
    for face, (quad, form) in enumerate(zip(QUADS, forms)):
        lines.append(groups[face])
        # Relative indices count back from the 8 positions, 4 texture coordinates and 6 normals.
        corners = [form.format(v=i + 1, t=k + 1, n=face + 1, rv=i - 8, rt=k - 4, rn=face - 6) for k, i in enumerate(quad)]
        lines.append("f " + " ".join(corners) + (" # -z" if face == 0 else ""))
    lines += ["l 1 2", "p 1 2 3"]
    return "\n".join(lines) + "\n"


def triangle_normal(t):
    a, b, c = (POSITIONS[i] for i in t)
    u = [b[k] - a[k] for k in range(3)]
    v = [c[k] - a[k] for k in range(3)]
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def ascii_stl():
    lines = ["solid cube"]
    for t in TRIANGLES:
        lines.append("  facet normal " + point_line(triangle_normal(t)))
        lines.append("    outer loop")
        lines += ["      vertex " + point_line(POSITIONS[i]) for i in t]
        lines.append("    endloop")
        lines.append("  endfacet")
    lines.append("endsolid cube")
    return "\n".join(lines) + "\n"


def binary_stl():
    data = b"unit cube, 12 triangles".ljust(80, b" ") + struct.pack("<I", len(TRIANGLES))
    for t in TRIANGLES:
        data += struct.pack("<3f", *triangle_normal(t))
        for i in t:
            data += struct.pack("<3f", *POSITIONS[i])
        data += struct.pack("<H", 0)
    return data


def vtp():
    offsets = " ".join(str(4 * (k + 1)) for k in range(len(QUADS)))
    connectivity = " ".join(str(i) for q in QUADS for i in q)
    points = " ".join(point_line(p) for p in POSITIONS)
    cluster_ids = " ".join(str(k // 2) for k in range(len(QUADS)))
    return f"""<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <PolyData>
    <Piece NumberOfPoints="8" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="6">
      <CellData>
        <DataArray type="Int32" Name="cluster_id" format="ascii">{cluster_ids}</DataArray>
        <DataArray type="Float32" Name="face_normal" NumberOfComponents="3" format="ascii">{" ".join(point_line(n) for n in QUAD_NORMALS)}</DataArray>
      </CellData>
      <Points>
        <DataArray type="Float32" NumberOfComponents="3" format="ascii">{points}</DataArray>
      </Points>
      <Polys>
        <DataArray type="Int64" Name="connectivity" format="ascii">{connectivity}</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">{offsets}</DataArray>
      </Polys>
    </Piece>
  </PolyData>
</VTKFile>
"""


def legacy_vtk():
    lines = ["# vtk DataFile Version 3.0", "unit cube, 6 quads, cluster_id per face", "ASCII", "DATASET POLYDATA",
             "POINTS 8 float"]
    lines += [point_line(p) for p in POSITIONS]
    lines.append(f"POLYGONS {len(QUADS)} {5 * len(QUADS)}")
    lines += ["4 " + " ".join(str(i) for i in q) for q in QUADS]
    lines += [f"CELL_DATA {len(QUADS)}", "SCALARS cluster_id int 1", "LOOKUP_TABLE default"]
    lines += [str(k // 2) for k in range(len(QUADS))]
    return "\n".join(lines) + "\n"


def legacy_vtk_strips():
    """Cube side walls as one triangle strip (8 triangles) plus the two caps as polygons."""
    lines = ["# vtk DataFile Version 3.0", "cube walls as a strip", "ASCII", "DATASET POLYDATA", "POINTS 8 float"]
    lines += [point_line(p) for p in POSITIONS]
    lines += ["POLYGONS 2 10", "4 0 2 3 1", "4 4 5 7 6"]
    # Around the walls (top corner, then bottom corner), so the first triangle (4 0 5) faces -y.
    strip = [4, 0, 5, 1, 7, 3, 6, 2, 4, 0]
    lines += [f"TRIANGLE_STRIPS 1 {len(strip) + 1}", f"{len(strip)} " + " ".join(str(i) for i in strip)]
    lines += ["CELL_DATA 3", "SCALARS part int 1", "LOOKUP_TABLE default", "0", "0", "1"]
    return "\n".join(lines) + "\n"


def unstructured_grid_vtk():
    """A legacy file that is not polygonal data: readMesh must refuse it clearly."""
    lines = ["# vtk DataFile Version 3.0", "one tetrahedron", "ASCII", "DATASET UNSTRUCTURED_GRID",
             "POINTS 4 float", "0 0 0", "1 0 0", "0 1 0", "0 0 1", "CELLS 1 5", "4 0 1 2 3", "CELL_TYPES 1", "10"]
    return "\n".join(lines) + "\n"


def main():
    os.makedirs(OUT, exist_ok=True)
    write("cube.ply", ascii_ply())
    write("cube-binary.ply", binary_ply(), "wb")
    write("cube.obj", obj())
    write("cube-textured.obj", textured_obj())
    write("cube-ascii.stl", ascii_stl())
    write("cube-binary.stl", binary_stl(), "wb")
    write("cube.vtp", vtp())
    write("cube.vtk", legacy_vtk())
    write("cube-strips.vtk", legacy_vtk_strips())
    write("tetrahedron-grid.vtk", unstructured_grid_vtk())


if __name__ == "__main__":
    main()
