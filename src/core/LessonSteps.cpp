#include "LessonSteps.h"

#include <algorithm>
#include <cmath>

#include "LessonText.h"
#include "RecordTests.h"

namespace conescope {

using namespace lessontext;

namespace {

const std::string manyDirections =
    "The eye sees each face from a slightly different direction, so one view vector can stand for all of them "
    "only with some care. ";

const std::string apexArgument =
    " An eye that sees the apex from behind the cone sees every face from behind, so one view vector, from the eye "
    "to the apex, stands for all of them.";

std::string apexSentence(const Lesson& lesson) {
    if (!lesson.why.cullable)
        return noConeSentence(lesson) + " Without a cone there is no apex either: the test has no point to look at.";
    const double behind = glm::distance(lesson.why.apex, lesson.sphere.center);
    // The apex is the centre moved back along -V1 until it is behind every face plane; a centre that
    // already is (a patch hollow towards V1) stays where it is.
    if (!(behind > 1e-9 * std::max(lesson.sphere.radius, 1e-300)))
        return "This test uses the apex, a point behind the plane of every one of the cluster's faces, on the cone's "
               "axis. For this cluster the centre of its bounding sphere already lies behind every face plane, so the "
               "apex is that centre itself." + apexArgument;
    return "This test uses the apex, a point " + number(behind) +
           " from the cluster's centre along \u2212V1, behind the plane of every one of its faces." + apexArgument;
}

std::string holdsOrFails(double margin) { return margin > 0.0 ? "so the test holds" : "so the test fails"; }

// The tests that read a record of their own (RecordTests.h) are told by their rule, not drawn.
std::string recordBound(const Lesson& lesson) {
    const std::string kept = reproducesEngineRecord(lesson.test)
                                 ? " It is scored as the engine ships it, not made safe: where it culls a cluster with a "
                                   "face the eye can see, that is the record's false cull, an engine bug."
                                 : " It is kept conservative, like the float octagon it is packed from.";
    return "This test reads a record of its own, " + std::to_string(recordBytes(lesson.test)) +
           " bytes a cluster, as an engine stores it; its bound is inside the record and is not drawn here." + kept;
}

std::string recordTest(const Lesson& lesson) {
    const double margin = lesson.why.margin;
    return "The record's rule: " + ownRecordRule(lesson.test) + ". From this eye it " +
           (margin > 0.0 ? "passes its threshold by " + amount(margin) : "falls short of its threshold by " + amount(-margin)) +
           " (in units of a unit view vector's dot product), " + holdsOrFails(margin) + ".";
}

std::string eyeSentence(const Lesson& lesson) {
    if (lesson.eye.orthographic)
        return "The eye is infinitely far away, looking along d = " + vector3(lesson.eye.direction) +
               ": every view vector is d. ";
    return "The eye is at e = " + vector3(lesson.eye.position) + ", " + number(lesson.why.distance) +
           " from the cluster's centre. ";
}

// v.V1 > sin(alpha) for one view vector `v` (named `name`): the apex test's form, and every round
// test's from a far eye.
std::string roundCone(const Lesson& lesson, const std::string& name) {
    const CullExplanation& why = lesson.why;
    const double angle = glm::degrees(std::acos(std::clamp(why.viewDotAxis, -1.0, 1.0)));
    const auto [value, threshold] = compared(why.viewDotAxis, why.threshold);
    return "The test culls when " + name + "\u00b7V1 > sin \u03b1, that is when " + name + " is within B = " +
           degrees(why.angleBDegrees) + " of V1. Here " + name + "\u00b7V1 = " + value + " and sin \u03b1 = " + threshold +
           ": " + inequality(why.viewDotAxis, why.threshold) + ", " + holdsOrFails(why.margin) + " (" + name + " is " +
           degrees(angle) + " from V1).";
}

// Every point or corner p: v = (p - e)/|p - e| must have v.V1 > sin(alpha).
std::string eachPoint(const Lesson& lesson, const std::string& points, size_t total) {
    const CullExplanation& why = lesson.why;
    const double lowest = why.margin + why.threshold;
    return "For each " + points + " p, v = (p \u2212 e)/|p \u2212 e|. The test culls when v\u00b7V1 > sin \u03b1 = " +
           dot(why.threshold) + " at all " + std::to_string(total) + " of them. Here " + std::to_string(why.pointsBack) +
           " of " + std::to_string(total) + " pass; the lowest has v\u00b7V1 = " + inequality(lowest, why.threshold) + ", " +
           holdsOrFails(why.margin) + ".";
}

std::string octagonTest(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    const double tightest = why.margin + why.threshold;
    const std::string v = lesson.eye.orthographic ? "d" : "v";
    return std::string(lesson.eye.orthographic ? "" : "The view vector v runs from the eye to the apex. ") +
           "The octagon test culls when g\u00b7" + v + " > 0 for each of the eight edges g of its cone of normals: then " +
           v + " sees every edge, and so every normal, from behind. Here " + std::to_string(why.edgesBack) +
           " of 8 edges pass; the smallest is g\u00b7" + v + " = " + compared(tightest, why.threshold).first +
           (why.margin > 0.0 ? " > 0" : " \u2264 0") + ", " + holdsOrFails(why.margin) + ".";
}

std::string sphereTest(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    if (why.eyeInsideSphere)
        return "The eye is inside the bounding sphere (d = " + number(why.distance) + ", r = " + number(why.radius) +
               "): from inside, a face may lie in any direction, so the test cannot cull.";
    const std::string spread = degrees(why.sphereAngleDegrees);
    if (!(why.angleBDegrees - why.sphereAngleDegrees > 0.0))
        return "From here the sphere spreads the view vectors by asin(r/d) = " + spread + ", more than the B = " +
               degrees(why.angleBDegrees) + " the cone leaves: the test cannot cull from this distance.";
    const auto [value, threshold] = compared(why.viewDotAxis, why.threshold);
    return "v runs from the eye to the sphere's centre, d = " + number(why.distance) + " away, so asin(r/d) = asin(" +
           number(why.radius) + "/" + number(why.distance) + ") = " + spread + ". The test culls when v\u00b7V1 > cos(B \u2212 asin(r/d)) = cos(" +
           degrees(why.angleBDegrees) + " \u2212 " + spread + ") = " + threshold + ". Here v\u00b7V1 = " + value + ": " +
           inequality(why.viewDotAxis, why.threshold) + ", " + holdsOrFails(why.margin) + ".";
}

std::string meshoptSphereTest(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    const double share = why.distance > 0.0 ? why.radius / why.distance : 0.0;
    const double threshold = why.threshold + share;
    return "v runs from the eye to the sphere's centre, d = " + number(why.distance) +
           " away. The test culls when v\u00b7V1 > sin \u03b1 + r/d = " + dot(why.threshold) + " + " + dot(share) + " = " +
           compared(why.viewDotAxis, threshold).second + ". Here v\u00b7V1 = " + inequality(why.viewDotAxis, threshold) + ", " +
           holdsOrFails(why.margin) + ".";
}

std::string boundWords(const Lesson& lesson) {
    switch (lesson.test) {
        case CullTest::Oracle:
            return "The oracle needs no bound: it checks every face at each of its corners q, n\u00b7(e \u2212 q) < 0. That is "
                   "exact, but costs a check per face; the cone tests cost one per cluster.";
        case CullTest::Apex: return manyDirections + apexSentence(lesson);
        case CullTest::Octagon: {
            const double round = lesson.why.cullable ? (1.0 - std::sin(glm::radians(lesson.why.halfAngleDegrees))) / 2.0 : 0.0;
            return manyDirections + apexSentence(lesson) +
                   " It also wraps the normals more tightly than the round cone, in an eight-sided cone (yellow on the "
                   "Gauss map): from far away it culls from " + percent(lesson.cullFraction) + " of all directions, the "
                   "round cone from " + percent(round) + ".";
        }
        case CullTest::Sphere:
            return manyDirections + "This test uses the smallest sphere around the cluster: centre c = " +
                   vector3(lesson.sphere.center) + ", radius r = " + number(lesson.sphere.radius) +
                   ". From an eye at distance d from c, every point of the sphere lies within asin(r/d) of the direction "
                   "to c, so the test takes asin(r/d) off the angle B.";
        case CullTest::MeshoptSphere:
            return manyDirections + "meshoptimizer's sphere test uses the sphere around the cluster (centre c = " +
                   vector3(lesson.sphere.center) + ", radius r = " + number(lesson.sphere.radius) +
                   ") and asks for r/d more room, d being the eye's distance from c.";
        case CullTest::Aabb:
        case CullTest::AabbFast:
            return manyDirections + "This test uses the cluster's bounding box, from " + vector3(lesson.why.corners[0]) +
                   " to " + vector3(lesson.why.corners[7]) +
                   ", and checks the view vector to each of its 8 corners. The view vectors that see the cone from behind "
                   "form a cone of their own; when all 8 corners lie in it, so does every point of the box." +
                   (lesson.test == CullTest::AabbFast ? " This form compares squares instead of normalising each view "
                                                        "vector, as the article's optimised version does."
                                                      : "");
        case CullTest::MeshoptApexF32:
        case CullTest::MeshoptSphereS8:
        case CullTest::CadsceneBoxS8:
        case CullTest::OctagonCompact: return recordBound(lesson);
        case CullTest::Vertices:
            return manyDirections + "This test checks the view vector to each of the cluster's " +
                   count(lesson.vertices, "vertex", "vertices") +
                   ": every face lies between its corners, so when all of them are seen from behind the cone, so is every "
                   "point of every face.";
    }
    return {};
}

}  // namespace

std::string noConeSentence(const Lesson& lesson) {
    if (!lesson.minimalCone.cullable)
        return "This cluster has no cone: its normals span more than a half-space, so no cone narrower than a "
               "half-sphere holds them and no cone test can cull it, from any eye.";
    return "The " + toString(lesson.coneMethod) + " cone of this cluster opens wider than 90\u00b0, so the test has no "
           "cone to use and draws the cluster from every eye; the narrowest cone would need \u03b1 = " +
           degrees(glm::degrees(lesson.minimalCone.halfAngle())) + ".";
}

std::string boundStep(const Lesson& lesson) {
    if (lesson.why.cullable || readsOwnRecord(lesson.test) || lesson.test == CullTest::Oracle) return boundWords(lesson);
    // Without a cone: no apex at all; the sphere, box and vertices exist, but nothing compares them.
    if (lesson.test == CullTest::Apex || lesson.test == CullTest::Octagon) return manyDirections + apexSentence(lesson);
    return boundWords(lesson) + " " + noConeSentence(lesson) + " The bound is drawn, but the test never gets to use it.";
}

std::string decisionLine(const CullExplanation& why, CullTest test, bool orthographic) {
    if (test == CullTest::Oracle)
        return count(why.backFaces, "face turns", "faces turn") + " away, " + count(why.frontFaces, "does", "do") + " not";
    if (readsOwnRecord(test))
        return why.margin > 0.0 ? "its record passes its threshold by " + amount(why.margin)
                                : "its record falls short of its threshold by " + amount(-why.margin);
    if (!why.cullable) return "it has no cone the test can use, so the test cannot cull it";
    const std::string v = orthographic ? "d" : "v";
    if (test == CullTest::Octagon)
        return std::to_string(why.edgesBack) + " of the 8 edges g of its cone have g\u00b7" + v + " > 0";
    if (!orthographic && (test == CullTest::Aabb || test == CullTest::AabbFast || test == CullTest::Vertices))
        return std::to_string(why.pointsBack) + " of its " + std::to_string(why.pointsTested) + (test == CullTest::Vertices ? " vertices" : " corners") +
               " have v\u00b7V1 > sin \u03b1 = " + dot(why.threshold);
    if (!orthographic && test == CullTest::Sphere && why.eyeInsideSphere) return "the eye is inside its bounding sphere";
    const double threshold = !orthographic && test == CullTest::MeshoptSphere && why.distance > 0.0 ? why.threshold + why.radius / why.distance
                                                                                                    : why.threshold;
    const std::string bound = orthographic || test == CullTest::Apex ? "sin \u03b1"
                              : test == CullTest::Sphere             ? "cos(B \u2212 asin(r/d))"
                                                                     : "sin \u03b1 + r/d";
    return v + "\u00b7V1 = " + compared(why.viewDotAxis, threshold).first + (why.viewDotAxis > threshold ? " > " : " \u2264 ") + bound +
           " = " + compared(why.viewDotAxis, threshold).second;
}

std::string testStep(const Lesson& lesson) {
    const CullExplanation& why = lesson.why;
    const std::string eye = eyeSentence(lesson);
    if (lesson.test == CullTest::Oracle)
        return eye + "The oracle checks n\u00b7(e \u2212 q) < 0 at every corner q of every face (for a far eye, n\u00b7d > 0): " +
               count(why.backFaces, "face passes", "faces pass") + ", " + count(why.frontFaces, "does", "do") +
               " not. It culls only when every face passes.";
    if (readsOwnRecord(lesson.test)) return eye + recordTest(lesson);
    if (!why.cullable) return eye + "Without a cone the test has nothing to compare: the cluster is drawn from every eye.";
    if (lesson.test == CullTest::Octagon) return eye + octagonTest(lesson);
    if (lesson.eye.orthographic) return eye + roundCone(lesson, "d");
    switch (lesson.test) {
        case CullTest::Apex:
            return eye + "The view vector v runs from the eye to the apex: v = " + vector3(why.view) + ", of length 1. " +
                   roundCone(lesson, "v");
        case CullTest::Sphere: return eye + sphereTest(lesson);
        case CullTest::MeshoptSphere: return eye + meshoptSphereTest(lesson);
        case CullTest::Aabb:
        case CullTest::AabbFast: return eye + eachPoint(lesson, "corner", 8);
        case CullTest::Vertices: return eye + eachPoint(lesson, "vertex", why.pointsTested);
        case CullTest::Oracle:
        case CullTest::Octagon:
        case CullTest::MeshoptApexF32:
        case CullTest::MeshoptSphereS8:
        case CullTest::CadsceneBoxS8:
        case CullTest::OctagonCompact: break;  // answered above
    }
    return eye;
}

}  // namespace conescope
