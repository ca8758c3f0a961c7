#include "io/GltfJson.h"

#include <cmath>

#include "io/FileChecks.h"
#include "io/MeshReader.h"

namespace conescope {

using nlohmann::json;

namespace {

std::string describe(const json& value) {
    return quotedForMessage(value.dump(-1, ' ', false, json::error_handler_t::replace), 40);
}

}  // namespace

std::string elementName(const char* arrayName, size_t index) {
    return std::string(arrayName) + "[" + std::to_string(index) + "]";
}

void GltfJson::fail(const std::string& where, const std::string& what) const {
    throw MeshReadError(path + ": " + (where.empty() ? "" : where + ": ") + what);
}

const json& GltfJson::array(const char* name) const {
    static const json empty = json::array();
    const json* value = member(root, name, "");
    if (!value) return empty;
    if (!value->is_array()) fail(name, "expected an array, found " + describe(*value));
    return *value;
}

const json* GltfJson::member(const json& object, const char* key, const std::string& where) const {
    if (!object.is_object()) fail(where, "expected a JSON object, found " + describe(object));
    auto found = object.find(key);
    return found == object.end() ? nullptr : &*found;
}

uint64_t GltfJson::count(const json& value, const std::string& where) const {
    if (!value.is_number_unsigned()) fail(where, "expected a non-negative integer, found " + describe(value));
    return value.get<uint64_t>();
}

size_t GltfJson::index(const json& value, const char* arrayName, const std::string& where) const {
    const uint64_t i = count(value, where);
    const size_t size = array(arrayName).size();
    if (i >= size)
        fail(where, std::to_string(i) + " is out of range: the file has " + std::to_string(size) + " " + arrayName);
    return size_t(i);
}

double GltfJson::number(const json& value, const std::string& where) const {
    if (!value.is_number() || !std::isfinite(value.get<double>()))
        fail(where, "expected a finite number, found " + describe(value));
    return value.get<double>();
}

uint64_t GltfJson::countOr(const json& object, const char* key, uint64_t fallback, const std::string& where) const {
    const json* value = member(object, key, where);
    return value ? count(*value, where + "." + key) : fallback;
}

}  // namespace conescope
