// What a lesson holds (Lesson.h makes one): its cluster, eye and test, every number the test compared,
// the cluster's normals and bounds, a neighbour the test decides the other way from the same eye, and
// the seven steps' words.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Culling.h"
#include "Pipeline.h"

namespace conescope {

constexpr int kLessonStepCount = 7;
// The step that sets the cluster beside its partner (Lesson::partner).
constexpr int kSideBySideStep = 7;

// What happened to the cluster from the eye, in the statistics' terms.
enum class LessonOutcome {
    Culled,           // culled, and every face faces away
    LostToTest,       // every face faces away, yet the test drew it
    LostToPartition,  // drawn: it holds back faces and a face that faces the eye
    Visible,          // drawn: no face turns away
    FalseCull,        // culled although a face faces the eye (never, if the tests are right)
};

// The cluster nearest the lesson's (centre to centre) that the test decides the other way from the same
// eye, one with a cone when there is one: what the side-by-side step compares it with.
struct LessonPartner {
    uint32_t cluster = 0;
    CullExplanation why;  // explainCull from the lesson's eye with the lesson's test
    LessonOutcome outcome = LessonOutcome::Visible;
    Sphere sphere;
    size_t triangles = 0;
};

struct LessonStep {
    std::string title;
    std::string text;
};

struct Lesson {
    uint32_t cluster = 0;
    CullTest test = kDefaultTest;
    ConeMethod coneMethod = kDefaultCone;
    Eye eye;
    CullExplanation why;                 // explainCull: every number the test compared
    size_t faces = 0, triangles = 0, vertices = 0;
    size_t backTriangles = 0;            // triangles of the faces that face away (the oracle's)
    std::vector<glm::dvec3> normals;     // unit normals of the non-degenerate faces
    std::vector<glm::dvec3> centroids;   // where those faces are (the same order)
    Sphere sphere;                       // the cluster's bounding sphere
    ConeOfNormals averageCone;           // seed 000's cone (V1 = the mean normal)
    ConeOfNormals minimalCone;           // the narrowest cone that holds the normals
    double cullFraction = 0.0;           // share of far view directions the test culls from (CullMap)
    double oracleFraction = 0.0;         // share from which every face faces away
    LessonOutcome outcome = LessonOutcome::Visible;
    std::optional<LessonPartner> partner;  // none when the test decides every cluster alike from this eye
    std::vector<LessonStep> steps;       // kLessonStepCount of them

    double alphaDegrees() const { return why.halfAngleDegrees; }
    std::string verdict() const { return why.culled ? "culled" : "drawn"; }
};

}  // namespace conescope
