// The chosen cone (ChosenCones.h): its eyes are the standard orbit's at kChoiceEyes views, and it
// counts the eyes a record culls exactly as the octagon test does, one eye at a time.
#include <algorithm>
#include <random>

#include <gtest/gtest.h>

#include "TestMeshes.h"
#include "core/ChosenCones.h"
#include "core/ClusterBounds.h"
#include "core/Culling.h"
#include "core/Settings.h"

namespace conescope {
namespace {

TEST(ChosenCone, EyesAreTheStandardOrbitsAtTheChoicesViews) {
    const Aabb box{glm::vec3(-1.0f, 2.0f, 0.5f), glm::vec3(3.0f, 2.5f, 7.0f)};
    const ChoiceEyes eyes = choiceEyes(box);
    std::vector<Eye> orbit = orbitViews(box, kChoiceEyes, kStandardOrbitDistance);
    ASSERT_EQ(eyes.groups->directions.size(), orbit.size());
    const auto less = [](const glm::dvec3& a, const glm::dvec3& b) { return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z); };
    std::vector<glm::dvec3> ours, theirs;
    for (size_t i = 0; i < orbit.size(); ++i) ours.push_back(eyes.position(i));
    for (const Eye& eye : orbit) theirs.push_back(eye.position);
    std::sort(ours.begin(), ours.end(), less), std::sort(theirs.begin(), theirs.end(), less);
    EXPECT_EQ(ours, theirs);  // bit for bit: a run at kChoiceEyes views looks from these eyes
    // Every direction is its eye's, and lies within the reach of its subgroup's and its group's centres.
    const DirectionGroups& groups = *eyes.groups;
    size_t seen = 0;
    for (size_t g = 0; g + 1 < groups.groupStarts.size(); ++g)
        for (uint32_t s = groups.groupStarts[g]; s < groups.groupStarts[g + 1]; ++s)
            for (uint32_t i = groups.subStarts[s]; i < groups.subStarts[s + 1]; ++i, ++seen) {
                EXPECT_NEAR(glm::length((eyes.position(i) - eyes.center) / eyes.radius - groups.directions[i]), 0.0, 1e-12);
                EXPECT_LE(glm::length(groups.directions[i] - groups.subCenters[s]), groups.subReach[s]);
                EXPECT_LE(glm::length(groups.directions[i] - groups.groupCenters[g]), groups.groupReach[g]);
            }
    EXPECT_EQ(seen, kChoiceEyes);
}

TEST(ChosenCone, CountsTheEyesExactlyAsTheOctagonTest) {
    std::mt19937_64 random(97);
    size_t records = 0, someCulled = 0;
    for (int trial = 0; trial < 12; ++trial) {
        const Mesh mesh = trial % 2 ? testmesh::randomPatch(random, 3 + trial, 20.0 + 10.0 * trial) : testmesh::roof(3 + trial, 0.2 * trial);
        const std::vector<glm::vec3> world = mesh.positions;
        const FaceGeometry faces = computeFaceGeometry(mesh);
        // Clusters of every size against the whole object's orbit, including one holding every face.
        for (uint32_t clusters : {1u, 2u, 5u}) {
            Partition partition{std::vector<uint32_t>(mesh.faceCount()), clusters};
            for (uint32_t f = 0; f < mesh.faceCount(); ++f) partition.clusterOfFace[f] = f * clusters / uint32_t(mesh.faceCount());
            const ClusterBounds bounds = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Minimal);
            const ChoiceEyes eyes = choiceEyes(computeAabb(world));
            for (size_t c = 0; c < bounds.count(); ++c) {
                size_t oneByOne = 0;
                for (size_t i = 0; i < kChoiceEyes; ++i) {
                    const glm::dvec3 eye = eyes.position(i);
                    oneByOne += bounds.cones[c].cullable &&
                                octagonSeesBack(bounds.octagons[c], bounds.apexes[c] - eye, apexRoundingSlack(bounds.apexes[c], eye));
                }
                EXPECT_EQ(eyesCulled(bounds.octagons[c], bounds.apexes[c], eyes), oneByOne) << "trial " << trial << " cluster " << c;
                ++records, someCulled += oneByOne > 0;
            }
        }
    }
    EXPECT_GT(someCulled, records / 4);  // the count is tested on records that do cull
}

TEST(ChosenCone, IsOneOfTheOfferedConesAndCullsFromAtLeastAsManyEyes) {
    std::mt19937_64 random(5);
    const Mesh mesh = testmesh::furnitureProp(random, 1, 2, true);
    const std::vector<glm::vec3> world = mesh.positions;
    const FaceGeometry faces = computeFaceGeometry(mesh);
    Partition partition{std::vector<uint32_t>(mesh.faceCount()), 3};
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) partition.clusterOfFace[f] = f * 3 / uint32_t(mesh.faceCount());
    const ChoiceEyes eyes = choiceEyes(computeAabb(world));
    const ClusterBounds chosen = computeClusterBounds(mesh, world, faces, partition, ConeMethod::Chosen);
    for (ConeMethod method : {ConeMethod::Minimal, ConeMethod::Meshopt, ConeMethod::Average, ConeMethod::SeedSphere}) {
        const ClusterBounds other = computeClusterBounds(mesh, world, faces, partition, method);
        for (size_t c = 0; c < chosen.count(); ++c)
            EXPECT_GE(eyesCulled(chosen.octagons[c], chosen.apexes[c], eyes), eyesCulled(other.octagons[c], other.apexes[c], eyes))
                << toString(method) << " cluster " << c;
    }
    // Its round cone is one of the offered ones: it holds every normal of its cluster.
    for (size_t c = 0; c < chosen.count(); ++c)
        for (uint32_t i = chosen.faces.starts[c]; i < chosen.faces.starts[c + 1]; ++i)
            EXPECT_GE(glm::dot(faces.normals[chosen.faces.faces[i]], chosen.cones[c].axis), chosen.cones[c].cosHalfAngle - 1e-12);
    // The Gauss map's cone of a cluster is the bounds' own.
    for (size_t c = 0; c < chosen.count(); ++c) {
        const ConeOfNormals one = clusterCone(mesh, world, faces, chosen.faces.faces.data() + chosen.faces.starts[c],
                                              chosen.faces.starts[c + 1] - chosen.faces.starts[c], ConeMethod::Chosen);
        EXPECT_EQ(one.axis, chosen.cones[c].axis);
    }
}

}  // namespace
}  // namespace conescope
