#include "batch/BatchInputs.h"

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

#include "batch/OutputFiles.h"
#include "io/MeshReader.h"

namespace conescope::cli {

namespace fs = std::filesystem;

namespace {

bool hidden(const fs::path& path) { return path.filename().string().rfind('.', 0) == 0; }

BatchMesh batchMesh(const fs::path& path) {
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(fs::absolute(path), error);
    if (error) canonical = fs::absolute(path);
    BatchMesh mesh{path.string(), canonical.string(), batchJsonName(canonical.string()), 0, ""};
    const uintmax_t bytes = fs::file_size(canonical, error);
    mesh.bytes = error ? 0 : bytes;
    return mesh;
}

BatchMesh pathProblem(const fs::path& path, const std::string& problem) {
    BatchMesh mesh = batchMesh(path);
    mesh.problem = path.string() + ": " + problem;
    return mesh;
}

// Why a path that is not a folder cannot be read as a mesh, in the reader's words; "" when it is a file.
std::string fileProblem(const fs::path& path) {
    std::error_code error;
    const fs::file_status status = fs::status(path, error), link = fs::symlink_status(path, error);
    if (fs::is_symlink(link) && !fs::exists(status)) {
        const fs::path target = fs::read_symlink(path, error);
        return "a link to " + target.string() + ", which does not exist";
    }
    if (!fs::exists(status)) return "no such file or folder";
    if (fs::is_directory(status)) return "a folder named like a mesh file, not a mesh (its meshes are looked for inside it)";
    if (!fs::is_regular_file(status)) return "not a regular file (a device, pipe or socket)";
    return "";
}

// The folder's meshes and path problems, and those of the folders below it (hidden ones and links
// to folders left out: a link may loop). A folder that cannot be listed is a problem of its own.
void addFolder(const fs::path& folder, std::vector<BatchMesh>& meshes) {
    std::error_code error;
    fs::directory_iterator entry(folder, error), end;
    for (; !error && entry != end; entry.increment(error)) {
        const fs::path& path = entry->path();
        if (hidden(path)) continue;
        std::error_code ignored;
        const bool folderBelow = entry->is_directory(ignored) && !entry->is_symlink(ignored);
        if (hasSupportedMeshExtension(path.string())) {
            const std::string problem = fileProblem(path);
            if (problem.empty()) meshes.push_back(batchMesh(path));
            else meshes.push_back(pathProblem(path, problem));
        }
        if (folderBelow) addFolder(path, meshes);
    }
    if (error) meshes.push_back(pathProblem(folder, "cannot list the folder (" + error.message() + ")"));
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

// Feeds the file's bytes to the hash; false when it cannot be read (a pipe would block the read).
bool hashFile(const std::string& path, XXH3_state_t* state) {
    std::error_code error;
    if (!fs::is_regular_file(path, error)) return false;
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
        if (fs::is_directory(fs::status(path, error))) {
            addFolder(path, meshes);
            continue;
        }
        // A file given is read whatever its extension: the reader names an unknown one.
        const std::string problem = fileProblem(path);
        meshes.push_back(problem.empty() ? batchMesh(path) : pathProblem(path, problem));
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

std::string settingsHash(const Settings& settings, const std::string& compare, const StatisticsDetail& detail, const std::string& extras) {
    std::string text = settingsToJson(settings).dump();
    if (!settings.clusterFile.empty()) text += "\ncluster file " + contentHash(settings.clusterFile);
    text += "\ncompare " + compare + "\nviews " + (detail.views ? "1" : "0") + " clusters " + (detail.clusters ? "1" : "0");
    if (!extras.empty()) text += "\nextras " + extras;  // batches without them keep their hashes
    text += "\nversion " + std::string(conescopeVersion());
    return textHash(text, 8);
}

}  // namespace conescope::cli
