// meshoptimizer's meshlets handed over in parts: every face in exactly one part, each part's meshlets
// those of buildMeshoptMeshlets (whole meshlets, none shared between parts), the work handed to the
// stream's thread run after the meshlets (each piece in turn) and its errors passed on, and a stream
// dropped while it builds stops.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>

#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <thread>

#include "TestMeshes.h"
#include "core/meshopt/Meshopt.h"
#include "core/meshopt/Reproduction.h"

namespace conescope {
namespace {

std::shared_ptr<const Mesh> shared(Mesh mesh) { return std::make_shared<const Mesh>(std::move(mesh)); }

// Quads of a grid, some split into triangles: polygons whose fan triangles can land in two parts.
Mesh mixedGrid(int cells) {
    Mesh mesh;
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j) mesh.positions.emplace_back(float(i), float(j), 0.05f * float((i * 7 + j * 3) % 5));
    auto at = [&](int i, int j) { return uint32_t(i * (cells + 1) + j); };
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            if ((i + j) % 3 == 0) {
                mesh.addFace({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
                mesh.addFace({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
            } else {
                mesh.addFace({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
        }
    return mesh;
}

void expectPartsAreTheWholeMeshlets(MeshletStream& stream) {
    const Mesh& mesh = stream.mesh();
    const Partition whole = stream.whole();
    EXPECT_EQ(whole.clusterOfFace, buildMeshoptMeshlets(mesh, stream.limits(), 1.0f).clusterOfFace);
    std::vector<int> partOfFace(mesh.faceCount(), -1);
    std::map<uint32_t, size_t> partOfMeshlet;  // global meshlet -> the part holding it
    size_t meshlets = 0;
    for (size_t i = 0; i < stream.partCount(); ++i) {
        const MeshletPart& part = stream.part(i);
        ASSERT_EQ(part.meshlets.clusterOfFace.size(), part.faces.size());
        EXPECT_TRUE(std::is_sorted(part.faces.begin(), part.faces.end()));
        std::map<uint32_t, uint32_t> globalOfLocal;
        for (size_t k = 0; k < part.faces.size(); ++k) {
            const uint32_t f = part.faces[k];
            ASSERT_LT(f, mesh.faceCount());
            EXPECT_EQ(partOfFace[f], -1) << "face " << f << " in two parts";
            partOfFace[f] = int(i);
            const uint32_t global = whole.clusterOfFace[f];
            // A local meshlet is one meshlet of the whole, and a meshlet lies in one part.
            const auto [it, added] = globalOfLocal.emplace(part.meshlets.clusterOfFace[k], global);
            EXPECT_EQ(it->second, global);
            const auto [where, first] = partOfMeshlet.emplace(global, i);
            EXPECT_EQ(where->second, i) << "meshlet " << global << " in two parts";
        }
        EXPECT_EQ(globalOfLocal.size(), part.meshlets.clusterCount);
        meshlets += part.meshlets.clusterCount;
    }
    for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_NE(partOfFace[f], -1) << "face " << f << " in no part";
    EXPECT_EQ(meshlets, whole.clusterCount);
    EXPECT_EQ(stream.meshletCount(), whole.clusterCount);
}

TEST(MeshletStream, PartsHoldEveryFaceOnceAndWholeMeshlets) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();  // the library's come as one part
    const MeshletLimits limits{64, 124};
    for (size_t parts : {size_t(1), size_t(2), size_t(5), size_t(40)}) {
        MeshletStream torus(shared(testmesh::torus(1.0, 0.3, 120, 60)), limits, parts);
        EXPECT_EQ(torus.partCount(), parts);
        expectPartsAreTheWholeMeshlets(torus);
        MeshletStream grid(shared(mixedGrid(60)), {32, 64}, parts);
        expectPartsAreTheWholeMeshlets(grid);
    }
    // Many small pieces: meshlets that jump between pieces through the k-d tree.
    std::mt19937_64 random(9);
    MeshletStream scattered(shared(testmesh::scatteredSpheres(random, 60)), limits, 6);
    expectPartsAreTheWholeMeshlets(scattered);
}

TEST(MeshletStream, PartsByFaceCount) {
    EXPECT_EQ(meshletPartsFor(0), 1u);
    EXPECT_EQ(meshletPartsFor(2047), 1u);
    EXPECT_EQ(meshletPartsFor(2048), 5u);  // four shares, the last in halves
    EXPECT_EQ(meshletPartsFor(2304), 5u);
    EXPECT_EQ(meshletPartsFor(16384), 27u);
    EXPECT_EQ(meshletPartsFor(40960), 65u);
    EXPECT_EQ(meshletPartsFor(3328000), 65u);
}

TEST(MeshletStream, TheLastShareComesInHalves) {
    if (!reproducesLinkedMeshopt()) GTEST_SKIP() << meshoptFallbackNote();  // the library's come as one part
    EXPECT_EQ(placedThroughPart(0, 5, 1000), 250u);
    EXPECT_EQ(placedThroughPart(2, 5, 1000), 750u);
    EXPECT_EQ(placedThroughPart(3, 5, 1000), 875u);
    EXPECT_EQ(placedThroughPart(4, 5, 1000), 1000u);
    EXPECT_EQ(placedThroughPart(0, 2, 1000), 500u);
    // As made: the last two parts hold about half the faces of the others.
    MeshletStream torus(shared(testmesh::torus(1.0, 0.3, 120, 60)), {64, 124}, 6);
    const double share = double(torus.part(0).faces.size());
    for (size_t i : {size_t(4), size_t(5)}) {
        EXPECT_GT(double(torus.part(i).faces.size()), 0.3 * share) << "part " << i;
        EXPECT_LT(double(torus.part(i).faces.size()), 0.7 * share) << "part " << i;
    }
}

TEST(MeshletStream, WorkRunsOnTheStreamsThreadAfterTheMeshletsAndPassesItsErrorOn) {
    MeshletStream stream(shared(testmesh::icosphere(4)), {64, 124}, 3);
    std::thread::id ranOn;
    size_t partsSeen = 0;
    stream.runAfterwards([&] {
        ranOn = std::this_thread::get_id();
        for (size_t i = 0; i < stream.partCount(); ++i) partsSeen += stream.part(i).faces.size();
    });
    stream.finishWork();
    EXPECT_NE(ranOn, std::this_thread::get_id());
    EXPECT_EQ(partsSeen, stream.mesh().faceCount());

    MeshletStream failing(shared(testmesh::icosphere(2)), {64, 124}, 1);
    failing.runAfterwards([] { throw std::runtime_error("work failed"); });
    EXPECT_THROW(failing.finishWork(), std::runtime_error);
    MeshletStream idle(shared(testmesh::icosphere(2)), {64, 124}, 1);
    idle.finishWork();  // no work handed over: nothing to wait for
    // Work that outlasts finishWork's watch: it then waits to be woken, and returns only after.
    MeshletStream slow(shared(testmesh::icosphere(2)), {64, 124}, 1);
    std::atomic<bool> finished{false};
    slow.runAfterwards([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        finished = true;
    });
    slow.finishWork();
    EXPECT_TRUE(finished);
}

// The climb's steps share one stream: each hands over its own piece of work, and every piece runs on
// the stream's thread (a second piece before the first is finished is refused, not lost).
TEST(MeshletStream, EachPieceOfWorkRunsOnTheStreamsThreadInTurn) {
    MeshletStream stream(shared(testmesh::icosphere(3)), {64, 124}, 2);
    std::vector<std::thread::id> ranOn;
    for (int piece = 0; piece < 3; ++piece) {
        stream.runAfterwards([&] { ranOn.push_back(std::this_thread::get_id()); });
        stream.finishWork();
    }
    ASSERT_EQ(ranOn.size(), 3u);
    for (const std::thread::id& id : ranOn) EXPECT_NE(id, std::this_thread::get_id());
    stream.runAfterwards([] { throw std::runtime_error("second step failed"); });
    EXPECT_THROW(stream.finishWork(), std::runtime_error);
    stream.runAfterwards([] {});  // an error does not stop the next piece
    EXPECT_THROW(stream.runAfterwards([] {}), std::logic_error);
    stream.finishWork();
}

TEST(MeshletStream, LimitsMeshoptimizerRefusesComeBackFromEveryPart) {
    MeshletStream stream(shared(testmesh::icosphere(2)), {300, 124}, 2);
    EXPECT_THROW(stream.part(0), std::invalid_argument);
    EXPECT_THROW(stream.whole(), std::invalid_argument);
}

// Dropped at once, and dropped after its first part: the builder stops at its next meshlet
// (MeshoptMeshlets.StopsWhenAListenerSaysSo) and the stream lets go of everything it held, its
// thread included, before its destructor returns.
TEST(MeshletStream, DroppedWhileBuildingStops) {
    for (int round = 0; round < 6; ++round) {
        std::shared_ptr<const Mesh> mesh = shared(testmesh::torus(1.0, 0.3, 200, 100));
        const std::weak_ptr<const Mesh> held = mesh;
        auto stream = std::make_unique<MeshletStream>(std::move(mesh), MeshletLimits{64, 124}, 8);
        if (round % 2) EXPECT_FALSE(stream->part(0).faces.empty());
        EXPECT_FALSE(held.expired());
        stream.reset();
        EXPECT_TRUE(held.expired()) << "round " << round;
    }
}

}  // namespace
}  // namespace conescope
