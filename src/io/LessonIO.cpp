#include "io/LessonIO.h"

#include "io/JsonWriter.h"

#include <cmath>

namespace conescope {

namespace {

nlohmann::json numberOrNull(double value) { return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr); }

nlohmann::json vectorJson(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

}  // namespace

nlohmann::json lessonToJson(const Lesson& lesson) {
    nlohmann::json steps = nlohmann::json::array();
    for (const LessonStep& step : lesson.steps) steps.push_back({{"title", step.title}, {"text", step.text}});
    nlohmann::json eye = {{"orthographic", lesson.eye.orthographic}};
    if (lesson.eye.orthographic) eye["direction"] = vectorJson(lesson.eye.direction);
    else eye["position"] = vectorJson(lesson.eye.position);
    return {{"cluster", lesson.cluster},
            {"alpha_degrees", numberOrNull(lesson.alphaDegrees())},
            {"margin", numberOrNull(lesson.why.margin)},
            {"verdict", lesson.verdict()},
            {"outcome", toString(lesson.outcome)},
            {"test", toString(lesson.test)},
            {"cone", toString(lesson.coneMethod)},
            {"cullable", lesson.why.cullable},
            {"eye", eye},
            {"steps", steps}};
}

void writeLessonJson(const Lesson& lesson, const std::string& path) { writeJsonFile(lessonToJson(lesson), path); }

}  // namespace conescope
