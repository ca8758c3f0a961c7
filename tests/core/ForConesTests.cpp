// The optimized builder aimed at K cones per cluster: the split it weighs is the record's split, and
// its moves keep the count, the limits and every cluster in one piece while the objective rises.
#include <gtest/gtest.h>

#include "PartitionChecks.h"
#include "TestMeshes.h"
#include "core/ClusterOptimizer.h"
#include "core/MultiCones.h"
#include "core/optimizer/ForCones.h"

namespace conescope {
namespace {

const MeshletLimits kLimits{64, 124};

std::vector<std::vector<uint32_t>> clusterFaces(const Partition& partition) {
    std::vector<std::vector<uint32_t>> members(partition.clusterCount);
    for (uint32_t f = 0; f < partition.clusterOfFace.size(); ++f) members[partition.clusterOfFace[f]].push_back(f);
    return members;
}

double objective(const Mesh& mesh, const FaceGeometry& faces, const Partition& partition, uint32_t k) {
    double value = 0.0;
    for (const std::vector<uint32_t>& members : clusterFaces(partition)) value += splitClusterForCones(mesh, faces, members, k).value;
    return value;
}

struct Elephant {
    Mesh mesh = testmesh::readBundledOff("elephant.off");
    FaceGeometry faces = computeFaceGeometry(mesh);
    Partition partition = buildOptimizedClusters(mesh, faces, kLimits);
};

TEST(ForCones, WeighsTheSplitTheRecordMakes) {
    const Elephant e;
    const ClusterBounds bounds = computeClusterBounds(e.mesh, worldPositions(e.mesh), e.faces, e.partition, ConeMethod::Minimal);
    for (uint32_t k : {2u, 4u}) {
        const MultiCones multi = computeMultiCones(e.mesh, e.faces, bounds, k);
        double recordValue = 0.0;
        for (size_t g = 0; g < multi.groupCount(); ++g) recordValue += expectedCulledTriangles(multi.cones[g], multi.groupTriangles[g]);
        EXPECT_NEAR(objective(e.mesh, e.faces, e.partition, k), recordValue, 1e-6 * recordValue) << "K=" << k;
    }
}

TEST(ForCones, MovesKeepTheCountTheLimitsAndOnePieceWhileTheObjectiveRises) {
    for (uint32_t k : {2u, 4u}) {
        Elephant e;
        const Partition before = e.partition;
        const size_t piecesBefore = disconnectedClusters(e.mesh, before);
        const size_t moves = refineForCones(e.mesh, e.faces, kLimits, k, e.partition);
        EXPECT_GT(moves, 0u) << "K=" << k;
        EXPECT_EQ(e.partition.clusterCount, before.clusterCount);
        expectValidWithinLimits(e.mesh, e.partition, kLimits);
        EXPECT_LE(disconnectedClusters(e.mesh, e.partition), piecesBefore);
        EXPECT_GT(objective(e.mesh, e.faces, e.partition, k), objective(e.mesh, e.faces, before, k) * 1.005) << "K=" << k;
    }
}

TEST(ForCones, TryingMoreMovesGainsAtLeastAsMuchHereAndIsRepeatable) {
    Elephant quick, thorough, again;
    refineForCones(quick.mesh, quick.faces, kLimits, 2, quick.partition, 6, 0.0);
    refineForCones(thorough.mesh, thorough.faces, kLimits, 2, thorough.partition, 6, 2.0);
    refineForCones(again.mesh, again.faces, kLimits, 2, again.partition, 6, 2.0);
    EXPECT_EQ(thorough.partition.clusterOfFace, again.partition.clusterOfFace);
    EXPECT_GE(objective(thorough.mesh, thorough.faces, thorough.partition, 2), objective(quick.mesh, quick.faces, quick.partition, 2));
}

TEST(ForCones, TheBuilderAimedAtKConesKeepsTheDefaultCountAndGains) {
    const Elephant e;
    std::vector<size_t> heard;
    const PartClusters hear = [&](size_t part, size_t, const std::vector<uint32_t>&, const Partition&) { heard.push_back(part); };
    const Partition aimed = buildOptimizedClusters(e.mesh, e.faces, kLimits, 0, {}, Effort::Balanced, nullptr, hear, 4);
    EXPECT_TRUE(heard.empty()) << "faces move across parts afterwards: a part heard would be bounded stale";
    EXPECT_EQ(aimed.clusterCount, e.partition.clusterCount);
    expectValidWithinLimits(e.mesh, aimed, kLimits);
    EXPECT_GT(objective(e.mesh, e.faces, aimed, 4), objective(e.mesh, e.faces, e.partition, 4));
    // The fast effort is not aimed: the default partition.
    EXPECT_EQ(buildOptimizedClusters(e.mesh, e.faces, kLimits, 0, {}, Effort::Fast, nullptr, {}, 4).clusterOfFace,
              buildOptimizedClusters(e.mesh, e.faces, kLimits, 0, {}, Effort::Fast).clusterOfFace);
}

TEST(ForCones, CancelStopsTheMoves) {
    Elephant e;
    const ProgressCallback cancel = [](double fraction, const std::string&) { return fraction <= 0.0; };  // stops at the second report
    EXPECT_THROW(refineForCones(e.mesh, e.faces, kLimits, 4, e.partition, 6, 0.0, cancel), OperationCancelled);
}

}  // namespace
}  // namespace conescope
