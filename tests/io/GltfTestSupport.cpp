#include "GltfTestSupport.h"

#include <cstring>
#include <fstream>

namespace conescope::testing {

std::filesystem::path gltfSamplesDir() { return std::filesystem::path(CONESCOPE_TESTDATA_DIR) / "gltf"; }

std::string gltfSample(const std::string& name) { return (gltfSamplesDir() / name).string(); }

nlohmann::json gltfSampleJson(const std::string& name) {
    std::ifstream input(gltfSample(name));
    return nlohmann::json::parse(input);
}

std::string writeGltf(const ScratchDirectory& scratch, const std::string& name, const nlohmann::json& document) {
    std::filesystem::copy_file(gltfSamplesDir() / "cube.bin", scratch.path() / "cube.bin",
                               std::filesystem::copy_options::overwrite_existing);
    return scratch.writeFile(name, document.dump(1));
}

std::string changedGltf(const ScratchDirectory& scratch, const std::string& sample, const std::string& name,
                        const std::function<void(nlohmann::json&)>& change) {
    nlohmann::json document = gltfSampleJson(sample);
    change(document);
    return writeGltf(scratch, name, document);
}

void putUint16(std::string& bytes, size_t offset, uint16_t value) {
    for (size_t k = 0; k < 2; ++k) bytes[offset + k] = char((value >> (8 * k)) & 0xff);
}

void putUint32(std::string& bytes, size_t offset, uint32_t value) {
    for (size_t k = 0; k < 4; ++k) bytes[offset + k] = char((value >> (8 * k)) & 0xff);
}

void putFloat(std::string& bytes, size_t offset, float value) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    putUint32(bytes, offset, bits);
}

}  // namespace conescope::testing
