// The cross-section's words, one caption per test: what each colour is, with the numbers the
// lesson's steps 3 to 6 write (alpha, B, asin(r/d), the corners that pass), so that picture and text
// say the same thing.
#include <algorithm>
#include <cmath>

#include "CrossSection.h"
#include "Lesson.h"
#include "LessonText.h"
#include "RecordTests.h"

namespace conescope {

using namespace lessontext;

namespace {

std::string angle(double radians) { return degrees(glm::degrees(radians)); }

std::string normalsSentence(const CrossSection& section) {
    if (section.normalAngles.empty()) return "The cluster has no face with an area, so no normal. ";
    double lowest = INFINITY, highest = 0.0;
    for (double a : section.normalAngles) {
        lowest = std::min(lowest, std::abs(a));
        highest = std::max(highest, std::abs(a));
    }
    const std::string spread = angle(lowest) == angle(highest) ? "all " + angle(highest) : angle(lowest) + " to " + angle(highest);
    // Without a cone there is no V1: the angles are to the axis the cone search tried.
    const std::string axis = section.cone ? "V1" : "the axis";
    std::string text = "Red: the " + count(section.normalAngles.size(), "face normal", "face normals") + " at " +
                       (section.normalAngles.size() == 1 ? "its" : "their") + " angle to " + axis + " (" + spread + "), turned about " +
                       axis + " into the page; the red bars outside the circle count them. ";
    if (!section.cone)
        text += "They point into more than a half-space: this cluster has no cone, so no V1 and no apex, and no cone test can cull "
                "it from any eye. ";
    else
        text += "Green: the cone that holds them, \u03b1 = " + angle(section.alpha) + " around V1. ";
    return text;
}

std::string roundBand(const Lesson& lesson, const CrossSection& section) {
    const CullExplanation& why = lesson.why;
    const std::string b = "B = 90\u00b0 \u2212 \u03b1 = " + angle(section.angleB);
    if (section.orthographic)
        return "Blue band: the view directions d within " + b + " of V1 (d\u00b7V1 > sin \u03b1); from a far eye every bound "
               "gives this test. ";
    switch (section.test) {
        case CullTest::Apex:
            return "Blue band: the view vectors v within " + b + " of V1 (v\u00b7V1 > sin \u03b1), from which the apex test culls. "
                   "v runs from the eye to the apex, the point behind every face; the small figure shows both in the page, and the "
                   "eyes that cull in blue. ";
        case CullTest::Sphere: {
            const std::string sizes = "(d = " + number(why.distance) + ", r = " + number(why.radius) + ")";
            if (why.eyeInsideSphere) return "The eye is inside the bounding sphere " + sizes + ": from inside no v culls. ";
            if (!section.hasRegion())
                return "The sphere " + sizes + " spreads the view vectors by asin(r/d) = " + angle(section.narrowing) +
                       ", more than " + b + ": no v culls from this distance. ";
            return "Blue band: the view vectors v to the sphere's centre within B \u2212 asin(r/d) = " + angle(section.angleB) +
                   " \u2212 " + angle(section.narrowing) + " = " + angle(section.regionHalfAngle) +
                   " of V1, from which the sphere test culls. The small figure shows why: the sphere " + sizes +
                   " spreads the view vectors to its points by asin(r/d) = " + angle(section.narrowing) + " around v. ";
        }
        case CullTest::MeshoptSphere:
            return "Blue band: the view vectors v to the sphere's centre within acos(sin \u03b1 + r/d) = " +
                   angle(section.regionHalfAngle) + " of V1 (d = " + number(why.distance) + ", r = " + number(why.radius) +
                   "): r/d takes " + angle(section.narrowing) + " off " + b + ". ";
        case CullTest::Aabb:
        case CullTest::AabbFast:
        case CullTest::Vertices: {
            const bool box = section.test != CullTest::Vertices;
            const size_t total = section.pointAngles.size();
            size_t inside = 0;
            for (double a : section.pointAngles) inside += section.inRegion(a);
            const std::string points = box ? "the box's 8 corners" : "the cluster's " + count(total, "vertex", "vertices");
            std::string text = "Blue band: the view vectors within " + b + " of V1. Dark red: the view vectors from the eye to " +
                               points + "; the test culls when every one lies in the band. " +
                               (inside == total ? "All " + std::to_string(total) + " do"
                                                : std::to_string(inside) + " of " + std::to_string(total) + " do (orange: those that do not)");
            return text + ". ";
        }
        default: return "";
    }
}

std::string regionSentence(const Lesson& lesson, const CrossSection& section) {
    const std::string& v = section.viewName;
    switch (section.rule) {
        case CullRegionRule::None: return "";
        case CullRegionRule::Round: return roundBand(lesson, section);
        case CullRegionRule::Octagon:
            if (!section.hasRegion()) return "No " + v + " in this page sees every edge of the octagon's cone from behind. ";
            return "Blue band: the view vectors " + v + " that see all eight edges g of the octagon's cone from behind (g\u00b7" + v +
                   " > 0 for each), " + angle(section.cullRegion[0][0]) + " to " + angle(section.cullRegion[0][1]) +
                   " from V1: it ends at the planes g\u00b7" + v + " = 0 of the two edges drawn in gold (each g projected into the "
                   "page). Dashed: the round cone's B = " + angle(section.angleB) + ". ";
        case CullRegionRule::Asked: {
            const std::string where = section.orthographic ? "asked for every direction d in the page"
                                                           : "asked from eyes on the circle through the eye around the cluster's centre, d = " +
                                                                 number(lesson.why.distance) + " away";
            std::string spans;
            for (const AngleRange& range : section.cullRegion)
                spans += (spans.empty() ? " (" : ", ") + angle(range[0]) + " to " + angle(range[1]);
            if (!spans.empty()) spans += " from V1)";
            if (lesson.test == CullTest::Oracle)
                return "Blue band: the directions " + v + " to the centre from which every face turns away" + spans + ", " + where + ". ";
            return "Blue band: where the record's own rule culls" + spans + ", " + where + "; its rule: " + ownRecordRule(lesson.test) +
                   ". The green cone is the one the other tests use; the record stores its own. ";
        }
    }
    return "";
}

std::string verdictSentence(const CrossSection& section) {
    if (section.rule == CullRegionRule::None) return "The test draws the cluster.";
    const std::string named = section.pointAngles.empty() ? section.viewName : "The lowest, " + section.viewName + ",";
    const std::string where = named + " is " + angle(std::abs(section.viewAngle)) + " from V1: ";
    if (!section.hasRegion()) return where + "the test fails.";
    return where + (section.culls ? "inside the band, so the test holds." : "outside the band, so the test fails.");
}

}  // namespace

std::string crossSectionCaption(const Lesson& lesson, const CrossSection& section) {
    return normalsSentence(section) + regionSentence(lesson, section) + verdictSentence(section);
}

}  // namespace conescope
