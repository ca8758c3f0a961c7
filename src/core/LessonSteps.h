// The two steps of a lesson that differ from test to test (Lesson.cpp writes the others): the bound
// a test uses for where the faces are, and its inequality with the cluster's numbers filled in.
#pragma once

#include <string>

#include "LessonData.h"

namespace conescope {

std::string boundStep(const Lesson& lesson);
std::string testStep(const Lesson& lesson);

}  // namespace conescope
