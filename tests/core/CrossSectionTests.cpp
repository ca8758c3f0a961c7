// The cross-section is true to each test: every normal at its angle to V1, v at its angle, v inside
// the region of view vectors that cull exactly when the test culls, and each end of that region
// where the core's own test changes its answer, for every test on ordinary and awkward clusters
// (normals all at one angle, no cone, a flat patch whose apex is its centre, far eyes).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <random>

#include "TestMeshes.h"
#include "core/CrossSection.h"
#include "core/Lesson.h"
#include "core/LessonText.h"
#include "core/RecordTests.h"

using namespace conescope;
using testmesh::randomUnit;

namespace {

constexpr double pi = 3.14159265358979323846;

struct Clusters {
    PreparedMesh mesh;
    ClusterSet clusters;
};

Clusters clustersOf(Mesh mesh, const std::string& name, Builder builder, size_t limit, ConeMethod cone = ConeMethod::Minimal) {
    Settings settings;
    settings.builder = builder;
    settings.cones = {cone};
    if (builder == Builder::KMeans)
        settings.clusterCount = limit;
    else
        settings.limits.maxTriangles = settings.limits.maxVertices = limit;
    PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(std::move(mesh)), name, false);
    ClusterSet clusters = buildClusters(prepared, settings);
    return {std::move(prepared), std::move(clusters)};
}

double angleTo(const glm::dvec3& n, const glm::dvec3& axis) { return std::atan2(glm::length(glm::cross(n, axis)), glm::dot(n, axis)); }

glm::dvec3 inPage(const CrossSection& s, double angle) { return std::sin(angle) * s.right + std::cos(angle) * s.up; }

// The core's answer for a view vector at `angle` in the page, asked as the figure's region means
// it: from an eye on the circle through this one around the point v runs to (a far eye: the
// direction), or for the box and vertex tests, whether one point's view vector sees the back.
bool coreCullsAt(const Lesson& lesson, const CullingInput& input, const CrossSection& s, double angle) {
    const glm::dvec3 u = inPage(s, angle);
    if (!s.pointAngles.empty()) return viewDirectionSeesBack(input.bounds.cones[lesson.cluster], u);
    if (lesson.eye.orthographic) return cullCluster(input, lesson.cluster, Eye::orthographicAlong(u), lesson.test);
    const bool toApex = lesson.test == CullTest::Apex || lesson.test == CullTest::Octagon;
    const glm::dvec3 target = toApex ? lesson.why.apex : lesson.sphere.center;
    const double distance = glm::distance(target, lesson.eye.position);
    return cullCluster(input, lesson.cluster, Eye::perspective(target - distance * u), lesson.test);
}

// Everything the figure draws, held against the core. Returns whether the test culled.
bool checkAgainstCore(const Lesson& lesson, const CullingInput& input, const std::string& where) {
    const CullExplanation& why = lesson.why;
    const CrossSection s = crossSectionOf(lesson, input);
    const std::string context = where + " " + toString(lesson.test) + " cluster " + std::to_string(lesson.cluster);
    EXPECT_EQ(s.culls, why.culled) << context;
    EXPECT_NEAR(glm::length(s.up), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(s.up, s.right), 0.0, 1e-12);
    // The normals at their true angles to V1, on the side they lean to.
    EXPECT_EQ(s.normalAngles.size(), lesson.normals.size()) << context;
    for (size_t i = 0; i < std::min(s.normalAngles.size(), lesson.normals.size()); ++i) {
        const glm::dvec3& n = lesson.normals[i];
        EXPECT_NEAR(std::abs(s.normalAngles[i]), angleTo(n, s.up), 1e-12) << context;
        if (std::abs(glm::dot(n, s.right)) > 1e-9) EXPECT_EQ(s.normalAngles[i] > 0.0, glm::dot(n, s.right) > 0.0) << context;
        if (s.cone) EXPECT_LE(std::abs(s.normalAngles[i]), s.alpha + 1e-9) << context;
    }
    if (s.cone) EXPECT_NEAR(s.alpha + s.angleB, pi / 2.0, 1e-12);
    // v: the test's view vector, or the corner (vertex) view vector with the lowest v.V1.
    if (s.pointAngles.empty()) {
        EXPECT_NEAR(s.viewAngle, angleTo(why.view, s.up), 1e-9) << context;
        EXPECT_NEAR(std::cos(s.viewAngle), why.viewDotAxis, 1e-9) << context;
    } else {
        const size_t expected = lesson.test == CullTest::Vertices ? why.vertices.size() : 8;
        EXPECT_EQ(s.pointAngles.size(), expected) << context;
        const double lowest = lesson.test == CullTest::Vertices ? why.margin + why.threshold
                                                                : *std::min_element(why.cornerDotAxis.begin(), why.cornerDotAxis.end());
        if (std::isfinite(lowest)) EXPECT_NEAR(std::cos(s.viewAngle), lowest, 1e-9) << context;
        size_t inside = 0;
        for (double a : s.pointAngles) inside += s.inRegion(a);
        if (s.hasRegion() && std::abs(why.margin) > 1e-7) EXPECT_EQ(inside, why.pointsBack) << context;
    }
    // Without a cone nothing culls, except by the oracle's or a record's own rule.
    if (!why.cullable && s.rule != CullRegionRule::Asked) EXPECT_FALSE(s.hasRegion()) << context;
    // v in the region exactly when the test culls (away from the threshold's rounding).
    const bool decided = s.rule == CullRegionRule::Asked ? why.culled == why.exactCulled : !std::isnan(why.margin) && std::abs(why.margin) > 1e-7;
    if (decided) EXPECT_EQ(s.inRegion(s.viewAngle), why.culled) << context << " v at " << glm::degrees(s.viewAngle);
    if (std::isnan(why.margin) && s.rule != CullRegionRule::Asked) EXPECT_FALSE(s.inRegion(s.viewAngle)) << context;
    // Each end of the region is where the core changes its answer.
    for (const AngleRange& range : s.cullRegion) {
        EXPECT_LT(range[0], range[1]) << context;
        const double step = 1e-6;
        for (int end = 0; end < 2; ++end) {
            if (std::abs(std::abs(range[end]) - pi) < 1e-9) continue;
            const double inward = end == 0 ? step : -step;
            EXPECT_TRUE(coreCullsAt(lesson, input, s, range[end] + inward)) << context << " end " << glm::degrees(range[end]);
            if (!s.inRegion(range[end] - inward))
                EXPECT_FALSE(coreCullsAt(lesson, input, s, range[end] - inward)) << context << " end " << glm::degrees(range[end]);
        }
    }
    // The round tests' region is what the text says: within B, B - asin(r/d) or acos(sin alpha + r/d) of V1.
    if (s.rule == CullRegionRule::Round && s.hasRegion()) {
        double expected = s.angleB;
        if (!lesson.eye.orthographic && lesson.test == CullTest::Sphere) expected = s.angleB - std::asin(why.radius / why.distance);
        if (!lesson.eye.orthographic && lesson.test == CullTest::MeshoptSphere)
            expected = std::acos(std::sin(s.alpha) + why.radius / why.distance);
        EXPECT_NEAR(s.cullRegion[0][1], expected, 1e-6) << context;
        EXPECT_NEAR(s.cullRegion[0][0], -expected, 1e-6) << context;
        EXPECT_NEAR(s.regionHalfAngle, expected, 1e-6) << context;
    }
    EXPECT_FALSE(s.caption.empty());
    return why.culled;
}

const std::vector<CullTest> everyTest = {CullTest::Oracle, CullTest::Vertices, CullTest::Aabb, CullTest::AabbFast, CullTest::Sphere,
                                         CullTest::Apex, CullTest::MeshoptSphere, CullTest::Octagon, CullTest::MeshoptApexF32,
                                         CullTest::MeshoptSphereS8, CullTest::CadsceneBoxS8, CullTest::OctagonCompact};

// Every test on every cluster of `c` (every `stride`-th) from these eyes; counts culled and drawn per test.
void checkAll(const Clusters& c, const std::vector<Eye>& eyes, uint32_t stride, std::map<CullTest, std::array<size_t, 2>>& seen,
              const std::string& where) {
    const CullingInput input = cullingInput(c.mesh, c.clusters);
    for (const Eye& eye : eyes)
        for (uint32_t cluster = 0; cluster < c.clusters.bounds.count(); cluster += stride)
            for (CullTest test : everyTest) {
                const Lesson lesson = makeLesson(c.mesh, c.clusters, cluster, eye, test);
                ++seen[test][checkAgainstCore(lesson, input, where) ? 1 : 0];
            }
}

}  // namespace

TEST(CrossSection, EveryTestOnATorusFromNearAndFarEyes) {
    for (ConeMethod method : {ConeMethod::Minimal, ConeMethod::Average, ConeMethod::Meshopt}) {
        const Clusters torus = clustersOf(testmesh::torus(1.0, 0.35, 48, 24), "torus", Builder::Meshlet, 24, method);
        std::mt19937_64 random(5);
        std::vector<Eye> eyes;
        for (int trial = 0; trial < 10; ++trial)
            eyes.push_back(trial % 4 == 3 ? Eye::orthographicAlong(randomUnit(random)) : Eye::perspective(randomUnit(random) * (1.3 + trial % 5)));
        std::map<CullTest, std::array<size_t, 2>> seen;
        checkAll(torus, eyes, 5, seen, "torus " + toString(method));
        // Each test both culls and draws somewhere, so both sides of the region were checked.
        for (CullTest test : everyTest) {
            EXPECT_GT(seen[test][1], 0u) << toString(test) << " " << toString(method);
            EXPECT_GT(seen[test][0], 0u) << toString(test) << " " << toString(method);
        }
    }
}

TEST(CrossSection, NormalsAllAtOneAngleAreEachDrawnThere) {
    // A roof as one cluster: its minimal cone is the roof's axis, every normal on its boundary.
    const Clusters c = clustersOf(testmesh::roof(24, 0.8), "roof", Builder::KMeans, 1);
    ASSERT_EQ(c.clusters.bounds.count(), 1u);
    std::map<CullTest, std::array<size_t, 2>> seen;
    checkAll(c, {Eye::perspective({0.1, 0.2, -3.0}), Eye::perspective({2.0, 0.5, 0.3}), Eye::orthographicAlong({0.0, 0.1, 1.0})}, 1, seen, "roof");
    const Lesson lesson = makeLesson(c.mesh, c.clusters, 0, Eye::perspective({0.1, 0.2, -3.0}), CullTest::Octagon);
    const CrossSection s = crossSectionOf(lesson, cullingInput(c.mesh, c.clusters));
    ASSERT_EQ(s.normalAngles.size(), 24u);
    for (double a : s.normalAngles) EXPECT_NEAR(std::abs(a), s.alpha, 1e-6);
    // Around a ring of normals the octagon's corners stand out of the round cone: its region is narrower.
    ASSERT_TRUE(s.hasRegion());
    EXPECT_GT(s.cullRegion[0][0], -s.angleB);
    EXPECT_LT(s.cullRegion[0][1], s.angleB);
    EXPECT_NE(s.caption.find("24 face normals"), std::string::npos) << s.caption;
}

TEST(CrossSection, AClusterWithoutAConeHasNoRegionAndSaysSo) {
    const Clusters c = clustersOf(testmesh::quadCube(), "cube", Builder::KMeans, 1);
    ASSERT_EQ(c.clusters.bounds.count(), 1u);
    std::map<CullTest, std::array<size_t, 2>> seen;
    checkAll(c, {Eye::perspective({3.0, 2.0, 4.0}), Eye::orthographicAlong({0.3, -1.0, 0.2})}, 1, seen, "cube");
    for (CullTest test : everyTest) EXPECT_EQ(seen[test][1], 0u) << toString(test);
    const Lesson lesson = makeLesson(c.mesh, c.clusters, 0, Eye::perspective({3.0, 2.0, 4.0}), CullTest::Apex);
    const CrossSection s = crossSectionOf(lesson, cullingInput(c.mesh, c.clusters));
    EXPECT_FALSE(s.cone);
    EXPECT_FALSE(s.hasRegion());
    EXPECT_NE(s.caption.find("no cone"), std::string::npos) << s.caption;
    double widest = 0.0;
    for (double a : s.normalAngles) widest = std::max(widest, std::abs(a));
    EXPECT_GT(widest, pi / 2.0);  // a normal points away from the axis: more than a half-space
}

TEST(CrossSection, AFlatPatchHasItsApexAtItsCentreAndBIsNinetyDegrees) {
    const Clusters c = clustersOf(testmesh::flatPatch(4), "flat", Builder::KMeans, 1);
    ASSERT_EQ(c.clusters.bounds.count(), 1u);
    const Lesson lesson = makeLesson(c.mesh, c.clusters, 0, Eye::perspective({0.3, 0.6, -2.0}), CullTest::Apex);
    EXPECT_LT(glm::distance(lesson.why.apex, lesson.sphere.center), 1e-6);
    const CrossSection s = crossSectionOf(lesson, cullingInput(c.mesh, c.clusters));
    EXPECT_NEAR(s.alpha, 0.0, 1e-5);
    EXPECT_TRUE(s.place.shown);
    EXPECT_NEAR(glm::length(s.place.target), 0.0, 1e-12);
    EXPECT_LT(glm::length(s.place.centre), 1e-6);  // the apex is the centre
    std::map<CullTest, std::array<size_t, 2>> seen;
    checkAll(c, {Eye::perspective({0.3, 0.6, -2.0}), Eye::perspective({0.5, 0.5, 2.0}), Eye::perspective({3.0, 0.5, -0.05}),
                 Eye::orthographicAlong({0.0, 0.0, 1.0})},
             1, seen, "flat");
    EXPECT_GT(seen[CullTest::Apex][1], 0u);
    EXPECT_GT(seen[CullTest::Apex][0], 0u);
}

TEST(CrossSection, ThePlaceHoldsTheEyeAndThePointVRunsTo) {
    const Clusters torus = clustersOf(testmesh::torus(1.0, 0.35, 48, 24), "torus", Builder::Meshlet, 24);
    const CullingInput input = cullingInput(torus.mesh, torus.clusters);
    const Eye eye = Eye::perspective({-1.6, 2.4, 1.5});
    for (CullTest test : {CullTest::Apex, CullTest::Octagon, CullTest::Sphere, CullTest::MeshoptSphere}) {
        const Lesson lesson = makeLesson(torus.mesh, torus.clusters, 3, eye, test);
        const CrossSection s = crossSectionOf(lesson, input);
        ASSERT_TRUE(s.place.shown) << toString(test);
        const bool toApex = test == CullTest::Apex || test == CullTest::Octagon;
        const glm::dvec3 target = toApex ? lesson.why.apex : lesson.sphere.center;
        // The eye lies in the page, at its distance, along -v from the target.
        EXPECT_NEAR(glm::length(s.place.eye), glm::distance(target, eye.position), 1e-9);
        const glm::dvec2 v = -s.place.eye / glm::length(s.place.eye);
        EXPECT_NEAR(std::atan2(v.x, v.y), s.viewAngle, 1e-9);
        if (!toApex) EXPECT_NEAR(s.place.spread, std::asin(lesson.sphere.radius / lesson.why.distance), 1e-12);
        // The eye is among the eyes that cull exactly when the test culls.
        bool among = false;
        for (const auto& t : s.place.cullingEyes) {
            const glm::dvec2 p = s.place.eye;
            auto side = [&p](const glm::dvec2& a, const glm::dvec2& b) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); };
            const double d0 = side(t[0], t[1]), d1 = side(t[1], t[2]), d2 = side(t[2], t[0]);
            among |= (d0 >= 0 && d1 >= 0 && d2 >= 0) || (d0 <= 0 && d1 <= 0 && d2 <= 0);
        }
        if (std::abs(lesson.why.margin) > 1e-3) EXPECT_EQ(among, lesson.why.culled) << toString(test);
    }
}

// The caption and the lesson's steps say the same: alpha, B, asin(r/d), the corners that pass, v's
// angle and whether the test holds, in the same words and digits.
TEST(CrossSection, TheCaptionSaysWhatTheLessonSays) {
    using lessontext::degrees;
    const Clusters torus = clustersOf(testmesh::torus(1.0, 0.35, 48, 24), "torus", Builder::Meshlet, 24);
    const CullingInput input = cullingInput(torus.mesh, torus.clusters);
    std::mt19937_64 random(9);
    size_t checked = 0;
    for (int trial = 0; trial < 8; ++trial) {
        const Eye eye = trial % 4 == 3 ? Eye::orthographicAlong(randomUnit(random)) : Eye::perspective(randomUnit(random) * (1.5 + trial));
        for (uint32_t c = 0; c < torus.clusters.bounds.count(); c += 6)
            for (CullTest test : {CullTest::Apex, CullTest::Sphere, CullTest::Aabb, CullTest::Octagon}) {
                const Lesson lesson = makeLesson(torus.mesh, torus.clusters, c, eye, test);
                if (!lesson.why.cullable || std::isnan(lesson.why.margin)) continue;
                const CrossSection s = crossSectionOf(lesson, input);
                const std::string& caption = s.caption;
                const std::string& step3 = lesson.steps[2].text;
                const std::string& step5 = lesson.steps[4].text;
                auto both = [&](const std::string& words, const std::string& step) {
                    EXPECT_NE(caption.find(words), std::string::npos) << words << " | " << caption;
                    EXPECT_NE(step.find(words), std::string::npos) << words << " | " << step;
                };
                const std::string verdict = lesson.why.margin > 0.0 ? "so the test holds" : "so the test fails";
                if (s.inRegion(s.viewAngle) == lesson.why.culled) both(verdict, step5);
                both("\u03b1 = " + degrees(lesson.why.halfAngleDegrees), step3);
                both(degrees(lesson.why.angleBDegrees), step3);
                if (test == CullTest::Apex && !eye.orthographic) {
                    both(degrees(lesson.why.angleBDegrees) + " of V1", step5);
                    both("v is " + degrees(glm::degrees(std::acos(lesson.why.viewDotAxis))) + " from V1", step5);
                }
                if (test == CullTest::Sphere && !eye.orthographic) both(" = " + degrees(lesson.why.sphereAngleDegrees), step5);
                if (test == CullTest::Aabb && !eye.orthographic) {
                    EXPECT_NE(step5.find("Here " + std::to_string(lesson.why.pointsBack) + " of 8 pass"), std::string::npos) << step5;
                    const std::string passing = lesson.why.pointsBack == 8 ? "All 8 do" : std::to_string(lesson.why.pointsBack) + " of 8 do";
                    EXPECT_NE(caption.find(passing), std::string::npos) << caption;
                }
                ++checked;
            }
    }
    EXPECT_GT(checked, 40u);
}
