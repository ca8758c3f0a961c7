// Helpers for the glTF reader tests: the samples of tests/data/gltf (make_gltf_samples.py) and
// copies of them changed on purpose, written into a scratch directory.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include <nlohmann/json.hpp>

#include "IoTestSupport.h"

namespace conescope::testing {

std::filesystem::path gltfSamplesDir();  // tests/data/gltf
std::string gltfSample(const std::string& name);

// The sample's JSON document (a .gltf's text).
nlohmann::json gltfSampleJson(const std::string& name);

// Writes `document` as `name` into the scratch directory, with a copy of cube.bin beside it (the
// buffer of cube.gltf), and returns the path.
std::string writeGltf(const ScratchDirectory& scratch, const std::string& name, const nlohmann::json& document);

// The sample, changed by `change`, written as `name` (with cube.bin beside it).
std::string changedGltf(const ScratchDirectory& scratch, const std::string& sample, const std::string& name,
                        const std::function<void(nlohmann::json&)>& change);

// Little-endian values written over bytes[offset ...], as glTF stores them.
void putFloat(std::string& bytes, size_t offset, float value);
void putUint16(std::string& bytes, size_t offset, uint16_t value);
void putUint32(std::string& bytes, size_t offset, uint32_t value);

}  // namespace conescope::testing
