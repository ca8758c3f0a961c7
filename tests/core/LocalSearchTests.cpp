// The optimized builder's local search steps on a real partition: what an annealing sweep reports
// as moved, and the refinement that then looks only at the clusters those moves touched; and the
// undo of recorded moves the reduction's failed steps rely on.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "TestMeshes.h"
#include "core/Partition.h"
#include "core/meshopt/Meshopt.h"
#include "core/optimizer/Steps.h"

namespace conescope {
namespace {

using optimizer::State;

const MeshletLimits kLimits{64, 124};

double objective(const State& state) {
    double value = 0.0;
    for (const optimizer::Cluster& cluster : state.clusters)
        if (!cluster.faces.empty()) value += optimizer::valueOf(cluster.triangles, cluster.cap);
    return value;
}

bool withinLimits(const State& state) {
    for (const optimizer::Cluster& cluster : state.clusters)
        if (cluster.triangles > kLimits.maxTriangles || cluster.vertices > kLimits.maxVertices) return false;
    return true;
}

// meshoptimizer's meshlets of the bundled elephant, refined greedily: where annealing starts.
struct Refined {
    Mesh mesh = testmesh::readBundledOff("elephant.off");
    FaceGeometry faces = computeFaceGeometry(mesh);
    State state{mesh, faces, kLimits};
    Refined() {
        optimizer::assign(state, buildMeshoptMeshlets(mesh, kLimits, 1.0f));
        optimizer::refine(state);
    }
};

TEST(LocalSearch, OneSweepReportsExactlyTheFacesItMoved) {
    Refined refined;
    const std::vector<uint32_t> before = refined.state.clusterOf;
    const std::vector<uint32_t> moved = optimizer::anneal(refined.state, 1);
    std::set<uint32_t> changed;
    for (uint32_t f = 0; f < before.size(); ++f)
        if (refined.state.clusterOf[f] != before[f]) changed.insert(f);
    ASSERT_FALSE(changed.empty());
    EXPECT_EQ(std::set<uint32_t>(moved.begin(), moved.end()), changed);
    EXPECT_EQ(moved.size(), changed.size());  // one sweep visits each face once
}

TEST(LocalSearch, RefiningAroundTheMovedFacesOnlyGainsAndKeepsTheLimits) {
    Refined refined;
    const std::vector<uint32_t> moved = optimizer::anneal(refined.state, 1);
    const double afterSweep = objective(refined.state);
    const std::vector<uint32_t> clustersAfterSweep = refined.state.clusterOf;
    optimizer::refineAround(refined.state, moved);
    EXPECT_GT(objective(refined.state), afterSweep);  // the cold sweep left greedy moves around it
    EXPECT_NE(refined.state.clusterOf, clustersAfterSweep);
    EXPECT_TRUE(withinLimits(refined.state));
    // Nothing moved, nothing to look at: the clusters stay as they are.
    const std::vector<uint32_t> settled = refined.state.clusterOf;
    optimizer::refineAround(refined.state, {});
    EXPECT_EQ(refined.state.clusterOf, settled);
}

// Looking only at the clusters the sweep touched leaves almost nothing for a full refinement to
// find, on the elephant as one part: the builder refines so after every annealing.
TEST(LocalSearch, AFullRefinementAfterwardsGainsLittle) {
    Refined around, full;
    optimizer::refineAround(around.state, optimizer::anneal(around.state, 1));
    optimizer::anneal(full.state, 1);
    optimizer::refine(full.state);
    const double aroundValue = objective(around.state), fullValue = objective(full.state);
    EXPECT_GT(aroundValue, 0.998 * fullValue);  // 0.12% less here; the faces around the moves alone gave 1.1% less
    optimizer::refine(around.state);
    EXPECT_LT(objective(around.state), 1.001 * aroundValue);
}

// The reduction skips a step that failed until a cluster it reads changes, which holds only if a
// failed step leaves every cluster as it was, down to the order of its faces (undoMoves).
TEST(State, UndoingRecordedMovesRestoresEveryClusterInItsOrder) {
    Refined refined;
    State& state = refined.state;
    const State before = state;
    // Border faces handed on, some twice and some out of a cluster that just took a face.
    size_t moves = 0;
    for (uint32_t face = 0; face < state.faceCount && moves < 200; face += 7) {
        uint32_t targets[8];
        const size_t count = optimizer::neighbourClusters(state, face, targets);
        if (count == 0 || state.clusters[state.clusterOf[face]].faces.size() <= 1) continue;
        optimizer::moveRecorded(state, face, targets[0]);
        ++moves;
        if (moves % 3 == 0 && optimizer::neighbourClusters(state, face, targets) > 0) optimizer::moveRecorded(state, face, targets[0]), ++moves;
    }
    ASSERT_GT(moves, 100u);
    ASSERT_NE(state.clusterOf, before.clusterOf);
    optimizer::undoMoves(state);
    EXPECT_TRUE(state.undo.empty());
    EXPECT_EQ(state.clusterOf, before.clusterOf);
    EXPECT_EQ(state.slotOf, before.slotOf);
    for (size_t c = 0; c < state.clusters.size(); ++c) {
        EXPECT_EQ(state.clusters[c].faces, before.clusters[c].faces) << c;
        EXPECT_EQ(state.clusters[c].vertices, before.clusters[c].vertices) << c;
        EXPECT_EQ(state.clusters[c].triangles, before.clusters[c].triangles) << c;
    }
}

}  // namespace
}  // namespace conescope
