// One descriptor per choice a run makes (cone method, cull test, builder): its name in the settings
// and statistics, its words for the glossary, its colour and lesson wording, its record's bytes.
// Settings, schema, glossary, Gauss map, lesson and record sizes read these tables, so adding a
// choice is one row here (docs/dev/recipes.md); a value without a row fails to compile.
#pragma once

#include <array>
#include <cstddef>

#include "CullTest.h"

namespace conescope {

enum class ConeMethod;  // ClusterBounds.h

// How the faces are grouped into clusters (BuildPartition.h); one row each in builderDescriptors().
enum class Builder { Meshlet, KMeans, Meshopt, File, Optimized };

struct ConeDescriptor {
    ConeMethod method;
    const char* name;                 // settings and statistics ("minimal")
    const char* glossary;             // what the cone is, one sentence (glossary "Cone: <name>")
    std::array<double, 3> colour;     // its rim and legend colour in the Gauss map and lesson, in [0, 1]
    // The lesson's sentence on the shown cone; "{average}" and "{minimal}" stand for those cones' α.
    const char* lessonWording;
};

struct CullTestDescriptor {
    CullTest test;
    const char* name;      // settings and statistics ("octagon")
    const char* glossary;  // what the test checks (glossary "Test: <name>")
    // Bytes per cluster of the record it reads, as a renderer would store it (docs/statistics-schema.md,
    // bytes_per_cluster); 0 for the oracle, which reads the faces themselves.
    size_t recordBytes;
    // The rule of a test that reads a record of its own (RecordTests.h), for the picked cluster's page;
    // empty for the others.
    const char* ownRecordRule;
};

struct BuilderDescriptor {
    Builder builder;
    const char* name;         // settings and statistics ("optimized")
    const char* explanation;  // what it does, one sentence (the settings panel's tooltip)
};

constexpr size_t kConeMethodCount = 5;
constexpr size_t kCullTestCount = 12;
constexpr size_t kBuilderCount = 5;

// In the order the settings list them (help, "all", the panel); every enum value exactly once.
const std::array<ConeDescriptor, kConeMethodCount>& coneDescriptors();
const std::array<CullTestDescriptor, kCullTestCount>& cullTestDescriptors();
const std::array<BuilderDescriptor, kBuilderCount>& builderDescriptors();

const ConeDescriptor& descriptor(ConeMethod method);
const CullTestDescriptor& descriptor(CullTest test);
const BuilderDescriptor& descriptor(Builder builder);

}  // namespace conescope
