#include "CompactOctagons.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "CullTest.h"

namespace conescope {

namespace {

constexpr int kTurnSteps = 16;       // over the octagon's 45 degree period
constexpr uint32_t kApexLast = 4095;  // 12 bits
constexpr int kAxisLast = 2047;       // signed 12 bits
constexpr int kStripLast = 255;       // 8 bits

// Little-endian bit fields in the 16 bytes.
struct Bits {
    std::array<uint8_t, 16>& bytes;
    int at = 0;
    void put(uint32_t value, int width) {
        for (int i = 0; i < width; ++i, ++at)
            if (value >> i & 1u) bytes[at / 8] |= uint8_t(1u << (at % 8));
    }
};
struct ReadBits {
    const std::array<uint8_t, 16>& bytes;
    int at = 0;
    uint32_t get(int width) {
        uint32_t value = 0;
        for (int i = 0; i < width; ++i, ++at) value |= uint32_t(bytes[at / 8] >> (at % 8) & 1u) << i;
        return value;
    }
    int getSigned(int width) {
        const uint32_t value = get(width);
        return value >> (width - 1) ? int(value) - (1 << width) : int(value);
    }
};

double signNotZero(double value) { return value >= 0.0 ? 1.0 : -1.0; }

std::array<int, 2> encodeAxis(const glm::dvec3& axis) {
    const double sum = std::abs(axis.x) + std::abs(axis.y) + std::abs(axis.z);
    if (!(sum > 0.0) || !std::isfinite(sum)) return {0, 0};
    glm::dvec2 p = glm::dvec2(axis.x, axis.y) / sum;
    if (axis.z <= 0.0) p = glm::dvec2((1.0 - std::abs(p.y)) * signNotZero(p.x), (1.0 - std::abs(p.x)) * signNotZero(p.y));
    return {int(std::lround(std::clamp(p.x, -1.0, 1.0) * kAxisLast)), int(std::lround(std::clamp(p.y, -1.0, 1.0) * kAxisLast))};
}

glm::dvec3 decodeAxis(int x, int y) {
    glm::dvec3 v(double(x) / kAxisLast, double(y) / kAxisLast, 0.0);
    v.z = 1.0 - std::abs(v.x) - std::abs(v.y);
    if (v.z < 0.0) v = glm::dvec3((1.0 - std::abs(v.y)) * signNotZero(v.x), (1.0 - std::abs(v.x)) * signNotZero(v.y), v.z);
    return glm::normalize(v);
}

double stripValue(int code) { return std::tan(double(code) / kStripLast * M_PI - M_PI / 2.0); }

// The code whose value is at least (up) or at most (down) `value`, as near as the steps allow.
int stripCode(double value, bool up) {
    if (std::isnan(value)) return up ? kStripLast : 0;  // open: never culls
    const double exact = (std::atan(value) + M_PI / 2.0) / M_PI * kStripLast;
    int code = int(std::clamp(up ? std::ceil(exact) : std::floor(exact), 0.0, double(kStripLast)));
    while (up && code < kStripLast && stripValue(code) < value) ++code;
    while (!up && code > 0 && stripValue(code) > value) --code;
    return code;
}

double turnAngle(int code) { return code * (M_PI / 4.0) / kTurnSteps; }

// The apex's codes, or none when the point is off the grid.
bool apexCodes(const glm::dvec3& point, const ApexGrid& grid, std::array<uint32_t, 3>& codes) {
    for (int k = 0; k < 3; ++k) {
        const double code = std::round((point[k] - grid.low[k]) / grid.step[k]);
        if (!(code >= 0.0 && code <= kApexLast)) return false;
        codes[k] = uint32_t(code);
    }
    return true;
}

glm::dvec3 apexAt(const std::array<uint32_t, 3>& codes, const ApexGrid& grid) {
    return grid.low + glm::dvec3(codes[0], codes[1], codes[2]) * grid.step;
}

// Whether `apex` is strictly behind the plane of every (non-degenerate) face of the cluster.
bool behindEveryFace(const glm::dvec3& apex, const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                     const uint32_t* clusterFaces, size_t faceCount) {
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t f = clusterFaces[i];
        if (faces.degenerate[f]) continue;
        for (size_t k = 0; k < mesh.faceSize(f); ++k)
            if (!(glm::dot(faces.normals[f], apex - glm::dvec3(world[mesh.faceBegin(f)[k]])) < 0.0)) return false;
    }
    return true;
}

// A grid point behind every face plane, on the axis behind the cluster's box centre: pushed back
// past its planes, then by the grid's half diagonal over the least n.axis, so rounding to the grid
// cannot bring it in front; further while the check in double fails. False when off the grid.
bool findApex(const glm::dvec3& axis, const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
              const uint32_t* clusterFaces, size_t faceCount, const ApexGrid& grid, std::array<uint32_t, 3>& codes) {
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-low);
    double leastAlong = 1.0, behind = 0.0;
    for (size_t i = 0; i < faceCount; ++i)
        for (size_t k = 0; k < mesh.faceSize(clusterFaces[i]); ++k) {
            const glm::dvec3 q(world[mesh.faceBegin(clusterFaces[i])[k]]);
            low = glm::min(low, q), high = glm::max(high, q);
        }
    const glm::dvec3 center = 0.5 * (low + high);
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t f = clusterFaces[i];
        if (faces.degenerate[f]) continue;
        const double along = glm::dot(faces.normals[f], axis);
        if (!(along > 0.0)) return false;
        leastAlong = std::min(leastAlong, along);
        for (size_t k = 0; k < mesh.faceSize(f); ++k)
            behind = std::max(behind, glm::dot(faces.normals[f], center - glm::dvec3(world[mesh.faceBegin(f)[k]])) / along);
    }
    const double push = 0.5 * glm::length(grid.step) / leastAlong;
    for (int attempt = 1; attempt <= 4; ++attempt) {
        if (!apexCodes(center - axis * (behind + attempt * push), grid, codes)) return false;
        if (behindEveryFace(apexAt(codes, grid), mesh, world, faces, clusterFaces, faceCount)) return true;
    }
    return false;
}

// The record for an axis code, turn and strips (the apex's codes zero): packed in the layout above.
CompactOctagon pack(const std::array<uint32_t, 3>& apex, const std::array<int, 2>& axis, int turn, const OctagonStrips& strips) {
    CompactOctagon record;
    Bits bits{record.bytes};
    for (uint32_t code : apex) bits.put(code, 12);
    for (int code : axis) bits.put(uint32_t(code) & 0xfffu, 12);
    bits.put(uint32_t(turn), 4);
    for (int j = 0; j < 4; ++j) {
        bits.put(uint32_t(stripCode(strips.high[j], true)), 8);
        bits.put(uint32_t(stripCode(strips.low[j], false)), 8);
    }
    return record;
}

}  // namespace

ApexGrid apexGridOver(const Aabb& object) {
    const glm::dvec3 low(object.min), high(object.max);
    const double margin = 0.5 * std::max({high.x - low.x, high.y - low.y, high.z - low.z, 1e-30});
    ApexGrid grid;
    grid.low = low - margin;
    grid.step = (high + margin - grid.low) / double(kApexLast);
    return grid;
}

CompactOctagon encodeCompactOctagon(const ConeOfNormals& cone, const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                                    const uint32_t* clusterFaces, size_t faceCount, const ApexGrid& grid) {
    if (!cone.cullable) return {};  // all zero: low codes 0, never culls
    const std::array<int, 2> axisCode = encodeAxis(cone.axis);
    const glm::dvec3 axis = decodeAxis(axisCode[0], axisCode[1]);
    std::vector<glm::dvec3> normals;
    for (size_t i = 0; i < faceCount; ++i) normals.push_back(faces.normals[clusterFaces[i]]);
    std::array<uint32_t, 3> apex{};
    if (!findApex(axis, mesh, world, faces, clusterFaces, faceCount, grid, apex)) return {};
    // Of the 16 turns, the one whose decoded octagon culls from the most directions.
    CompactOctagon best;
    double bestShare = 0.0;
    for (int turn = 0; turn < kTurnSteps; ++turn) {
        const std::optional<OctagonStrips> strips = octagonStripsOf(axis, turnAngle(turn), normals.data(), normals.size());
        if (!strips) return {};
        const CompactOctagon record = pack(apex, axisCode, turn, *strips);
        const double share = octagonCullShare(decodeCompactOctagon(record, grid).octagon);
        if (share > bestShare) bestShare = share, best = record;
    }
    return best;
}

DecodedOctagon decodeCompactOctagon(const CompactOctagon& record, const ApexGrid& grid) {
    ReadBits bits{record.bytes};
    std::array<uint32_t, 3> apex{};
    for (uint32_t& code : apex) code = bits.get(12);
    const int x = bits.getSigned(12), y = bits.getSigned(12);
    OctagonStrips strips;
    strips.turn = turnAngle(int(bits.get(4)));
    bool open = false;
    for (int j = 0; j < 4; ++j) {
        const int high = int(bits.get(8)), low = int(bits.get(8));
        open = open || high == kStripLast || low == 0;
        strips.high[j] = stripValue(high), strips.low[j] = stripValue(low);
    }
    DecodedOctagon decoded;
    decoded.apex = apexAt(apex, grid);
    if (open) return decoded;
    strips.axis = decodeAxis(x, y);
    decoded.octagon = octagonFromStrips(strips);
    return decoded;
}

bool compactOctagonCulls(const DecodedOctagon& decoded, const Eye& eye) {
    if (eye.orthographic) return octagonSeesBack(decoded.octagon, eye.direction);
    return octagonSeesBack(decoded.octagon, decoded.apex - eye.position, apexRoundingSlack(decoded.apex, eye.position));
}

}  // namespace conescope
