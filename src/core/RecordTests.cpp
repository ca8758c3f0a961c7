#include "RecordTests.h"

#include <stdexcept>

#include "Choices.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

RecordSource sourceOf(const RecordInput& input) {
    return {input.mesh, input.world, input.faces, input.bounds.faces, input.bounds.cones};
}

const EngineRecords& recordsOf(const RecordInput& input) { return *input.bounds.records; }

}  // namespace

// Which tests read records of their own, their rules and every test's bytes are rows of Choices.cpp.
bool readsOwnRecord(CullTest test) { return *descriptor(test).ownRecordRule != '\0'; }

std::string ownRecordRule(CullTest test) { return descriptor(test).ownRecordRule; }

bool reproducesEngineRecord(CullTest test) { return readsOwnRecord(test) && test != CullTest::OctagonCompact; }

size_t recordBytes(CullTest test) { return descriptor(test).recordBytes; }

bool ownRecordCulls(const RecordInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
    const RecordSource source = sourceOf(input);
    switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexCulls(records.meshopt(source)[cluster], eye);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8Culls(records.meshopt(source)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneCulls(records.cadscene(source)[cluster], records.object(source), eye);
        case CullTest::OctagonCompact: return compactOctagonCulls(records.decodedOctagons(source)[cluster], eye);
        default: throw std::logic_error("ownRecordCulls: " + std::to_string(int(test)) + " reads no record of its own");
    }
}

bool hasFloatOriginal(CullTest test) {
    return test == CullTest::MeshoptSphereS8 || test == CullTest::CadsceneBoxS8 || test == CullTest::OctagonCompact;
}

bool floatOriginalCulls(const RecordInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
    const RecordSource source = sourceOf(input);
    switch (test) {
        case CullTest::MeshoptSphereS8: return meshoptSphereF32Culls(records.meshopt(source)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneFloatCulls(records.cadsceneFloat(source)[cluster], eye);
        default: return false;
    }
}

double ownRecordMargin(const RecordInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    const EngineRecords& records = recordsOf(input);
    const RecordSource source = sourceOf(input);
    switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexMargin(records.meshopt(source)[cluster], eye);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8Margin(records.meshopt(source)[cluster], eye);
        case CullTest::CadsceneBoxS8: return cadsceneMargin(records.cadscene(source)[cluster], records.object(source), eye);
        case CullTest::OctagonCompact: {
            const DecodedOctagon& decoded = records.decodedOctagons(source)[cluster];
            if (!decoded.octagon.cullable) return -1.0;
            return octagonTightest(decoded.octagon, eye.orthographic ? eye.direction : decoded.apex - eye.position) - kCullMargin;
        }
        default: return 0.0;
    }
}

double ownRecordCullShare(const RecordInput& input, uint32_t cluster, CullTest test) {
    const EngineRecords& records = recordsOf(input);
    const RecordSource source = sourceOf(input);
    switch (test) {
        case CullTest::MeshoptApexF32: return meshoptApexCullShare(records.meshopt(source)[cluster]);
        case CullTest::MeshoptSphereS8: return meshoptSphereS8CullShare(records.meshopt(source)[cluster]);
        case CullTest::CadsceneBoxS8: return cadsceneCullShare(records.cadscene(source)[cluster]);
        case CullTest::OctagonCompact: return octagonCullShare(records.decodedOctagons(source)[cluster].octagon);
        default: return 0.0;
    }
}

}  // namespace conescope
