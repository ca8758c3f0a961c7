// The legend as it is drawn: swatches beside their text, a colour bar for the fraction colourings,
// and one meaning per colour in any one legend.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <vtkImageData.h>

#include "RenderTestSupport.h"
#include "core/Culling.h"
#include "core/CullMap.h"
#include "core/Pipeline.h"
#include "core/CullTestGeometry.h"
#include "scene/ClusterScene.h"
#include "scene/GaussMapScene.h"
#include "scene/SceneRendering.h"

namespace conescope {
namespace {

using rendertest::SceneInput;

// The picture's pixels, bottom row first as VTK stores them.
struct Pixels {
    vtkSmartPointer<vtkImageData> image;
    int width = 0, height = 0, channels = 0;
    explicit Pixels(vtkSmartPointer<vtkImageData> rendered) : image(std::move(rendered)) {
        int dimensions[3];
        image->GetDimensions(dimensions);
        width = dimensions[0], height = dimensions[1];
        channels = image->GetNumberOfScalarComponents();
    }
    std::array<int, 3> at(int x, int y) const {
        const auto* p = static_cast<const unsigned char*>(image->GetScalarPointer()) + (size_t(y) * width + x) * channels;
        return {p[0], p[1], p[2]};
    }
    bool is(int x, int y, const Rgb& colour, int tolerance = 4) const {
        const std::array<int, 3> p = at(x, y);
        for (int c = 0; c < 3; ++c)
            if (std::abs(p[c] - int(std::lround(colour[c] * 255.0))) > tolerance) return false;
        return true;
    }
    bool white(int x, int y) const {
        const std::array<int, 3> p = at(x, y);
        return p[0] >= 245 && p[1] >= 245 && p[2] >= 245;
    }
};

struct Torus {
    SceneInput input = rendertest::loadDataset("torus.off", 64);
    PreparedMesh prepared;
    ClusterSet clusters;
    Torus() {
        prepared.culled = std::make_shared<Mesh>(input.mesh);
        prepared.world = input.world;
        prepared.faces = input.faces;
        clusters.partition = input.partition;
        clusters.bounds = input.bounds;
        clusters.cullMap = computeCullMap(clusters.bounds);
    }
    ClusterScene scene() const { return ClusterScene(input.mesh, input.world, input.faces, input.partition, input.bounds); }
    // Coloured by the sphere test's decisions from `eye`, against the oracle's.
    ClusterScene decidedScene() const;
};

const Eye eye = Eye::perspective({-1.6, 2.4, 1.5});

ClusterScene Torus::decidedScene() const {
    ClusterScene decided = scene();
    const CullingInput culling = cullingInput(prepared, clusters);
    decided.setClusterDecisions(cullClusters(culling, eye, CullTest::Sphere), cullClusters(culling, eye, CullTest::Oracle));
    decided.setFaceColoring(FaceColoring::CullDecision);
    return decided;
}

RenderOptions picture() {
    RenderOptions options;
    options.width = 400;
    options.height = 300;
    options.cameraPosition = glm::dvec3(2.2, -2.6, 2.4);
    options.focalPoint = glm::dvec3(0.0);
    options.viewUp = glm::dvec3(0.0, 0.0, 1.0);
    return options;
}

TEST(Legend, SwatchesAreWideAndLeaveAGapBeforeTheirText) {
    const Torus torus;
    ClusterScene scene = torus.decidedScene();
    const Pixels pixels(renderToImage(scene, picture()));
    // The missed-cull swatch: orange pixels inside the legend's box (the mesh behind it is dimmed).
    const SceneLegend::Rectangle box = scene.legend().box();
    int left = pixels.width, right = -1, bottom = pixels.height, top = -1;
    for (int y = int(box[1]); y < int(box[3]); ++y)
        for (int x = int(box[0]); x < int(box[2]); ++x)
            if (pixels.is(x, y, SceneColours::missedCull)) left = std::min(left, x), right = std::max(right, x), bottom = std::min(bottom, y), top = std::max(top, y);
    ASSERT_GE(right, 0) << "no missed-cull swatch drawn";
    EXPECT_GE(right - left + 1, 14) << "a swatch too narrow to read";
    EXPECT_GE(top - bottom + 1, 8);
    // Its text: the first white pixel right of the swatch on the swatch's rows.
    int text = pixels.width;
    for (int y = bottom; y <= top; ++y)
        for (int x = left; x < int(box[2]); ++x)
            if (pixels.white(x, y)) text = std::min(text, x);
    ASSERT_LT(text, pixels.width) << "no text beside the swatch";
    EXPECT_GE(text - right - 1, 4) << "the swatch runs into its text: swatch ends at " << right << ", text starts at " << text;
}

// On a HiDPI screen (Qt's device pixel ratio 2, so VTK draws text at 144 dpi) the box, rows and
// swatches grow with the text: every white text pixel near the legend lies inside its box, and the
// box is about twice the size it has at ratio 1.
TEST(Legend, AtPixelRatioTwoTheTextStaysInsideItsBox) {
    const Torus torus;
    ClusterScene scene = torus.decidedScene();
    scene.fitLegend(600, 1.0);
    const SceneLegend::Rectangle single = scene.legend().box();
    scene.fitLegend(600, 2.0);
    const SceneLegend::Rectangle box = scene.legend().box();
    EXPECT_NEAR(box[2] - box[0], 2.0 * (single[2] - single[0]), 0.1 * (single[2] - single[0]));
    EXPECT_NEAR(box[3] - box[1], 2.0 * (single[3] - single[1]), 0.1 * (single[3] - single[1]));
    RenderOptions options = picture();
    options.width = 800, options.height = 600, options.dpi = 144;
    options.cameraPosition = glm::dvec3(22.0, -26.0, 24.0);  // the torus small in the middle, away from the legend
    const Pixels pixels(renderToImage(scene, options));
    int inside = 0, outside = 0;
    for (int y = 0; y < std::min(pixels.height, int(2.0 * box[3])); ++y)
        for (int x = 0; x < std::min(pixels.width, int(2.0 * box[2])); ++x)
            if (pixels.white(x, y)) ++(x >= box[0] && x <= box[2] && y >= box[1] && y <= box[3] ? inside : outside);
    EXPECT_GT(inside, 200) << "no text drawn in the legend";
    EXPECT_EQ(outside, 0) << "text drawn outside the legend's box " << box[0] << " " << box[1] << " " << box[2] << " " << box[3];
}

TEST(Legend, FractionColouringsHaveAColourBarWithItsEndsWritten) {
    const Torus torus;
    ClusterScene scene = torus.scene();
    const size_t count = torus.clusters.bounds.count();
    std::vector<double> cull(count);
    std::vector<uint8_t> cullable(count);
    for (uint32_t c = 0; c < count; ++c) {
        cull[c] = cullFraction(torus.clusters.cullMap, c, CullTest::Apex);
        cullable[c] = torus.clusters.bounds.cones[c].cullable;
    }
    scene.setClusterFractions(cull, torus.clusters.cullMap.oracleFraction, cullable);
    for (FaceColoring coloring : {FaceColoring::CullFraction, FaceColoring::OracleFraction}) {
        scene.setFaceColoring(coloring);
        const SceneLegend& legend = scene.legend();
        const auto bar = std::find_if(legend.entries().begin(), legend.entries().end(), [](const LegendEntry& e) { return bool(e.scale); });
        ASSERT_NE(bar, legend.entries().end()) << toString(coloring);
        EXPECT_EQ((*bar->scale)[0], 0.0);
        EXPECT_EQ((*bar->scale)[1], maxClusterFraction);
        // Its ends are written beside its ends: "0" left of the bar, "0.5" right of it.
        const SceneLegend::Rectangle* barBox = nullptr;
        for (const SceneLegend::Rectangle& swatch : legend.swatches())
            if (swatch[2] - swatch[0] >= 100.0) barBox = &swatch;
        ASSERT_NE(barBox, nullptr) << "no colour bar 100 pixels wide";
        bool zero = false, half = false;
        for (const SceneLegend::Placed& text : legend.texts()) {
            const bool sameRow = std::abs(0.5 * (text.box[1] + text.box[3]) - 0.5 * ((*barBox)[1] + (*barBox)[3])) < 2.0;
            zero |= sameRow && text.text == "0" && text.box[2] <= (*barBox)[0];
            half |= sameRow && text.text == "0.5" && text.box[0] >= (*barBox)[2];
        }
        EXPECT_TRUE(zero && half) << toString(coloring);
    }
    // In the picture: a run of the ramp's colours over 100 pixels, from its dark end to its bright one.
    scene.setFaceColoring(FaceColoring::CullFraction);
    scene.setLayerVisible(Layer::Faces, true);
    const Pixels pixels(renderToImage(scene, picture()));
    int longest = 0;
    for (int y = 0; y < pixels.height / 2; ++y) {
        int first = -1;
        for (int x = 0; x < pixels.width; ++x) {
            const bool start = pixels.is(x, y, fractionRamp(1.0 / 128.0), 10);
            if (first < 0 && start) first = x;
            if (first >= 0 && pixels.is(x, y, fractionRamp(1.0 - 1.0 / 128.0), 10)) longest = std::max(longest, x - first);
        }
    }
    EXPECT_GE(longest, 100) << "no colour bar from the ramp's start to its end";
}

// Distance in RGB: colours nearer than this read as the same colour in a legend.
constexpr double alike = 0.35;

std::string meaning(const std::string& label) { return label.substr(0, label.find(" (")); }

// Every colour of every one- or two-colour entry (multi-colour swatches stand for many things at
// once: a colour per cluster, the decision colours on glyphs) with the meaning of its entry.
void expectOneMeaningPerColour(const std::vector<LegendEntry>& entries, const std::string& where) {
    std::vector<std::pair<std::string, Rgb>> colours;
    for (const LegendEntry& entry : entries)
        if (!entry.scale && entry.colours.size() <= 2)
            for (const Rgb& colour : entry.colours) colours.emplace_back(meaning(entry.label), colour);
    for (size_t i = 0; i < colours.size(); ++i)
        for (size_t j = i + 1; j < colours.size(); ++j) {
            if (colours[i].first == colours[j].first) continue;
            double distance = 0.0;
            for (int c = 0; c < 3; ++c) distance += (colours[i].second[c] - colours[j].second[c]) * (colours[i].second[c] - colours[j].second[c]);
            EXPECT_GE(std::sqrt(distance), alike) << where << ": '" << colours[i].first << "' and '" << colours[j].first << "' look alike";
        }
}

TEST(Legend, EachColourMeansOneThingInAnyLegend) {
    const Torus torus;
    ClusterScene scene = torus.scene();
    for (Layer layer : allLayers()) scene.setLayerVisible(layer, true);
    const PreparedMesh& prepared = torus.prepared;
    const EyeMeasurement measured = measureEye(prepared, torus.clusters, eye, CullTest::Octagon);
    scene.setEye(eye, glm::dvec3(0.0));
    scene.setClusterDecisions(measured.culled, allBackFacingClusters(measured));
    const std::vector<Facing> facing = classifyFaces(prepared.mesh(), prepared.world, prepared.faces, eye);
    scene.setFaceFacing(facing);
    scene.setFaceLoss(faceLosses(torus.clusters, measured, facing));
    std::vector<FaceDiff> diff(facing.size());
    for (size_t f = 0; f < diff.size(); ++f) diff[f] = FaceDiff(f % 4);
    scene.setFaceComparison(diff, "unequal");
    const size_t count = torus.clusters.bounds.count();
    std::vector<double> cull(count, 0.2);
    std::vector<uint8_t> cullable(count, 1);
    cullable[0] = 0;
    scene.setClusterFractions(cull, cull, cullable);
    scene.setHighlightedCluster(5);
    const CullingInput input = cullingInput(prepared, torus.clusters);
    for (CullTest test : {CullTest::Octagon, CullTest::Apex, CullTest::Aabb, CullTest::Sphere}) {
        scene.setTestDrawing(makeTestDrawing(input, 5, eye, test));
        for (FaceColoring coloring : allFaceColorings()) {
            scene.setFaceColoring(coloring);
            expectOneMeaningPerColour(scene.legend().entries(), toString(coloring) + " with the " + toString(test) + " test");
        }
    }
    // A LOD level's classes: the cut's three colours mean one thing each beside every other entry.
    ClusterLodClasses lod;
    for (uint32_t c = 0; c < count; ++c) lod.level.push_back(c % 3), lod.group.push_back(c / 4), lod.cut.push_back(uint8_t(c % 3));
    lod.levelCount = 3;
    scene.setClusterLod(lod);
    for (FaceColoring coloring : {FaceColoring::LodLevel, FaceColoring::LodGroup, FaceColoring::LodCut}) {
        scene.setFaceColoring(coloring);
        expectOneMeaningPerColour(scene.legend().entries(), toString(coloring) + " with LOD classes");
    }
    // The Gauss map's legend: its view vector is not any cone method's colour.
    GaussMapScene gauss;
    gauss.show(gaussMapOf(prepared, torus.clusters, 5, explainCull(input, 5, eye, CullTest::Apex)), ConeMethod::Minimal, 5);
    expectOneMeaningPerColour(gauss.legend().entries(), "Gauss map");
    // The eye, the view vector and a face lost to the partition, in one legend, are three colours.
    scene.setFaceColoring(FaceColoring::Loss);
    std::map<std::string, Rgb> shown;
    for (const LegendEntry& entry : scene.legend().entries()) shown.emplace(meaning(entry.label), entry.colours.front());
    ASSERT_EQ(shown.count("cull eye") + shown.count("view vector v") + shown.count("lost to the partition"), 3u);
}

}  // namespace
}  // namespace conescope
