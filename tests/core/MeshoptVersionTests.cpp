// The one check of which meshoptimizer is linked (core/meshopt/Meshopt.h). The tests of the
// reproduction skip with another version; this one fails, so that the app does not run the
// library's builder instead (slower, its meshlets in one part) without anyone noticing.
#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "core/meshopt/Meshopt.h"
#include "core/meshopt/Reproduction.h"

namespace conescope {
namespace {

TEST(MeshoptVersion, TheLinkedLibraryIsTheOneReproduced) {
    EXPECT_EQ(linkedMeshoptVersion(), kReproducedMeshoptVersion)
        << meshoptFallbackNote() << ". Reproduce the new version's builder in src/core/meshopt/ (its tests compare it with the "
        << "library triangle for triangle) and raise kReproducedMeshoptVersion.";
    EXPECT_TRUE(reproducesLinkedMeshopt());
    EXPECT_EQ(meshoptFallbackNote(), "");
}

// What the app runs by default takes the reproduction: only the reproduction hands its meshlets
// over in parts as they are made.
TEST(MeshoptVersion, TheDefaultPipelineRunsTheReproduction) {
    const Mesh torus = testmesh::torus(1.0, 0.3, 64, 32);
    MeshletStream stream(std::make_shared<const Mesh>(torus), {64, 124}, 5);
    ASSERT_EQ(stream.partCount(), 5u) << meshoptFallbackNote();
    size_t faces = 0;
    for (size_t i = 0; i < stream.partCount(); ++i) {
        EXPECT_LT(stream.part(i).faces.size(), torus.faceCount()) << "part " << i;
        faces += stream.part(i).faces.size();
    }
    EXPECT_EQ(faces, torus.faceCount());
    EXPECT_EQ(stream.whole().clusterOfFace, meshoptReproducedMeshlets(torus, {64, 124}, 1.0f).clusterOfFace);
}

}  // namespace
}  // namespace conescope
