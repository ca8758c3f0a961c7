// Small meshes made in code, so core tests need no reader, and the bundled ones read simply.
#pragma once

#include <random>
#include <string>

#include <glm/glm.hpp>

#include "core/Mesh.h"

namespace conescope::testmesh {

// Subdivided icosahedron on the unit sphere, counter-clockwise seen from outside.
Mesh icosphere(int subdivisions);
// Torus around the y axis, quads split into triangles.
Mesh torus(double majorRadius, double minorRadius, int majorSegments, int minorSegments);
// Unit cube as six quads (polygon faces).
Mesh quadCube();
// A roof of `sides` triangles from a unit circle in z = 0 up to (0, 0, height): every normal at the
// same angle from +z.
Mesh roof(int sides, double height);
// A flat unit square of cells x cells quads in z = 0, facing +z.
Mesh flatPatch(int cells);
// A uniformly random unit vector.
glm::dvec3 randomUnit(std::mt19937_64& random);
// A random height-field patch: a bumpy grid whose normals spread up to about maxTiltDegrees.
Mesh randomPatch(std::mt19937_64& random, int cells, double maxTiltDegrees);
// A random triangle soup around the origin whose normals spread up to spreadDegrees around one
// axis; above 90 every third normal is turned over, so they span more than a hemisphere.
Mesh randomSoup(std::mt19937_64& random, size_t triangles, double spreadDegrees);
// Translated, rotated and stretched (mirrored half of the time) at coordinates of size `scale`.
glm::dmat4 randomModel(std::mt19937_64& random, double scale);
// Icospheres of 0 to 2 subdivisions scattered within +-20 of the origin, 0.05 to 2 across: separate
// pieces, between which meshoptimizer's builder jumps through its k-d tree.
Mesh scatteredSpheres(std::mt19937_64& random, int pieces);

// Foliage: `leaves` leaves scattered in a ball of radius 1, each a pentagon and a quad folded along
// their shared edge (about 30 degrees), turned every way, 0.06 across, with vertices of their own:
// a mesh of thousands of small parts whose nearby faces face every way, as trees and plants are.
Mesh foliage(std::mt19937_64& random, int leaves);

// Furniture made of closed boxes (a desk top on legs, shelves, a door): `boxes` boxes of random
// sizes side by side, each side a grid of cells x cells quads, as modelling tools export them.
Mesh boxProp(std::mt19937_64& random, int boxes, int cells);
// One closed box from `low` across `extent`, each side cells x cells quads (or each quad as two
// triangles), wound outwards.
void addBox(Mesh& mesh, const glm::dvec3& low, const glm::dvec3& extent, int cells, bool triangles);
// Furniture of closed boxes as props are modelled: kind 0 a desk (a top on legs, a drawer box),
// 1 shelves (sides, a back, 2 to 5 boards), 2 a door with handles; random sizes, boards 2 to 6 cm.
Mesh furnitureProp(std::mt19937_64& random, int kind, int cells, bool triangles);

// A mesh of datasets/ (OFF), read without the io layer, which the core tests do not link.
Mesh readBundledOff(const std::string& name);
// A mesh of tests/data/ (OFF) the same way, say "cgal/bones.off".
Mesh readTestDataOff(const std::string& name);

}  // namespace conescope::testmesh
