#include "scene/ClusterScene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkArrowSource.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkConeSource.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkIntArray.h>
#include <vtkLegendBoxActor.h>
#include <vtkLineSource.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkSphereSource.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWeakPointer.h>

#include "scene/SceneGeometry.h"

namespace conescope {

const std::vector<Layer>& allLayers() {
    static const std::vector<Layer> layers = {Layer::Faces, Layer::Borders, Layer::Cones,     Layer::Normals, Layer::Boxes,
                                              Layer::Spheres, Layer::Eye,   Layer::Highlight, Layer::Legend};
    return layers;
}

std::string toString(Layer layer) {
    switch (layer) {
    case Layer::Faces: return "faces";
    case Layer::Borders: return "borders";
    case Layer::Cones: return "cones";
    case Layer::Normals: return "normals";
    case Layer::Boxes: return "boxes";
    case Layer::Spheres: return "spheres";
    case Layer::Eye: return "eye";
    case Layer::Highlight: return "highlight";
    case Layer::Legend: return "legend";
    }
    return "unknown";
}

std::string toString(FaceColoring coloring) {
    switch (coloring) {
    case FaceColoring::Cluster: return "cluster";
    case FaceColoring::CullDecision: return "decision";
    case FaceColoring::FaceFacing: return "facing";
    }
    return "unknown";
}

namespace {

constexpr int coneSegments = 32;
constexpr int sphereSegments = 24;
// Legend size in pixels.
constexpr double legendMargin = 8.0, legendWidth = 210.0, legendEntryHeight = 16.0;

// A table of `count` colours for integer values 0 .. count-1: the range is widened by half a step on
// each side so value v falls in the middle of entry v.
vtkSmartPointer<vtkLookupTable> indexedTable(size_t count) {
    auto table = vtkSmartPointer<vtkLookupTable>::New();
    table->SetNumberOfTableValues(vtkIdType(std::max<size_t>(count, 1)));
    table->SetTableRange(-0.5, double(std::max<size_t>(count, 1)) - 0.5);
    return table;
}

void setEntry(vtkLookupTable* table, size_t index, const Rgb& colour, double alpha = 1.0) {
    table->SetTableValue(vtkIdType(index), colour[0], colour[1], colour[2], alpha);
}

// A mapper that colours cells through `table` by an int cell array, without touching the array.
vtkSmartPointer<vtkPolyDataMapper> cellArrayMapper(vtkPolyData* input, const char* arrayName, vtkLookupTable* table) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(input);
    mapper->ScalarVisibilityOn();
    mapper->SetScalarModeToUseCellFieldData();
    mapper->SelectColorArray(arrayName);
    mapper->SetColorModeToMapScalars();
    mapper->InterpolateScalarsBeforeMappingOff();
    mapper->SetLookupTable(table);
    mapper->UseLookupTableScalarRangeOn();
    return mapper;
}

vtkSmartPointer<vtkPolyDataMapper> plainMapper(vtkPolyData* input) {
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(input);
    mapper->ScalarVisibilityOff();
    return mapper;
}

vtkSmartPointer<vtkActor> actorFor(vtkMapper* mapper) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    actor->SetMapper(mapper);
    return actor;
}

vtkSmartPointer<vtkActor> lineActor(vtkMapper* mapper, double width) {
    auto actor = actorFor(mapper);
    actor->GetProperty()->SetLineWidth(float(width));
    actor->GetProperty()->LightingOff();
    return actor;
}

void setColour(vtkActor* actor, const Rgb& colour) { actor->GetProperty()->SetColor(colour[0], colour[1], colour[2]); }

vtkSmartPointer<vtkPolyData> emptyPolyData() {
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(vtkSmartPointer<vtkPoints>::New());
    return polyData;
}

// A unit square split into vertical bars, one per colour, inside a light frame so that dark colours
// stay visible on the legend's dark background. Coloured by its own cell scalars: the legend box would
// otherwise colour the entry's text with the symbol colour.
vtkSmartPointer<vtkPolyData> legendSymbol(const std::vector<Rgb>& colours) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polygons = vtkSmartPointer<vtkCellArray>::New();
    auto scalars = vtkSmartPointer<vtkUnsignedCharArray>::New();
    scalars->SetNumberOfComponents(3);
    auto addRectangle = [&](double x0, double y0, double x1, double y1, const Rgb& colour) {
        const vtkIdType first = points->GetNumberOfPoints();
        points->InsertNextPoint(x0, y0, 0);
        points->InsertNextPoint(x1, y0, 0);
        points->InsertNextPoint(x1, y1, 0);
        points->InsertNextPoint(x0, y1, 0);
        const vtkIdType corners[4] = {first, first + 1, first + 2, first + 3};
        polygons->InsertNextCell(4, corners);
        scalars->InsertNextTuple3(std::lround(colour[0] * 255.0), std::lround(colour[1] * 255.0), std::lround(colour[2] * 255.0));
    };
    // 2D polygons are drawn in order: the frame first, the colours over it.
    addRectangle(0.0, 0.0, 1.0, 1.0, {0.85, 0.85, 0.85});
    const double inset = 0.12, width = (1.0 - 2.0 * inset) / double(colours.size());
    for (size_t i = 0; i < colours.size(); ++i)
        addRectangle(inset + i * width, inset, inset + (i + 1) * width, 1.0 - inset, colours[i]);
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(polygons);
    polyData->GetCellData()->SetScalars(scalars);
    return polyData;
}

}  // namespace

struct ClusterScene::Impl {
    Mesh mesh;  // faces only (positions are in `points`, world space)
    std::vector<uint32_t> clusterOfFace;
    ClusterBounds bounds;
    std::vector<Rgb> palette;
    Aabb worldBox;
    double meanEdge = 0.0;

    vtkSmartPointer<vtkPoints> points;
    vtkSmartPointer<vtkPolyData> meshData, borderData, coneData, boxData, sphereData, centroidData;
    vtkSmartPointer<vtkUnsignedCharArray> facing;
    vtkSmartPointer<vtkLookupTable> paletteTable, decisionTable, visibleTable, facingTable;
    vtkSmartPointer<vtkPolyDataMapper> facesMapper, conesMapper, boxesMapper, spheresMapper;
    vtkSmartPointer<vtkGlyph3D> normalGlyphs;
    vtkSmartPointer<vtkActor> faces, borders, cones, normals, boxes, spheres, eyeMarker;
    vtkSmartPointer<vtkActor> highlightOutline, highlightCone, highlightBox, highlightSphere;
    vtkSmartPointer<vtkLegendBoxActor> legend;
    mutable std::vector<vtkWeakPointer<vtkActor>> visibleClusterActors;

    std::map<Layer, bool> visible;
    FaceColoring coloring = FaceColoring::Cluster;
    bool hasDecisions = false;
    size_t culledCount = 0, wronglyCulledCount = 0, missedCount = 0, drawnCount = 0;
    bool hasFacing = false;
    bool hasEye = false;
    Eye eye;
    glm::dvec3 lookAt{0.0};
    int highlighted = -1;

    std::vector<vtkActor*> highlightActors() const { return {highlightOutline, highlightCone, highlightBox, highlightSphere}; }
    std::vector<vtkActor*> perClusterActors() const {
        return {faces, borders, cones, normals, boxes, spheres, highlightOutline, highlightCone, highlightBox, highlightSphere};
    }
    vtkLookupTable* glyphTable() const { return coloring == FaceColoring::CullDecision ? decisionTable : paletteTable; }
    double sceneRadius() const { return std::max(double(worldBox.halfDiagonal()), 1e-12); }

    void applyVisibility();
    void applyColouring();
    void updateLegend();
    void fillDecisionTables(const std::vector<uint8_t>* culled, const std::vector<uint8_t>* allBackFacing);
};

ClusterScene::ClusterScene(const Mesh& mesh, const std::vector<glm::vec3>& world, const FaceGeometry& faces,
                           const Partition& partition, const ClusterBounds& bounds)
    : impl_(std::make_unique<Impl>()) {
    const size_t faceCount = mesh.faceCount();
    if (world.size() != mesh.positions.size() || faces.normals.size() != faceCount ||
        faces.centroids.size() != faceCount || partition.clusterOfFace.size() != faceCount ||
        bounds.count() != partition.clusterCount || bounds.spheres.size() != bounds.count() ||
        bounds.boxes.size() != bounds.count() || bounds.faces.starts.size() != size_t(partition.clusterCount) + 1)
        throw std::invalid_argument("ClusterScene: mesh, world positions, face geometry, partition and cluster bounds do not match");
    for (uint32_t cluster : partition.clusterOfFace)
        if (cluster >= partition.clusterCount) throw std::invalid_argument("ClusterScene: a face has a cluster id out of range");

    Impl& s = *impl_;
    s.mesh.faceStarts = mesh.faceStarts;
    s.mesh.faceVertices = mesh.faceVertices;
    s.clusterOfFace = partition.clusterOfFace;
    s.bounds = bounds;
    s.worldBox = computeAabb(world);
    s.meanEdge = conescope::meanEdgeLength(mesh, world);
    s.palette = clusterPalette(clusterAdjacency(mesh, partition));
    const size_t clusterCount = partition.clusterCount;

    // Lookup tables: the only thing a new eye or a new colouring rewrites.
    s.paletteTable = indexedTable(clusterCount);
    for (size_t c = 0; c < clusterCount; ++c) setEntry(s.paletteTable, c, s.palette[c]);
    s.decisionTable = indexedTable(clusterCount);
    s.visibleTable = indexedTable(clusterCount);
    s.fillDecisionTables(nullptr, nullptr);
    s.facingTable = indexedTable(4);
    setEntry(s.facingTable, size_t(Facing::Front), SceneColours::front);
    setEntry(s.facingTable, size_t(Facing::Back), SceneColours::back);
    setEntry(s.facingTable, size_t(Facing::Degenerate), SceneColours::degenerate);
    setEntry(s.facingTable, 3, SceneColours::unclassified);

    // The mesh and the borders share one vtkPoints.
    s.points = pointsFrom(world);
    s.meshData = conescope::meshPolyData(mesh, s.points, partition);
    s.facing = vtkSmartPointer<vtkUnsignedCharArray>::New();
    s.facing->SetName(facingArrayName);
    s.facing->SetNumberOfTuples(vtkIdType(faceCount));
    s.facing->FillValue(3);
    s.meshData->GetCellData()->AddArray(s.facing);
    s.facesMapper = cellArrayMapper(s.meshData, clusterIdArrayName, s.paletteTable);
    s.faces = actorFor(s.facesMapper);
    s.faces->GetProperty()->SetInterpolationToFlat();

    s.borderData = polyDataFrom(borderEdges(mesh, partition), CellKind::Lines, s.points);
    s.borders = lineActor(plainMapper(s.borderData), 1.5);
    setColour(s.borders, SceneColours::border);

    const double fallbackLength = std::max(s.meanEdge, 1e-6 * s.sceneRadius());
    s.coneData = polyDataFrom(coneGlyphs(bounds, coneSegments, fallbackLength), CellKind::Polygons);
    s.conesMapper = cellArrayMapper(s.coneData, clusterIdArrayName, s.paletteTable);
    s.cones = actorFor(s.conesMapper);
    s.cones->GetProperty()->SetOpacity(coneOpacity);

    s.boxData = polyDataFrom(boxGlyphs(bounds), CellKind::Lines);
    s.boxesMapper = cellArrayMapper(s.boxData, clusterIdArrayName, s.paletteTable);
    s.boxes = lineActor(s.boxesMapper, 1.5);

    s.sphereData = polyDataFrom(sphereGlyphs(bounds, sphereSegments), CellKind::Lines);
    s.spheresMapper = cellArrayMapper(s.sphereData, clusterIdArrayName, s.paletteTable);
    s.spheres = lineActor(s.spheresMapper, 1.0);

    // Normals: arrows at (a regular subset of) the face centroids; the glyph filter only runs once
    // the layer is shown.
    {
        const size_t stride = std::max<size_t>(1, (faceCount + maxNormalArrows - 1) / maxNormalArrows);
        std::vector<glm::vec3> centroids;
        auto directions = vtkSmartPointer<vtkFloatArray>::New();
        directions->SetName("normal");
        directions->SetNumberOfComponents(3);
        auto clusterIds = vtkSmartPointer<vtkIntArray>::New();
        clusterIds->SetName(clusterIdArrayName);
        for (size_t f = 0; f < faceCount; f += stride) {
            if (faces.degenerate.size() == faceCount && faces.degenerate[f]) continue;
            centroids.push_back(glm::vec3(faces.centroids[f]));
            const glm::vec3 normal(faces.normals[f]);
            directions->InsertNextTuple3(normal.x, normal.y, normal.z);
            clusterIds->InsertNextValue(int(partition.clusterOfFace[f]));
        }
        s.centroidData = vtkSmartPointer<vtkPolyData>::New();
        s.centroidData->SetPoints(pointsFrom(centroids));
        s.centroidData->GetPointData()->SetVectors(directions);
        s.centroidData->GetPointData()->AddArray(clusterIds);
        auto arrow = vtkSmartPointer<vtkArrowSource>::New();
        arrow->SetTipResolution(6);
        arrow->SetShaftResolution(4);
        s.normalGlyphs = vtkSmartPointer<vtkGlyph3D>::New();
        s.normalGlyphs->SetInputData(s.centroidData);
        s.normalGlyphs->SetSourceConnection(arrow->GetOutputPort());
        s.normalGlyphs->SetVectorModeToUseVector();
        s.normalGlyphs->OrientOn();
        s.normalGlyphs->SetScaleModeToDataScalingOff();
        s.normalGlyphs->SetScaleFactor(0.6 * (s.meanEdge > 0 ? s.meanEdge : s.sceneRadius() * 0.05));
        auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
        mapper->SetInputConnection(s.normalGlyphs->GetOutputPort());
        mapper->ScalarVisibilityOff();
        s.normals = actorFor(mapper);
        setColour(s.normals, SceneColours::normals);
    }

    s.eyeMarker = actorFor(plainMapper(emptyPolyData()));
    setColour(s.eyeMarker, SceneColours::eye);

    s.highlightOutline = lineActor(plainMapper(emptyPolyData()), 4.0);
    s.highlightCone = actorFor(plainMapper(emptyPolyData()));
    s.highlightBox = lineActor(plainMapper(emptyPolyData()), 3.0);
    s.highlightSphere = lineActor(plainMapper(emptyPolyData()), 2.5);
    for (vtkActor* actor : s.highlightActors()) setColour(actor, SceneColours::highlight);

    s.legend = vtkSmartPointer<vtkLegendBoxActor>::New();
    // Placed and sized in pixels, so its text has the same size in any window.
    s.legend->GetPositionCoordinate()->SetCoordinateSystemToDisplay();
    s.legend->GetPositionCoordinate()->SetValue(legendMargin, legendMargin);
    s.legend->GetPosition2Coordinate()->SetCoordinateSystemToDisplay();
    s.legend->BorderOn();
    s.legend->UseBackgroundOn();
    s.legend->SetBackgroundColor(0.0, 0.0, 0.0);
    s.legend->SetBackgroundOpacity(0.55);
    s.legend->ScalarVisibilityOn();
    s.legend->GetEntryTextProperty()->SetFontFamilyToArial();
    s.legend->GetEntryTextProperty()->ShadowOff();
    s.legend->PickableOff();

    for (Layer layer : allLayers())
        s.visible[layer] = !(layer == Layer::Normals || layer == Layer::Boxes || layer == Layer::Spheres);
    s.applyVisibility();
    s.updateLegend();
}

ClusterScene::~ClusterScene() = default;
ClusterScene::ClusterScene(ClusterScene&&) noexcept = default;
ClusterScene& ClusterScene::operator=(ClusterScene&&) noexcept = default;

void ClusterScene::Impl::applyVisibility() {
    faces->SetVisibility(visible[Layer::Faces]);
    borders->SetVisibility(visible[Layer::Borders]);
    cones->SetVisibility(visible[Layer::Cones]);
    normals->SetVisibility(visible[Layer::Normals]);
    boxes->SetVisibility(visible[Layer::Boxes]);
    spheres->SetVisibility(visible[Layer::Spheres]);
    eyeMarker->SetVisibility(visible[Layer::Eye] && hasEye);
    for (vtkActor* actor : highlightActors()) actor->SetVisibility(visible[Layer::Highlight] && highlighted >= 0);
    legend->SetVisibility(visible[Layer::Legend] && legend->GetNumberOfEntries() > 0);
}

void ClusterScene::Impl::applyColouring() {
    if (coloring == FaceColoring::FaceFacing) {
        facesMapper->SelectColorArray(facingArrayName);
        facesMapper->SetLookupTable(facingTable);
    } else {
        facesMapper->SelectColorArray(clusterIdArrayName);
        facesMapper->SetLookupTable(glyphTable());
    }
    for (vtkPolyDataMapper* mapper : {conesMapper.Get(), boxesMapper.Get(), spheresMapper.Get()}) mapper->SetLookupTable(glyphTable());
}

void ClusterScene::Impl::fillDecisionTables(const std::vector<uint8_t>* culled, const std::vector<uint8_t>* allBackFacing) {
    culledCount = wronglyCulledCount = missedCount = drawnCount = 0;
    for (size_t c = 0; c < palette.size(); ++c) {
        if (!culled) {
            setEntry(decisionTable, c, SceneColours::undecided);
            setEntry(visibleTable, c, palette[c]);
            continue;
        }
        const bool isCulled = (*culled)[c] != 0, back = (*allBackFacing)[c] != 0;
        const Rgb& colour = isCulled ? (back ? SceneColours::culled : SceneColours::wronglyCulled)
                                     : (back ? SceneColours::missedCull : SceneColours::drawn);
        (isCulled ? (back ? culledCount : wronglyCulledCount) : (back ? missedCount : drawnCount))++;
        setEntry(decisionTable, c, colour);
        // Alpha 0 removes the cluster from the eye's view (discarded in the fragment shader).
        setEntry(visibleTable, c, palette[c], isCulled ? 0.0 : 1.0);
    }
    decisionTable->Modified();
    visibleTable->Modified();
}

void ClusterScene::Impl::updateLegend() {
    struct Entry {
        std::string label;
        std::vector<Rgb> colours;  // more than one: "a colour per cluster"
    };
    const std::vector<Rgb> hues(baseHues().begin(), baseHues().begin() + 4);
    std::vector<Entry> entries;
    auto count = [](size_t n) { return " (" + std::to_string(n) + ")"; };
    if (visible[Layer::Faces]) {
        if (coloring == FaceColoring::Cluster) {
            entries.push_back({"clusters" + count(palette.size()), hues});
        } else if (coloring == FaceColoring::CullDecision) {
            if (!hasDecisions) {
                entries.push_back({"no cull decision yet", {SceneColours::undecided}});
            } else {
                entries.push_back({"culled" + count(culledCount), {SceneColours::culled}});
                entries.push_back({"missed cull: all back" + count(missedCount), {SceneColours::missedCull}});
                entries.push_back({"drawn: front faces" + count(drawnCount), {SceneColours::drawn}});
                if (wronglyCulledCount)
                    entries.push_back({"culled with front faces" + count(wronglyCulledCount), {SceneColours::wronglyCulled}});
            }
        } else {
            if (!hasFacing) entries.push_back({"faces not classified yet", {SceneColours::unclassified}});
            entries.push_back({"front-facing face", {SceneColours::front}});
            entries.push_back({"back-facing face", {SceneColours::back}});
            entries.push_back({"degenerate face", {SceneColours::degenerate}});
        }
    }
    // Glyphs take the faces' cluster colours, or the decision colours in decision mode.
    const std::vector<Rgb> glyphColours = coloring == FaceColoring::CullDecision
                                              ? std::vector<Rgb>{SceneColours::culled, SceneColours::missedCull, SceneColours::drawn}
                                              : hues;
    if (visible[Layer::Borders]) entries.push_back({"cluster borders", {SceneColours::border}});
    if (visible[Layer::Cones])
        entries.push_back({"normal cones" + count(size_t(coneData->GetNumberOfCells() / coneSegments)), glyphColours});
    if (visible[Layer::Normals]) entries.push_back({"face normals", {SceneColours::normals}});
    if (visible[Layer::Boxes]) entries.push_back({"cluster AABBs", glyphColours});
    if (visible[Layer::Spheres]) entries.push_back({"bounding spheres", glyphColours});
    if (visible[Layer::Eye] && hasEye)
        entries.push_back({eye.orthographic ? "cull eye (direction)" : "cull eye", {SceneColours::eye}});
    if (visible[Layer::Highlight] && highlighted >= 0)
        entries.push_back({"picked cluster " + std::to_string(highlighted), {SceneColours::highlight}});

    legend->SetNumberOfEntries(int(entries.size()));
    for (size_t i = 0; i < entries.size(); ++i) {
        double white[3] = {1.0, 1.0, 1.0};  // the entry colour is the text colour
        legend->SetEntry(int(i), legendSymbol(entries[i].colours), entries[i].label.c_str(), white);
    }
    legend->GetPosition2Coordinate()->SetValue(legendWidth, legendEntryHeight * double(entries.size()));
    legend->SetVisibility(visible[Layer::Legend] && !entries.empty());
}

void ClusterScene::addTo(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->perClusterActors()) renderer->AddActor(actor);
    renderer->AddActor(impl_->eyeMarker);
    renderer->AddViewProp(impl_->legend);
}

void ClusterScene::removeFrom(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->perClusterActors()) renderer->RemoveActor(actor);
    renderer->RemoveActor(impl_->eyeMarker);
    renderer->RemoveViewProp(impl_->legend);
}

void ClusterScene::setLayerVisible(Layer layer, bool visible) {
    impl_->visible[layer] = visible;
    impl_->applyVisibility();
    impl_->updateLegend();
}

bool ClusterScene::layerVisible(Layer layer) const { return impl_->visible.at(layer); }

void ClusterScene::setFaceColoring(FaceColoring coloring) {
    impl_->coloring = coloring;
    impl_->applyColouring();
    impl_->updateLegend();
}

FaceColoring ClusterScene::faceColoring() const { return impl_->coloring; }

void ClusterScene::setClusterDecisions(const std::vector<uint8_t>& culled, const std::vector<uint8_t>& allBackFacing) {
    if (culled.size() != clusterCount() || allBackFacing.size() != clusterCount())
        throw std::invalid_argument("setClusterDecisions: expected " + std::to_string(clusterCount()) +
                                    " values per array, got " + std::to_string(culled.size()) + " and " +
                                    std::to_string(allBackFacing.size()));
    impl_->fillDecisionTables(&culled, &allBackFacing);
    impl_->hasDecisions = true;
    impl_->updateLegend();
}

void ClusterScene::clearClusterDecisions() {
    impl_->fillDecisionTables(nullptr, nullptr);
    impl_->hasDecisions = false;
    impl_->updateLegend();
}

bool ClusterScene::hasClusterDecisions() const { return impl_->hasDecisions; }

void ClusterScene::setFaceFacing(const std::vector<Facing>& facing) {
    if (facing.size() != faceCount())
        throw std::invalid_argument("setFaceFacing: expected " + std::to_string(faceCount()) + " faces, got " +
                                    std::to_string(facing.size()));
    static_assert(sizeof(Facing) == 1, "Facing is stored as one byte per face");
    std::copy(reinterpret_cast<const uint8_t*>(facing.data()), reinterpret_cast<const uint8_t*>(facing.data()) + facing.size(),
              impl_->facing->GetPointer(0));
    impl_->facing->Modified();
    impl_->hasFacing = true;
    impl_->updateLegend();
}

void ClusterScene::setEye(const Eye& eye, const glm::dvec3& lookAt) {
    Impl& s = *impl_;
    s.eye = eye;
    s.lookAt = lookAt;
    s.hasEye = true;
    const double size = 0.06 * s.sceneRadius();
    auto append = vtkSmartPointer<vtkAppendPolyData>::New();
    auto line = vtkSmartPointer<vtkLineSource>::New();
    auto cone = vtkSmartPointer<vtkConeSource>::New();
    cone->SetResolution(24);
    cone->SetHeight(2.5 * size);
    cone->SetRadius(1.2 * size);
    if (!eye.orthographic) {
        // A ball at the eye and a cone opening from it towards the target, like a view frustum, plus
        // the line of sight.
        glm::dvec3 towards = lookAt - eye.position;
        if (glm::length(towards) <= 0.0) towards = glm::dvec3(0, 0, -1);
        towards = glm::normalize(towards);
        auto ball = vtkSmartPointer<vtkSphereSource>::New();
        ball->SetCenter(eye.position.x, eye.position.y, eye.position.z);
        ball->SetRadius(size);
        ball->SetThetaResolution(16);
        ball->SetPhiResolution(12);
        const glm::dvec3 coneCenter = eye.position + towards * (1.25 * size);
        cone->SetCenter(coneCenter.x, coneCenter.y, coneCenter.z);
        cone->SetDirection(-towards.x, -towards.y, -towards.z);  // apex at the eye
        line->SetPoint1(eye.position.x, eye.position.y, eye.position.z);
        line->SetPoint2(lookAt.x, lookAt.y, lookAt.z);
        append->AddInputConnection(ball->GetOutputPort());
    } else {
        // An arrow along the direction, ending outside the mesh's bounds on the side the eye looks from.
        const glm::dvec3 direction = glm::normalize(eye.direction);
        const glm::dvec3 tip = lookAt - direction * (1.15 * s.sceneRadius() + glm::distance(lookAt, glm::dvec3(s.worldBox.center())));
        const glm::dvec3 tail = tip - direction * (0.6 * s.sceneRadius());
        const glm::dvec3 coneCenter = tip - direction * (1.25 * size);
        cone->SetCenter(coneCenter.x, coneCenter.y, coneCenter.z);
        cone->SetDirection(direction.x, direction.y, direction.z);  // apex at the tip
        line->SetPoint1(tail.x, tail.y, tail.z);
        line->SetPoint2(tip.x, tip.y, tip.z);
    }
    append->AddInputConnection(cone->GetOutputPort());
    append->AddInputConnection(line->GetOutputPort());
    append->Update();
    vtkMapper::SafeDownCast(s.eyeMarker->GetMapper())->SetInputDataObject(append->GetOutput());
    s.eyeMarker->GetProperty()->SetLineWidth(2.0f);
    s.applyVisibility();
    s.updateLegend();
}

bool ClusterScene::hasEye() const { return impl_->hasEye; }
const Eye& ClusterScene::eye() const { return impl_->eye; }
glm::dvec3 ClusterScene::eyeLookAt() const { return impl_->lookAt; }

void ClusterScene::setHighlightedCluster(int cluster) {
    Impl& s = *impl_;
    if (cluster < -1 || cluster >= int(clusterCount()))
        throw std::out_of_range("setHighlightedCluster: cluster " + std::to_string(cluster) + " of " +
                                std::to_string(clusterCount()));
    s.highlighted = cluster;
    auto setInput = [](vtkActor* actor, vtkPolyData* data) { vtkMapper::SafeDownCast(actor->GetMapper())->SetInputDataObject(data); };
    if (cluster < 0) {
        for (vtkActor* actor : s.highlightActors()) setInput(actor, emptyPolyData());
    } else {
        const uint32_t* faces = s.bounds.faces.faces.data() + s.bounds.faces.starts[cluster];
        const size_t count = s.bounds.faces.starts[cluster + 1] - s.bounds.faces.starts[cluster];
        setInput(s.highlightOutline, polyDataFrom(clusterOutline(s.mesh, faces, count, cluster), CellKind::Lines, s.points));
        GlyphGeometry cone, box, sphere;
        appendCone(cone, s.bounds.cones[cluster], s.bounds.spheres[cluster], cluster, coneSegments,
                   std::max(s.meanEdge, 1e-6 * s.sceneRadius()));
        appendBox(box, s.bounds.boxes[cluster], cluster);
        appendSphere(sphere, s.bounds.spheres[cluster], cluster, sphereSegments);
        setInput(s.highlightCone, polyDataFrom(cone, CellKind::Polygons));
        setInput(s.highlightBox, polyDataFrom(box, CellKind::Lines));
        setInput(s.highlightSphere, polyDataFrom(sphere, CellKind::Lines));
    }
    s.applyVisibility();
    s.updateLegend();
}

int ClusterScene::highlightedCluster() const { return impl_->highlighted; }

int ClusterScene::clusterOfCell(vtkActor* pickedActor, vtkIdType cellId) const {
    if (!pickedActor || cellId < 0) return -1;
    const auto ours = impl_->perClusterActors();
    bool known = std::find(ours.begin(), ours.end(), pickedActor) != ours.end();
    for (const auto& actor : impl_->visibleClusterActors) known |= actor.GetPointer() == pickedActor;
    if (!known || !pickedActor->GetMapper()) return -1;
    auto* data = vtkPolyData::SafeDownCast(pickedActor->GetMapper()->GetInputAsDataSet());
    if (!data || cellId >= data->GetNumberOfCells()) return -1;
    if (auto* ids = vtkIntArray::SafeDownCast(data->GetCellData()->GetArray(clusterIdArrayName))) return ids->GetValue(cellId);
    // Glyphs made by vtkGlyph3D carry the id on their points.
    if (auto* ids = vtkIntArray::SafeDownCast(data->GetPointData()->GetArray(clusterIdArrayName))) {
        vtkIdType pointCount = 0;
        const vtkIdType* pointIds = nullptr;
        data->GetCellPoints(cellId, pointCount, pointIds);
        if (pointCount > 0) return ids->GetValue(pointIds[0]);
    }
    return -1;
}

vtkSmartPointer<vtkActor> ClusterScene::makeVisibleClustersActor() const {
    auto mapper = cellArrayMapper(impl_->meshData, clusterIdArrayName, impl_->visibleTable);
    auto actor = actorFor(mapper);
    actor->GetProperty()->SetInterpolationToFlat();
    // The table has alpha 0 only to mark culled clusters: keep the actor in the opaque pass and drop
    // those fragments, instead of sorting a million translucent triangles.
    actor->ForceOpaqueOn();
    actor->GetShaderProperty()->AddFragmentShaderReplacement(
        "//VTK::Color::Impl", true, "//VTK::Color::Impl\n  if (opacity <= 0.0) { discard; }\n", false);
    auto& made = impl_->visibleClusterActors;
    made.erase(std::remove_if(made.begin(), made.end(), [](const vtkWeakPointer<vtkActor>& a) { return !a; }), made.end());
    made.push_back(actor.Get());
    return actor;
}

void ClusterScene::applyEyeToCamera(vtkCamera* camera) const {
    const Impl& s = *impl_;
    const glm::dvec3 center(s.worldBox.center());
    const double radius = s.sceneRadius();
    glm::dvec3 position, focal, direction;
    if (s.eye.orthographic) {
        direction = glm::normalize(s.eye.direction);
        focal = center;
        position = center - direction * (3.0 * radius);
    } else {
        position = s.eye.position;
        focal = glm::length(s.lookAt - position) > 0 ? s.lookAt : center;
        direction = glm::normalize(focal - position);
    }
    glm::dvec3 up(0, 1, 0);
    if (std::abs(glm::dot(up, direction)) > 0.99) up = glm::dvec3(0, 0, 1);
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(up.x, up.y, up.z);
    camera->OrthogonalizeViewUp();
    // Near and far planes around the mesh's bounding sphere, measured along the view direction.
    const double along = glm::dot(center - position, direction);
    const double nearPlane = std::max(along - 1.05 * radius, 1e-3 * radius);
    const double farPlane = std::max(along + 1.05 * radius, nearPlane * 2.0);
    if (s.eye.orthographic) {
        camera->ParallelProjectionOn();
        camera->SetParallelScale(1.05 * radius);
    } else {
        camera->ParallelProjectionOff();
        const double distance = glm::distance(position, center);
        const double angle = distance > 1.05 * radius ? 2.0 * std::asin(1.05 * radius / distance) * 180.0 / M_PI : 90.0;
        camera->SetViewAngle(std::clamp(angle, 5.0, 90.0));
    }
    camera->SetClippingRange(nearPlane, farPlane);
}

size_t ClusterScene::clusterCount() const { return impl_->palette.size(); }
size_t ClusterScene::faceCount() const { return impl_->clusterOfFace.size(); }
std::array<double, 6> ClusterScene::meshBounds() const {
    const Aabb& box = impl_->worldBox;
    return {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
}
double ClusterScene::meanEdgeLength() const { return impl_->meanEdge; }
const std::vector<Rgb>& ClusterScene::palette() const { return impl_->palette; }
vtkPolyData* ClusterScene::meshPolyData() const { return impl_->meshData; }
vtkPolyData* ClusterScene::borderPolyData() const { return impl_->borderData; }
vtkPolyData* ClusterScene::conePolyData() const { return impl_->coneData; }
vtkPolyData* ClusterScene::boxPolyData() const { return impl_->boxData; }
vtkPolyData* ClusterScene::spherePolyData() const { return impl_->sphereData; }
vtkLookupTable* ClusterScene::paletteLookupTable() const { return impl_->paletteTable; }
vtkLookupTable* ClusterScene::decisionLookupTable() const { return impl_->decisionTable; }
vtkLookupTable* ClusterScene::visibleClustersLookupTable() const { return impl_->visibleTable; }
vtkLegendBoxActor* ClusterScene::legend() const { return impl_->legend; }

vtkActor* ClusterScene::actor(Layer layer) const {
    switch (layer) {
    case Layer::Faces: return impl_->faces;
    case Layer::Borders: return impl_->borders;
    case Layer::Cones: return impl_->cones;
    case Layer::Normals: return impl_->normals;
    case Layer::Boxes: return impl_->boxes;
    case Layer::Spheres: return impl_->spheres;
    case Layer::Eye: return impl_->eyeMarker;
    case Layer::Highlight: return impl_->highlightOutline;
    case Layer::Legend: return nullptr;
    }
    return nullptr;
}

}  // namespace conescope
