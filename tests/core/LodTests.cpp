// Cluster LOD hierarchies: a valid DAG (groups of adjacent clusters, every group made again above,
// errors and spheres growing going up), a cut that covers the surface once from any eye, threshold 0
// as the flat run and cone culling of the cut without a false cull.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>

#include "IcosphereHierarchy.h"
#include "TestMeshes.h"
#include "core/Granularity.h"
#include "core/lod/HierarchyRecords.h"
#include "core/lod/LodCut.h"

namespace conescope {
namespace {

using testmesh::icosphere;

PreparedMesh prepared(const Mesh& mesh) { return prepareMesh(std::make_shared<const Mesh>(mesh), "test", false); }

double faceArea(const PreparedMesh& prepared, size_t face) {
    const Mesh& mesh = prepared.mesh();
    const uint32_t* corners = mesh.faceBegin(face);
    glm::dvec3 area(0.0);
    for (size_t i = 1; i + 1 < mesh.faceSize(face); ++i)
        area += glm::cross(glm::dvec3(prepared.world[corners[i]] - prepared.world[corners[0]]),
                           glm::dvec3(prepared.world[corners[i + 1]] - prepared.world[corners[0]]));
    return 0.5 * glm::length(area);
}

// Per cluster of a level, the clusters it shares an edge with.
std::vector<std::set<uint32_t>> clusterNeighbours(const LodLevel& level) {
    const Mesh& mesh = level.prepared.mesh();
    std::map<std::pair<uint32_t, uint32_t>, std::set<uint32_t>> clustersOfEdge;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t i = 0; i < mesh.faceSize(f); ++i) {
            const uint32_t a = mesh.faceBegin(f)[i], b = mesh.faceBegin(f)[(i + 1) % mesh.faceSize(f)];
            clustersOfEdge[std::minmax(a, b)].insert(level.clusters.partition.clusterOfFace[f]);
        }
    std::vector<std::set<uint32_t>> neighbours(level.clusters.partition.clusterCount);
    for (const auto& [edge, clusters] : clustersOfEdge)
        for (uint32_t a : clusters)
            for (uint32_t b : clusters)
                if (a != b) neighbours[a].insert(b);
    return neighbours;
}

class LodHierarchy : public testmesh::IcosphereHierarchy<5> {};

TEST_F(LodHierarchy, LevelsHalveDownToOneCluster) {
    const std::vector<LodLevel>& levels = hierarchy_->levels;
    ASSERT_GE(levels.size(), 5u);
    EXPECT_EQ(levels.back().clusters.partition.clusterCount, 1u);
    for (size_t l = 1; l < levels.size(); ++l) {
        const double share = double(levels[l].triangles()) / double(levels[l - 1].triangles());
        EXPECT_GT(share, 0.3) << "level " << l;
        EXPECT_LT(share, 0.85) << "level " << l;
        for (size_t c = 0; c < levels[l].clusters.partition.clusterCount; ++c) {
            size_t triangles = 0;
            for (uint32_t owner : levels[l].clusters.partition.clusterOfFace) triangles += owner == c;
            EXPECT_LE(triangles, Settings{}.limits.maxTriangles);
        }
    }
}

TEST_F(LodHierarchy, GroupsAreAdjacentClustersEachMadeAgainAbove) {
    const std::vector<LodLevel>& levels = hierarchy_->levels;
    for (size_t l = 0; l + 1 < levels.size(); ++l) {
        const LodLevel& level = levels[l];
        std::vector<std::vector<uint32_t>> members(level.groups);
        for (uint32_t c = 0; c < level.place.size(); ++c) {
            ASSERT_LT(level.place[c].group, level.groups);
            members[level.place[c].group].push_back(c);
        }
        const std::vector<std::set<uint32_t>> neighbours = clusterNeighbours(level);
        std::vector<size_t> made(level.groups, 0);
        for (const LodCluster& above : levels[l + 1].place) ++made[above.sourceGroup];
        for (size_t g = 0; g < level.groups; ++g) {
            ASSERT_FALSE(members[g].empty());
            EXPECT_LE(members[g].size(), 8u);
            EXPECT_GT(made[g], 0u) << "group " << g << " of level " << l << " made nothing above";
            // Connected: every member reached from the first through members.
            std::set<uint32_t> reached{members[g][0]}, inGroup(members[g].begin(), members[g].end());
            for (std::vector<uint32_t> frontier{members[g][0]}; !frontier.empty();) {
                const uint32_t c = frontier.back();
                frontier.pop_back();
                for (uint32_t n : neighbours[c])
                    if (inGroup.count(n) && reached.insert(n).second) frontier.push_back(n);
            }
            EXPECT_EQ(reached.size(), members[g].size()) << "group " << g << " of level " << l;
        }
    }
    for (const LodCluster& top : levels.back().place) EXPECT_TRUE(std::isinf(top.parentError));
}

TEST_F(LodHierarchy, ErrorsAndSpheresGrowGoingUp) {
    const std::vector<LodLevel>& levels = hierarchy_->levels;
    for (const LodCluster& base : levels[0].place) EXPECT_EQ(base.error, 0.0);
    for (size_t l = 0; l + 1 < levels.size(); ++l)
        for (const LodCluster& place : levels[l].place) {
            EXPECT_LT(place.error, place.parentError);
            EXPECT_LE(glm::length(place.errorSphere.center - place.parentSphere.center) + place.errorSphere.radius,
                      place.parentSphere.radius * (1.0 + 1e-12));
        }
    // A cluster made from a group has that group's error and sphere as its own.
    for (size_t l = 1; l < levels.size(); ++l)
        for (const LodCluster& above : levels[l].place)
            for (const LodCluster& member : levels[l - 1].place)
                if (member.group == above.sourceGroup) {
                    EXPECT_EQ(member.parentError, above.error);
                    EXPECT_EQ(member.parentSphere.radius, above.errorSphere.radius);
                }
}

// From any eye and threshold the cut draws as much area as a level (simplification moves the surface
// a little: between the least and the most of them), and never a cluster together with one made from its group, or from a group made from it.
TEST_F(LodHierarchy, CutCoversTheSurfaceOnce) {
    const std::vector<LodLevel>& levels = hierarchy_->levels;
    double meshArea = 0.0;
    for (size_t f = 0; f < sphere_->mesh().faceCount(); ++f) meshArea += faceArea(*sphere_, f);
    std::vector<std::vector<double>> clusterArea(levels.size());
    double least = meshArea, most = meshArea;  // each level covers the surface once: the cut lies between them
    for (size_t l = 0; l < levels.size(); ++l) {
        clusterArea[l].assign(levels[l].place.size(), 0.0);
        for (size_t f = 0; f < levels[l].prepared.mesh().faceCount(); ++f)
            clusterArea[l][levels[l].clusters.partition.clusterOfFace[f]] += faceArea(levels[l].prepared, f);
        double area = 0.0;
        for (double a : clusterArea[l]) area += a;
        least = std::min(least, area), most = std::max(most, area);
    }
    EXPECT_GT(least / meshArea, 0.9);
    std::set<size_t> levelsSeen;
    for (double threshold : {0.0, 0.5, 2.0, 8.0, 40.0, 1e9})
        for (const glm::dvec3& eye : {glm::dvec3(0.0, 0.0, 1.5), glm::dvec3(3.0, 1.0, 0.0), glm::dvec3(0.0, -12.0, 4.0), glm::dvec3(0.2, 0.1, 0.0)}) {
            LodThreshold rule;
            rule.value = threshold;
            const std::vector<std::vector<uint8_t>> cut = cutFrom(*hierarchy_, eye, rule);
            double area = 0.0;
            for (size_t l = 0; l < levels.size(); ++l)
                for (size_t c = 0; c < cut[l].size(); ++c)
                    if (cut[l][c]) area += clusterArea[l][c], levelsSeen.insert(l);
            EXPECT_GE(area, least * 0.999) << "threshold " << threshold;
            EXPECT_LE(area, most * 1.001) << "threshold " << threshold << " eye " << eye.x << " " << eye.y << " " << eye.z;
            // A group is replaced as a whole: its members all drawn (or all below), or none.
            for (size_t l = 0; l + 1 < levels.size(); ++l) {
                std::map<uint32_t, std::set<uint8_t>> drawnInGroup, drawnAbove;
                for (size_t c = 0; c < cut[l].size(); ++c) drawnInGroup[levels[l].place[c].group].insert(cut[l][c]);
                for (size_t c = 0; c < cut[l + 1].size(); ++c) drawnAbove[levels[l + 1].place[c].sourceGroup].insert(cut[l + 1][c]);
                for (const auto& [group, drawn] : drawnInGroup)
                    if (drawn.count(1)) EXPECT_FALSE(drawnAbove[group].count(1)) << "level " << l << " group " << group << " drawn twice";
            }
        }
    EXPECT_GE(levelsSeen.size(), 3u);
    EXPECT_TRUE(levelsSeen.count(0));
    EXPECT_TRUE(levelsSeen.count(levels.size() - 1));
}

// Threshold 0 draws level 0 from every eye, and its statistics are the flat run's.
TEST_F(LodHierarchy, ThresholdZeroIsTheFlatRun) {
    Settings settings;
    settings.views = 32;
    LodThreshold zero;
    zero.value = 0.0;
    const LodStatistics lod = measureHierarchy(*hierarchy_, settings, zero);
    const RunStatistics flat = runStatistics(sphere_->mesh(), settings);
    ASSERT_EQ(lod.cut.levelsUsed, std::vector<size_t>{0});
    EXPECT_EQ(lod.cut.trianglesCulled, flat.results[0].trianglesCulled);
    EXPECT_EQ(lod.cut.backFacingTriangles, flat.results[0].backFacingTriangles);
    EXPECT_EQ(lod.cut.efficiency, flat.results[0].efficiency);
    EXPECT_EQ(lod.levels[0].culling.trianglesCulled, flat.results[0].trianglesCulled);
    EXPECT_EQ(lod.cut.falseCulls, 0u);
    for (size_t v = 0; v < lod.cut.views.size(); ++v) EXPECT_EQ(lod.cut.views[v].trianglesCulled, flat.results[0].views[v].trianglesCulled);
}

// Coarser levels have wider cones and cull less; the cut from far culls no face it should draw.
TEST_F(LodHierarchy, CoarseLevelsCullLessAndTheCutIsConservative) {
    Settings settings;
    settings.views = 32;
    settings.distance = 6.0;
    LodThreshold pixels;
    pixels.value = 4.0;
    const LodStatistics lod = measureHierarchy(*hierarchy_, settings, pixels);
    EXPECT_GT(lod.levels.front().culling.efficiency, lod.levels[lod.levels.size() - 2].culling.efficiency);
    EXPECT_LT(lod.levels.front().meanHalfAngleDegrees, lod.levels[lod.levels.size() - 2].meanHalfAngleDegrees);
    for (const LodLevelStatistics& level : lod.levels) EXPECT_EQ(level.culling.falseCulls, 0u);
    EXPECT_EQ(lod.cut.falseCulls, 0u);
    EXPECT_LT(lod.cut.meanTriangles, double(sphere_->triangles));
    EXPECT_GT(lod.cut.levelsUsed.size(), 0u);
    EXPECT_NE(lod.cut.levelsUsed, std::vector<size_t>{0});
}

// K cones per cluster: level 0 is granularity's cones-K row on the same partition and views; no
// false cull at any level or in the cut, from far and from eyes near the surface; the cut's numbers
// are its views' sums, and at threshold 0 its level 0's. Cancelling stops between views.
TEST_F(LodHierarchy, ConesPerClusterOnLevelsAndCut) {
    for (const double distance : {6.0, 1.3}) {
        Settings settings;
        settings.views = 24;
        settings.distance = distance;
        LodThreshold pixels;
        pixels.value = 2.0;
        const LodStatistics lod = measureHierarchy(*hierarchy_, settings, pixels, {}, 8);
        const LodLevel& level0 = hierarchy_->levels[0];
        size_t compared = 0;
        for (const GranularityRow& row : finerRows(level0.prepared, level0.clusters, viewsFor(settings, level0.prepared.box), settings))
            if (row.record == "cones-8") {
                EXPECT_EQ(lod.levels[0].multiCones.trianglesCulled, row.trianglesCulled);
                EXPECT_EQ(lod.levels[0].multiCones.backFacingTriangles, row.backFacingTriangles);
                ++compared;
            }
        EXPECT_EQ(compared, 1u);
        for (const LodLevelStatistics& level : lod.levels) {
            EXPECT_EQ(level.multiCones.cones, 8u);
            EXPECT_EQ(level.multiCones.falseCulls, 0u) << level.level;
            EXPECT_EQ(level.multiCones.backFacingTriangles, level.culling.backFacingTriangles) << level.level;
        }
        LodMultiConeCulling sum;
        for (const LodCutView& view : lod.cut.views) {
            sum.trianglesCulled += view.multiCones.trianglesCulled, sum.falseCulls += view.multiCones.falseCulls;
            EXPECT_LE(view.multiCones.trianglesCulled, view.backFacingTriangles);
            EXPECT_EQ(view.multiCones.backFacingTriangles, view.backFacingTriangles);
        }
        EXPECT_EQ(lod.cut.multiCones.trianglesCulled, sum.trianglesCulled);
        EXPECT_EQ(lod.cut.multiCones.backFacingTriangles, lod.cut.backFacingTriangles);
        EXPECT_EQ(sum.falseCulls, 0u);
        EXPECT_GT(sum.trianglesCulled, 0u) << distance;
        LodThreshold zero;
        zero.value = 0.0;
        const LodStatistics flat = measureHierarchy(*hierarchy_, settings, zero, {}, 8);
        EXPECT_EQ(flat.cut.multiCones.trianglesCulled, flat.levels[0].multiCones.trianglesCulled);
        EXPECT_EQ(flat.cut.multiCones.efficiency, flat.levels[0].multiCones.efficiency);
    }
    size_t heard = 0;
    const ProgressCallback cancelLate = [&](double fraction, const std::string&) { return ++heard < 40 || fraction < 0.0; };
    EXPECT_THROW(measureHierarchy(*hierarchy_, Settings{}, {}, cancelLate, 4), OperationCancelled);
    const LodStatistics none = measureHierarchy(*hierarchy_, Settings{}, {});
    EXPECT_EQ(none.cut.multiCones.cones, 0u);
    EXPECT_EQ(none.levels[0].multiCones.cones, 0u);
}

// The records give back the same hierarchy: every level's clusters, places and numbers.
TEST_F(LodHierarchy, RecordsGiveTheSameHierarchyBack) {
    const ClusterHierarchy back = hierarchyFromRecords(*sphere_, hierarchyRecordsOf(*hierarchy_, {}), Settings{});
    ASSERT_EQ(back.levels.size(), hierarchy_->levels.size());
    for (size_t l = 0; l < back.levels.size(); ++l) {
        EXPECT_EQ(back.levels[l].clusters.partition.clusterCount, hierarchy_->levels[l].clusters.partition.clusterCount);
        EXPECT_EQ(back.levels[l].triangles(), hierarchy_->levels[l].triangles());
        EXPECT_EQ(back.levels[l].groups, hierarchy_->levels[l].groups);
        for (size_t c = 0; c < back.levels[l].place.size(); ++c) {
            EXPECT_EQ(back.levels[l].place[c].group, hierarchy_->levels[l].place[c].group);
            EXPECT_EQ(back.levels[l].place[c].sourceGroup, hierarchy_->levels[l].place[c].sourceGroup);
            EXPECT_EQ(back.levels[l].place[c].parentError, hierarchy_->levels[l].place[c].parentError);
        }
    }
    Settings settings;
    settings.views = 16;
    const LodStatistics a = measureHierarchy(*hierarchy_, settings, {}), b = measureHierarchy(back, settings, {});
    EXPECT_EQ(a.cut.trianglesCulled, b.cut.trianglesCulled);
    EXPECT_EQ(a.cut.backFacingTriangles, b.cut.backFacingTriangles);
    for (size_t l = 0; l < a.levels.size(); ++l) EXPECT_EQ(a.levels[l].culling.trianglesCulled, b.levels[l].culling.trianglesCulled);
}

// Every fault the cut cannot live with is refused, naming the cluster or group.
TEST_F(LodHierarchy, FaultyRecordsAreRefusedNamingTheCluster) {
    const HierarchyRecords good = hierarchyRecordsOf(*hierarchy_, {});
    const size_t top = good.clusters.size() - 1, firstAbove = hierarchy_->levels[0].place.size();
    const auto refused = [&](const std::function<void(HierarchyRecords&)>& spoil, const std::string& named) {
        HierarchyRecords records = good;
        spoil(records);
        try {
            hierarchyFromRecords(*sphere_, records, Settings{});
            ADD_FAILURE() << "accepted: " << named;
        } catch (const HierarchyError& error) {
            EXPECT_NE(std::string(error.what()).find(named), std::string::npos) << error.what();
        }
    };
    refused([](HierarchyRecords& r) { r.clusters[3].error = r.groups[size_t(r.clusters[3].group)].error * 2.0 + 1.0; }, "cluster 3");
    refused([](HierarchyRecords& r) { r.clusters[5].sphere.radius *= 100.0; }, "cluster 5");
    refused([&](HierarchyRecords& r) { r.clusters[firstAbove].group = 0; }, "cluster " + std::to_string(firstAbove));
    refused([&](HierarchyRecords& r) { r.clusters[top].group = 0; }, "cluster " + std::to_string(top));
    refused([](HierarchyRecords& r) { r.clusters[2].refined = 0; }, "cluster 2");
    refused([](HierarchyRecords& r) { r.clusters[0].level = 1; }, "cluster 1");
    refused([](HierarchyRecords& r) { r.groups[1].error = std::nan(""); }, "group 1");
    refused([](HierarchyRecords& r) { r.clusters.pop_back(); }, "meshlets");
    refused([](HierarchyRecords& r) { r.arrays.vertices[r.arrays.meshlets[4][0]] = 1u << 30; }, "cluster 4");
}

TEST(LodBuild, ReportsEachLevelAndCancels) {
    const PreparedMesh mesh = prepared(icosphere(4));
    std::set<std::string> stages;
    buildClusterHierarchy(mesh, Settings{}, {}, [&](double, const std::string& stage) {
        stages.insert(stage);
        return true;
    });
    EXPECT_TRUE(stages.count("level 1"));
    EXPECT_TRUE(stages.count("level 2"));
    EXPECT_THROW(buildClusterHierarchy(mesh, Settings{}, {}, [](double, const std::string& stage) { return stage != "level 2"; }),
                 OperationCancelled);
}

TEST(LodBuild, ProjectedErrorGrowsAsTheEyeComesNear) {
    const Sphere sphere{glm::dvec3(0.0), 1.0};
    LodThreshold pixels;
    EXPECT_GT(projectedError(0.01, sphere, {0.0, 0.0, 3.0}, pixels), projectedError(0.01, sphere, {0.0, 0.0, 30.0}, pixels));
    EXPECT_TRUE(std::isinf(projectedError(0.01, sphere, {0.0, 0.0, 0.5}, pixels)));
    EXPECT_EQ(projectedError(0.0, sphere, {0.0, 0.0, 0.5}, pixels), 0.0);
    // 1080 pixels over a 60 degree field: an error of 0.01 seen from 2 beyond the sphere.
    EXPECT_NEAR(projectedError(0.01, sphere, {0.0, 0.0, 3.0}, pixels), 0.01 / 2.0 * 1080.0 / (2.0 * std::tan(M_PI / 6.0)), 1e-9);
    pixels.worldUnits = true;
    EXPECT_EQ(projectedError(0.01, sphere, {0.0, 0.0, 30.0}, pixels), 0.01);
}

// A flat patch simplifies without error: the levels above still replace it only past threshold 0.
TEST(LodBuild, ZeroErrorLevelsStillAboveThresholdZero) {
    const PreparedMesh patch = prepared(testmesh::flatPatch(40));
    const ClusterHierarchy hierarchy = buildClusterHierarchy(patch, Settings{});
    ASSERT_GE(hierarchy.levels.size(), 2u);
    LodThreshold zero;
    zero.value = 0.0;
    const std::vector<std::vector<uint8_t>> cut = cutFrom(hierarchy, {0.5, 0.5, 1.0}, zero);
    EXPECT_TRUE(std::all_of(cut[0].begin(), cut[0].end(), [](uint8_t drawn) { return drawn == 1; }));
}

}  // namespace
}  // namespace conescope
