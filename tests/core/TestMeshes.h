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
// A uniformly random unit vector.
glm::dvec3 randomUnit(std::mt19937_64& random);
// A random height-field patch: a bumpy grid whose normals spread up to about maxTiltDegrees.
Mesh randomPatch(std::mt19937_64& random, int cells, double maxTiltDegrees);

// A mesh of datasets/ (OFF), read without the io layer, which the core tests do not link.
Mesh readBundledOff(const std::string& name);

}  // namespace conescope::testmesh
