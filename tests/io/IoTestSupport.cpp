#include "IoTestSupport.h"

#include <algorithm>
#include <clocale>
#include <cstring>
#include <cstdlib>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "io/MeshReader.h"

namespace conescope::testing {

std::filesystem::path datasetsDir() { return CONESCOPE_DATASETS_DIR; }

std::filesystem::path testDataDir() { return CONESCOPE_TESTDATA_DIR; }
std::filesystem::path formatSamplesDir() { return testDataDir() / "formats"; }

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream input(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(input), std::istreambuf_iterator<char>());
}

std::string utf16(const std::string& ascii, bool bigEndian) {
    std::string bytes = bigEndian ? "\xfe\xff" : "\xff\xfe";
    for (char c : ascii) bytes += bigEndian ? std::string{'\0', c} : std::string{c, '\0'};
    return bytes;
}

void expectProgressAndCancellation(const std::string& path) {
    std::vector<double> fractions;
    readMeshFile(path, [&](double fraction, const std::string&) {
        fractions.push_back(fraction);
        return true;
    });
    ASSERT_FALSE(fractions.empty()) << path;
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GT(fractions.front(), 0.0);
    EXPECT_LT(fractions.back(), 1.0);
    EXPECT_THROW(readMeshFile(path, [](double, const std::string&) { return false; }), OperationCancelled);
}

void expectSameMesh(const Mesh& actual, const Mesh& expected) {
    EXPECT_EQ(actual.positions, expected.positions);
    EXPECT_EQ(actual.faceStarts, expected.faceStarts);
    EXPECT_EQ(actual.faceVertices, expected.faceVertices);
}

void appendBinaryInteger(std::string& out, uint32_t value, int bytes, bool bigEndian) {
    for (int k = 0; k < bytes; ++k) {
        const int shift = bigEndian ? 8 * (bytes - 1 - k) : 8 * k;
        out.push_back(char((value >> shift) & 0xff));
    }
}

void appendBinaryFloat(std::string& out, float value, bool bigEndian) {
    uint32_t bits = 0;
    std::memcpy(&bits, &value, 4);
    appendBinaryInteger(out, bits, 4, bigEndian);
}

namespace {
struct CommaDecimalPoint : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};
}  // namespace

ScopedCommaDecimalLocale::ScopedCommaDecimalLocale()
    : previousGlobal_(std::locale::global(std::locale(std::locale::classic(), new CommaDecimalPoint))),
      previousC_(std::setlocale(LC_ALL, nullptr)) {
    if (!std::setlocale(LC_ALL, "de_DE.UTF-8")) std::setlocale(LC_ALL, "de_DE");
}

ScopedCommaDecimalLocale::~ScopedCommaDecimalLocale() {
    std::setlocale(LC_ALL, previousC_.c_str());
    std::locale::global(previousGlobal_);
}

std::string readErrorMessage(const std::string& path) {
    try {
        Mesh mesh = readMesh(path);
        ADD_FAILURE() << "readMesh(" << path << ") succeeded with " << mesh.faceCount() << " faces";
    } catch (const MeshReadError& error) {
        return error.what();
    } catch (const std::exception& error) {
        ADD_FAILURE() << "readMesh(" << path << ") threw a non-MeshReadError: " << error.what();
    }
    return "";
}

void replaceFirst(std::string& text, const std::string& from, const std::string& to) {
    size_t position = text.find(from);
    ASSERT_NE(position, std::string::npos) << from;
    text.replace(position, from.size(), to);
}

void replaceLast(std::string& text, const std::string& from, const std::string& to) {
    size_t position = text.rfind(from);
    ASSERT_NE(position, std::string::npos) << from;
    text.replace(position, from.size(), to);
}

void expectErrorWhenReplaced(const std::string& sample, const std::string& from, const std::string& to,
                             const std::string& fragment) {
    SCOPED_TRACE(sample + ": '" + from + "' -> '" + to + "'");
    std::string text = fileBytes(formatSamplesDir() / sample);
    replaceFirst(text, from, to);
    ScratchDirectory scratch;
    EXPECT_READ_ERROR(scratch.writeFile(sample, text), fragment);
}

glm::dvec3 unitFaceNormal(const Mesh& mesh, size_t face) {
    return glm::normalize(newellNormal(mesh.positions.data(), mesh.faceBegin(face), mesh.faceSize(face)));
}

size_t faceNearest(const Mesh& mesh, const glm::dvec3& point) {
    size_t nearest = 0;
    double nearestDistance = std::numeric_limits<double>::max();
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        glm::dvec3 centroid(0.0);
        for (size_t k = 0; k < mesh.faceSize(f); ++k) centroid += glm::dvec3(mesh.positions[mesh.faceBegin(f)[k]]);
        centroid /= double(mesh.faceSize(f));
        double distance = glm::length(centroid - point);
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = f;
        }
    }
    return nearest;
}

}  // namespace conescope::testing
