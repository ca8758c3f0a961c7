// How a lesson writes numbers (Lesson.cpp, LessonTestSteps.cpp): few digits a newcomer can read,
// but never so few that a comparison reads wrong (0.4120 > 0.4120).
#pragma once

#include <string>
#include <utility>

#include <glm/glm.hpp>

namespace conescope::lessontext {

// printf into a std::string.
std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

std::string number(double value);              // 4 significant digits: 0.7685, 123.5, 1.25e-05
std::string dot(double value);                 // a dot product or cosine: 4 decimals
std::string degrees(double value);             // 23.4°
std::string percent(double share);             // 0.301 -> 30.1%
std::string vector3(const glm::dvec3& value);  // (0.12, −0.98, 0.15)
// A small positive amount (a margin): enough decimals to show its first two digits.
std::string amount(double value);
// `a` and `b` with as many decimals (4 to 12) as it takes to tell them apart when they differ.
std::pair<std::string, std::string> compared(double a, double b);
// "a > b" when a > b, else "a ≤ b", both written by compared().
std::string inequality(double a, double b);
// "1 face", "3 faces".
std::string count(size_t n, const char* one, const char* many);

}  // namespace conescope::lessontext
