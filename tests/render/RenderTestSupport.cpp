#include "RenderTestSupport.h"

#include "scene/SceneRendering.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>

#include <vtkImageData.h>
#include <vtkImageDifference.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>

#include "io/MeshReader.h"

namespace conescope::rendertest {

SceneInput loadDataset(const std::string& name, size_t maxTriangles) {
    SceneInput input;
    input.mesh = readMesh(std::string(CONESCOPE_DATASETS_DIR) + "/" + name);
    input.world = worldPositions(input.mesh);
    input.faces = computeFaceGeometry(input.mesh);
    MeshletLimits limits;
    limits.maxTriangles = maxTriangles;
    input.partition = buildMeshlets(input.mesh, input.faces, limits);
    input.bounds = computeClusterBounds(input.mesh, input.world, input.faces, input.partition, ConeMethod::Minimal,
                                        SphereMethod::Minimal);
    return input;
}

std::vector<std::vector<uint32_t>> clustersAroundVertices(const SceneInput& input) {
    std::vector<std::vector<uint32_t>> clusters(input.mesh.positions.size());
    for (size_t f = 0; f < input.mesh.faceCount(); ++f)
        for (size_t k = 0; k < input.mesh.faceSize(f); ++k) {
            auto& around = clusters[input.mesh.faceBegin(f)[k]];
            const uint32_t cluster = input.partition.clusterOfFace[f];
            if (std::find(around.begin(), around.end(), cluster) == around.end()) around.push_back(cluster);
        }
    return clusters;
}

ImageComparison compareImages(vtkImageData* actual, vtkImageData* expected) {
    ImageComparison result;
    int a[3], b[3];
    actual->GetDimensions(a);
    expected->GetDimensions(b);
    result.sameSize = a[0] == b[0] && a[1] == b[1] && a[2] == b[2] &&
                      actual->GetNumberOfScalarComponents() == expected->GetNumberOfScalarComponents();
    if (!result.sameSize) return result;

    auto difference = vtkSmartPointer<vtkImageDifference>::New();
    difference->SetInputData(actual);
    difference->SetImageData(expected);
    difference->Update();
    result.thresholdedError = difference->GetThresholdedError();

    const auto* p = static_cast<const unsigned char*>(actual->GetScalarPointer());
    const auto* q = static_cast<const unsigned char*>(expected->GetScalarPointer());
    const size_t count = size_t(a[0]) * a[1] * a[2] * actual->GetNumberOfScalarComponents();
    double sum = 0.0;
    for (size_t i = 0; i < count; ++i) sum += std::abs(int(p[i]) - int(q[i]));
    result.meanChannelDifference = count ? sum / double(count) : 0.0;
    return result;
}

vtkSmartPointer<vtkImageData> readPng(const std::string& path) {
    auto reader = vtkSmartPointer<vtkPNGReader>::New();
    reader->SetFileName(path.c_str());
    reader->Update();
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->DeepCopy(reader->GetOutput());
    return image;
}

std::string checkAgainstBaseline(vtkImageData* actual, const std::string& name) {
    const std::string baseline = std::string(CONESCOPE_BASELINE_DIR) + "/" + name + ".png";
    const std::string actualPath = std::string(CONESCOPE_RENDER_OUTPUT_DIR) + "/" + name + ".actual.png";
    const char* update = std::getenv("CONESCOPE_UPDATE_BASELINES");
    if (update && std::string(update) == "1") {
        writePng(actual, baseline);
        return "";
    }
    if (!std::filesystem::exists(baseline)) {
        writePng(actual, actualPath);
        return "no baseline " + baseline + " (actual image: " + actualPath +
               "); run with CONESCOPE_UPDATE_BASELINES=1 to create it";
    }
    const ImageComparison comparison = compareImages(actual, readPng(baseline));
    if (comparison.sameSize && comparison.thresholdedError <= maxThresholdedError &&
        comparison.meanChannelDifference <= maxMeanChannelDifference) {
        std::filesystem::remove(actualPath);
        return "";
    }
    writePng(actual, actualPath);
    return name + " differs from " + baseline + ": " +
           (comparison.sameSize ? "thresholded error " + std::to_string(comparison.thresholdedError) +
                                      ", mean channel difference " + std::to_string(comparison.meanChannelDifference)
                                : std::string("size or channel count differs")) +
           "; actual image: " + actualPath;
}

}  // namespace conescope::rendertest
