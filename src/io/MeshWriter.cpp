#include "io/MeshWriter.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>

#include "io/FileChecks.h"
#include "io/FormatModules.h"

namespace conescope {

namespace {

void requireValidMesh(const Mesh& mesh, const std::string& path) {
    try {
        validateMesh(mesh);
    } catch (const std::runtime_error& error) {
        throw MeshWriteError(path + ": refusing to write an invalid mesh: " + error.what());
    }
    if (mesh.faceCount() == 0) throw MeshWriteError(path + ": refusing to write a mesh with no faces");
}

void appendNumber(std::string& out, uint64_t value) {
    char buffer[24];
    auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, error == std::errc() ? end : buffer);
}

std::string offText(const Mesh& mesh) {
    std::string text = "OFF\n# written by ConeScope\n";
    text.reserve(mesh.positions.size() * 36 + mesh.faceVertices.size() * 8);
    appendNumber(text, uint64_t{mesh.positions.size()});
    text += ' ';
    appendNumber(text, uint64_t{mesh.faceCount()});
    text += " 0\n";
    for (const glm::vec3& p : mesh.positions) appendPointLine(text, p);
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        appendNumber(text, uint64_t{mesh.faceSize(f)});
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            text += ' ';
            appendNumber(text, uint64_t{mesh.faceBegin(f)[k]});
        }
        text += '\n';
    }
    return text;
}

Mesh withExtraArrays(const Mesh& mesh, const std::string& path,
                     const std::map<std::string, std::vector<double>>& extraFaceArrays) {
    Mesh combined = mesh;
    for (const auto& [name, values] : extraFaceArrays) {
        if (name.empty()) throw MeshWriteError(path + ": per-face array with an empty name");
        if (values.size() != mesh.faceCount())
            throw MeshWriteError(path + ": per-face array '" + name + "' has " + std::to_string(values.size()) +
                                 " values for " + std::to_string(mesh.faceCount()) + " faces");
        combined.faceArrays[name] = values;
    }
    return combined;
}

}  // namespace

void writeOff(const Mesh& mesh, const std::string& path) {
    requireValidMesh(mesh, path);
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) throw MeshWriteError(path + ": cannot open for writing (" + std::strerror(errno) + ")");
    std::string text = offText(mesh);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw MeshWriteError(path + ": write failed (disk full?)");
}

void writePolyData(const Mesh& mesh, const std::string& path,
                   const std::map<std::string, std::vector<double>>& extraFaceArrays) {
    std::string extension = lowerCaseExtension(path);
    std::vector<std::string> writable = writableMeshExtensions();
    if (std::find(writable.begin(), writable.end(), extension) == writable.end())
        throw MeshWriteError(path + ": cannot write extension " + quotedForMessage(extension) +
                             "; supported: .vtp .vtk .ply .off");
    requireValidMesh(mesh, path);
    Mesh combined = withExtraArrays(mesh, path, extraFaceArrays);
    if (extension == ".off") return writeOff(combined, path);
    const VtkFormats* formats = nullptr;
    try {
        formats = &vtkFormats();
    } catch (const std::exception& error) {
        throw MeshWriteError(path + ": " + error.what());
    }
    formats->write(combined, path, extension);
}

std::vector<std::string> writableMeshExtensions() { return {".vtp", ".vtk", ".ply", ".off"}; }

}  // namespace conescope
