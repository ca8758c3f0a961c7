// A lesson as the explanation export writes it: {"cluster", "alpha_degrees", "margin", "verdict",
// "test", "steps": [{"title", "text"}, ...]} plus the outcome, the cone and the eye, all from the one
// Lesson the window's lesson dock shows (core/Lesson.h). A margin that does not exist (the oracle, a
// cluster without a cone) is null.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/Lesson.h"

namespace conescope {

nlohmann::json lessonToJson(const Lesson& lesson);

// Throws std::runtime_error naming the path when it cannot be written.
void writeLessonJson(const Lesson& lesson, const std::string& path);

}  // namespace conescope
