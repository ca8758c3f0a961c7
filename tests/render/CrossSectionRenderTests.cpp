// The cross-section's picture against the core, through the JSON the export writes beside it: the
// drawn angles are the true ones, v lies in the drawn region exactly when the test culls, and no two
// texts overlap, for every test on a torus and on awkward clusters (normals all at one angle, no
// cone, a flat patch whose apex is its centre, a far eye), at 1280x720, 1920x1080 and at twice the
// dots per inch. The pictures confirm it: under each text's box nothing else is drawn, and the text
// drawn lies in its box.
#include <cmath>
#include <memory>
#include <string>

#include <gtest/gtest.h>
#include <vtkImageData.h>

#include "RenderTestSupport.h"
#include "TestMeshes.h"
#include "core/CrossSection.h"
#include "core/Lesson.h"
#include "core/Pipeline.h"
#include "io/CrossSectionIO.h"
#include "io/MeshReader.h"
#include "scene/CrossSectionScene.h"
#include "scene/LabelPlacement.h"
#include "scene/SceneRendering.h"

namespace conescope {
namespace {

using nlohmann::json;

struct Case {
    std::string name;
    std::shared_ptr<PreparedMesh> mesh;
    std::shared_ptr<ClusterSet> clusters;
    uint32_t cluster = 0;
    Eye eye;
};

Case caseOf(const std::string& name, Mesh mesh, Builder builder, size_t limit, uint32_t cluster, const Eye& eye) {
    Settings settings;
    settings.builder = builder;
    if (builder == Builder::KMeans)
        settings.clusterCount = limit;
    else
        settings.limits.maxTriangles = limit;
    auto prepared = std::make_shared<PreparedMesh>(prepareMesh(std::make_shared<Mesh>(std::move(mesh)), name, false));
    auto clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, settings));
    return {name, prepared, clusters, cluster, eye};
}

const std::vector<Case>& cases() {
    static const std::vector<Case> all = [] {
        Mesh torus = readMeshFile(std::string(CONESCOPE_DATASETS_DIR) + "/torus.off").mesh;
        return std::vector<Case>{
            caseOf("torus", torus, Builder::Meshlet, 64, 25, Eye::perspective({-1.6, 2.4, 1.5})),
            caseOf("torus-far", torus, Builder::Meshlet, 64, 25, Eye::orthographicAlong({0.3, -0.9, 0.2})),
            caseOf("roof", testmesh::roof(40, 0.8), Builder::KMeans, 1, 0, Eye::perspective({0.2, 0.3, -3.0})),
            caseOf("cube", testmesh::quadCube(), Builder::KMeans, 1, 0, Eye::perspective({3.0, 2.0, 4.0})),
            caseOf("flat", testmesh::flatPatch(4), Builder::KMeans, 1, 0, Eye::perspective({0.3, 0.6, -2.0})),
        };
    }();
    return all;
}

const std::vector<CullTest> everyTest = {CullTest::Apex, CullTest::Sphere, CullTest::MeshoptSphere, CullTest::Aabb, CullTest::AabbFast,
                                         CullTest::Vertices, CullTest::Octagon, CullTest::Oracle, CullTest::MeshoptApexF32,
                                         CullTest::MeshoptSphereS8, CullTest::CadsceneBoxS8, CullTest::OctagonCompact};

struct Size {
    int width, height, dpi;
};
const std::vector<Size> sizes = {{1280, 720, 72}, {1920, 1080, 72}, {1280, 720, 144}};

bool inside(const json& ranges, double angle) {
    for (const json& range : ranges)
        if (range[0].get<double>() < angle && angle < range[1].get<double>()) return true;
    return false;
}

double degreesTo(const glm::dvec3& n, const glm::dvec3& axis) {
    return glm::degrees(std::atan2(glm::length(glm::cross(n, axis)), glm::dot(n, axis)));
}

// The JSON against the core's lesson: angles, verdict, region, and texts apart from each other.
void checkJson(const json& drawn, const Lesson& lesson, const Size& size, const std::string& context) {
    const CullExplanation& why = lesson.why;
    const glm::dvec3 axis = glm::normalize(why.axis);
    ASSERT_EQ(drawn["normals_deg"].size(), lesson.normals.size()) << context;
    for (size_t i = 0; i < lesson.normals.size(); ++i)
        EXPECT_NEAR(std::abs(drawn["normals_deg"][i].get<double>()), degreesTo(lesson.normals[i], axis), 1e-9) << context;
    if (why.cullable)
        EXPECT_NEAR(drawn["half_angle_deg"].get<double>(), why.halfAngleDegrees, 1e-9) << context;
    else
        EXPECT_TRUE(drawn["half_angle_deg"].is_null()) << context;
    EXPECT_EQ(drawn["culls"].get<bool>(), why.culled) << context;
    const double v = drawn["v_deg"].get<double>();
    if (drawn.contains("points_deg")) {
        double lowest = 2.0;
        for (int i = 0; i < 8 && lesson.test != CullTest::Vertices; ++i) lowest = std::min(lowest, why.cornerDotAxis[i]);
        if (lesson.test == CullTest::Vertices) lowest = why.margin + why.threshold;
        if (std::isfinite(lowest)) {
            EXPECT_NEAR(std::cos(glm::radians(v)), lowest, 1e-9) << context;
        }
    } else {
        EXPECT_NEAR(v, degreesTo(why.view, axis), 1e-9) << context;
    }
    const bool asked = drawn["cull_region_rule"] == "asked";
    const bool decided = asked ? why.culled == why.exactCulled : !std::isnan(why.margin) && std::abs(why.margin) > 1e-7;
    if (decided) {
        EXPECT_EQ(inside(drawn["cull_region_deg"], v), why.culled) << context << " v " << v;
    }
    if (!decided && !asked) {
        EXPECT_FALSE(inside(drawn["cull_region_deg"], v)) << context;
    }
    // Every text in the picture, none over another, none left out.
    const json& labels = drawn["labels"];
    EXPECT_GE(labels.size(), 3u) << context;
    EXPECT_TRUE(drawn["labels_left_out"].empty()) << context << " " << drawn["labels_left_out"].dump();
    for (size_t a = 0; a < labels.size(); ++a) {
        const json& box = labels[a]["box"];
        EXPECT_GE(box[0].get<double>(), 0.0) << context;
        EXPECT_GE(box[1].get<double>(), 0.0) << context;
        EXPECT_LE(box[2].get<double>(), size.width) << context;
        EXPECT_LE(box[3].get<double>(), size.height) << context;
        const PixelBox first{box[0], box[1], box[2], box[3]};
        for (size_t b = a + 1; b < labels.size(); ++b) {
            const json& other = labels[b]["box"];
            EXPECT_FALSE(first.intersects({other[0], other[1], other[2], other[3]}))
                << context << ": '" << labels[a]["text"] << "' and '" << labels[b]["text"] << "'";
        }
    }
}

std::array<int, 3> pixel(vtkImageData* image, int x, int y) {
    // Image rows run from the bottom; the JSON's boxes from the top.
    const int height = image->GetDimensions()[1];
    const auto* p = static_cast<unsigned char*>(image->GetScalarPointer(x, height - 1 - y, 0));
    return {p[0], p[1], p[2]};
}

// Under each text's box only the background (white, or the pale eyes that cull) is drawn; what the
// texts add to the picture lies within their boxes.
void checkPixels(CrossSectionScene& scene, const json& drawn, const Size& size, const std::string& context, const std::string& file) {
    scene.setTextVisible(false);
    const vtkSmartPointer<vtkImageData> bare = renderCrossSectionToImage(scene, size.width, size.height, size.dpi);
    scene.setTextVisible(true);
    const vtkSmartPointer<vtkImageData> full = renderCrossSectionToImage(scene, size.width, size.height, size.dpi);
    writePng(full, std::string(CONESCOPE_RENDER_OUTPUT_DIR) + "/" + file);  // to look at
    const json& labels = drawn["labels"];
    size_t covered = 0;
    for (const json& label : labels) {
        const json& box = label["box"];
        for (int y = int(box[1]) + 1; y < int(box[3]) - 1; ++y)
            for (int x = int(box[0]) + 1; x < int(box[2]) - 1; ++x) {
                const std::array<int, 3> c = pixel(bare, x, y);
                const bool background = (c[0] == 255 && c[1] == 255 && c[2] == 255) || (c[0] >= 215 && c[1] >= 225 && c[2] == 255);
                ASSERT_TRUE(background) << context << ": '" << label["text"] << "' lies on a drawn pixel (" << c[0] << "," << c[1] << ","
                                        << c[2] << ") at " << x << "," << y;
                ++covered;
            }
    }
    EXPECT_GT(covered, 0u);
    for (int y = 0; y < size.height; ++y)
        for (int x = 0; x < size.width; ++x) {
            if (pixel(bare, x, y) == pixel(full, x, y)) continue;
            bool inBox = false;
            for (const json& label : labels) {
                const json& box = label["box"];
                inBox |= x >= box[0].get<double>() - 2 && x <= box[2].get<double>() + 2 && y >= box[1].get<double>() - 2 &&
                         y <= box[3].get<double>() + 2;
            }
            ASSERT_TRUE(inBox) << context << ": text drawn outside every box at " << x << "," << y;
        }
}

TEST(CrossSectionPictures, TheJsonIsTheCoresForEveryTestAndEveryTextHasItsOwnPlace) {
    for (const Case& c : cases()) {
        const CullingInput input = cullingInput(*c.mesh, *c.clusters);
        for (CullTest test : everyTest) {
            const Lesson lesson = makeLesson(*c.mesh, *c.clusters, c.cluster, c.eye, test);
            const CrossSection section = crossSectionOf(lesson, input);
            CrossSectionScene scene;
            scene.show(section);
            for (const Size& size : sizes) {
                scene.fitTo(size.width, size.height, size.dpi);
                const json drawn = crossSectionToJson(section, scene.labels(), scene.leftOut(), size.width, size.height);
                checkJson(drawn, lesson, size,
                          c.name + " " + toString(test) + " " + std::to_string(size.width) + "x" + std::to_string(size.height) + "@" +
                              std::to_string(size.dpi));
            }
        }
    }
}

TEST(CrossSectionPictures, NoTextLiesOnAnythingDrawnAndEachTextIsInItsBox) {
    const std::vector<std::pair<size_t, CullTest>> shown = {{0, CullTest::Apex}, {0, CullTest::Sphere}, {0, CullTest::Aabb},
                                                            {2, CullTest::Octagon}, {3, CullTest::Apex}, {4, CullTest::Apex},
                                                            {1, CullTest::MeshoptSphereS8}};
    for (const auto& [which, test] : shown) {
        const Case& c = cases()[which];
        const Lesson lesson = makeLesson(*c.mesh, *c.clusters, c.cluster, c.eye, test);
        CrossSectionScene scene;
        scene.show(crossSectionOf(lesson, cullingInput(*c.mesh, *c.clusters)));
        for (const Size& size : sizes) {
            const std::string context = c.name + " " + toString(test) + " " + std::to_string(size.width) + "@" + std::to_string(size.dpi);
            scene.fitTo(size.width, size.height, size.dpi);
            const json drawn = crossSectionToJson(crossSectionOf(lesson, cullingInput(*c.mesh, *c.clusters)), scene.labels(),
                                                  scene.leftOut(), size.width, size.height);
            checkPixels(scene, drawn, size, context,
                        "cross-section-" + c.name + "-" + toString(test) + "-" + std::to_string(size.width) + "@" + std::to_string(size.dpi) + ".png");
        }
    }
}

TEST(CrossSectionPictures, LabelsAvoidEveryLineAndEachOther) {
    // A crowd of lines through one point and labels that all want to sit there.
    LabelPlacer placer(400, 300, {0.0, 0.0, 400.0, 300.0}, 2.0, 8.0);
    std::vector<std::vector<glm::dvec2>> lines;
    for (int k = 0; k < 24; ++k) {
        const double angle = 2.0 * M_PI * k / 24;
        lines.push_back({{200.0, 150.0}, {200.0 + 100.0 * std::cos(angle), 150.0 + 100.0 * std::sin(angle)}});
        placer.blockLine(lines.back(), 2.0);
    }
    std::vector<PixelBox> boxes;
    for (int k = 0; k < 8; ++k) {
        const std::optional<LabelSpot> spot = placer.place({200.0, 150.0}, {1.0, 0.0}, {60.0, 14.0}, 400.0);
        ASSERT_TRUE(spot) << k;
        for (const PixelBox& box : boxes) EXPECT_FALSE(box.intersects(spot->box));
        for (const auto& line : lines) {
            // No point of a line (two pixels wide) within the box.
            for (int s = 0; s <= 200; ++s) {
                const glm::dvec2 p = line[0] + (line[1] - line[0]) * (s / 200.0);
                EXPECT_FALSE(p.x > spot->box.x0 - 1 && p.x < spot->box.x1 + 1 && p.y > spot->box.y0 - 1 && p.y < spot->box.y1 + 1) << k;
            }
        }
        boxes.push_back(spot->box);
    }
}

}  // namespace
}  // namespace conescope
