#include "scene/ClusterScene.h"

#include <vtkActor.h>
#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>

#include "scene/BordersLayer.h"
#include "scene/EyeLayer.h"
#include "scene/EyeViewActors.h"
#include "scene/FacesLayer.h"
#include "scene/GlyphLayer.h"
#include "scene/HighlightLayer.h"
#include "scene/LessonLayer.h"
#include "scene/NormalsLayer.h"
#include "scene/SceneData.h"
#include "scene/SceneLegend.h"
#include "scene/CullTestLayer.h"

namespace conescope {

struct ClusterScene::Impl {
    Impl(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faceGeometry, const Partition& partition,
         const ClusterBounds& clusterBounds)
        : data(mesh, world, partition, clusterBounds), faces(data), borders(data, mesh, partition), cones(conesLayer(data)),
          normals(data, faceGeometry, partition), boxes(boxesLayer(data)), spheres(spheresLayer(data)), eye(data),
          highlight(data), test(data), lesson(data), eyeView(data) {}

    SceneData data;
    FacesLayer faces;
    BordersLayer borders;
    GlyphLayer cones;
    NormalsLayer normals;
    GlyphLayer boxes, spheres;
    EyeLayer eye;
    HighlightLayer highlight;
    CullTestLayer test;
    LessonLayer lesson;
    SceneLegend legend;
    EyeViewActors eyeView;
    FaceColoring coloring = FaceColoring::Cluster;

    // nullptr for Legend, which is no SceneLayer.
    SceneLayer* layer(Layer which) {
        switch (which) {
        case Layer::Faces: return &faces;
        case Layer::Borders: return &borders;
        case Layer::Cones: return &cones;
        case Layer::Normals: return &normals;
        case Layer::Boxes: return &boxes;
        case Layer::Spheres: return &spheres;
        case Layer::Eye: return &eye;
        case Layer::Highlight: return &highlight;
        case Layer::Test: return &test;
        case Layer::Legend: return nullptr;
        case Layer::Lesson: return &lesson;
        }
        return nullptr;
    }
    // The order the actors go into a renderer: the picked cluster and its test over the glyphs, the eye last.
    std::vector<SceneLayer*> drawingOrder() {
        return {&faces, &borders, &cones, &normals, &boxes, &spheres, &highlight, &test, &lesson, &eye};
    }

    // The legend lists the visible layers' entries in the order of allLayers().
    void updateLegend() {
        legendStale = false;
        std::vector<LegendEntry> entries;
        for (Layer which : allLayers())
            if (SceneLayer* shown = layer(which); shown && shown->visible() && shown->hasContent())
                shown->addLegendEntries(coloring, entries);
        legend.show(entries);
    }
    // Laying the legend out measures its text with VTK's FreeType tools, which are not thread-safe:
    // a scene made on a worker thread lays it out when it is first added to a view or asked for.
    bool legendStale = true;
    void updateStaleLegend() {
        if (legendStale) updateLegend();
    }
};

ClusterScene::ClusterScene(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                           const Partition& partition, const ClusterBounds& bounds) {
    checkSceneInput(mesh, world, faces, partition, bounds);
    impl_ = std::make_unique<Impl>(mesh, world, faces, partition, bounds);
    for (Layer layer : allLayers()) {
        const bool shown = !(layer == Layer::Normals || layer == Layer::Boxes || layer == Layer::Spheres);
        if (layer == Layer::Legend) impl_->legend.setVisible(shown);
        else impl_->layer(layer)->setVisible(shown);
    }
}

ClusterScene::~ClusterScene() = default;
ClusterScene::ClusterScene(ClusterScene&&) noexcept = default;
ClusterScene& ClusterScene::operator=(ClusterScene&&) noexcept = default;

void ClusterScene::addTo(vtkRenderer* renderer) const {
    for (SceneLayer* layer : impl_->drawingOrder())
        for (vtkActor* actor : layer->actors()) renderer->AddActor(actor);
    for (SceneLayer* layer : impl_->drawingOrder())
        for (vtkProp* overlay : layer->overlays()) renderer->AddViewProp(overlay);
    impl_->updateStaleLegend();
    renderer->AddViewProp(impl_->legend.prop());
}

void ClusterScene::removeFrom(vtkRenderer* renderer) const {
    for (SceneLayer* layer : impl_->drawingOrder())
        for (vtkActor* actor : layer->actors()) renderer->RemoveActor(actor);
    for (SceneLayer* layer : impl_->drawingOrder())
        for (vtkProp* overlay : layer->overlays()) renderer->RemoveViewProp(overlay);
    renderer->RemoveViewProp(impl_->legend.prop());
}

void ClusterScene::setLayerVisible(Layer layer, bool visible) {
    if (layer == Layer::Legend) impl_->legend.setVisible(visible);
    else impl_->layer(layer)->setVisible(visible);
    impl_->updateLegend();
}

bool ClusterScene::layerVisible(Layer layer) const {
    return layer == Layer::Legend ? impl_->legend.visible() : impl_->layer(layer)->visible();
}

void ClusterScene::setFaceColoring(FaceColoring coloring) {
    impl_->coloring = coloring;
    for (SceneLayer* layer : impl_->drawingOrder()) layer->recolour(coloring);
    impl_->updateLegend();
}

FaceColoring ClusterScene::faceColoring() const { return impl_->coloring; }

void ClusterScene::setClusterDecisions(const std::vector<uint8_t>& culled, const std::vector<uint8_t>& allBackFacing) {
    impl_->data.tables.setDecisions(culled, allBackFacing);
    impl_->updateLegend();
}

void ClusterScene::clearClusterDecisions() {
    impl_->data.tables.clearDecisions();
    impl_->updateLegend();
}

bool ClusterScene::hasClusterDecisions() const { return impl_->data.tables.hasDecisions(); }

void ClusterScene::setFaceFacing(const std::vector<Facing>& facing) {
    impl_->faces.setFaceFacing(facing);
    impl_->updateLegend();
}

void ClusterScene::setFaceLoss(const std::vector<FaceLoss>& loss) {
    impl_->faces.setFaceLoss(loss);
    impl_->updateLegend();
}

void ClusterScene::setFaceComparison(const std::vector<FaceDiff>& comparison, const std::string& warning) {
    impl_->faces.setFaceComparison(comparison, warning);
    impl_->updateLegend();
}

void ClusterScene::setSubGroups(const std::vector<uint8_t>& groupOfFace, const std::vector<uint8_t>& culledGroups, uint32_t cones) {
    impl_->faces.setSubGroups(groupOfFace, culledGroups, cones);
    impl_->updateLegend();
}

void ClusterScene::setClusterLod(const ClusterLodClasses& lod) {
    impl_->data.tables.setLod(lod);
    impl_->updateLegend();
}

void ClusterScene::setClusterFractions(const std::vector<double>& cullFraction, const std::vector<double>& oracleFraction,
                                       const std::vector<uint8_t>& cullable) {
    impl_->data.tables.setFractions(cullFraction, oracleFraction, cullable);
    impl_->updateLegend();
}

void ClusterScene::setTestDrawing(const CullTestDrawing& drawing) {
    impl_->test.setDrawing(drawing);
    impl_->updateLegend();
}

const CullTestDrawing& ClusterScene::testDrawing() const { return impl_->test.drawing(); }

void ClusterScene::setLessonDrawing(const LessonDrawing& drawing) {
    impl_->lesson.setDrawing(drawing);
    impl_->updateLegend();
}

const LessonDrawing& ClusterScene::lessonDrawing() const { return impl_->lesson.drawing(); }

void ClusterScene::setEye(const Eye& eye, const glm::dvec3& lookAt) {
    impl_->eye.setEye(eye, lookAt);
    impl_->updateLegend();
}

bool ClusterScene::hasEye() const { return impl_->eye.hasEye(); }
const Eye& ClusterScene::eye() const { return impl_->eye.eye(); }

void ClusterScene::setHighlightedCluster(int cluster) {
    impl_->highlight.setCluster(cluster);
    impl_->updateLegend();
}

int ClusterScene::highlightedCluster() const { return impl_->highlight.cluster(); }

int ClusterScene::clusterOfCell(vtkActor* pickedActor, vtkIdType cellId) const {
    if (!pickedActor) return -1;
    for (SceneLayer* layer : impl_->drawingOrder())
        if (layer->owns(pickedActor)) return layer->clusterOfCell(pickedActor, cellId);
    return impl_->eyeView.owns(pickedActor) ? clusterIdOfCell(pickedActor, cellId) : -1;
}

vtkSmartPointer<vtkActor> ClusterScene::makeVisibleClustersActor() const { return impl_->eyeView.makeActor(); }

void ClusterScene::applyEyeToCamera(vtkCamera* camera) const { impl_->eye.applyToCamera(camera); }

size_t ClusterScene::clusterCount() const { return impl_->data.palette.size(); }
size_t ClusterScene::faceCount() const { return impl_->data.clusterOfFace.size(); }
std::array<double, 6> ClusterScene::meshBounds() const {
    const Aabb& box = impl_->data.worldBox;
    return {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
}
double ClusterScene::meanEdgeLength() const { return impl_->data.meanEdge; }
const std::vector<Rgb>& ClusterScene::palette() const { return impl_->data.palette; }
vtkPolyData* ClusterScene::meshPolyData() const { return impl_->data.meshData; }
vtkPolyData* ClusterScene::borderPolyData() const { return impl_->borders.lines(); }
vtkPolyData* ClusterScene::conePolyData() const { return impl_->cones.glyphs(); }
vtkPolyData* ClusterScene::boxPolyData() const { return impl_->boxes.glyphs(); }
vtkPolyData* ClusterScene::spherePolyData() const { return impl_->spheres.glyphs(); }
vtkLookupTable* ClusterScene::paletteLookupTable() const { return impl_->data.tables.palette; }
vtkLookupTable* ClusterScene::decisionLookupTable() const { return impl_->data.tables.decision; }
vtkLookupTable* ClusterScene::visibleClustersLookupTable() const { return impl_->data.tables.visible; }
const SceneLegend& ClusterScene::legend() const {
    impl_->updateStaleLegend();
    return impl_->legend;
}

void ClusterScene::fitLegend(int viewHeight, double pixelRatio) {
    impl_->updateStaleLegend();
    impl_->legend.fitTo(viewHeight, pixelRatio);
}

vtkActor* ClusterScene::actor(Layer layer) const {
    SceneLayer* shown = impl_->layer(layer);
    return shown ? shown->actors().front() : nullptr;
}

}  // namespace conescope
