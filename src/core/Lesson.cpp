#include "Lesson.h"

#include <cctype>
#include <cmath>
#include <utility>

#include "BatchCulling.h"
#include "Choices.h"
#include "LessonSteps.h"
#include "LessonText.h"
#include "RecordTests.h"

namespace conescope {

using namespace lessontext;

std::string toString(LessonOutcome outcome) {
    switch (outcome) {
        case LessonOutcome::Culled: return "culled";
        case LessonOutcome::LostToTest: return "lost to the test";
        case LessonOutcome::LostToPartition: return "lost to the partition";
        case LessonOutcome::Visible: return "visible";
        case LessonOutcome::FalseCull: return "false cull";
    }
    return "visible";
}

std::string testInWords(CullTest test) {
    switch (test) {
        case CullTest::Oracle: return "the oracle";
        case CullTest::Vertices: return "the vertex test";
        case CullTest::Aabb: return "the bounding-box test";
        case CullTest::AabbFast: return "the bounding-box test without square roots";
        case CullTest::Sphere: return "the bounding-sphere test";
        case CullTest::Apex: return "the apex test";
        case CullTest::MeshoptSphere: return "meshoptimizer's sphere test";
        case CullTest::Octagon: return "the octagon test";
        case CullTest::MeshoptApexF32: return "meshoptimizer's float apex record";
        case CullTest::MeshoptSphereS8: return "meshoptimizer's 8-bit cone with niagara's sphere test";
        case CullTest::CadsceneBoxS8: return "cadscene's 8-bit box record";
        case CullTest::OctagonCompact: return "the octagon test on its 16-byte record";
    }
    return "the test";
}

std::string viewInWords(const CullTestStatistics& view, size_t clusterCount) {
    std::string text = testInWords(view.test) + " culls " + std::to_string(view.clustersCulled) + " of " +
                       count(clusterCount, "cluster", "clusters") + ": " + std::to_string(view.trianglesCulled) + " of the " +
                       count(view.backFacingTriangles, "back-facing triangle", "back-facing triangles") + ", an efficiency of " +
                       percent(view.efficiency) + ". ";
    text[0] = char(std::toupper(static_cast<unsigned char>(text[0])));
    return text + std::to_string(view.testLossTriangles) + " are lost to the test (their whole cluster faces away) and " +
           std::to_string(view.partitionLossTriangles) + " to the partition (their cluster also holds a face turned to the eye).";
}

LessonOutcome outcomeOf(bool culled, size_t frontFaces, size_t backFaces) {
    if (culled) return frontFaces > 0 ? LessonOutcome::FalseCull : LessonOutcome::Culled;
    if (backFaces == 0) return LessonOutcome::Visible;
    return frontFaces == 0 ? LessonOutcome::LostToTest : LessonOutcome::LostToPartition;
}

namespace {

std::string facesStep(const Lesson& lesson, const std::string& meshName) {
    const CullExplanation& why = lesson.why;
    std::string text = "Cluster " + std::to_string(lesson.cluster) + (meshName.empty() ? "" : " of " + meshName) +
                       " is a patch of " + count(lesson.faces, "neighbouring face", "neighbouring faces");
    if (lesson.triangles != lesson.faces) text += " (" + count(lesson.triangles, "triangle", "triangles") + ")";
    text += " with " + count(lesson.vertices, "vertex", "vertices") + ". ";
    text += "Each arrow is a face normal: it stands at right angles on its face and points out of the surface, "
            "to the side the face can be seen from. A face turns its back on the eye when the eye is behind it, "
            "on the side its normal points away from.";
    if (why.degenerateFaces > 0)
        text += " " + count(why.degenerateFaces, "face has", "faces have") + " no area and so no normal; it never decides anything.";
    return text;
}

std::string gaussStep(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    std::string text = "Slide the " + count(lesson.normals.size(), "arrow", "arrows") +
                       " so that they all start at one point: their tips then lie on a sphere of radius 1, the Gauss "
                       "sphere. Where the patch is flat the tips bunch together; where it bends they spread apart. "
                       "Seen from the eye, a face turns away when its normal points away from the eye. ";
    if (why.backFaces == 0)
        text += "From the current eye no face turns away";
    else if (why.frontFaces == 0)
        text += "From the current eye all " + count(why.backFaces, "face turns", "faces turn") + " away";
    else
        text += "From the current eye " + count(why.backFaces, "face turns", "faces turn") + " away and " +
                count(why.frontFaces, "faces", "face") + " the eye";
    return text + ": the cluster may be skipped only when every one turns away.";
}

// The cone's lesson wording (Choices.cpp) with the average and minimal cones' half-angles filled in.
std::string withConeAngles(std::string wording, const std::string& average, const std::string& minimal) {
    for (const auto& [mark, angle] : {std::pair<std::string, const std::string&>{"{average}", average}, {"{minimal}", minimal}})
        for (size_t at = wording.find(mark); at != std::string::npos; at = wording.find(mark, at + angle.size()))
            wording.replace(at, mark.size(), angle);
    return wording;
}

std::string coneStep(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    const std::string shown = toString(lesson.coneMethod);
    if (!why.cullable)
        return "A cone holds the normals when none is more than its half-angle \u03b1 away from its axis V1. " + noConeSentence(lesson);
    std::string text = "A cone holds the normals when none is more than its half-angle \u03b1 away from its axis V1. The " +
                       shown + " cone the test uses has V1 = " + vector3(why.axis) + " and \u03b1 = " +
                       degrees(why.halfAngleDegrees) + ": the normal farthest from V1 has n\u00b7V1 = cos \u03b1 = " +
                       dot(why.cosHalfAngle) + ". The classic article calls 90\u00b0 \u2212 \u03b1 = " + degrees(why.angleBDegrees) +
                       " the angle B. ";
    const double average = glm::degrees(lesson.averageCone.halfAngle());
    const double minimal = glm::degrees(lesson.minimalCone.halfAngle());
    const std::string averageText = lesson.averageCone.cullable ? degrees(average) : "more than 90\u00b0";
    text += withConeAngles(descriptor(lesson.coneMethod).lessonWording, averageText, degrees(minimal));
    return text + "A narrower cone culls from more places: seen from far away this one culls from (1 \u2212 sin \u03b1)/2 = " +
           percent((1.0 - std::sin(glm::radians(why.halfAngleDegrees))) / 2.0) + " of all directions.";
}

std::string verdictStep(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    const std::string unit = lesson.test == CullTest::Octagon ? "g\u00b7v" : "v\u00b7V1";
    std::string text;
    if (lesson.test == CullTest::Oracle)
        text = why.culled ? "Culled: the oracle found every face turned away. " : "Drawn: the oracle found a face that is not turned away. ";
    else if (why.culled)
        text = "Culled: the test holds with " + amount(why.margin) + " to spare (" + unit + " could drop that much). ";
    else if (std::isnan(why.margin))
        text = "Drawn: " + testInWords(lesson.test) + " cannot cull this cluster from here. ";
    else
        text = "Drawn: the test falls short by " + amount(-why.margin) + ". ";
    if (why.culled != why.exactCulled)
        text += "The exact test would cull it, but it lies within the fast kernel's rounding slack of the threshold. ";
    const std::string triangles = count(lesson.backTriangles, "back-facing triangle", "back-facing triangles");
    switch (lesson.outcome) {
        case LessonOutcome::Culled:
            text += "The oracle, which checks every face, agrees: all " + count(why.backFaces, "face turns", "faces turn") +
                    " away, and " + count(lesson.triangles, "triangle is", "triangles are") + " skipped. ";
            break;
        case LessonOutcome::FalseCull:
            text += "But the oracle finds " + count(why.frontFaces, "face", "faces") +
                    " facing the eye: a false cull, which must never happen. Please report it. ";
            break;
        case LessonOutcome::LostToTest:
            text += "Yet the oracle, which checks every face, finds all of them turned away: the cluster could have been "
                    "skipped. Its " + triangles + " are lost to the test: a narrower cone, a tighter bound or another test "
                    "could save them, with the same clusters. ";
            break;
        case LessonOutcome::LostToPartition:
            text += "The oracle finds " + count(why.frontFaces, "face", "faces") + " facing the eye, so the cluster must be "
                    "drawn and no test may cull it. Its " + triangles + " are lost to the partition: only grouping the "
                    "faces differently could save them. ";
            break;
        case LessonOutcome::Visible:
            text += "The oracle agrees: no face turns away, so nothing is lost. ";
            break;
    }
    if (lesson.test == CullTest::Oracle)
        return text + "From far away every face turns away from " + percent(lesson.oracleFraction) + " of all directions.";
    return text + "From far away, the test culls this cluster from " + percent(lesson.cullFraction) +
           " of all directions; every face turns away from " + percent(lesson.oracleFraction) +
           " of them, the most any test could reach with these faces.";
}

// "culled", "drawn (lost to the test)", ...
std::string outcomeWords(bool culled, LessonOutcome outcome) {
    if (culled) return outcome == LessonOutcome::FalseCull ? "culled (a false cull)" : "culled";
    return outcome == LessonOutcome::Visible ? "drawn: its faces turn to the eye" : "drawn, " + toString(outcome);
}

// How far the view vector `v` is from a cluster's axis: what the two clusters' cones make of one eye.
std::string angleToAxis(const CullExplanation& why, uint32_t cluster, const std::string& v) {
    return v + " is " + degrees(glm::degrees(std::acos(std::clamp(why.viewDotAxis, -1.0, 1.0)))) + " from cluster " +
           std::to_string(cluster) + "'s axis (its B = " + degrees(why.angleBDegrees) + ")";
}

// The rule the angles obey, for the tests whose rule is an angle to the axis.
std::string angleRule(CullTest test, bool orthographic, const std::string& v) {
    if (orthographic && test != CullTest::Octagon && !readsOwnRecord(test))
        return " The test culls a cluster when " + v + " lies within B of its axis.";
    if (test == CullTest::Apex) return " The test culls a cluster when v, to its apex, lies within B of its axis.";
    if (test == CullTest::Sphere)
        return " The test culls a cluster when v lies within B \u2212 asin(r/d) of its axis: the sphere takes its share off B.";
    return {};
}

std::string sideBySideStep(const Lesson& lesson) {
    const std::string here = lesson.eye.orthographic ? "this direction" : "this eye";
    if (!lesson.partner)
        return "From " + here + " " + testInWords(lesson.test) + (lesson.why.culled ? " culls" : " draws") +
               " every cluster alike: there is no cluster decided the other way to set beside cluster " + std::to_string(lesson.cluster) +
               ". Move the eye, or choose a culled (or a drawn) cluster, to see one of each side by side.";
    const LessonPartner& partner = *lesson.partner;
    // The culled one first, as the slide shows it on the left.
    const bool lessonFirst = lesson.why.culled;
    const uint32_t first = lessonFirst ? lesson.cluster : partner.cluster, second = lessonFirst ? partner.cluster : lesson.cluster;
    const CullExplanation& a = lessonFirst ? lesson.why : partner.why;
    const CullExplanation& b = lessonFirst ? partner.why : lesson.why;
    const LessonOutcome outcomeA = lessonFirst ? lesson.outcome : partner.outcome, outcomeB = lessonFirst ? partner.outcome : lesson.outcome;
    std::string text = "The same eye, two clusters " + number(glm::distance(lesson.sphere.center, partner.sphere.center)) +
                       " apart. Cluster " + std::to_string(first) + " is " + outcomeWords(a.culled, outcomeA) + ": " +
                       decisionLine(a, lesson.test, lesson.eye.orthographic) + ". Cluster " + std::to_string(second) + " is " +
                       outcomeWords(b.culled, outcomeB) + ": " + decisionLine(b, lesson.test, lesson.eye.orthographic) + ". ";
    const std::string v = lesson.eye.orthographic ? "d" : "v";
    if (a.cullable && b.cullable)
        return text + "What differs is not the eye but each cone: " + angleToAxis(a, first, v) + ", " + angleToAxis(b, second, v) + "." +
               angleRule(lesson.test, lesson.eye.orthographic, v);
    return text + "What differs is not the eye but the clusters: only one of them has a cone the test can use.";
}

// The nearest cluster (centre to centre) the test decides the other way from the lesson's eye, one
// with a cone before one without: the clearest contrast the same eye offers.
std::optional<LessonPartner> partnerOf(const CullingInput& input, const Lesson& lesson) {
    const ClusterBounds& bounds = input.bounds;
    const std::vector<uint8_t> culled = cullClusters(input, lesson.eye, lesson.test);
    long best = -1;
    bool bestCullable = false;
    double bestDistance = 0.0;
    for (uint32_t c = 0; c < bounds.count(); ++c) {
        if (c == lesson.cluster || (culled[c] != 0) == lesson.why.culled) continue;
        const bool cullable = bounds.cones[c].cullable;
        const double distance = glm::distance(bounds.spheres[c].center, lesson.sphere.center);
        if (best < 0 || (cullable && !bestCullable) || (cullable == bestCullable && distance < bestDistance)) {
            best = long(c);
            bestCullable = cullable;
            bestDistance = distance;
        }
    }
    if (best < 0) return std::nullopt;
    LessonPartner partner;
    partner.cluster = uint32_t(best);
    partner.why = explainCull(input, partner.cluster, lesson.eye, lesson.test);
    partner.outcome = outcomeOf(partner.why.culled, partner.why.frontFaces, partner.why.backFaces);
    partner.sphere = bounds.spheres[partner.cluster];
    partner.triangles = bounds.triangles[partner.cluster];
    return partner;
}

}  // namespace

Lesson makeLesson(const PreparedMesh& prepared, const ClusterSet& clusters, uint32_t cluster, const Eye& eye, CullTest test) {
    Lesson lesson;
    const ClusterBounds& bounds = clusters.bounds;
    lesson.cluster = cluster;
    lesson.test = test;
    lesson.coneMethod = bounds.coneMethod;
    lesson.eye = eye;
    // One float batch for the lesson's decision and its partner's (explainCull would make one each).
    const ClusterBatch batch = makeClusterBatch(bounds);
    CullingInput input = cullingInput(prepared, clusters);
    input.batch = &batch;
    lesson.why = explainCull(input, cluster, eye, test);
    const uint32_t* faces = bounds.faces.faces.data() + bounds.faces.starts[cluster];
    lesson.faces = bounds.faces.starts[cluster + 1] - bounds.faces.starts[cluster];
    lesson.triangles = bounds.triangles[cluster];
    lesson.vertices = bounds.vertexStarts[cluster + 1] - bounds.vertexStarts[cluster];
    lesson.sphere = bounds.spheres[cluster];
    for (size_t i = 0; i < lesson.faces; ++i) {
        const uint32_t face = faces[i];
        if (!prepared.faces.degenerate[face]) {
            lesson.normals.push_back(prepared.faces.normals[face]);
            lesson.centroids.push_back(prepared.faces.centroids[face]);
        }
        if (classifyFace(prepared.mesh(), prepared.world, prepared.faces, face, eye) == Facing::Back)
            lesson.backTriangles += prepared.mesh().faceSize(face) - 2;
    }
    lesson.averageCone = clusterCone(prepared.mesh(), prepared.world, prepared.faces, faces, lesson.faces, ConeMethod::Average);
    lesson.minimalCone = clusterCone(prepared.mesh(), prepared.world, prepared.faces, faces, lesson.faces, ConeMethod::Minimal);
    lesson.cullFraction = testCullFraction(clusters.cullMap, input, cluster, test);  // a record's own share for its tests
    lesson.oracleFraction = clusters.cullMap.oracleFraction[cluster];
    lesson.outcome = outcomeOf(lesson.why.culled, lesson.why.frontFaces, lesson.why.backFaces);
    lesson.partner = partnerOf(input, lesson);
    lesson.steps = {
        {"The cluster and its face normals", facesStep(lesson, prepared.name)},
        {"The normals on the Gauss sphere", gaussStep(lesson)},
        {"The cone that holds them", coneStep(lesson)},
        {"The bound: where the faces are", boundStep(lesson)},
        {"The eye, the view vector and the test", testStep(lesson)},
        {"The verdict, and what the oracle says", verdictStep(lesson)},
        {"Side by side: a culled and a drawn cluster, one eye", sideBySideStep(lesson)},
    };
    return lesson;
}

}  // namespace conescope
