// Randomly damaged copies of good files (fixed seeds, so failures reproduce): each read must give a
// valid mesh or a MeshReadError naming the file, never a crash. This is how the VTK 9.1 crashes
// worked around in HeaderChecks.h were found; a longer run is a matter of raising the count.
#include <fstream>
#include <random>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

namespace conescope {
namespace {

using testing::fileBytes;
using testing::ScratchDirectory;

constexpr int mutationsPerFile = 120;

// One to four edits: overwrite, delete, insert a number, insert a digit or separator, cut.
std::string mutated(std::string bytes, std::mt19937& random) {
    int edits = 1 + static_cast<int>(random() % 4);
    for (int e = 0; e < edits && !bytes.empty(); ++e) {
        size_t position = random() % bytes.size();
        switch (random() % 5) {
            case 0: bytes[position] = static_cast<char>(random()); break;
            case 1: bytes.erase(position, 1 + random() % 8); break;
            case 2: bytes.insert(position, std::to_string(static_cast<long>(random() % 4000000000u) - 1000)); break;
            case 3: bytes[position] = "0123456789-. \n"[random() % 14]; break;
            case 4: bytes.resize(position); break;
        }
    }
    return bytes.empty() ? std::string("x") : bytes;
}

void expectNoCrashOnMutations(const std::string& originalPath, unsigned seed) {
    std::string original = fileBytes(originalPath);
    ASSERT_FALSE(original.empty()) << originalPath;
    std::string extension = std::filesystem::path(originalPath).extension().string();
    ScratchDirectory scratch;
    std::mt19937 random(seed);
    for (int i = 0; i < mutationsPerFile; ++i) {
        std::string path = scratch.writeFile("mutation" + std::to_string(i) + extension, mutated(original, random));
        try {
            Mesh mesh = readMesh(path);
            EXPECT_NO_THROW(validateMesh(mesh)) << path;
        } catch (const MeshReadError& error) {
            EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
        }
    }
}

class MutatedSample : public ::testing::TestWithParam<const char*> {};

TEST_P(MutatedSample, NeverCrashes) {
    std::string name = GetParam();
    std::filesystem::path path = testing::formatSamplesDir() / name;
    if (!std::filesystem::exists(path)) path = testing::datasetsDir() / name;
    expectNoCrashOnMutations(path.string(), static_cast<unsigned>(std::hash<std::string>()(name)));
}

INSTANTIATE_TEST_SUITE_P(Files, MutatedSample,
                         ::testing::Values("cube.ply", "cube-binary.ply", "cube.obj", "cube-textured.obj", "cube-ascii.stl", "cube-binary.stl",
                                           "cube.vtp", "cube.vtk", "cube-strips.vtk", "cube-quads.off",
                                           "icosphere-clusters.vtp"),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                             std::string name = info.param;
                             for (char& c : name)
                                 if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                             return name;
                         });

// Our own binary outputs: compressed appended .vtp, binary legacy 5.1 .vtk, binary .ply.
class MutatedWrittenFile : public ::testing::TestWithParam<const char*> {};

TEST_P(MutatedWrittenFile, NeverCrashes) {
    Mesh prism = readMesh((testing::datasetsDir() / "hexagonal-prism.off").string());
    prism.model[3] = glm::dvec4(1.0, 2.0, 3.0, 1.0);
    ScratchDirectory scratch;
    std::string path = scratch.file(std::string("prism") + GetParam());
    std::vector<double> clusterIds;
    for (size_t f = 0; f < prism.faceCount(); ++f) clusterIds.push_back(double(f % 3));
    writePolyData(prism, path, {{"cluster_id", clusterIds}});
    expectNoCrashOnMutations(path, 1234u);
}

INSTANTIATE_TEST_SUITE_P(Formats, MutatedWrittenFile, ::testing::Values(".vtp", ".vtk", ".ply"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param + 1); });

}  // namespace
}  // namespace conescope
