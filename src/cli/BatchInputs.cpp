#include "cli/BatchInputs.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <stdexcept>

#include <nlohmann/json.hpp>

#define XXH_INLINE_ALL
#include <xxhash.h>

#include "cli/OutputFiles.h"
#include "io/MeshReader.h"

namespace conescope::cli {

namespace fs = std::filesystem;

namespace {

bool hidden(const fs::path& path) { return path.filename().string().rfind('.', 0) == 0; }

BatchMesh batchMesh(const fs::path& path) {
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
    if (error) canonical = fs::absolute(path);
    BatchMesh mesh{path.string(), canonical.string(), batchJsonName(canonical.string()), 0};
    const uintmax_t bytes = fs::file_size(canonical, error);
    mesh.bytes = error ? 0 : bytes;
    return mesh;
}

void addFolder(const fs::path& folder, std::vector<BatchMesh>& meshes) {
    std::error_code error;
    fs::recursive_directory_iterator entry(folder, fs::directory_options::skip_permission_denied, error), end;
    if (error) throw std::runtime_error(folder.string() + ": cannot list (" + error.message() + ")");
    for (; !error && entry != end; entry.increment(error)) {
        if (hidden(entry->path())) {
            if (entry->is_directory(error)) entry.disable_recursion_pending();
            continue;
        }
        if (entry->is_regular_file(error) && hasSupportedMeshExtension(entry->path().string()))
            meshes.push_back(batchMesh(entry->path()));
    }
    if (error) throw std::runtime_error(folder.string() + ": cannot list (" + error.message() + ")");
}

std::string hex(const void* bytes, size_t count) {
    static const char digits[] = "0123456789abcdef";
    std::string text;
    for (size_t k = 0; k < count; ++k) {
        const unsigned char byte = static_cast<const unsigned char*>(bytes)[k];
        text += digits[byte >> 4];
        text += digits[byte & 15];
    }
    return text;
}

// Feeds the file's bytes to the hash; false when it cannot be read.
bool hashFile(const std::string& path, XXH3_state_t* state) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::vector<char> buffer(1 << 20);
    while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0)
        XXH3_128bits_update(state, buffer.data(), size_t(in.gcount()));
    return !in.bad();
}

// The files a .gltf's buffers name (not data URIs), beside it; none when it is no JSON.
std::vector<std::string> gltfBufferFiles(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    const nlohmann::json document = nlohmann::json::parse(in, nullptr, false);
    std::vector<std::string> files;
    if (!document.is_object() || !document.contains("buffers") || !document["buffers"].is_array()) return files;
    for (const nlohmann::json& buffer : document["buffers"])
        if (buffer.is_object() && buffer.contains("uri") && buffer["uri"].is_string()) {
            const std::string uri = buffer["uri"];
            if (uri.rfind("data:", 0) != 0) files.push_back((fs::path(path).parent_path() / uri).string());
        }
    return files;
}

std::string textHash(const std::string& text, size_t bytes) {
    const XXH128_hash_t hash = XXH3_128bits(text.data(), text.size());
    XXH128_canonical_t canonical;
    XXH128_canonicalFromHash(&canonical, hash);
    return hex(canonical.digest, bytes);
}

}  // namespace

std::vector<BatchMesh> findBatchMeshes(const std::vector<std::string>& paths) {
    std::vector<BatchMesh> meshes;
    for (const std::string& path : paths) {
        std::error_code error;
        const fs::file_status status = fs::status(path, error);
        if (!fs::exists(status)) throw std::runtime_error(path + ": no such file or folder");
        if (fs::is_directory(status))
            addFolder(path, meshes);
        else
            meshes.push_back(batchMesh(path));
    }
    std::sort(meshes.begin(), meshes.end(), [](const BatchMesh& a, const BatchMesh& b) { return a.path < b.path; });
    std::set<std::string> seen;
    meshes.erase(std::remove_if(meshes.begin(), meshes.end(), [&](const BatchMesh& mesh) { return !seen.insert(mesh.canonical).second; }),
                 meshes.end());
    return meshes;
}

Shard parseShard(const std::string& text) {
    Shard shard;
    const size_t slash = text.find('/');
    const auto parse = [](const std::string& part, size_t& value) {
        const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
        return !part.empty() && error == std::errc() && end == part.data() + part.size();
    };
    if (slash == std::string::npos || !parse(text.substr(0, slash), shard.index) || !parse(text.substr(slash + 1), shard.count) ||
        shard.index < 1 || shard.index > shard.count)
        throw std::invalid_argument("--shard '" + text + "' is not I/N with 1 <= I <= N");
    return shard;
}

std::vector<BatchMesh> meshesOfShard(const std::vector<BatchMesh>& meshes, const Shard& shard) {
    std::vector<BatchMesh> taken;
    for (size_t k = shard.index - 1; k < meshes.size(); k += shard.count) taken.push_back(meshes[k]);
    return taken;
}

std::string batchJsonName(const std::string& canonicalPath, const std::string& suffix) {
    return "meshes/" + fs::path(canonicalPath).filename().string() + "-" + textHash(canonicalPath, 4) + suffix + ".json";
}

std::string contentHash(const std::string& path) {
    XXH3_state_t* state = XXH3_createState();
    XXH3_128bits_reset(state);
    bool readable = hashFile(path, state);
    if (readable && hasExtension(path, {".gltf"}))
        for (const std::string& buffer : gltfBufferFiles(path)) {
            XXH3_128bits_update(state, buffer.data(), buffer.size() + 1);  // the name, then its bytes
            hashFile(buffer, state);
        }
    XXH128_canonical_t canonical;
    XXH128_canonicalFromHash(&canonical, XXH3_128bits_digest(state));
    XXH3_freeState(state);
    return readable ? hex(canonical.digest, sizeof canonical.digest) : std::string();
}

std::string settingsHash(const Settings& settings, const std::string& compare, const StatisticsDetail& detail) {
    std::string text = settingsToJson(settings).dump();
    if (!settings.clusterFile.empty()) text += "\ncluster file " + contentHash(settings.clusterFile);
    text += "\ncompare " + compare + "\nviews " + (detail.views ? "1" : "0") + " clusters " + (detail.clusters ? "1" : "0");
    text += "\nversion " + std::string(conescopeVersion());
    return textHash(text, 8);
}

}  // namespace conescope::cli
