// The steps of a lesson that differ from test to test (Lesson.cpp writes the others): the bound a test
// uses for where the faces are, its inequality with the cluster's numbers filled in, and the cluster
// beside its partner from the same eye.
#pragma once

#include <string>

#include "LessonData.h"

namespace conescope {

std::string boundStep(const Lesson& lesson);
std::string testStep(const Lesson& lesson);

// One decision in a line, the comparison the test made ("v·V1 = 0.83 > sin α = 0.41"), for the
// side-by-side step.
std::string decisionLine(const CullExplanation& why, CullTest test, bool orthographic);

// Why a cluster without a usable cone is drawn from every eye: it has none (its normals span more than
// a half-space), or the method's cone opens past 90 degrees while a narrower one exists.
std::string noConeSentence(const Lesson& lesson);

}  // namespace conescope
