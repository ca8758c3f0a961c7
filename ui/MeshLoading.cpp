#include "MeshLoading.h"

#include <cctype>
#include <chrono>
#include <filesystem>

#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/MeshletFiles.h"

namespace conescope {

PreparedMesh loadMesh(const std::string& path, const Settings& settings, const ProgressCallback& progress,
                      std::shared_ptr<MeshletStream>* meshlets) {
    if (progress && !progress(0.0, "reading " + std::filesystem::path(path).filename().string())) throw OperationCancelled();
    const auto start = std::chrono::steady_clock::now();
    MeshFile file = readMeshFile(path, progressWithin(progress, 0.0, 0.3));
    try {
        readClusterFileOf(file.mesh, settings, file.notes);
    } catch (const ClusterFileError& error) {
        // The mesh is still shown, with another builder (builderForMesh says which); the error stays in its notes.
        file.notes.push_back(error.what());
    }
    auto mesh = std::make_shared<const Mesh>(std::move(file.mesh));
    const double readSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string unused;
    if (meshlets) *meshlets = meshoptStartInBackground(mesh, builderForMesh(withClusterIds(settings), *mesh, unused));
    PreparedMesh prepared = prepareMesh(mesh, path, settings.fixWinding, progress);
    prepared.prepareSeconds += readSeconds;
    prepared.readerNotes = std::move(file.notes);
    return prepared;
}

bool needsClusterFile(const PreparedMesh& prepared, const Settings& settings) {
    // Id files travel in the settings (withClusterIds); only a meshlet file is read onto the mesh.
    return settings.builder == Builder::File && !settings.clusterFile.empty() && !prepared.original->fileClusters.count(settings.clusterFile) &&
           isMeshletFile(settings.clusterFile);
}

PreparedMesh reprepareMesh(const PreparedMesh& prepared, const Settings& settings, const ProgressCallback& progress) {
    std::shared_ptr<const Mesh> mesh = prepared.original;
    std::vector<std::string> notes = prepared.readerNotes;
    if (needsClusterFile(prepared, settings)) {
        auto withClusters = std::make_shared<Mesh>(*mesh);
        readClusterFileOf(*withClusters, settings, notes);
        mesh = withClusters;
    }
    PreparedMesh again = prepareMesh(mesh, prepared.path, settings.fixWinding, progress);
    again.readerNotes = std::move(notes);
    return again;
}

std::string loadMessage(const PreparedMesh& prepared) {
    std::vector<std::string> pieces = prepared.readerNotes;
    const std::string warning = windingWarning(prepared.report);
    if (!warning.empty())
        pieces.push_back("Warning: " + warning +
                         (prepared.windingFixedFaces > 0 ? " (repaired: " + std::to_string(prepared.windingFixedFaces) + " faces flipped)"
                                                         : "; tick 'Fix winding' in Settings to repair"));
    const std::string sides = doubleSidedWarning(prepared.report);
    if (!sides.empty()) pieces.push_back("Warning: " + sides);
    return joinSentences(pieces);
}

std::string joinSentences(const std::vector<std::string>& pieces) {
    std::string text;
    for (std::string piece : pieces) {
        while (!piece.empty() && std::isspace(static_cast<unsigned char>(piece.back()))) piece.pop_back();
        if (piece.empty()) continue;
        piece[0] = char(std::toupper(static_cast<unsigned char>(piece[0])));
        if (piece.back() != '.' && piece.back() != '!' && piece.back() != '?') piece += '.';
        text += (text.empty() ? "" : " ") + piece;
    }
    return text;
}

}  // namespace conescope
