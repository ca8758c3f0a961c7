// The octagon test's record in 16 bytes (CullTest::OctagonCompact), beside the float one of 112
// (OctagonCones.h), kept conservative: every quantity is rounded so that it only ever culls less.
//
// Bits, least significant first (128 in all):
//   apex     3 x 12 bits  unsigned, on a grid over the object's box grown by half its largest side on
//                         every side; the apex is pushed back along the axis until the grid point is
//                         behind every face plane (checked in double)
//   axis     2 x 12 bits  signed, octahedral (value / 2047), the axis of the run's cone rounded
//                         to nearest; the octagon is then built around the decoded axis
//   turn     4 bits       the sides' turn, t x 45/16 degrees (the turn of the 16 that culls most)
//   strips   8 x 8 bits   high, low of each of the four strips (sides at turn + k 45 degrees) in the
//                         gnomonic plane, as atan(value) on [-90, 90] degrees in 255 steps, high
//                         rounded up, low rounded down; high 255 or low 0 says: never cull
// The test is the float octagon's on the decoded octagon and apex, with the same margins.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "Cones.h"
#include "Mesh.h"
#include "OctagonCones.h"
#include "Views.h"

namespace conescope {

struct CompactOctagon {
    std::array<uint8_t, 16> bytes{};
};

// The apex's grid: over the object's box grown by half its largest side on every side.
struct ApexGrid {
    glm::dvec3 low{0.0};
    glm::dvec3 step{1.0};  // per 12-bit code
};
ApexGrid apexGridOver(const Aabb& object);

// The record of one cluster (faces `clusterFaces` of the mesh, world positions and face geometry
// as the bounds used) with `cone` the round cone the float octagon is built around. A record that
// never culls when no quantised octagon or apex holds the cluster.
CompactOctagon encodeCompactOctagon(const ConeOfNormals& cone, const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                    const uint32_t* clusterFaces, size_t faceCount, const ApexGrid& grid);

struct DecodedOctagon {
    OctagonCone octagon;  // not cullable for a record that never culls
    glm::dvec3 apex{0.0};
};
DecodedOctagon decodeCompactOctagon(const CompactOctagon& record, const ApexGrid& grid);

// The octagon test on the decoded record, exactly as CullTest::Octagon tests the float one.
bool compactOctagonCulls(const DecodedOctagon& decoded, const Eye& eye);

}  // namespace conescope
