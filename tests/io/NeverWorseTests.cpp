// Never worse than meshoptimizer's own pipeline (its builder at cone weight 1, its cone, the apex
// test) on small props: at defaults, over 64 orbit views at distance 3, the default culls at least
// the back-facing triangles meshoptimizer's culls, with no more clusters, and never none where
// meshoptimizer's culls some. Box and panel furniture of 2 to 42 clusters made in code, and real
// props (tests/data/props) read from their files: the kind of mesh where the default once lost.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <random>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "TestMeshes.h"
#include "core/Comparison.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

Settings orbitOf64() {
    Settings settings;
    settings.views = 64;
    settings.distance = 3.0;
    return settings;
}

Settings meshoptPipeline() {
    Settings settings = orbitOf64();
    settings.builder = Builder::Meshopt;
    settings.meshoptConeWeight = 1.0f;
    settings.cones = {ConeMethod::Meshopt};
    settings.tests = {CullTest::Apex};
    return settings;
}

// The defaults against meshoptimizer's pipeline on `mesh`; returns the defaults' cluster count.
size_t expectNeverWorse(const Mesh& mesh, const std::string& name) {
    SCOPED_TRACE(name + ": " + std::to_string(mesh.faceCount()) + " faces");
    const PreparedMesh prepared = prepareMesh(std::make_shared<const Mesh>(mesh), name, false);
    const Settings theirs = meshoptPipeline(), ours = orbitOf64();
    const ClusterSet meshopt = buildClusters(prepared, theirs), defaults = buildClusters(prepared, ours);
    const Comparison c = compareClusterSets(prepared, {meshopt, theirs}, {defaults, ours}, orbitOf(ours, prepared.box));
    EXPECT_LE(c.clustersB, c.clustersA);
    const size_t culledTheirs = c.trianglesCulledOnlyA + c.trianglesCulledBoth, culledOurs = c.trianglesCulledOnlyB + c.trianglesCulledBoth;
    EXPECT_GE(culledOurs, culledTheirs) << "meshoptimizer's " << c.clustersA << " clusters, ours " << c.clustersB;
    if (culledTheirs > 0) {
        EXPECT_GT(culledOurs, 0u);
    }
    return c.clustersB;
}

TEST(NeverWorse, GeneratedBoxAndPanelProps) {
    std::mt19937_64 random(3117);
    size_t fewest = SIZE_MAX, most = 0;
    for (int kind = 0; kind < 3; ++kind)
        for (int cells : {1, 2, 3, 4, 6})
            for (bool triangles : {false, true})
                for (int copy = 0; copy < 3; ++copy) {
                    const Mesh mesh = testmesh::furnitureProp(random, kind, cells, triangles);
                    const std::string name = "kind " + std::to_string(kind) + ", " + std::to_string(cells) + " cells" +
                                             (triangles ? ", triangles" : ", quads") + ", copy " + std::to_string(copy);
                    const size_t clusters = expectNeverWorse(mesh, name);
                    fewest = std::min(fewest, clusters), most = std::max(most, clusters);
                }
    // The props span the sizes where the default once lost (2 to 35 clusters) and a little more.
    EXPECT_LE(fewest, 3u);
    EXPECT_GE(most, 25u);
    EXPECT_LE(most, 45u);
}

TEST(NeverWorse, RealFurnitureProps) {
    size_t props = 0;
    for (const auto& entry : std::filesystem::directory_iterator(testing::testDataDir() / "props")) {
        const MeshFile file = readMeshFile(entry.path().string());
        expectNeverWorse(file.mesh, entry.path().filename().string());
        ++props;
    }
    EXPECT_EQ(props, 10u);
}

}  // namespace
}  // namespace conescope
