// Pixels: the eye's view without culled clusters, the missing-display error, and the image baselines.
#include <cstdlib>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include "RenderTestSupport.h"
#include "core/Culling.h"
#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "core/CullTestGeometry.h"
#include "scene/ClusterScene.h"
#include "scene/GaussMapScene.h"
#include "scene/SceneRendering.h"

namespace conescope {
namespace {

using rendertest::SceneInput;

ClusterScene makeScene(const SceneInput& input) {
    return ClusterScene(input.mesh, input.world, input.faces, input.partition, input.bounds);
}

// Pixels that differ from the background colour by more than a little.
size_t foregroundPixels(vtkImageData* image, const Rgb& background) {
    int dimensions[3];
    image->GetDimensions(dimensions);
    const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer());
    const int channels = image->GetNumberOfScalarComponents();
    size_t count = 0;
    for (size_t i = 0; i < size_t(dimensions[0]) * dimensions[1]; ++i) {
        int difference = 0;
        for (int c = 0; c < 3; ++c) difference += std::abs(int(p[i * channels + c]) - int(std::lround(background[c] * 255.0)));
        count += difference > 6;
    }
    return count;
}

RenderOptions smallImage() {
    RenderOptions options;
    options.width = 400;
    options.height = 300;
    return options;
}

TEST(SceneRendering, EyeViewDropsCulledClustersWithoutChangingWhatIsSeen) {
    const SceneInput input = rendertest::loadDataset("icosphere.off", 32);
    ClusterScene scene = makeScene(input);
    const Eye eye = Eye::perspective({0.5, 0.8, 2.6});
    scene.setEye(eye, {0, 0, 0});
    RenderOptions options = smallImage();
    options.fromEye = true;

    const auto everything = renderToImage(scene, options);
    const size_t covered = foregroundPixels(everything, options.background);
    EXPECT_GT(covered, 400u * 300u / 10);

    // A closed mesh: culled clusters face away, so removing them leaves the picture as it was.
    const CullingInput cullInput{input.mesh, input.world, input.faces, input.bounds};
    const std::vector<uint8_t> culled = cullClusters(cullInput, eye, CullTest::Vertices);
    const std::vector<uint8_t> allBack = cullClusters(cullInput, eye, CullTest::Oracle);
    size_t culledCount = 0;
    for (uint8_t c : culled) culledCount += c;
    ASSERT_GT(culledCount, 0u);
    scene.setClusterDecisions(culled, allBack);
    const auto withCulling = renderToImage(scene, options);
    const rendertest::ImageComparison same = rendertest::compareImages(withCulling, everything);
    EXPECT_TRUE(same.sameSize);
    EXPECT_LT(same.meanChannelDifference, 0.05);

    // Marking every cluster culled empties the view: the culled clusters really are removed.
    scene.setClusterDecisions(std::vector<uint8_t>(scene.clusterCount(), 1), std::vector<uint8_t>(scene.clusterCount(), 1));
    EXPECT_EQ(foregroundPixels(renderToImage(scene, options), options.background), 0u);

    // Culling the front clusters instead opens holes where they were.
    std::vector<uint8_t> front(scene.clusterCount());
    for (size_t c = 0; c < front.size(); ++c) front[c] = !allBack[c];
    scene.setClusterDecisions(front, std::vector<uint8_t>(scene.clusterCount(), 0));
    const auto holes = renderToImage(scene, options);
    EXPECT_GT(rendertest::compareImages(holes, everything).meanChannelDifference, 2.0);
}

// Where a world point lands in normalised device coordinates ([-1, 1] inside the picture).
glm::dvec3 deviceCoordinates(vtkCamera* camera, const RenderOptions& options, const glm::dvec3& point) {
    vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(double(options.width) / options.height, -1.0, 1.0);
    const double in[4] = {point.x, point.y, point.z, 1.0};
    double out[4];
    m->MultiplyPoint(in, out);
    return glm::dvec3(out[0], out[1], out[2]) / out[3];
}

TEST(SceneRendering, FramingTheEyeKeepsAFarEyeInThePicture) {
    const SceneInput input = rendertest::loadDataset("icosphere.off", 32);
    ClusterScene scene = makeScene(input);
    const glm::dvec3 eye(0.0, 0.0, 12.0);
    scene.setEye(Eye::perspective(eye), glm::dvec3(0.0));
    RenderOptions options = smallImage();
    vtkNew<vtkCamera> camera;
    placeObserverCamera(scene, options, camera);
    EXPECT_GT(glm::length(glm::dvec2(deviceCoordinates(camera, options, eye))), 1.0) << "fitted to the mesh alone, the eye is out";
    options.frameEye = true;
    placeObserverCamera(scene, options, camera);
    const glm::dvec3 shown = deviceCoordinates(camera, options, eye);
    EXPECT_LT(std::abs(shown.x), 1.0);
    EXPECT_LT(std::abs(shown.y), 1.0);
    for (const glm::vec3& p : input.world) {
        const glm::dvec3 q = deviceCoordinates(camera, options, glm::dvec3(p));
        ASSERT_LT(std::abs(q.x), 1.0);
        ASSERT_LT(std::abs(q.y), 1.0);
    }
}

TEST(SceneRendering, MissingDisplayGivesAClearError) {
    const SceneInput input = rendertest::loadDataset("cube.off", 4);
    ClusterScene scene = makeScene(input);
    const char* display = std::getenv("DISPLAY");
    const std::string saved = display ? display : "";
    unsetenv("DISPLAY");
    try {
        renderToPng(scene, smallImage(), std::string(CONESCOPE_RENDER_OUTPUT_DIR) + "/never-written.png");
        ADD_FAILURE() << "rendering without a display did not throw";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("xvfb-run"), std::string::npos) << error.what();
    }
    if (display) setenv("DISPLAY", saved.c_str(), 1);
}

TEST(SceneRendering, UnwritablePngPathThrows) {
    const SceneInput input = rendertest::loadDataset("cube.off", 4);
    ClusterScene scene = makeScene(input);
    EXPECT_THROW(renderToPng(scene, smallImage(), "/nonexistent-directory/image.png"), std::runtime_error);
}

// The three baseline pictures share one torus split into small clusters and one observer camera.
class RenderImages : public ::testing::Test {
protected:
    static void SetUpTestSuite() { torus_ = new SceneInput(rendertest::loadDataset("torus.off", 64)); }
    static void TearDownTestSuite() { delete torus_; }
    static RenderOptions observer() {
        RenderOptions options = smallImage();
        options.cameraPosition = glm::dvec3(2.2, -2.6, 2.4);
        options.focalPoint = glm::dvec3(0.0, 0.0, 0.0);
        options.viewUp = glm::dvec3(0.0, 0.0, 1.0);
        return options;
    }
    static SceneInput* torus_;
};
SceneInput* RenderImages::torus_ = nullptr;

// The eye of the decision pictures, and its decisions by the sphere test (some missed culls).
const Eye decisionEye = Eye::perspective({-1.6, 2.4, 1.5});

TEST_F(RenderImages, ClustersColouredByPalette) {
    ClusterScene scene = makeScene(*torus_);
    const auto image = renderToImage(scene, observer());
    const std::string failure = rendertest::checkAgainstBaseline(image, "clusters");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, CullDecisionsWithConesAndBoxes) {
    ClusterScene scene = makeScene(*torus_);
    const CullingInput cullInput{torus_->mesh, torus_->world, torus_->faces, torus_->bounds};
    scene.setClusterDecisions(cullClusters(cullInput, decisionEye, CullTest::Sphere),
                              cullClusters(cullInput, decisionEye, CullTest::Oracle));
    scene.setFaceColoring(FaceColoring::CullDecision);
    scene.setLayerVisible(Layer::Boxes, true);
    scene.setLayerVisible(Layer::Borders, false);
    scene.setEye(decisionEye, {0, 0, 0});
    // From below the side facing away from the eye: culled, missed and drawn clusters all in view.
    RenderOptions options = observer();
    options.cameraPosition = glm::dvec3(3.9, -3.6, -2.1);
    const auto image = renderToImage(scene, options);
    const std::string failure = rendertest::checkAgainstBaseline(image, "decisions");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, SpheresEyeAndPickedCluster) {
    ClusterScene scene = makeScene(*torus_);
    scene.setLayerVisible(Layer::Cones, false);
    scene.setLayerVisible(Layer::Spheres, true);
    scene.setEye(decisionEye, {0, 0, 0});
    scene.setHighlightedCluster(5);
    scene.setLayerVisible(Layer::Legend, false);
    RenderOptions options = observer();
    // Aimed between the torus and the eye, so the eye marker is in view.
    options.cameraPosition = glm::dvec3(4.2, -7.6, 5.6);
    options.focalPoint = glm::dvec3(-0.5, 0.8, 0.6);
    const auto image = renderToImage(scene, options);
    const std::string failure = rendertest::checkAgainstBaseline(image, "spheres_eye");
    EXPECT_TRUE(failure.empty()) << failure;
}

// The torus input as the pipeline's stages, for the core functions the debugger pictures draw.
PreparedMesh preparedOf(const SceneInput& input) {
    PreparedMesh prepared;
    prepared.culled = std::make_shared<Mesh>(input.mesh);
    prepared.world = input.world;
    prepared.faces = input.faces;
    return prepared;
}

ClusterSet clustersOf(const SceneInput& input) {
    ClusterSet clusters;
    clusters.partition = input.partition;
    clusters.bounds = input.bounds;
    return clusters;
}

// The picked cluster's test drawn in 3D, framed as the headless --pick screenshot frames it: for the
// apex test the cone of eye positions from the apex, for the box test the numbered corners.
std::string renderTestDrawing(const SceneInput& input, CullTest test, uint32_t cluster, const std::string& baseline) {
    ClusterScene scene = makeScene(input);
    const CullingInput cullInput{input.mesh, input.world, input.faces, input.bounds};
    scene.setLayerVisible(Layer::Cones, false);
    scene.setLayerVisible(Layer::Legend, false);
    scene.setHighlightedCluster(int(cluster));
    scene.setEye(decisionEye, {0, 0, 0});
    scene.setTestDrawing(makeTestDrawing(cullInput, cluster, decisionEye, test));
    RenderOptions options = smallImage();
    frameTestDrawing(scene, options);
    return rendertest::checkAgainstBaseline(renderToImage(scene, options), baseline);
}

TEST_F(RenderImages, ApexTestDrawnForThePickedCluster) {
    const std::string failure = renderTestDrawing(*torus_, CullTest::Apex, 5, "test_apex");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, OctagonTestPyramidForThePickedCluster) {
    const std::string failure = renderTestDrawing(*torus_, CullTest::Octagon, 5, "test_octagon");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, BoxTestCornersNumberedWithTheirVerdicts) {
    const std::string failure = renderTestDrawing(*torus_, CullTest::Aabb, 5, "test_aabb");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, GaussMapShowsNormalsCapsAndViewHorizon) {
    const PreparedMesh prepared = preparedOf(*torus_);
    const ClusterSet clusters = clustersOf(*torus_);
    const CullingInput cullInput{torus_->mesh, torus_->world, torus_->faces, torus_->bounds};
    const CullExplanation why = explainCull(cullInput, 5, decisionEye, CullTest::Apex);
    GaussMapScene gauss;
    gauss.show(gaussMapOf(prepared, clusters, 5, why), ConeMethod::Minimal, 5);
    const std::string failure = rendertest::checkAgainstBaseline(renderGaussMapToImage(gauss, 400, 300), "gauss_map");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, FacesColouredByLossClass) {
    ClusterScene scene = makeScene(*torus_);
    const PreparedMesh prepared = preparedOf(*torus_);
    const ClusterSet clusters = clustersOf(*torus_);
    const EyeMeasurement measurement = measureEye(prepared, clusters, decisionEye, CullTest::Sphere);
    scene.setFaceLoss(faceLosses(clusters, measurement, classifyFaces(torus_->mesh, torus_->world, torus_->faces, decisionEye)));
    scene.setFaceColoring(FaceColoring::Loss);
    scene.setLayerVisible(Layer::Cones, false);
    scene.setEye(decisionEye, {0, 0, 0});
    RenderOptions options = observer();
    options.cameraPosition = glm::dvec3(3.9, -3.6, -2.1);
    const std::string failure = rendertest::checkAgainstBaseline(renderToImage(scene, options), "loss");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, FacesColouredByAnABComparison) {
    // A: the torus in clusters of at most 64 triangles; B: at most 16. Seen from behind the eye.
    const PreparedMesh prepared = preparedOf(*torus_);
    const ClusterSet a = clustersOf(*torus_);
    const rendertest::SceneInput small = rendertest::loadDataset("torus.off", 16);
    const ClusterSet b = clustersOf(small);
    ClusterScene scene = ClusterScene(small.mesh, small.world, small.faces, small.partition, small.bounds);
    const EyeMeasurement measuredA = measureEye(prepared, a, decisionEye, CullTest::Apex);
    const EyeMeasurement measuredB = measureEye(prepared, b, decisionEye, CullTest::Apex);
    Settings apex;
    apex.tests = {CullTest::Apex};
    const Comparison comparison = compareClusterSets(prepared, {a, apex}, {b, apex}, {decisionEye});
    scene.setFaceComparison(faceDiff(a, measuredA.culled, b, measuredB.culled), clusterCountWarning(comparison));
    scene.setFaceColoring(FaceColoring::Comparison);
    scene.setLayerVisible(Layer::Cones, false);
    scene.setEye(decisionEye, {0, 0, 0});
    RenderOptions options = observer();
    options.cameraPosition.reset();
    options.fromBehind = true;
    const std::string failure = rendertest::checkAgainstBaseline(renderToImage(scene, options), "comparison");
    EXPECT_TRUE(failure.empty()) << failure;
}

TEST_F(RenderImages, ComparisonRejectsADifferentPicture) {
    // The same scene from another side must fail against the clusters baseline: the limits catch real changes.
    ClusterScene scene = makeScene(*torus_);
    RenderOptions options = observer();
    options.cameraPosition = glm::dvec3(-2.2, 2.6, 2.4);
    const auto image = renderToImage(scene, options);
    const std::string baseline = std::string(CONESCOPE_BASELINE_DIR) + "/clusters.png";
    const rendertest::ImageComparison comparison = rendertest::compareImages(image, rendertest::readPng(baseline));
    ASSERT_TRUE(comparison.sameSize) << "baseline " << baseline << " missing or of another size";
    EXPECT_TRUE(comparison.thresholdedError > rendertest::maxThresholdedError ||
                comparison.meanChannelDifference > rendertest::maxMeanChannelDifference);
}

}  // namespace
}  // namespace conescope
