// The lesson's pictures: each of the seven steps of one torus cluster (the layers it talks about,
// framed as lessonCamera frames it) and the textbook cross-section, against PNG baselines; the seven
// steps must differ from each other, and the lesson layer must hold what each step says.
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkActorCollection.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "RenderTestSupport.h"
#include "core/CrossSection.h"
#include "core/Lesson.h"
#include "core/Pipeline.h"
#include "io/MeshReader.h"
#include "scene/ClusterScene.h"
#include "scene/CrossSectionScene.h"
#include "scene/SceneRendering.h"

namespace conescope {
namespace {

// The torus in meshlets of at most 64 triangles, as the pipeline makes them.
class LessonPictures : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        MeshFile file = readMeshFile(std::string(CONESCOPE_DATASETS_DIR) + "/torus.off");
        prepared_ = new PreparedMesh(prepareMesh(std::make_shared<Mesh>(std::move(file.mesh)), "torus.off", false));
        Settings settings;
        settings.builder = Builder::Meshlet;
        settings.limits.maxTriangles = 64;
        settings.cones = {ConeMethod::Minimal};  // the lesson's pair: the minimal cone beside the article's average one
        clusters_ = new ClusterSet(buildClusters(*prepared_, settings));
        // The first cluster the octagon test loses from this eye: every face turned away, yet drawn.
        for (uint32_t c = 0; c < clusters_->bounds.count() && !lesson_; ++c) {
            Lesson lesson = makeLesson(*prepared_, *clusters_, c, eye, CullTest::Octagon);
            if (lesson.outcome == LessonOutcome::LostToTest) lesson_ = new Lesson(std::move(lesson));
        }
    }
    static void TearDownTestSuite() {
        delete lesson_;
        delete clusters_;
        delete prepared_;
    }

    // The scene as the window shows step `step`: its layers, colouring, decisions, eye and test.
    static std::unique_ptr<ClusterScene> sceneAt(int step) {
        auto scene = std::make_unique<ClusterScene>(prepared_->mesh(), prepared_->world, prepared_->faces, clusters_->partition,
                                                    clusters_->bounds);
        const EyeMeasurement measured = measureEye(*prepared_, *clusters_, eye, CullTest::Octagon);
        scene->setClusterDecisions(measured.culled, allBackFacingClusters(measured));
        scene->setFaceLoss(faceLosses(*clusters_, measured, classifyFaces(prepared_->mesh(), prepared_->world, prepared_->faces, eye)));
        scene->setEye(eye, glm::dvec3(prepared_->box.center()));
        scene->setHighlightedCluster(int(lesson_->cluster));
        scene->setTestDrawing(makeTestDrawing(cullingInput(*prepared_, *clusters_), lesson_->cluster, eye, CullTest::Octagon));
        for (const auto& [layer, shown] : lessonLayers(step)) scene->setLayerVisible(layer, shown);
        scene->setFaceColoring(lessonColouring(step));
        scene->setLessonDrawing({step, *lesson_});
        return scene;
    }

    static vtkSmartPointer<vtkImageData> picture(const ClusterScene& scene, int step) {
        RenderOptions options;
        options.width = 400;
        options.height = 300;
        const CameraPlacement camera = lessonCamera(*lesson_, step, options.viewAngleDegrees);
        options.cameraPosition = camera.position;
        options.focalPoint = camera.focalPoint;
        options.viewUp = camera.viewUp;
        return renderToImage(scene, options);
    }

    static inline const Eye eye = Eye::perspective({-1.6, 2.4, 1.5});
    static PreparedMesh* prepared_;
    static ClusterSet* clusters_;
    static Lesson* lesson_;
};
PreparedMesh* LessonPictures::prepared_ = nullptr;
ClusterSet* LessonPictures::clusters_ = nullptr;
Lesson* LessonPictures::lesson_ = nullptr;

TEST_F(LessonPictures, EachStepShowsWhatItTalksAbout) {
    ASSERT_TRUE(lesson_);
    for (int step = 1; step <= kLessonStepCount; ++step) {
        const std::unique_ptr<ClusterScene> scene = sceneAt(step);
        std::string legend;
        for (const LegendEntry& entry : scene->legend().entries()) legend += entry.label + "\n";
        EXPECT_NE(legend.find("cluster " + std::to_string(lesson_->cluster)), std::string::npos) << legend;
        EXPECT_EQ(legend.find("its face normals") != std::string::npos, step == 1) << step;
        EXPECT_EQ(legend.find("Gauss sphere") != std::string::npos, step == 2 || step == 3) << step;
        EXPECT_EQ(legend.find("minimal cone") != std::string::npos, step == 3) << step;
        EXPECT_EQ(legend.find("average cone") != std::string::npos, step == 3) << step;
        // Side by side (step 7): both clusters, their view vectors and axes, no bound.
        EXPECT_EQ(legend.find("apex") != std::string::npos, step >= 4 && step != kSideBySideStep) << step;
        EXPECT_EQ(legend.find("view vector v") != std::string::npos, step >= 5) << step;
        EXPECT_EQ(legend.find("lost to the test") != std::string::npos, step == 6) << legend;
        if (step == kSideBySideStep) {
            ASSERT_TRUE(lesson_->partner);
            EXPECT_NE(legend.find("cluster " + std::to_string(lesson_->partner->cluster) + ", culled"), std::string::npos) << legend;
            EXPECT_NE(legend.find("cluster " + std::to_string(lesson_->cluster) + ", drawn"), std::string::npos) << legend;
        }
        EXPECT_FALSE(scene->layerVisible(Layer::Cones));
        EXPECT_FALSE(scene->layerVisible(Layer::Boxes));
    }
    // Step 0 draws nothing.
    const std::unique_ptr<ClusterScene> none = sceneAt(1);
    none->setLessonDrawing({});
    EXPECT_EQ(none->actor(Layer::Lesson)->GetMapper()->GetInput()->GetNumberOfCells(), 0);
}

TEST_F(LessonPictures, EveryStepADifferentPictureMatchingItsBaseline) {
    ASSERT_TRUE(lesson_);
    std::vector<vtkSmartPointer<vtkImageData>> pictures;
    for (int step = 1; step <= kLessonStepCount; ++step) {
        const std::unique_ptr<ClusterScene> scene = sceneAt(step);
        scene->setLayerVisible(Layer::Legend, false);  // checked above; here it would hide the picture
        pictures.push_back(picture(*scene, step));
        const std::string failure = rendertest::checkAgainstBaseline(pictures.back(), "lesson_step" + std::to_string(step));
        EXPECT_TRUE(failure.empty()) << failure;
    }
    for (size_t a = 0; a < pictures.size(); ++a)
        for (size_t b = a + 1; b < pictures.size(); ++b)
            // More apart than any picture may be from its own baseline.
            EXPECT_GT(rendertest::compareImages(pictures[a], pictures[b]).meanChannelDifference, rendertest::maxMeanChannelDifference) << a + 1 << " and " << b + 1;
}

TEST_F(LessonPictures, CrossSectionMatchesItsBaseline) {
    ASSERT_TRUE(lesson_);
    CrossSectionScene scene;
    scene.show(crossSectionOf(*lesson_, cullingInput(*prepared_, *clusters_)));
    EXPECT_TRUE(scene.hasSection());
    const std::string failure = rendertest::checkAgainstBaseline(renderCrossSectionToImage(scene, 480, 480), "cross_section");
    EXPECT_TRUE(failure.empty()) << failure;
}

// The scene's actors in a renderer that draw something of `kind` (lines or points) in `colour`.
size_t drawnIn(const ClusterScene& scene, const Rgb& colour, bool lines) {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    scene.addTo(renderer);
    size_t found = 0;
    vtkActorCollection* actors = renderer->GetActors();
    actors->InitTraversal();
    while (vtkActor* actor = actors->GetNextActor()) {
        auto* data = vtkPolyData::SafeDownCast(actor->GetMapper() ? actor->GetMapper()->GetInput() : nullptr);
        if (!data || !actor->GetVisibility()) continue;
        double c[3];
        actor->GetProperty()->GetColor(c);
        const bool same = std::abs(c[0] - colour[0]) < 1e-6 && std::abs(c[1] - colour[1]) < 1e-6 && std::abs(c[2] - colour[2]) < 1e-6;
        if (same && (lines ? data->GetNumberOfLines() : data->GetNumberOfVerts()) > 0) ++found;
    }
    scene.removeFrom(renderer);
    return found;
}

// A closed cube as one cluster has no cone: its lesson draws no axis V1 (step 3) and no apex (step 4),
// nor does the test layer draw an axis; a torus cluster with a cone gets both.
TEST(LessonLayerStructure, AClusterWithoutAConeGetsNoAxisAndNoApex) {
    for (const bool cone : {false, true}) {
        MeshFile file = readMeshFile(std::string(CONESCOPE_DATASETS_DIR) + (cone ? "/torus.off" : "/cube.off"));
        const PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(std::move(file.mesh)), "mesh", false);
        Settings settings;
        settings.builder = cone ? Builder::Meshlet : Builder::KMeans;
        settings.clusterCount = 1;
        const ClusterSet clusters = buildClusters(prepared, settings);
        const Eye eye = Eye::perspective({3.0, 2.0, 4.0});
        const Lesson lesson = makeLesson(prepared, clusters, 0, eye, CullTest::Apex);
        ASSERT_EQ(lesson.why.cullable, cone);
        ClusterScene scene(prepared.mesh(), prepared.world, prepared.faces, clusters.partition, clusters.bounds);
        scene.setEye(eye, glm::dvec3(prepared.box.center()));
        scene.setTestDrawing(makeTestDrawing(cullingInput(prepared, clusters), 0, eye, CullTest::Apex));
        for (const int step : {3, 4, 5}) {
            for (const auto& [layer, shown] : lessonLayers(step)) scene.setLayerVisible(layer, shown);
            scene.setLessonDrawing({step, lesson});
            std::string legend;
            for (const LegendEntry& entry : scene.legend().entries()) legend += entry.label + "\n";
            EXPECT_EQ(legend.find("cone axis V1") != std::string::npos, cone && step != 4) << step << legend;
            EXPECT_EQ(legend.find("apex") != std::string::npos, cone && step >= 4) << step << legend;
            // The axis: a white line (the lesson's at step 3, the test layer's at step 5); the apex: a yellow point.
            if (step != 4) {
                EXPECT_EQ(drawnIn(scene, SceneColours::normalTip, true), cone ? 1u : 0u) << step;
            }
            if (step == 4) {
                EXPECT_EQ(drawnIn(scene, SceneColours::highlight, false), cone ? 1u : 0u);
            }
        }
    }
}

}  // namespace
}  // namespace conescope
