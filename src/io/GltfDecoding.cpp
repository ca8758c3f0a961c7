#include "io/GltfDecoding.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <assimp/IOStream.hpp>
#include <assimp/IOSystem.hpp>
#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include "io/MeshReader.h"

namespace conescope {

using nlohmann::json;

namespace {

// Bytes read from disk against the bytes the buffers hold, reported as progress. A cancel is
// remembered and turns every later read short, which makes assimp give up (it cannot be told).
struct ByteProgress {
    const ProgressCallback& progress;
    uint64_t total = 0;
    uint64_t done = 0;
    bool cancelled = false;

    bool add(uint64_t bytes) {
        done += bytes;
        if (progress && !cancelled)
            cancelled = !progress(total ? std::min(1.0, double(done) / double(total)) : 1.0, "decoding glTF buffers");
        return !cancelled;
    }
};

// A file as assimp sees it: `prefix` (held in memory), then `tailLength` bytes of the file `tailPath`
// from `tailOffset`. The main file is the reduced document (for a .glb, followed by the original's
// BIN chunk); a buffer file is all tail.
class SplicedStream : public Assimp::IOStream {
public:
    SplicedStream(std::string prefix, const std::string& tailPath, uint64_t tailOffset, uint64_t tailLength,
                  ByteProgress& progress)
        : prefix_(std::move(prefix)), tailOffset_(tailOffset), tailLength_(tailLength), progress_(progress) {
        if (tailLength_ > 0) tail_ = std::fopen(tailPath.c_str(), "rb");
    }
    ~SplicedStream() override {
        if (tail_) std::fclose(tail_);
    }
    bool isOpen() const { return tailLength_ == 0 || tail_; }

    size_t Read(void* buffer, size_t size, size_t count) override {
        if (size == 0) return 0;
        count = std::min(count, (FileSize() - std::min(position_, FileSize())) / size);
        char* out = static_cast<char*>(buffer);
        size_t wanted = size * count, copied = 0;
        if (position_ < prefix_.size()) {
            copied = std::min(wanted, prefix_.size() - position_);
            std::memcpy(out, prefix_.data() + position_, copied);
            position_ += copied;
        }
        // The tail in slices, so progress moves and a cancel stops a large buffer part way.
        constexpr size_t slice = size_t(16) << 20;
        while (copied < wanted) {
            const size_t bytes = std::min(slice, wanted - copied);
            if (fseeko(tail_, off_t(tailOffset_ + position_ - prefix_.size()), SEEK_SET) != 0) break;
            const size_t read = std::fread(out + copied, 1, bytes, tail_);
            copied += read;
            position_ += read;
            if (read < bytes || !progress_.add(read)) break;
        }
        return copied / size;
    }
    size_t Write(const void*, size_t, size_t) override { return 0; }
    aiReturn Seek(size_t offset, aiOrigin origin) override {
        const size_t base = origin == aiOrigin_SET ? 0 : origin == aiOrigin_CUR ? position_ : FileSize();
        if (offset > FileSize() - std::min(base, FileSize())) return aiReturn_FAILURE;
        position_ = base + offset;
        return aiReturn_SUCCESS;
    }
    size_t Tell() const override { return position_; }
    size_t FileSize() const override { return prefix_.size() + size_t(tailLength_); }
    void Flush() override {}

private:
    std::string prefix_;
    std::FILE* tail_ = nullptr;
    uint64_t tailOffset_;
    uint64_t tailLength_;
    size_t position_ = 0;
    ByteProgress& progress_;
};

// The files assimp opens: the main path as the reduced document, anything else (the buffers) from disk.
class DecodingFiles : public Assimp::IOSystem {
public:
    DecodingFiles(std::string mainPath, std::string mainPrefix, uint64_t binOffset, uint64_t binLength,
                  ByteProgress& progress)
        : mainPath_(std::move(mainPath)), mainPrefix_(std::move(mainPrefix)), binOffset_(binOffset),
          binLength_(binLength), progress_(progress) {}

    bool Exists(const char* file) const override {
        std::error_code error;
        return file == mainPath_ || std::filesystem::is_regular_file(file, error);
    }
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override {
        if (std::strchr(mode, 'w') || std::strchr(mode, 'a')) return nullptr;
        std::unique_ptr<SplicedStream> stream;
        if (file == mainPath_) {
            stream = std::make_unique<SplicedStream>(mainPrefix_, mainPath_, binOffset_, binLength_, progress_);
        } else {
            std::error_code error;
            const uint64_t size = std::filesystem::file_size(file, error);
            if (error || !std::filesystem::is_regular_file(file, error)) return nullptr;
            stream = std::make_unique<SplicedStream>(std::string(), file, 0, size, progress_);
        }
        return stream->isOpen() ? stream.release() : nullptr;
    }
    void Close(Assimp::IOStream* stream) override { delete stream; }

private:
    std::string mainPath_;
    std::string mainPrefix_;
    uint64_t binOffset_;
    uint64_t binLength_;
    ByteProgress& progress_;
};

std::string nodeName(size_t slot) { return "conescope mesh " + std::to_string(slot); }

// What assimp is given: the original buffers, views and accessors; one mesh per drawn mesh holding
// only its triangle primitives with only their positions and indices (so points, lines, normals,
// texture coordinates, materials, morph targets and skins, none of which ConeScope uses, cannot
// fail the read); and one node per mesh in a single scene, so that assimp's node n holds exactly
// the primitives of GltfScene::meshes[n] in order. Node placement is ConeScope's (GltfDocument).
json decodingDocument(const GltfScene& scene) {
    const json& original = scene.document;
    json document = {{"asset", {{"version", "2.0"}}}, {"scene", 0}};
    for (const char* key : {"buffers", "bufferViews", "accessors"})
        if (original.contains(key)) document[key] = original[key];
    for (size_t i = 0; i < scene.bufferFileNames.size(); ++i)
        if (!scene.bufferFileNames[i].empty()) document["buffers"][i]["uri"] = scene.bufferFileNames[i];
    json meshes = json::array(), nodes = json::array(), roots = json::array();
    for (size_t slot = 0; slot < scene.meshes.size(); ++slot) {
        const GltfMesh& mesh = scene.meshes[slot];
        json primitives = json::array();
        for (const GltfPrimitive& primitive : mesh.primitives) {
            const json& source = original["meshes"][mesh.index]["primitives"][primitive.index];
            json reduced = {{"attributes", {{"POSITION", source["attributes"]["POSITION"]}}}, {"mode", primitive.mode}};
            if (source.contains("indices")) reduced["indices"] = source["indices"];
            if (primitive.draco) {
                json draco = source["extensions"]["KHR_draco_mesh_compression"];
                if (draco.is_object() && draco.contains("attributes") && draco["attributes"].is_object())
                    draco["attributes"] = {{"POSITION", draco["attributes"].value("POSITION", json())}};
                reduced["extensions"]["KHR_draco_mesh_compression"] = draco;
            }
            primitives.push_back(reduced);
        }
        meshes.push_back({{"name", "mesh " + std::to_string(mesh.index)}, {"primitives", primitives}});
        nodes.push_back({{"name", nodeName(slot)}, {"mesh", slot}});
        roots.push_back(slot);
    }
    document["meshes"] = meshes;
    document["nodes"] = nodes;
    document["scenes"] = json::array({{{"nodes", roots}}});
    if (scene.usesDraco) document["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    return document;
}

void appendLittleEndian32(std::string& out, uint64_t value) {
    for (int k = 0; k < 4; ++k) out.push_back(char((value >> (8 * k)) & 0xff));
}

// The reduced document as the main file's first bytes: JSON text, or for a .glb the 12-byte header
// and the JSON chunk, after which the original BIN chunk (header included) follows from the file.
std::string mainFilePrefix(const GltfScene& scene) {
    // Invalid UTF-8 can only come from a %-decoded file name; replaced, that file is not found.
    std::string text = decodingDocument(scene).dump(-1, ' ', false, json::error_handler_t::replace);
    if (!scene.binary) return text;
    text.append((4 - text.size() % 4) % 4, ' ');
    const uint64_t binBytes = scene.binChunkOffset ? 8 + scene.binChunkLength : 0;
    std::string prefix = "glTF";
    appendLittleEndian32(prefix, 2);
    appendLittleEndian32(prefix, 12 + 8 + text.size() + binBytes);
    appendLittleEndian32(prefix, text.size());
    prefix += "JSON";
    return prefix + text;
}

[[noreturn]] void refuseDecoding(const std::string& path, const std::string& assimpError) {
    if (assimpError.find("Draco mesh compression not supported") != std::string::npos)
        throw MeshReadError(path + ": requires KHR_draco_mesh_compression, which this build of assimp cannot decode");
    // The reduced document keeps only primitives with triangles, so assimp finds none in one only
    // when it dropped them all for indices beyond the primitive's vertices.
    if (assimpError.find("has no faces") != std::string::npos)
        throw MeshReadError(path + ": every triangle of a primitive uses a vertex index out of range (assimp: " +
                            assimpError + ")");
    throw MeshReadError(path + ": " + (assimpError.empty() ? std::string("assimp could not decode the file") : assimpError));
}

// The decoded primitive against what its accessors promise: anything else means data assimp
// dropped or made up.
void checkDecoded(const std::string& path, const GltfMesh& mesh, const GltfPrimitive& primitive, const aiMesh& decoded) {
    const std::string where = path + ": meshes[" + std::to_string(mesh.index) + "].primitives[" +
                              std::to_string(primitive.index) + "]: ";
    if (decoded.mNumVertices != primitive.vertexCount)
        throw MeshReadError(where + "decoded " + std::to_string(decoded.mNumVertices) + " vertices, but POSITION holds " +
                            std::to_string(primitive.vertexCount));
    if (decoded.mNumFaces < primitive.triangleCount)
        throw MeshReadError(where + std::to_string(primitive.triangleCount - decoded.mNumFaces) + " of its " +
                            std::to_string(primitive.triangleCount) + " triangles use a vertex index out of range (" +
                            std::to_string(primitive.vertexCount) + " vertices)");
    if (decoded.mNumFaces != primitive.triangleCount || decoded.mPrimitiveTypes != aiPrimitiveType_TRIANGLE)
        throw MeshReadError(where + "decoded " + std::to_string(decoded.mNumFaces) + " faces, expected " +
                            std::to_string(primitive.triangleCount) + " triangles");
    for (unsigned v = 0; v < decoded.mNumVertices; ++v) {
        const aiVector3D& p = decoded.mVertices[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw MeshReadError(where + "vertex " + std::to_string(v) + " has a non-finite coordinate (" +
                                std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")");
    }
}

}  // namespace

GltfDecoded decodeGltfPrimitives(const std::string& path, const GltfScene& scene, const ProgressCallback& progress) {
    ByteProgress bytes{progress};
    bytes.total = scene.bufferBytes;
    GltfDecoded decoded;
    decoded.importer = std::make_shared<Assimp::Importer>();
    DecodingFiles files(path, mainFilePrefix(scene), scene.binChunkOffset,
                        scene.binChunkOffset ? 8 + scene.binChunkLength : 0, bytes);
    const aiScene* result = nullptr;
    {
        // Lent for the read only: an importer deletes the file system it holds at its end, and
        // SetIOHandler(nullptr) takes it back without deleting it.
        struct LentFileSystem {
            Assimp::Importer& importer;
            ~LentFileSystem() { importer.SetIOHandler(nullptr); }
        } lent{*decoded.importer};
        decoded.importer->SetIOHandler(&files);
        result = decoded.importer->ReadFile(path, 0);
    }
    if (bytes.cancelled) throw OperationCancelled();
    if (!result || !result->mRootNode) refuseDecoding(path, decoded.importer->GetErrorString());
    for (size_t slot = 0; slot < scene.meshes.size(); ++slot) {
        const GltfMesh& mesh = scene.meshes[slot];
        const aiNode* node = result->mRootNode->FindNode(nodeName(slot).c_str());
        if (!node || node->mNumMeshes != mesh.primitives.size())
            throw MeshReadError(path + ": assimp did not decode meshes[" + std::to_string(mesh.index) + "] as expected");
        std::vector<const aiMesh*> primitives;
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            const aiMesh* primitive = result->mMeshes[node->mMeshes[p]];
            checkDecoded(path, mesh, mesh.primitives[p], *primitive);
            primitives.push_back(primitive);
        }
        decoded.primitives.push_back(std::move(primitives));
    }
    return decoded;
}

}  // namespace conescope
