// Helpers shared by the io tests: data folders, checks on read errors (and ScratchDirectory.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <locale>
#include <string>

#include <glm/glm.hpp>

#include "ScratchDirectory.h"
#include "core/Mesh.h"

namespace conescope::testing {

std::filesystem::path datasetsDir();
std::filesystem::path formatSamplesDir();  // tests/data/formats, written by make_format_samples.py
std::filesystem::path testDataDir();       // tests/data

// While alive, numbers are formatted the German way: the global C++ locale uses ',' as decimal
// point (what iostreams would then read and write), and the C locale is de_DE when installed
// (what strtod/printf would use; Qt applications call setlocale(LC_ALL, "")). Restores both.
class ScopedCommaDecimalLocale {
public:
    ScopedCommaDecimalLocale();
    ~ScopedCommaDecimalLocale();
    ScopedCommaDecimalLocale(const ScopedCommaDecimalLocale&) = delete;
    ScopedCommaDecimalLocale& operator=(const ScopedCommaDecimalLocale&) = delete;

private:
    std::locale previousGlobal_;
    std::string previousC_;
};

// The whole file's bytes ("" when it cannot be read).
std::string fileBytes(const std::filesystem::path& path);

// ASCII text as UTF-16 in the chosen byte order, with its byte order mark.
std::string utf16(const std::string& ascii, bool bigEndian);

// Expects readMeshFile(path) to report rising fractions in (0, 1) and to throw OperationCancelled
// when the callback says stop. The file must be a few megabytes, so there is progress to report.
void expectProgressAndCancellation(const std::string& path);

// Expects equal positions and faces (the same vertices in the same order).
void expectSameMesh(const Mesh& actual, const Mesh& expected);

// Appends value as a `bytes`-byte integer (a float's bits for appendBinaryFloat) in the chosen byte
// order: how tests write binary PLY bodies of either endianness.
void appendBinaryInteger(std::string& out, uint32_t value, int bytes, bool bigEndian);
void appendBinaryFloat(std::string& out, float value, bool bigEndian);

// The message of the MeshReadError readMesh(path) throws; fails the test (and returns "") when it
// throws nothing or another type.
std::string readErrorMessage(const std::string& path);

// Replaces the first (or last) occurrence of `from` in text, failing the test if there is none.
void replaceFirst(std::string& text, const std::string& from, const std::string& to);
void replaceLast(std::string& text, const std::string& from, const std::string& to);

// Reading a sample of tests/data/formats with the first `from` replaced by `to` must fail with a
// message naming the file and holding `fragment`.
void expectErrorWhenReplaced(const std::string& sample, const std::string& from, const std::string& to,
                             const std::string& fragment);

// Unit normal of face f by Newell's method (the core's definition).
glm::dvec3 unitFaceNormal(const Mesh& mesh, size_t face);

// Index of the face whose centroid is closest to point.
size_t faceNearest(const Mesh& mesh, const glm::dvec3& point);

}  // namespace conescope::testing

// Expects readMesh(path) to throw MeshReadError whose message names the file and contains fragment.
#define EXPECT_READ_ERROR(path, fragment)                                                 \
    do {                                                                                  \
        const std::string expectReadErrorPath = (path);                                   \
        const std::string expectReadErrorMessage =                                        \
            ::conescope::testing::readErrorMessage(expectReadErrorPath);                  \
        EXPECT_NE(expectReadErrorMessage.find(expectReadErrorPath), std::string::npos)    \
            << "message does not name the file: " << expectReadErrorMessage;              \
        EXPECT_NE(expectReadErrorMessage.find(fragment), std::string::npos)               \
            << "message lacks \"" << (fragment) << "\": " << expectReadErrorMessage;      \
    } while (false)
