// A/B comparison: identities against each side's own statistics, A = B, the cluster-count warning
// and the K=V configuration text.
#include <gtest/gtest.h>

#include <memory>

#include "TestMeshes.h"
#include "core/Comparison.h"

using namespace conescope;

namespace {

PreparedMesh preparedTorus() {
    return prepareMesh(std::make_shared<Mesh>(testmesh::torus(1.0, 0.35, 64, 24)), "torus", false);
}

// The torus as quads, every third ring of quad pairs merged into hexagons, and a zero-area triangle
// on every eighth ring: polygons weigh their triangles and degenerate faces never face away.
PreparedMesh preparedPolygonTorus() {
    const int rings = 48, sides = 24;
    Mesh mesh = testmesh::torus(1.0, 0.35, rings, sides);
    mesh.faceStarts = {0};
    mesh.faceVertices.clear();
    auto index = [&](int i, int j) { return uint32_t((i % rings) * sides + (j % sides)); };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; j += (i % 3 == 0 ? 2 : 1)) {
            if (i % 3 == 0)
                mesh.addFace({index(i, j), index(i, j + 1), index(i, j + 2), index(i + 1, j + 2), index(i + 1, j + 1), index(i + 1, j)});
            else
                mesh.addFace({index(i, j), index(i, j + 1), index(i + 1, j + 1), index(i + 1, j)});
        }
        if (i % 8 == 0) {
            const glm::vec3 middle = 0.5f * (mesh.positions[index(i, 0)] + mesh.positions[index(i + 1, 0)]);
            mesh.positions.push_back(middle);
            mesh.addFace({index(i, 0), uint32_t(mesh.positions.size() - 1), index(i + 1, 0)});
        }
    }
    return prepareMesh(std::make_shared<Mesh>(mesh), "polygon torus", false);
}

Settings withBuilder(Builder builder, size_t maxTriangles = 48) {
    Settings settings;
    settings.builder = builder;
    settings.limits.maxTriangles = maxTriangles;
    settings.views = 24;
    return settings;
}

// only A + both is A's triangles_culled, only B + both is B's, view by view and in total.
void expectIdentities(const PreparedMesh& prepared, const ClusterSet& a, const ClusterSet& b, const std::vector<Eye>& views) {
    const Comparison comparison = compareClusterSets(prepared, {a, a.builtWith}, {b, b.builtWith}, views);
    const CullTestStatistics statsA = measureCulling(cullingInput(prepared, a), views, displayedTest(a.builtWith));
    const CullTestStatistics statsB = measureCulling(cullingInput(prepared, b), views, displayedTest(b.builtWith));
    ASSERT_EQ(comparison.views.size(), views.size());
    for (size_t v = 0; v < views.size(); ++v) {
        const ViewComparison& view = comparison.views[v];
        EXPECT_EQ(view.trianglesCulledOnlyA + view.trianglesCulledBoth, statsA.views[v].trianglesCulled) << "view " << v;
        EXPECT_EQ(view.trianglesCulledOnlyB + view.trianglesCulledBoth, statsB.views[v].trianglesCulled) << "view " << v;
        EXPECT_EQ(view.backFacingTriangles, statsA.views[v].backFacingTriangles);
        EXPECT_DOUBLE_EQ(view.efficiencyA, statsA.views[v].efficiency);
        EXPECT_DOUBLE_EQ(view.efficiencyB, statsB.views[v].efficiency);
    }
    EXPECT_EQ(comparison.trianglesCulledOnlyA + comparison.trianglesCulledBoth, statsA.trianglesCulled);
    EXPECT_EQ(comparison.trianglesCulledOnlyB + comparison.trianglesCulledBoth, statsB.trianglesCulled);
    EXPECT_DOUBLE_EQ(comparison.efficiencyA, statsA.efficiency);
    EXPECT_DOUBLE_EQ(comparison.efficiencyB, statsB.efficiency);
    // The per-face view counts, each face weighted by its triangles, add up to the triangle totals.
    const Mesh& mesh = prepared.mesh();
    ASSERT_EQ(comparison.viewsCulledOnlyA.size(), mesh.faceCount());
    size_t onlyA = 0, onlyB = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        onlyA += comparison.viewsCulledOnlyA[f] * (mesh.faceSize(f) - 2), onlyB += comparison.viewsCulledOnlyB[f] * (mesh.faceSize(f) - 2);
    EXPECT_EQ(onlyA, comparison.trianglesCulledOnlyA);
    EXPECT_EQ(onlyB, comparison.trianglesCulledOnlyB);
}

}  // namespace

TEST(Comparison, SameConfigurationDiffersNowhere) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet clusters = buildClusters(prepared, withBuilder(Builder::Optimized));
    const std::vector<Eye> views = orbitOf(clusters.builtWith, prepared.box);
    const Comparison comparison = compareClusterSets(prepared, {clusters, clusters.builtWith}, {clusters, clusters.builtWith}, views);
    for (const ViewComparison& view : comparison.views) {
        EXPECT_EQ(view.trianglesCulledOnlyA, 0u);
        EXPECT_EQ(view.trianglesCulledOnlyB, 0u);
        EXPECT_DOUBLE_EQ(view.efficiencyA, view.efficiencyB);
    }
    EXPECT_GT(comparison.trianglesCulledBoth, 0u);
    for (size_t f = 0; f < comparison.viewsCulledOnlyA.size(); ++f) {
        EXPECT_EQ(comparison.viewsCulledOnlyA[f], 0u);
        EXPECT_EQ(comparison.viewsCulledOnlyB[f], 0u);
    }
    EXPECT_FALSE(comparison.clusterCountsDiffer());
    EXPECT_EQ(clusterCountWarning(comparison), "");
}

TEST(Comparison, EachSideAddsUpToItsOwnStatistics) {
    const PreparedMesh prepared = preparedTorus();
    const Settings base = withBuilder(Builder::Optimized);
    const ClusterSet optimized = buildClusters(prepared, base);
    const ClusterSet meshopt = buildClusters(prepared, withBuilder(Builder::Meshopt));
    Settings averageSphere = base;
    averageSphere.cones = {ConeMethod::Average};
    averageSphere.tests = {CullTest::Sphere};
    const ClusterSet average = buildClusters(prepared, averageSphere);
    Settings orthographic = base;
    orthographic.orthographic = true;
    for (const std::vector<Eye>& views : {orbitOf(base, prepared.box), orbitOf(orthographic, prepared.box)}) {
        expectIdentities(prepared, optimized, meshopt, views);
        expectIdentities(prepared, meshopt, optimized, views);
        expectIdentities(prepared, optimized, average, views);
    }
    // Different partitions really do cull different faces.
    const ClusterSet meshlet = buildClusters(prepared, withBuilder(Builder::Meshlet));
    expectIdentities(prepared, optimized, meshlet, orbitOf(base, prepared.box));
    const Comparison comparison =
        compareClusterSets(prepared, {optimized, optimized.builtWith}, {meshlet, meshlet.builtWith}, orbitOf(base, prepared.box));
    EXPECT_GT(comparison.trianglesCulledOnlyA + comparison.trianglesCulledOnlyB, 0u);
}

TEST(Comparison, PolygonsWeighTheirTrianglesAndDegenerateFacesNeverCount) {
    const PreparedMesh prepared = preparedPolygonTorus();
    ASSERT_GT(prepared.faces.degenerateCount, 0u);
    ASSERT_GT(triangleCount(prepared.mesh()), prepared.mesh().faceCount());  // most faces are not triangles
    const Settings base = withBuilder(Builder::Optimized, 32);
    Settings averageSphere = withBuilder(Builder::Meshlet, 32);
    averageSphere.cones = {ConeMethod::Average};
    averageSphere.tests = {CullTest::Sphere};
    const ClusterSet optimized = buildClusters(prepared, base);
    const ClusterSet meshlet = buildClusters(prepared, averageSphere);
    const std::vector<Eye> views = orbitOf(base, prepared.box);
    expectIdentities(prepared, optimized, meshlet, views);
    const Comparison comparison = compareClusterSets(prepared, {optimized, base}, {meshlet, averageSphere}, views);
    EXPECT_GT(comparison.trianglesCulledOnlyA + comparison.trianglesCulledOnlyB, 0u);
    for (size_t f = 0; f < prepared.mesh().faceCount(); ++f)
        if (prepared.faces.degenerate[f]) EXPECT_EQ(comparison.viewsCulledOnlyA[f] + comparison.viewsCulledOnlyB[f], 0u) << f;
}

// The window changes the test without new clusters: each side is scored with the test of the
// settings it is shown with, never with the one its clusters were built under.
TEST(Comparison, EachSideCullsWithTheTestOfItsOwnSettings) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet clusters = buildClusters(prepared, withBuilder(Builder::Optimized));  // built under octagon
    ASSERT_EQ(displayedTest(clusters.builtWith), CullTest::Octagon);
    Settings apex = clusters.builtWith;
    apex.tests = {CullTest::Apex};
    const std::vector<Eye> views = orbitOf(apex, prepared.box);
    const Comparison same = compareClusterSets(prepared, {clusters, apex}, {clusters, apex}, views);
    EXPECT_EQ(same.testA, CullTest::Apex);
    EXPECT_EQ(same.trianglesCulledOnlyA, 0u);
    EXPECT_EQ(same.trianglesCulledOnlyB, 0u);
    EXPECT_DOUBLE_EQ(same.efficiencyA, measureCulling(cullingInput(prepared, clusters), views, CullTest::Apex).efficiency);
    const Comparison mixed = compareClusterSets(prepared, {clusters, apex}, {clusters, clusters.builtWith}, views);
    EXPECT_EQ(mixed.testB, CullTest::Octagon);
    EXPECT_EQ(mixed.trianglesCulledOnlyA, 0u);  // the octagon culls whatever the apex test culls here
    EXPECT_GT(mixed.trianglesCulledOnlyB, 0u);
}

TEST(Comparison, SharedOptionsComeFromTheCurrentSide) {
    Settings pinned = withBuilder(Builder::Meshopt);
    pinned.views = 16, pinned.distance = 2.0, pinned.tests = {CullTest::Apex};
    Settings current;
    current.views = 64, current.distance = 3.5, current.orthographic = true, current.fixWinding = true;
    current.eye = glm::dvec3(1.0, 2.0, 3.0);
    const Settings a = withSharedOptions(pinned, current);
    EXPECT_EQ(a.views, 64u);
    EXPECT_EQ(a.distance, 3.5);
    EXPECT_TRUE(a.orthographic);
    EXPECT_TRUE(a.fixWinding);
    EXPECT_EQ(a.eye, current.eye);
    EXPECT_EQ(a.builder, Builder::Meshopt);
    EXPECT_EQ(a.tests, std::vector<CullTest>{CullTest::Apex});
}

TEST(Comparison, ProgressHearsOfTheViewsAndMayCancel) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet clusters = buildClusters(prepared, withBuilder(Builder::Optimized));
    const std::vector<Eye> views = orbitOf(clusters.builtWith, prepared.box);
    const ClusterConfiguration side{clusters, clusters.builtWith};
    size_t calls = 0;
    compareClusterSets(prepared, side, side, views, [&calls](double fraction, const std::string&) {
        EXPECT_GE(fraction, 0.0);
        EXPECT_LT(fraction, 1.0);
        return ++calls > 0;
    });
    EXPECT_EQ(calls, (views.size() + 15) / 16);
    EXPECT_THROW(compareClusterSets(prepared, side, side, views, [](double, const std::string&) { return false; }),
                 OperationCancelled);
}

TEST(Comparison, FaceDiffFollowsEachSidesClusterDecision) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet a = buildClusters(prepared, withBuilder(Builder::Optimized));
    const ClusterSet b = buildClusters(prepared, withBuilder(Builder::Meshlet));
    const Eye eye = Eye::perspective({0.5, -2.0, 2.5});
    const EyeMeasurement measuredA = measureEye(prepared, a, eye, CullTest::Apex);
    const EyeMeasurement measuredB = measureEye(prepared, b, eye, CullTest::Apex);
    const std::vector<FaceDiff> diff = faceDiff(a, measuredA.culled, b, measuredB.culled);
    ASSERT_EQ(diff.size(), prepared.mesh().faceCount());
    size_t counts[4] = {0, 0, 0, 0};
    for (size_t f = 0; f < diff.size(); ++f) {
        const bool byA = measuredA.culled[a.partition.clusterOfFace[f]], byB = measuredB.culled[b.partition.clusterOfFace[f]];
        EXPECT_EQ(diff[f], FaceDiff((byA ? 1 : 0) | (byB ? 2 : 0)));
        ++counts[size_t(diff[f])];
    }
    EXPECT_GT(counts[0], 0u);
    EXPECT_GT(counts[3], 0u);
}

// The window's and the headless path: one eye from decisions already made is the same comparison as
// culling both sides again.
TEST(Comparison, OneEyeFromMeasuredDecisionsIsTheFullComparison) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet a = buildClusters(prepared, withBuilder(Builder::Optimized));
    Settings sphere = withBuilder(Builder::Meshlet);
    sphere.tests = {CullTest::Sphere};
    const ClusterSet b = buildClusters(prepared, sphere);
    for (const Eye& eye : {Eye::perspective({0.5, -2.0, 2.5}), Eye::perspective({-3.0, 0.2, 0.4})}) {
        std::vector<FaceDiff> diff;
        const Comparison atEye = compareAtEye(prepared, {a, a.builtWith}, measureEye(prepared, a, eye, displayedTest(a.builtWith)).culled,
                                              {b, sphere}, measureEye(prepared, b, eye, CullTest::Sphere).culled, eye, diff);
        const Comparison full = compareClusterSets(prepared, {a, a.builtWith}, {b, sphere}, {eye});
        ASSERT_EQ(atEye.views.size(), 1u);
        EXPECT_EQ(atEye.trianglesCulledOnlyA, full.trianglesCulledOnlyA);
        EXPECT_EQ(atEye.trianglesCulledOnlyB, full.trianglesCulledOnlyB);
        EXPECT_EQ(atEye.trianglesCulledBoth, full.trianglesCulledBoth);
        EXPECT_EQ(atEye.backFacingTriangles, full.backFacingTriangles);
        EXPECT_DOUBLE_EQ(atEye.efficiencyA, full.efficiencyA);
        EXPECT_DOUBLE_EQ(atEye.efficiencyB, full.efficiencyB);
        EXPECT_EQ(atEye.viewsCulledOnlyA, full.viewsCulledOnlyA);
        EXPECT_EQ(atEye.clustersB, b.bounds.count());
        EXPECT_EQ(diff.size(), prepared.mesh().faceCount());
        EXPECT_GT(full.trianglesCulledOnlyA + full.trianglesCulledOnlyB + full.trianglesCulledBoth, 0u);
    }
}

TEST(Comparison, ClusterCountsMoreThanFivePercentApartAreWarnedAbout) {
    const PreparedMesh prepared = preparedTorus();
    const ClusterSet large = buildClusters(prepared, withBuilder(Builder::Meshlet, 96));
    const ClusterSet small = buildClusters(prepared, withBuilder(Builder::Meshlet, 24));
    const Comparison comparison =
        compareClusterSets(prepared, {large, large.builtWith}, {small, small.builtWith}, {Eye::perspective({0, 0, 4})});
    EXPECT_EQ(comparison.clustersA, large.bounds.count());
    EXPECT_EQ(comparison.clustersB, small.bounds.count());
    EXPECT_TRUE(comparison.clusterCountsDiffer());
    EXPECT_NE(clusterCountWarning(comparison).find("more than 5%"), std::string::npos);
    Comparison close = comparison;
    close.clustersA = 100, close.clustersB = 105;
    EXPECT_FALSE(close.clusterCountsDiffer());
    close.clustersB = 106;
    EXPECT_TRUE(close.clusterCountsDiffer());
}

TEST(Comparison, ConfigurationTextSetsOptionsOnTopOfTheBase) {
    Settings base;
    base.limits.maxTriangles = 100;
    const Settings a = parseConfiguration("builder=meshopt,max-verts=32", base);
    EXPECT_EQ(a.builder, Builder::Meshopt);
    EXPECT_EQ(a.limits.maxVertices, 32u);
    EXPECT_EQ(a.limits.maxTriangles, 100u);  // from the base
    const Settings lists = parseConfiguration("cone=average,minimal,test=sphere", base);
    EXPECT_EQ(lists.cones, (std::vector<ConeMethod>{ConeMethod::Average, ConeMethod::Minimal}));
    EXPECT_EQ(lists.tests, (std::vector<CullTest>{CullTest::Sphere}));
    EXPECT_EQ(parseConfiguration("builder=file,cluster-file=ids,a.txt", base).clusterFile, "ids,a.txt");
    EXPECT_EQ(parseConfiguration("", base).limits.maxTriangles, 100u);
}

TEST(Comparison, ConfigurationTextRefusesSharedUnknownAndBadOptions) {
    auto message = [](const std::string& text) {
        try {
            parseConfiguration(text, Settings{});
        } catch (const std::invalid_argument& error) {
            return std::string(error.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("views=3").find("shared by both sides"), std::string::npos);
    EXPECT_NE(message("fix-winding").find("shared by both sides"), std::string::npos);
    EXPECT_NE(message("colour=red").find("unknown option 'colour'"), std::string::npos);
    EXPECT_NE(message("colour=red").find("max-tris"), std::string::npos) << "lists what it accepts";
    EXPECT_NE(message("max-tris=64,max-trs=32").find("unknown option 'max-trs'"), std::string::npos) << "not part of 64";
    EXPECT_NE(message("builder=meshopt,colour=red").find("unknown option 'colour'"), std::string::npos);
    EXPECT_NE(message("cone=minimal,averag").find("averag"), std::string::npos) << "a continued list names its bad item";
    EXPECT_NE(message("max-tris=0"), "accepted");
    EXPECT_NE(message("cone=widest"), "accepted");
    EXPECT_NE(message("builder").find("needs a value"), std::string::npos);
}
