#!/usr/bin/env python3
"""Rebuilds the synthetic meshes in this folder (standard library only).

    python3 datasets/generate.py            # writes next to this script
    python3 datasets/generate.py OUT_DIR

Every closed mesh is written with outward, counter-clockwise winding: seen from
outside, the vertices of each face go round anticlockwise, so the right-hand
normal points away from the solid. The script checks this before writing
(positive signed volume, and each face normal pointing away from a known
interior point) so a typo in a face table cannot slip into the data set.
"""

import math
import os
import sys


def subtract(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def normalized(a):
    length = math.sqrt(dot(a, a))
    return (a[0] / length, a[1] / length, a[2] / length)


def newell_normal(positions, face):
    """Polygon normal by Newell's method; equals the cross product for triangles."""
    nx = ny = nz = 0.0
    for i, current_index in enumerate(face):
        current = positions[current_index]
        following = positions[face[(i + 1) % len(face)]]
        nx += (current[1] - following[1]) * (current[2] + following[2])
        ny += (current[2] - following[2]) * (current[0] + following[0])
        nz += (current[0] - following[0]) * (current[1] + following[1])
    return (nx, ny, nz)


def face_centroid(positions, face):
    count = float(len(face))
    return tuple(sum(positions[i][axis] for i in face) / count for axis in range(3))


def signed_volume(positions, faces):
    """Divergence theorem over a fan triangulation; positive when the winding is outward."""
    volume = 0.0
    for face in faces:
        origin = positions[face[0]]
        for k in range(1, len(face) - 1):
            volume += dot(origin, cross(positions[face[k]], positions[face[k + 1]])) / 6.0
    return volume


def check_outward(name, positions, faces, interior_point_of_face):
    """Fails loudly if any face normal points towards the interior point given for it."""
    if signed_volume(positions, faces) <= 0.0:
        raise SystemExit(f"{name}: signed volume is not positive, winding is inward")
    for index, face in enumerate(faces):
        outward = subtract(face_centroid(positions, face), interior_point_of_face(face))
        if dot(newell_normal(positions, face), outward) <= 0.0:
            raise SystemExit(f"{name}: face {index} {face} is wound inward")


def icosahedron():
    t = (1.0 + math.sqrt(5.0)) / 2.0
    positions = [normalized(p) for p in [
        (-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0),
        (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
        (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]]
    faces = [
        (0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
        (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
        (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
        (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    return positions, faces


def icosphere(subdivisions):
    """Unit sphere; each level splits every triangle into four. Also returns, per face,
    the icosahedron face it came from (a natural 20-cluster partition)."""
    positions, faces = icosahedron()
    base_face = list(range(len(faces)))
    for _ in range(subdivisions):
        midpoint_index = {}

        def midpoint(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint_index:
                pa, pb = positions[a], positions[b]
                positions.append(normalized(((pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2)))
                midpoint_index[key] = len(positions) - 1
            return midpoint_index[key]

        finer_faces, finer_base_face = [], []
        for (a, b, c), origin in zip(faces, base_face):
            ab, bc, ca = midpoint(a, b), midpoint(b, c), midpoint(c, a)
            finer_faces += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
            finer_base_face += [origin] * 4
        faces, base_face = finer_faces, finer_base_face
    return positions, faces, base_face


def cube_positions():
    # Vertex i has x = bit 0, y = bit 1, z = bit 2, centred on the origin.
    return [(float(i & 1) - 0.5, float((i >> 1) & 1) - 0.5, float((i >> 2) & 1) - 0.5) for i in range(8)]


def cube_quads():
    return [
        (0, 2, 3, 1),  # z = -0.5, normal -z
        (4, 5, 7, 6),  # z = +0.5, normal +z
        (0, 1, 5, 4),  # y = -0.5, normal -y
        (2, 6, 7, 3),  # y = +0.5, normal +y
        (0, 4, 6, 2),  # x = -0.5, normal -x
        (1, 3, 7, 5),  # x = +0.5, normal +x
    ]


def split_quads(quads):
    triangles = []
    for a, b, c, d in quads:
        triangles += [(a, b, c), (a, c, d)]
    return triangles


def torus(ring_count, tube_count, major_radius, minor_radius):
    """Ring around the z axis; quad (i, j) spans ring steps i..i+1 and tube steps j..j+1."""
    positions = []
    for i in range(ring_count):
        u = 2.0 * math.pi * i / ring_count
        for j in range(tube_count):
            v = 2.0 * math.pi * j / tube_count
            radius = major_radius + minor_radius * math.cos(v)
            positions.append((radius * math.cos(u), radius * math.sin(u), minor_radius * math.sin(v)))

    def index(i, j):
        return (i % ring_count) * tube_count + (j % tube_count)

    quads = [(index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1))
             for i in range(ring_count) for j in range(tube_count)]
    return positions, split_quads(quads)


def hexagonal_prism(radius, half_height):
    """Two hexagon caps and six quad sides: a polygon mesh with faces of 4 and 6 vertices."""
    positions = []
    for z in (-half_height, half_height):
        for k in range(6):
            angle = 2.0 * math.pi * k / 6
            positions.append((radius * math.cos(angle), radius * math.sin(angle), z))
    bottom = tuple(reversed(range(6)))  # clockwise from above = anticlockwise from below
    top = tuple(range(6, 12))
    sides = [(k, (k + 1) % 6, 6 + (k + 1) % 6, 6 + k) for k in range(6)]
    return positions, [bottom, top] + sides


def cylinder(segments, rings, radius, height):
    """Capped cylinder around z from 0 to height: side quads split, each cap a fan around its centre."""
    positions = []
    for r in range(rings + 1):
        z = height * r / rings
        for k in range(segments):
            angle = 2.0 * math.pi * k / segments
            positions.append((radius * math.cos(angle), radius * math.sin(angle), z))

    def index(r, k):
        return r * segments + k % segments

    quads = [(index(r, k), index(r, k + 1), index(r + 1, k + 1), index(r + 1, k))
             for r in range(rings) for k in range(segments)]
    bottom_centre, top_centre = len(positions), len(positions) + 1
    positions += [(0.0, 0.0, 0.0), (0.0, 0.0, height)]
    caps = [(bottom_centre, index(0, k + 1), index(0, k)) for k in range(segments)]
    caps += [(top_centre, index(rings, k), index(rings, k + 1)) for k in range(segments)]
    return positions, split_quads(quads) + caps


def bumpy_plane(cells, size, bump):
    """Open height field over [-size/2, size/2]^2, faces up (+z): z = bump * sin(2 pi x / size * 2) * cos(...)."""
    positions = []
    for j in range(cells + 1):
        for i in range(cells + 1):
            x = size * (i / cells - 0.5)
            y = size * (j / cells - 0.5)
            positions.append((x, y, bump * math.sin(4.0 * math.pi * x / size) * math.cos(4.0 * math.pi * y / size)))

    def index(i, j):
        return j * (cells + 1) + i

    quads = [(index(i, j), index(i + 1, j), index(i + 1, j + 1), index(i, j + 1))
             for j in range(cells) for i in range(cells)]
    return positions, split_quads(quads)


def format_number(value):
    text = f"{value:.9g}"
    return "0" if text == "-0" else text


def write_off(path, positions, faces, comment):
    with open(path, "w", newline="\n") as out:
        out.write("OFF\n")
        out.write(f"# {comment}\n")
        out.write(f"{len(positions)} {len(faces)} 0\n")
        for p in positions:
            out.write(" ".join(format_number(c) for c in p) + "\n")
        for face in faces:
            out.write(f"{len(face)} " + " ".join(str(i) for i in face) + "\n")


def write_vtp_with_cluster_ids(path, positions, faces, cluster_ids):
    """Hand-written ASCII VTK XML PolyData with a per-face Int32 "cluster_id" array."""
    offsets, running = [], 0
    for face in faces:
        running += len(face)
        offsets.append(running)
    with open(path, "w", newline="\n") as out:
        out.write('<?xml version="1.0"?>\n')
        out.write('<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n')
        out.write("  <PolyData>\n")
        out.write(f'    <Piece NumberOfPoints="{len(positions)}" NumberOfVerts="0" NumberOfLines="0" '
                  f'NumberOfStrips="0" NumberOfPolys="{len(faces)}">\n')
        out.write("      <CellData Scalars=\"cluster_id\">\n")
        out.write('        <DataArray type="Int32" Name="cluster_id" format="ascii">\n')
        out.write("          " + " ".join(str(c) for c in cluster_ids) + "\n")
        out.write("        </DataArray>\n")
        out.write("      </CellData>\n")
        out.write("      <Points>\n")
        out.write('        <DataArray type="Float32" NumberOfComponents="3" format="ascii">\n')
        for p in positions:
            out.write("          " + " ".join(format_number(c) for c in p) + "\n")
        out.write("        </DataArray>\n")
        out.write("      </Points>\n")
        out.write("      <Polys>\n")
        out.write('        <DataArray type="Int64" Name="connectivity" format="ascii">\n')
        for face in faces:
            out.write("          " + " ".join(str(i) for i in face) + "\n")
        out.write("        </DataArray>\n")
        out.write('        <DataArray type="Int64" Name="offsets" format="ascii">\n')
        out.write("          " + " ".join(str(o) for o in offsets) + "\n")
        out.write("        </DataArray>\n")
        out.write("      </Polys>\n")
        out.write("    </Piece>\n")
        out.write("  </PolyData>\n")
        out.write("</VTKFile>\n")


def main():
    out_dir = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    os.makedirs(out_dir, exist_ok=True)
    origin = (0.0, 0.0, 0.0)

    sphere_positions, sphere_faces, sphere_base_face = icosphere(3)
    check_outward("icosphere", sphere_positions, sphere_faces, lambda face: origin)
    write_off(os.path.join(out_dir, "icosphere.off"), sphere_positions, sphere_faces,
              "unit icosphere, icosahedron subdivided 3 times: 642 vertices, 1280 triangles")

    cube = cube_positions()
    check_outward("cube", cube, cube_quads(), lambda face: origin)
    write_off(os.path.join(out_dir, "cube.off"), cube, split_quads(cube_quads()),
              "unit cube centred on the origin, 12 triangles")
    write_off(os.path.join(out_dir, "cube-quads.off"), cube, cube_quads(),
              "unit cube centred on the origin, 6 quads")

    torus_positions, torus_faces = torus(48, 24, 1.0, 0.35)

    def tube_centre(face):
        x, y, _ = face_centroid(torus_positions, face)
        scale = 1.0 / math.hypot(x, y)
        return (x * scale, y * scale, 0.0)

    check_outward("torus", torus_positions, torus_faces, tube_centre)
    write_off(os.path.join(out_dir, "torus.off"), torus_positions, torus_faces,
              "torus around z, radii 1 and 0.35, 48 x 24 quads split into 2304 triangles")

    prism_positions, prism_faces = hexagonal_prism(1.0, 0.5)
    check_outward("prism", prism_positions, prism_faces, lambda face: origin)
    write_off(os.path.join(out_dir, "hexagonal-prism.off"), prism_positions, prism_faces,
              "hexagonal prism: 2 hexagon caps and 6 quad sides")

    # Teaching meshes (File > Examples): a capped cylinder and a bumpy plane beside the sphere and torus.
    cylinder_positions, cylinder_faces = cylinder(32, 8, 0.5, 1.5)
    check_outward("cylinder", cylinder_positions, cylinder_faces,
                  lambda face: (0.0, 0.0, face_centroid(cylinder_positions, face)[2] if
                                0.0 < face_centroid(cylinder_positions, face)[2] < 1.5 else 0.75))
    write_off(os.path.join(out_dir, "cylinder.off"), cylinder_positions, cylinder_faces,
              "capped cylinder around z, radius 0.5, height 1.5, 32 x 8 side quads split and two 32-triangle fans")

    plane_positions, plane_faces = bumpy_plane(32, 2.0, 0.12)
    if any(newell_normal(plane_positions, face)[2] <= 0.0 for face in plane_faces):
        raise SystemExit("bumpy plane: a face does not face up")
    write_off(os.path.join(out_dir, "bumpy-plane.off"), plane_positions, plane_faces,
              "open 2 x 2 height field facing +z, 32 x 32 quads split, bumps of height 0.12")

    clustered_positions, clustered_faces, clustered_base_face = icosphere(2)
    write_vtp_with_cluster_ids(os.path.join(out_dir, "icosphere-clusters.vtp"), clustered_positions,
                               clustered_faces, clustered_base_face)


if __name__ == "__main__":
    main()
