#include "LessonText.h"

#include <cmath>
#include <cstdarg>
#include <cstdio>

namespace conescope::lessontext {

std::string format(const char* pattern, ...) {
    char buffer[1024];
    va_list arguments;
    va_start(arguments, pattern);
    std::vsnprintf(buffer, sizeof buffer, pattern, arguments);
    va_end(arguments);
    return buffer;
}

namespace {

// A minus sign, not a hyphen, in front of negative numbers.
std::string withMinus(std::string text) {
    if (!text.empty() && text[0] == '-') text.replace(0, 1, "\u2212");
    return text;
}

std::string fixed(double value, int decimals) { return withMinus(format("%.*f", decimals, value)); }

}  // namespace

std::string number(double value) {
    if (value == 0.0) return "0";
    return withMinus(format("%.4g", value));
}

std::string dot(double value) { return fixed(value, 4); }

std::string degrees(double value) { return fixed(value, 1) + "\u00b0"; }

std::string percent(double share) { return fixed(100.0 * share, 1) + "%"; }

std::string vector3(const glm::dvec3& value) {
    return "(" + fixed(value.x, 3) + ", " + fixed(value.y, 3) + ", " + fixed(value.z, 3) + ")";
}

std::string amount(double value) {
    const double size = std::abs(value);
    if (!(size > 0.0) || !std::isfinite(size)) return fixed(value, 4);
    const int decimals = std::max(4, std::min(12, 1 - int(std::floor(std::log10(size)))));
    return fixed(value, decimals);
}

std::pair<std::string, std::string> compared(double a, double b) {
    for (int decimals = 4; decimals <= 12; ++decimals) {
        std::pair<std::string, std::string> texts{fixed(a, decimals), fixed(b, decimals)};
        if (a == b || texts.first != texts.second) return texts;
    }
    return {fixed(a, 12), fixed(b, 12)};
}

std::string inequality(double a, double b) {
    const auto [left, right] = compared(a, b);
    return left + (a > b ? " > " : " \u2264 ") + right;
}

std::string count(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace conescope::lessontext
