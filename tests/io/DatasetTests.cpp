// The meshes in datasets/: every one loads and validates, the synthetic ones have their documented
// counts and outward winding, and the fetched CGAL meshes (if present) load too.
#include <set>

#include <gtest/gtest.h>

#include "IoTestSupport.h"
#include "io/MeshReader.h"

namespace conescope {
namespace {

using testing::datasetsDir;

// Divergence theorem over fan triangles: positive when the faces wind outward (counter-clockwise
// seen from outside).
double signedVolume(const Mesh& mesh) {
    double volume = 0.0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        glm::dvec3 origin(mesh.positions[face[0]]);
        for (size_t k = 1; k + 1 < mesh.faceSize(f); ++k)
            volume += glm::dot(origin, glm::cross(glm::dvec3(mesh.positions[face[k]]), glm::dvec3(mesh.positions[face[k + 1]]))) / 6.0;
    }
    return volume;
}

// Every edge used exactly twice, once in each direction: closed and consistently oriented.
bool isClosedAndConsistentlyWound(const Mesh& mesh) {
    std::set<std::pair<uint32_t, uint32_t>> directedEdges;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            uint32_t from = mesh.faceBegin(f)[k], to = mesh.faceBegin(f)[(k + 1) % mesh.faceSize(f)];
            if (!directedEdges.insert({from, to}).second) return false;  // same direction twice
        }
    for (const auto& [from, to] : directedEdges)
        if (!directedEdges.count({to, from})) return false;  // border edge
    return true;
}

struct Dataset {
    const char* file;
    size_t vertexCount;
    size_t faceCount;
    bool closed;
    double volume;  // expected signed volume, 0 = only check the sign
};

// Names the file in test listings instead of dumping the struct's bytes.
void PrintTo(const Dataset& dataset, std::ostream* out) { *out << dataset.file; }

class BundledDataset : public ::testing::TestWithParam<Dataset> {};

TEST_P(BundledDataset, LoadsWithDocumentedCountsAndOutwardWinding) {
    const Dataset& dataset = GetParam();
    Mesh mesh = readMesh((datasetsDir() / dataset.file).string());
    EXPECT_EQ(mesh.positions.size(), dataset.vertexCount);
    EXPECT_EQ(mesh.faceCount(), dataset.faceCount);
    EXPECT_NO_THROW(validateMesh(mesh));
    if (!dataset.closed) return;
    EXPECT_TRUE(isClosedAndConsistentlyWound(mesh));
    double volume = signedVolume(mesh);
    EXPECT_GT(volume, 0.0) << "faces wind inward";
    if (dataset.volume > 0.0) {
        EXPECT_NEAR(volume, dataset.volume, 0.05 * dataset.volume);
    }
}

const double pi = 3.14159265358979;

INSTANTIATE_TEST_SUITE_P(
    Datasets, BundledDataset,
    ::testing::Values(Dataset{"icosphere.off", 642, 1280, true, 4.0 / 3.0 * pi},
                      Dataset{"cube.off", 8, 12, true, 1.0},
                      Dataset{"cube-quads.off", 8, 6, true, 1.0},
                      Dataset{"torus.off", 1152, 2304, true, 2.0 * pi * pi * 1.0 * 0.35 * 0.35},
                      Dataset{"hexagonal-prism.off", 12, 8, true, 1.5 * std::sqrt(3.0) * 1.0},
                      Dataset{"cylinder.off", 290, 576, true, pi * 0.5 * 0.5 * 1.5},
                      Dataset{"bumpy-plane.off", 1089, 2048, false, 0.0},
                      Dataset{"icosphere-clusters.vtp", 162, 320, true, 4.0 / 3.0 * pi},
                      Dataset{"elephant.off", 2775, 5558, true, 0.0462},
                      Dataset{"fandisk.off", 6475, 12946, true, 0.1404}),
    [](const ::testing::TestParamInfo<Dataset>& info) {
        std::string name = info.param.file;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
        return name;
    });

// Catches datasets added later without a test entry: whatever is in datasets/ must load and stay small.
TEST(BundledDatasets, EveryMeshFileLoadsAndIsUnderOneMegabyte) {
    size_t checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(datasetsDir())) {
        if (!entry.is_regular_file() || !hasSupportedMeshExtension(entry.path().string())) continue;
        SCOPED_TRACE(entry.path().string());
        EXPECT_LT(entry.file_size(), 1u << 20);
        Mesh mesh;
        EXPECT_NO_THROW(mesh = readMesh(entry.path().string()));
        EXPECT_GT(mesh.faceCount(), 0u);
        ++checked;
    }
    EXPECT_GE(checked, 8u);
}

// datasets/cgal/ is filled by scripts/fetch-datasets.sh and not in git; skip when absent.
TEST(FetchedDatasets, EveryCgalMeshLoads) {
    std::filesystem::path folder = datasetsDir() / "cgal";
    if (!std::filesystem::is_directory(folder)) GTEST_SKIP() << "run scripts/fetch-datasets.sh to fetch them";
    size_t checked = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (!entry.is_regular_file() || !hasSupportedMeshExtension(entry.path().string())) continue;
        SCOPED_TRACE(entry.path().string());
        Mesh mesh;
        EXPECT_NO_THROW(mesh = readMesh(entry.path().string()));
        EXPECT_GT(mesh.faceCount(), 1000u);
        ++checked;
    }
    if (checked == 0) GTEST_SKIP() << "datasets/cgal/ holds no meshes";
}

}  // namespace
}  // namespace conescope
