#include "RecordTests.h"

#include <stdexcept>

#include "EngineRecords.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

const EngineRecords& recordsOf(const CullingInput& input) { return *input.bounds.records; }

}  // namespace

bool readsOwnRecord(CullTest test) {
    return test == CullTest::MeshoptApexF32 || test == CullTest::MeshoptSphereS8 || test == CullTest::CadsceneBoxS8 ||
           test == CullTest::OctagonCompact;
}

std::string ownRecordRule(CullTest test) {
    switch (test) {
        case CullTest::MeshoptApexF32: return "meshoptimizer's apex test in float: culled iff dot(normalize(cone_apex - e), cone_axis) >= cone_cutoff";
        case CullTest::MeshoptSphereS8:
            return "niagara's test on meshoptimizer's 8-bit cone: culled iff dot(c - e, a) >= k |c - e| + r, a = cone_axis_s8 / 127, "
                   "k = cone_cutoff_s8 / 127";
        case CullTest::CadsceneBoxS8:
            return "cadscene's test: culled iff its 8-bit angle is negative and dot(N, normalize(e - k)) < angle at all 8 corners k of "
                   "its 8-bit box (N its octahedral axis)";
        case CullTest::OctagonCompact: return "the octagon test on the 16-byte record: culled iff g.(apex - e) > 0 for every decoded edge g";
        default: return "";
    }
}

bool reproducesEngineRecord(CullTest test) { return readsOwnRecord(test) && test != CullTest::OctagonCompact; }

size_t recordBytes(CullTest test) {
    switch (test) {
        case CullTest::Oracle: return 0;
        case CullTest::Vertices: return 16;          // axis (3 floats), sin alpha; statistics add 12 per vertex it reads
        case CullTest::Aabb:
        case CullTest::AabbFast: return 40;          // axis, sin alpha, box (6 floats)
        case CullTest::Sphere: return 36;            // axis, sin and cos alpha, centre, radius
        case CullTest::Apex: return 28;              // apex, axis, sin alpha
        case CullTest::MeshoptSphere: return 32;     // centre, radius, axis, sin alpha
        case CullTest::Octagon: return 112;          // apex, eight edges (27 floats) and a rounding slack
        case CullTest::MeshoptApexF32: return 28;    // cone_apex, cone_axis, cone_cutoff
        case CullTest::MeshoptSphereS8: return 20;   // center, radius, cone_axis_s8, cone_cutoff_s8
        case CullTest::CadsceneBoxS8: return 9;      // box 6 x UNORM8, octahedral axis 2 x SNORM8, -sin angle SNORM8
        case CullTest::OctagonCompact: return 16;    // CompactOctagons.h
    }
    return 0;
}

bool ownRecordCulls(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
        switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexCulls(records.meshopt(input)[cluster], eye);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8Culls(records.meshopt(input)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneCulls(records.cadscene(input)[cluster], records.object(input), eye);
        case CullTest::OctagonCompact: return compactOctagonCulls(records.decodedOctagons(input)[cluster], eye);
        default: throw std::logic_error("ownRecordCulls: " + std::to_string(int(test)) + " reads no record of its own");
    }
}

bool hasFloatOriginal(CullTest test) {
    return test == CullTest::MeshoptSphereS8 || test == CullTest::CadsceneBoxS8 || test == CullTest::OctagonCompact;
}

bool floatOriginalCulls(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
        switch (test) {
        case CullTest::MeshoptSphereS8: return meshoptSphereF32Culls(records.meshopt(input)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneFloatCulls(records.cadsceneFloat(input)[cluster], eye);
        default: return false;
    }
}

double ownRecordMargin(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
        switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexMargin(records.meshopt(input)[cluster], eye);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8Margin(records.meshopt(input)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneMargin(records.cadscene(input)[cluster], records.object(input), eye);
        case CullTest::OctagonCompact: {
            const DecodedOctagon& decoded = records.decodedOctagons(input)[cluster];
            if (!decoded.octagon.cullable) return -1.0;
            return octagonTightest(decoded.octagon, eye.orthographic ? eye.direction : decoded.apex - eye.position) - kCullMargin;
        }
        default: return 0.0;
    }
}

double ownRecordCullShare(const CullingInput& input, uint32_t cluster, CullTest test) {
    const EngineRecords& records = recordsOf(input);
        switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexCullShare(records.meshopt(input)[cluster]);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8CullShare(records.meshopt(input)[cluster]);
        case CullTest::CadsceneBoxS8: return cadsceneCullShare(records.cadscene(input)[cluster]);
        case CullTest::OctagonCompact: return octagonCullShare(records.decodedOctagons(input)[cluster].octagon);
        default: return 0.0;
    }
}

}  // namespace conescope
