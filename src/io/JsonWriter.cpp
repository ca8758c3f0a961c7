#include "io/JsonWriter.h"

#include <fstream>
#include <stdexcept>

namespace conescope {

namespace {

constexpr unsigned kIndent = 2;

bool plainKey(std::string_view name) {
    if (name.empty()) return false;
    for (char c : name)
        if (!((c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_')) return false;
    return true;
}

}  // namespace

JsonWriter::JsonWriter(std::string& out)
    : out_(out), serializer_(nlohmann::detail::output_adapter<char>(out), ' ') {}

// A member or element starts on its own line, after a comma unless it is the first.
void JsonWriter::newItem() {
    Level& level = levels_.back();
    out_ += level.empty ? "\n" : ",\n";
    level.empty = false;
    out_.append(kIndent * levels_.size(), ' ');
}

// In an array a value is an element; in an object key() has already started the member.
void JsonWriter::beforeValue() {
    if (levels_.empty()) return;
    Level& level = levels_.back();
    if (!level.object) return newItem();
    if (!level.keyed) throw std::logic_error("JsonWriter: a value in an object without its key");
    level.keyed = false;
}

void JsonWriter::beginObject() {
    beforeValue();
    out_ += '{';
    levels_.push_back(Level{true, true, false, {}});
}

void JsonWriter::beginArray() {
    beforeValue();
    out_ += '[';
    levels_.push_back(Level{false, true, false, {}});
}

void JsonWriter::end(char close) {
    if (levels_.back().keyed) throw std::logic_error("JsonWriter: a key without its value");
    const bool empty = levels_.back().empty;
    levels_.pop_back();
    if (!empty) {
        out_ += '\n';
        out_.append(kIndent * levels_.size(), ' ');
    }
    out_ += close;
}

void JsonWriter::endObject() {
    if (levels_.empty() || !levels_.back().object) throw std::logic_error("JsonWriter: no object to end");
    end('}');
}

void JsonWriter::endArray() {
    if (levels_.empty() || levels_.back().object) throw std::logic_error("JsonWriter: no array to end");
    end(']');
}

void JsonWriter::key(std::string_view name) {
    if (levels_.empty() || !levels_.back().object) throw std::logic_error("JsonWriter: a key outside an object");
    Level& level = levels_.back();
    if (!plainKey(name)) throw std::logic_error("JsonWriter: key '" + std::string(name) + "' is not snake_case");
    if (level.keyed) throw std::logic_error("JsonWriter: a key without its value");
    if (!level.empty && !(level.lastKey < name))
        throw std::logic_error("JsonWriter: key '" + std::string(name) + "' after '" + std::string(level.lastKey) + "'");
    newItem();
    level.lastKey = name;
    level.keyed = true;
    out_ += '"';
    out_ += name;
    out_ += "\": ";
}

void JsonWriter::value(const nlohmann::json& any) {
    beforeValue();
    serializer_.dump(any, true, false, kIndent, kIndent * unsigned(levels_.size()));
}

void writeJsonFile(const nlohmann::json& document, const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw std::runtime_error(path + ": cannot open for writing");
    out << document.dump(2) << '\n';
    out.close();
    if (!out) throw std::runtime_error(path + ": write failed");
}

}  // namespace conescope
