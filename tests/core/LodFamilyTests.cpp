// A cluster's family in a LOD hierarchy (its group, parents and children) and the cut as one level:
// the same clusters, faces and culling as the levels it is drawn from.
#include <gtest/gtest.h>

#include <algorithm>

#include "IcosphereHierarchy.h"
#include "core/lod/LodFamily.h"

namespace conescope {
namespace {

bool holds(const std::vector<uint32_t>& list, uint32_t value) { return std::find(list.begin(), list.end(), value) != list.end(); }

class LodFamilyTest : public testmesh::IcosphereHierarchy<4> {};

// Parents and children are each other's: a cluster is a parent of each of its children, it shares its
// group with its group mates (who have the same parents), and every cluster below the top has parents.
TEST_F(LodFamilyTest, ParentsAndChildrenAreEachOthers) {
    const std::vector<LodLevel>& levels = hierarchy_->levels;
    ASSERT_GE(levels.size(), 3u);
    for (size_t l = 0; l < levels.size(); ++l)
        for (uint32_t c = 0; c < levels[l].place.size(); ++c) {
            const LodFamily family = lodFamilyOf(*hierarchy_, {l, c});
            EXPECT_FALSE(holds(family.groupMates, c));
            for (uint32_t mate : family.groupMates) {
                EXPECT_EQ(levels[l].place[mate].group, family.group);
                EXPECT_EQ(lodFamilyOf(*hierarchy_, {l, mate}).parents, family.parents);
            }
            EXPECT_EQ(family.parents.empty(), l + 1 == levels.size()) << "level " << l << " cluster " << c;
            EXPECT_EQ(family.children.empty(), l == 0) << "level " << l << " cluster " << c;
            for (uint32_t child : family.children) EXPECT_TRUE(holds(lodFamilyOf(*hierarchy_, {l - 1, child}).parents, c));
            for (uint32_t parent : family.parents) EXPECT_TRUE(holds(lodFamilyOf(*hierarchy_, {l + 1, parent}).children, c));
        }
    EXPECT_THROW(lodFamilyOf(*hierarchy_, {levels.size(), 0}), std::out_of_range);
    EXPECT_THROW(lodFamilyOf(*hierarchy_, {0, uint32_t(levels[0].place.size())}), std::out_of_range);
}

// The cut as one level holds exactly the drawn clusters, with their triangles, and the test culls the
// same triangles of it as measureHierarchy counts for the cut from that eye.
TEST_F(LodFamilyTest, CutAsOneLevelCullsAsTheCut) {
    Settings settings;
    for (double threshold : {0.0, 2.0, 30.0})
        for (const glm::dvec3& eye : {glm::dvec3(0.0, 0.0, 2.5), glm::dvec3(5.0, 1.0, -2.0)}) {
            LodThreshold rule;
            rule.value = threshold;
            const std::vector<std::vector<uint8_t>> drawn = cutFrom(*hierarchy_, eye, rule);
            std::vector<LodClusterId> origin;
            const LodLevel cut = levelOfCut(*hierarchy_, drawn, settings, origin);
            ASSERT_EQ(cut.clusters.partition.clusterCount, origin.size());
            size_t drawnCount = 0;
            for (const std::vector<uint8_t>& level : drawn) drawnCount += size_t(std::count(level.begin(), level.end(), uint8_t(1)));
            EXPECT_EQ(origin.size(), drawnCount);
            for (size_t c = 0; c < origin.size(); ++c) {
                const LodLevel& from = hierarchy_->levels[origin[c].level];
                EXPECT_TRUE(drawn[origin[c].level][origin[c].cluster]);
                const ClusterFaces& cutFaces = cut.clusters.bounds.faces;
                const ClusterFaces& levelFaces = from.clusters.bounds.faces;
                EXPECT_EQ(cutFaces.starts[c + 1] - cutFaces.starts[c], levelFaces.starts[origin[c].cluster + 1] - levelFaces.starts[origin[c].cluster]);
                EXPECT_DOUBLE_EQ(cut.clusters.bounds.cones[c].halfAngle(), from.clusters.bounds.cones[origin[c].cluster].halfAngle());
            }
            Settings one = exportSettings(settings, eye);
            const LodStatistics statistics = measureHierarchy(*hierarchy_, one, rule);
            const EyeMeasurement measured = measureEye(cut.prepared, cut.clusters, statistics.cut.views[0].eye, displayedTest(one));
            EXPECT_EQ(cut.triangles(), statistics.cut.views[0].triangles);
            EXPECT_EQ(measured.view().trianglesCulled, statistics.cut.views[0].trianglesCulled);
            EXPECT_EQ(measured.view().backFacingTriangles, statistics.cut.views[0].backFacingTriangles);
            if (threshold == 0.0) EXPECT_EQ(origin.size(), hierarchy_->levels[0].place.size());
            // The classes say what the cut draws: 0 exactly for its clusters; above a drawn cluster a finer
            // level is drawn, below it a coarser one.
            const std::vector<std::vector<uint8_t>> classes = cutClassesFrom(*hierarchy_, eye, rule);
            for (size_t l = 0; l < drawn.size(); ++l)
                for (uint32_t c = 0; c < drawn[l].size(); ++c) {
                    EXPECT_EQ(classes[l][c] == 0, drawn[l][c] == 1);
                    if (!drawn[l][c]) continue;
                    const LodFamily family = lodFamilyOf(*hierarchy_, {l, c});
                    for (uint32_t parent : family.parents) EXPECT_EQ(classes[l + 1][parent], 2);
                    for (uint32_t child : family.children) EXPECT_EQ(classes[l - 1][child], 1);
                }
        }
}

}  // namespace
}  // namespace conescope
