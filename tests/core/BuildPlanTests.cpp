// The optimized builder's policy (optimizer/BuildPlan.h): which branch each effort and budget takes,
// and partitions equal to the ones recorded in tests/data/optimizer-partitions.txt on a sample of
// meshes, efforts and budgets, so a change of the policy's form does not change what it builds.
// CONESCOPE_WRITE_PARTITIONS=FILE writes the record instead (only when the builder is meant to change).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "TestMeshes.h"
#include "core/ClusterOptimizer.h"
#include "core/Settings.h"
#include "core/meshopt/Meshopt.h"
#include "core/optimizer/BuildPlan.h"

using namespace conescope;

namespace {

BuildFacts factsOf(size_t faces, size_t meshletCount, size_t fewest) { return {faces, true, meshletCount, fewest, 1.0}; }

}  // namespace

// The default budget starts from meshoptimizer's searched meshlets; the balanced level also grows
// clusters over the whole of a mesh of several meshlet parts below kGrowWholeBelowFaces (a mesh of
// one part grows its own in the search, Runs.h).
TEST(BuildPlan, TheDefaultBudgetKeepsMeshoptimizersSearchedMeshlets) {
    for (Effort effort : {Effort::Fast, Effort::Balanced})
        for (size_t faces : {size_t(1000), size_t(5000), kGrowWholeBelowFaces - 1, kGrowWholeBelowFaces}) {
            const BuildPlan plan = planBuild(effort, 0, factsOf(faces, 0, 20));
            EXPECT_EQ(plan.start, BuildStart::Meshlets);
            const bool whole = effort == Effort::Balanced && meshletPartsFor(faces) > 1 && faces < kGrowWholeBelowFaces;
            EXPECT_EQ(plan.alsoGrown, whole ? AlsoGrown::Always : AlsoGrown::Never) << toString(effort) << " " << faces;
            EXPECT_FALSE(plan.annealFurther || plan.packWhenMissed || plan.climb || plan.alsoBalanced);
        }
}

TEST(BuildPlan, ExplicitBudgetsBelowTheCount) {
    const BuildPlan balanced = planBuild(Effort::Balanced, 50, factsOf(5000, 60, 41));
    EXPECT_EQ(balanced.start, BuildStart::Meshlets);
    EXPECT_EQ(balanced.alsoGrown, AlsoGrown::Always);
    EXPECT_TRUE(balanced.annealFurther && balanced.packWhenMissed);
    EXPECT_GT(balanced.finishSweeps, 0u);
    const BuildPlan fast = planBuild(Effort::Fast, 50, factsOf(5000, 60, 41));
    EXPECT_EQ(fast.alsoGrown, AlsoGrown::WhenMissed);
    EXPECT_FALSE(fast.annealFurther);
    EXPECT_TRUE(fast.packWhenMissed);
    EXPECT_EQ(fast.finishSweeps, 0u);
    // Below the fewest clusters the limits allow nothing packs to it.
    EXPECT_FALSE(planBuild(Effort::Balanced, 40, factsOf(5000, 60, 41)).packWhenMissed);
}

TEST(BuildPlan, BudgetsAboveTheCountSplitMeshoptimizersMeshlets) {
    const BuildPlan plan = planBuild(Effort::Balanced, 80, factsOf(5000, 60, 41));
    EXPECT_EQ(plan.start, BuildStart::SplitMeshlets);
}

TEST(BuildPlan, TheClimbIsForSmallMeshesUpToAQuarterAboveTheCount) {
    // 400 faces: every budget searched within kClimbWork.
    EXPECT_TRUE(planBuild(Effort::Balanced, 6, factsOf(400, 5, 3)).climb);
    EXPECT_EQ(climbStride(400, 5, highestClimb(5)), 1u);
    EXPECT_FALSE(planBuild(Effort::Balanced, 7, factsOf(400, 5, 3)).climb);  // above 1.25x the count
    EXPECT_FALSE(planBuild(Effort::Balanced, 3, factsOf(400, 5, 3)).climb);  // at the fewest
    EXPECT_FALSE(planBuild(Effort::Fast, 6, factsOf(400, 5, 3)).climb);
    EXPECT_FALSE(planBuild(Effort::Balanced, 1200, factsOf(100000, 1000, 800)).climb);  // too large to climb
    EXPECT_EQ(climbStride(100000, 1000, highestClimb(1000)), 0u);
}

TEST(BuildPlan, TheBestLevelGrowsAndRunsTheBalancedPlanToo) {
    const BuildPlan plan = planBuild(Effort::Best, 0, factsOf(5000, 0, 41));
    EXPECT_EQ(plan.start, BuildStart::Grown);
    EXPECT_TRUE(plan.alsoBalanced);
    EXPECT_FALSE(plan.climb);
    // Limits meshoptimizer does not take: every level grows.
    BuildFacts facts = factsOf(5000, 0, 41);
    facts.meshoptLimits = false;
    EXPECT_EQ(planBuild(Effort::Balanced, 0, facts).start, BuildStart::Grown);
    EXPECT_FALSE(planBuild(Effort::Balanced, 50, facts).climb);
}

TEST(BuildPlan, BalancedAndBestAimAtKConesFastDoesNot) {
    BuildFacts facts = factsOf(5000, 0, 41);
    EXPECT_EQ(planBuild(Effort::Balanced, 0, facts).forCones, 1u);
    facts.conesPerCluster = 4;
    EXPECT_EQ(planBuild(Effort::Fast, 0, facts).forCones, 1u);
    const BuildPlan balanced = planBuild(Effort::Balanced, 0, facts), best = planBuild(Effort::Best, 0, facts);
    EXPECT_EQ(balanced.forCones, 4u);
    EXPECT_EQ(balanced.forConesTryBelow, 0.0);
    EXPECT_EQ(best.forCones, 4u);
    EXPECT_EQ(best.forConesTryBelow, kForConesTryBelowBest);
    // Everything else is the plan for one cone.
    EXPECT_EQ(balanced.start, planBuild(Effort::Balanced, 0, factsOf(5000, 0, 41)).start);
}

TEST(BuildPlan, LargeMeshesSkipTheFinish) {
    const BuildPlan plan = planBuild(Effort::Balanced, 500, factsOf(kPackingFacesAtMost + 1, 600, 300));
    EXPECT_FALSE(plan.annealFurther || plan.packWhenMissed);
}

namespace {

// FNV-1a of the partition with clusters numbered in order of their first face, so the record
// holds which faces go together.
uint64_t partitionHash(const Partition& partition) {
    std::map<uint32_t, uint32_t> renumbered;
    uint64_t hash = 1469598103934665603ull;
    for (uint32_t cluster : partition.clusterOfFace) {
        const uint32_t id = renumbered.emplace(cluster, uint32_t(renumbered.size())).first->second;
        for (int shift = 0; shift < 32; shift += 8) hash = (hash ^ ((id >> shift) & 0xffu)) * 1099511628211ull;
    }
    return hash;
}

struct Sample {
    std::string name;
    Mesh mesh;
};

std::vector<Sample> samples() {
    std::vector<Sample> meshes;
    // Test data under tests/data, the bundled meshes under datasets/ (named so in the record). Files
    // only: a generated mesh can differ between compilers (the order a call's arguments draw their
    // random numbers in is theirs to choose), a file cannot.
    for (const char* name : {"cgal/pinion.off", "cgal/bones.off"}) meshes.push_back({name, testmesh::readTestDataOff(name)});
    for (const char* name : {"elephant.off", "torus.off", "cube-quads.off", "bumpy-plane.off"})
        meshes.push_back({std::string("datasets/") + name, testmesh::readBundledOff(name)});
    return meshes;
}

const char* effortName(Effort effort) { return effort == Effort::Fast ? "fast" : effort == Effort::Balanced ? "balanced" : "best"; }

// Every (mesh, effort, budget) of the sample with its partition's hash.
std::map<std::string, uint64_t> sampleHashes() {
    const MeshletLimits limits{64, 124};
    std::map<std::string, uint64_t> hashes;
    for (const Sample& sample : samples()) {
        const FaceGeometry faces = computeFaceGeometry(sample.mesh);
        const size_t count = defaultClusterBudget(sample.mesh, limits);
        auto record = [&](Effort effort, size_t budget) {
            std::ostringstream key;
            key << sample.name << ' ' << effortName(effort) << ' ' << budget;
            hashes[key.str()] = partitionHash(buildOptimizedClusters(sample.mesh, faces, limits, budget, {}, effort));
        };
        for (size_t budget : {size_t(0), count * 7 / 10, count, count * 11 / 10, count * 14 / 10})
            if (budget != 0 || count != 0) record(Effort::Balanced, budget);
        record(Effort::Fast, 0);
        record(Effort::Fast, count * 7 / 10);
        record(Effort::Fast, count * 14 / 10);
        if (sample.mesh.faceCount() <= 6000) {
            record(Effort::Best, 0);
            record(Effort::Best, count * 9 / 10);
        }
    }
    return hashes;
}

std::filesystem::path recordPath() { return std::filesystem::path(__FILE__).parent_path().parent_path() / "data" / "optimizer-partitions.txt"; }

}  // namespace

TEST(BuildPlan, PartitionsAsRecorded) {
    const std::map<std::string, uint64_t> hashes = sampleHashes();
    if (const char* out = std::getenv("CONESCOPE_WRITE_PARTITIONS")) {
        std::ofstream file(out);
        for (const auto& [key, hash] : hashes) file << key << '\t' << std::hex << hash << std::dec << '\n';
        GTEST_SKIP() << "wrote " << out;
    }
    std::ifstream file(recordPath());
    ASSERT_TRUE(file) << recordPath();
    std::map<std::string, uint64_t> recorded;
    for (std::string line; std::getline(file, line);) {
        const size_t tab = line.find('\t');
        ASSERT_NE(tab, std::string::npos) << line;
        recorded[line.substr(0, tab)] = std::stoull(line.substr(tab + 1), nullptr, 16);
    }
    EXPECT_EQ(recorded.size(), hashes.size());
    for (const auto& [key, hash] : hashes) {
        const auto found = recorded.find(key);
        ASSERT_NE(found, recorded.end()) << key << " is not in the record";
        EXPECT_EQ(found->second, hash) << key << ": another partition than the recorded one";
    }
}
