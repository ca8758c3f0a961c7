#include "RecordTests.h"

#include <stdexcept>

#include "Choices.h"
#include "EngineRecords.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

const EngineRecords& recordsOf(const CullingInput& input) { return *input.bounds.records; }

}  // namespace

// Which tests read records of their own, their rules and every test's bytes are rows of Choices.cpp.
bool readsOwnRecord(CullTest test) { return *descriptor(test).ownRecordRule != '\0'; }

std::string ownRecordRule(CullTest test) { return descriptor(test).ownRecordRule; }

bool reproducesEngineRecord(CullTest test) { return readsOwnRecord(test) && test != CullTest::OctagonCompact; }

size_t recordBytes(CullTest test) { return descriptor(test).recordBytes; }

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
