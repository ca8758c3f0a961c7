#include "MeshLoading.h"

#include <cctype>
#include <chrono>
#include <filesystem>

#include "io/MeshReader.h"

namespace conescope {

PreparedMesh loadMesh(const std::string& path, const Settings& settings, const ProgressCallback& progress,
                      std::shared_ptr<MeshletStream>* meshlets) {
    if (progress && !progress(0.0, "reading " + std::filesystem::path(path).filename().string())) throw OperationCancelled();
    const auto start = std::chrono::steady_clock::now();
    MeshFile file = readMeshFile(path, progressWithin(progress, 0.0, 0.3));
    auto mesh = std::make_shared<const Mesh>(std::move(file.mesh));
    const double readSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string unused;
    if (meshlets) *meshlets = meshoptStartInBackground(mesh, builderForMesh(settings, *mesh, unused));
    PreparedMesh prepared = prepareMesh(mesh, path, settings.fixWinding, progress);
    prepared.prepareSeconds += readSeconds;
    prepared.readerNotes = std::move(file.notes);
    return prepared;
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
