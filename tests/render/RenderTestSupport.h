// Shared inputs of the scene tests: a bundled mesh with its partition and cluster bounds, and the
// image comparison against the PNG baselines.
#pragma once

#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "core/ClusterBounds.h"
#include "core/Mesh.h"
#include "core/Partition.h"

class vtkImageData;

namespace conescope::rendertest {

// Everything a ClusterScene is built from.
struct SceneInput {
    Mesh mesh;
    std::vector<glm::vec3> world;
    FaceGeometry faces;
    Partition partition;
    ClusterBounds bounds;
};

// datasets/<name> read with readMesh, split by buildMeshlets with at most maxTriangles per cluster,
// minimal cones and spheres.
SceneInput loadDataset(const std::string& name, size_t maxTriangles);

// Faces around each vertex, brute force, to check the scene's adjacency-based results independently.
std::vector<std::vector<uint32_t>> clustersAroundVertices(const SceneInput& input);

// Result of comparing an image with its baseline.
struct ImageComparison {
    bool sameSize = false;
    double thresholdedError = 0.0;  // vtkImageDifference::GetThresholdedError
    double meanChannelDifference = 0.0;  // mean |a - b| over all pixels and channels, 0..255
};
ImageComparison compareImages(vtkImageData* actual, vtkImageData* expected);

// The acceptance limits: vtkImageDifference's thresholded error as vtkTesting uses it, and a small
// mean difference so a picture that is broadly different can never pass.
constexpr double maxThresholdedError = 10.0;
constexpr double maxMeanChannelDifference = 1.0;

vtkSmartPointer<vtkImageData> readPng(const std::string& path);

// Compares with baselines/<name>.png. With CONESCOPE_UPDATE_BASELINES=1 in the environment it writes
// the baseline instead and returns an empty string. On a mismatch it writes <name>.actual.png into the
// build directory and returns a message naming both files; an empty string means the image matches.
std::string checkAgainstBaseline(vtkImageData* actual, const std::string& name);

}  // namespace conescope::rendertest
