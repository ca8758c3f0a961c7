// Tokenising helpers shared by the text parsers and format checks (internal to conescope_io).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>

namespace conescope::text {

inline bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Fills `words` (cleared first) with the line's words: a parser reading millions of lines keeps
// one vector instead of allocating one per line.
inline void splitWords(std::string_view line, std::vector<std::string_view>& words) {
    words.clear();
    size_t position = 0;
    while (position < line.size()) {
        while (position < line.size() && isBlank(line[position])) ++position;
        size_t start = position;
        while (position < line.size() && !isBlank(line[position])) ++position;
        if (position > start) words.push_back(line.substr(start, position - start));
    }
}

inline std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    splitWords(line, words);
    return words;
}

// The whole word as an integer of type Integer (a leading '+' allowed), or nothing when it is not
// one or the type cannot hold it.
template <typename Integer = int64_t>
std::optional<Integer> parseInteger(std::string_view word) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    Integer value = 0;
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size()) return std::nullopt;
    return value;
}

// The whole word as a number (a leading '+' allowed), or nothing.
inline std::optional<double> parseNumber(std::string_view word) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    double value = 0.0;
    auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    if (word.empty() || error != std::errc() || end != word.data() + word.size()) return std::nullopt;
    return value;
}

inline bool isNumber(std::string_view word) { return parseNumber(word).has_value(); }

// A finite number that a float can hold: what a coordinate must be. VTK's text readers turn
// anything else (nan, inf, 1e39, "abc") into 0 or FLT_MAX without a word, so the checks reject it first.
inline std::optional<float> parseFiniteFloat(std::string_view word) {
    std::optional<double> value = parseNumber(word);
    if (!value || !std::isfinite(*value) || std::abs(*value) > double(std::numeric_limits<float>::max())) return std::nullopt;
    return float(*value);
}

inline bool isFiniteFloat(std::string_view word) { return parseFiniteFloat(word).has_value(); }

// Splits text into lines one at a time, remembering 1-based line numbers.
class LineCursor {
public:
    LineCursor(std::string_view text, size_t offset, size_t linesBefore)
        : text_(text), position_(offset), lineNumber_(linesBefore) {}
    bool atEnd() const { return position_ >= text_.size(); }
    std::string_view next() {
        size_t end = text_.find('\n', position_);
        if (end == std::string_view::npos) end = text_.size();
        std::string_view line = text_.substr(position_, end - position_);
        lastLineHadNewline_ = end < text_.size();
        position_ = lastLineHadNewline_ ? end + 1 : end;
        ++lineNumber_;
        return line;
    }
    // False when the line just returned ran to the end of the text without a '\n'.
    bool lastLineHadNewline() const { return lastLineHadNewline_; }
    size_t lineNumber() const { return lineNumber_; }
    size_t position() const { return position_; }

private:
    std::string_view text_;
    size_t position_;
    size_t lineNumber_;
    bool lastLineHadNewline_ = true;
};

}  // namespace conescope::text
