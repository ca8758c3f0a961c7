// Typed reads from a glTF JSON document that fail with a MeshReadError naming the file and the
// member ("path: nodes[3].mesh: ..."), so a wrong type or index is never read as something else
// (internal to conescope_io).
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

namespace conescope {

struct GltfJson {
    const std::string& path;
    const nlohmann::json& root;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const;
    // The top-level array `name` ("nodes", "accessors", ...); an empty one when absent.
    const nlohmann::json& array(const char* name) const;
    // object[key], or nullptr when absent; fails when `object` is not a JSON object.
    const nlohmann::json* member(const nlohmann::json& object, const char* key, const std::string& where) const;
    // A non-negative integer (JSON 3, not 3.0 or "3").
    uint64_t count(const nlohmann::json& value, const std::string& where) const;
    // An index into the top-level array `arrayName`.
    size_t index(const nlohmann::json& value, const char* arrayName, const std::string& where) const;
    // A finite number.
    double number(const nlohmann::json& value, const std::string& where) const;
    // object[key] as a count, or `fallback` when absent.
    uint64_t countOr(const nlohmann::json& object, const char* key, uint64_t fallback, const std::string& where) const;
};

// "nodes[3]"
std::string elementName(const char* arrayName, size_t index);

}  // namespace conescope
