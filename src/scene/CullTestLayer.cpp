#include "scene/CullTestLayer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkCellArray.h>
#include <vtkLabeledDataMapper.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkStringArray.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

#include "scene/SceneGeometry.h"

namespace conescope {

namespace {

// Colours of the drawing; the target takes the highlight's (it is the picked cluster's point).
constexpr Rgb regionColour{0.20, 0.85, 0.35};
constexpr Rgb axisColour{0.95, 0.95, 0.95};
constexpr Rgb pointBack{0.20, 0.80, 0.30};
constexpr Rgb pointFront{1.00, 0.35, 0.55};  // rose: red is a false cull, orange a miss
constexpr double regionOpacity = 0.15;

// Points around a region's boundary at one distance: a circle, or the pyramid's eight edges.
int ringSegments(const CullRegion& region) { return region.pyramid() ? int(region.edges.size()) : coneSegments; }

// The region's boundary as rings of quads around its axis (around the pyramid's edges).
GlyphGeometry regionSurface(const CullRegion& region, int cluster) {
    GlyphGeometry geometry;
    if (region.empty()) return geometry;
    const int segments = ringSegments(region);
    const glm::dvec3 axis = glm::normalize(region.direction);
    const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 u = glm::normalize(glm::cross(axis, helper)), w = glm::cross(axis, u);
    for (size_t i = 0; i < region.distances.size(); ++i) {
        const double d = region.distances[i], angle = region.angles[i];
        const glm::dvec3 centre = region.origin + axis * (d * std::cos(angle));
        const double radius = d * std::sin(angle);
        for (int k = 0; k < segments; ++k) {
            const double phi = 2.0 * M_PI * k / segments;
            geometry.points.emplace_back(region.pyramid() ? region.origin + d * region.edges[size_t(k)]
                                                          : centre + radius * (std::cos(phi) * u + std::sin(phi) * w));
        }
    }
    for (size_t i = 0; i + 1 < region.distances.size(); ++i)
        for (int k = 0; k < segments; ++k) {
            const int64_t a = int64_t(i) * segments, b = a + segments, next = (k + 1) % segments;
            geometry.addCell({a + k, a + next, b + next, b + k}, cluster);
        }
    return geometry;
}

// The region's outline: a few lines along it and a few rings across it, so its shape reads at any
// opacity (the surface alone is a faint veil).
GlyphGeometry regionOutline(const GlyphGeometry& surface, size_t rings, int segments) {
    GlyphGeometry geometry;
    if (rings < 2) return geometry;
    geometry.points = surface.points;
    for (int k = 0; k < segments; k += std::max(segments / 8, 1))
        for (size_t i = 0; i + 1 < rings; ++i) geometry.addCell({int64_t(i) * segments + k, int64_t(i + 1) * segments + k}, 0);
    for (size_t i = rings / 4; i < rings; i += std::max<size_t>(rings / 4, 1))
        for (int k = 0; k < segments; ++k)
            geometry.addCell({int64_t(i) * segments + k, int64_t(i) * segments + (k + 1) % segments}, 0);
    for (int k = 0; k < segments; ++k)
        geometry.addCell({int64_t(rings - 1) * segments + k, int64_t(rings - 1) * segments + (k + 1) % segments}, 0);
    return geometry;
}

GlyphGeometry segment(const glm::dvec3& from, const glm::dvec3& to, int cluster) {
    GlyphGeometry geometry;
    geometry.points = {glm::vec3(from), glm::vec3(to)};
    geometry.addCell({0, 1}, cluster);
    return geometry;
}

// Points as vertex cells with direct RGB colours, and an optional label per point.
vtkSmartPointer<vtkPolyData> colouredPoints(const std::vector<glm::dvec3>& points, const std::vector<Rgb>& colours,
                                            const std::vector<std::string>& labels = {}) {
    auto vtkPointsList = vtkSmartPointer<vtkPoints>::New();
    auto vertices = vtkSmartPointer<vtkCellArray>::New();
    auto rgb = vtkSmartPointer<vtkUnsignedCharArray>::New();
    rgb->SetName("colour");
    rgb->SetNumberOfComponents(3);
    auto text = vtkSmartPointer<vtkStringArray>::New();
    text->SetName("label");
    for (size_t i = 0; i < points.size(); ++i) {
        const vtkIdType id = vtkPointsList->InsertNextPoint(points[i].x, points[i].y, points[i].z);
        vertices->InsertNextCell(1, &id);
        rgb->InsertNextTuple3(std::lround(colours[i][0] * 255.0), std::lround(colours[i][1] * 255.0), std::lround(colours[i][2] * 255.0));
        text->InsertNextValue(i < labels.size() ? labels[i] : std::string());
    }
    auto data = vtkSmartPointer<vtkPolyData>::New();
    data->SetPoints(vtkPointsList);
    data->SetVerts(vertices);
    data->GetPointData()->SetScalars(rgb);
    data->GetPointData()->AddArray(text);
    return data;
}

vtkSmartPointer<vtkActor> pointActor(double size) {
    auto mapper = plainMapper(emptyPolyData());
    mapper->ScalarVisibilityOn();
    mapper->SetColorModeToDirectScalars();
    auto actor = actorFor(mapper);
    actor->GetProperty()->SetPointSize(float(size));
    actor->GetProperty()->RenderPointsAsSpheresOn();
    return actor;
}

}  // namespace

glm::dvec3 testViewTarget(const CullTestDrawing& drawing, const Sphere& sphere) {
    const bool apexTest = drawing.test == CullTest::Apex || drawing.test == CullTest::Octagon;
    return apexTest && !drawing.eye.orthographic ? drawing.why.apex : sphere.center;
}

CullTestDrawing makeTestDrawing(const CullingInput& input, uint32_t cluster, const Eye& eye, CullTest test) {
    CullTestDrawing drawing;
    drawing.cluster = int(cluster);
    drawing.test = test;
    drawing.eye = eye;
    drawing.why = explainCull(input, cluster, eye, test);
    const Sphere& sphere = input.bounds.spheres[cluster];
    drawing.sphere = sphere;
    const double radius = std::max(sphere.radius, 1e-9);
    // Near the cluster the region shows what the view vector must pass through; drawn out to a far
    // eye it would cover the whole picture.
    const double reach = eye.orthographic ? 4.0 * radius : std::min(1.05 * glm::distance(eye.position, sphere.center), 8.0 * radius);
    drawing.region = cullRegion(input.bounds, cluster, test, eye.orthographic, reach);
    return drawing;
}

CullTestLayer::CullTestLayer(const SceneData& data)
    : SceneLayer(data), region_(actorFor(plainMapper(emptyPolyData()))), regionOutline_(lineActor(plainMapper(emptyPolyData()), 1.5)),
      axis_(lineActor(plainMapper(emptyPolyData()), 3.0)),
      view_(lineActor(plainMapper(emptyPolyData()), 2.5)), target_(pointActor(12.0)), points_(pointActor(9.0)),
      labels_(vtkSmartPointer<vtkActor2D>::New()) {
    setColour(region_, regionColour);
    setColour(regionOutline_, regionColour);
    region_->GetProperty()->SetOpacity(regionOpacity);
    region_->GetProperty()->BackfaceCullingOff();
    setColour(axis_, axisColour);
    setColour(view_, SceneColours::viewVector);
    auto labelMapper = vtkSmartPointer<vtkLabeledDataMapper>::New();
    labelMapper->SetInputData(emptyPolyData());
    labelMapper->SetLabelModeToLabelFieldData();
    labelMapper->SetFieldDataName("label");
    labelMapper->GetLabelTextProperty()->SetFontSize(15);
    labelMapper->GetLabelTextProperty()->SetFontFamilyToArial();
    labelMapper->GetLabelTextProperty()->BoldOn();
    labelMapper->GetLabelTextProperty()->ShadowOn();
    labelMapper->GetLabelTextProperty()->SetColor(1.0, 1.0, 1.0);
    labels_->SetMapper(labelMapper);
    labels_->PickableOff();
    applyVisibility();
}

std::vector<vtkActor*> CullTestLayer::actors() const { return {region_, regionOutline_, axis_, view_, target_, points_}; }
std::vector<vtkProp*> CullTestLayer::overlays() const { return {labels_}; }

void CullTestLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    const std::string test = toString(drawing_.test);
    if (!drawing_.region.empty()) entries.push_back({"eyes " + test + " culls from", {regionColour}});
    entries.push_back({"view vector v", {SceneColours::viewVector}});
    if (drawing_.why.cullable) entries.push_back({"cone axis V1", {axisColour}});
    if (!drawing_.why.vertices.empty() || drawing_.test == CullTest::Aabb || drawing_.test == CullTest::AabbFast)
        entries.push_back({"point sees back / may face", {pointBack, pointFront}});
}

void CullTestLayer::setDrawing(const CullTestDrawing& drawing) {
    const size_t clusterCount = data_.palette.size();
    if (drawing.cluster < -1 || drawing.cluster >= int(clusterCount))
        throw std::out_of_range("setTestDrawing: cluster " + std::to_string(drawing.cluster) + " of " + std::to_string(clusterCount));
    drawing_ = drawing;
    auto* labelMapper = vtkLabeledDataMapper::SafeDownCast(labels_->GetMapper());
    if (drawing.cluster < 0) {
        for (vtkActor* actor : actors()) setInput(actor, emptyPolyData());
        labelMapper->SetInputData(emptyPolyData());
        applyVisibility();
        return;
    }
    const int c = drawing.cluster;
    const Sphere& sphere = data_.bounds.spheres[c];
    const double length = 1.5 * std::max(sphere.radius, data_.coneFallbackLength());
    const GlyphGeometry surface = regionSurface(drawing.region, c);
    setInput(region_, polyDataFrom(surface, CellKind::Polygons));
    setInput(regionOutline_, polyDataFrom(regionOutline(surface, drawing.region.distances.size(), ringSegments(drawing.region)),
                                          CellKind::Lines));
    // A cluster without a cone has no axis V1 to draw.
    setInput(axis_, drawing.why.cullable ? polyDataFrom(segment(sphere.center, sphere.center + drawing.why.axis * length, c), CellKind::Lines)
                                         : emptyPolyData());
    const glm::dvec3 target = testViewTarget(drawing, sphere);
    const glm::dvec3 from = drawing.eye.orthographic ? target - drawing.eye.direction * (4.0 * length) : drawing.eye.position;
    setInput(view_, polyDataFrom(segment(from, target, c), CellKind::Lines));
    setInput(target_, colouredPoints({target}, {SceneColours::highlight}));
    // The points the test looks at: the box's corners (numbered) or the cluster's vertices.
    std::vector<glm::dvec3> points;
    std::vector<Rgb> colours;
    std::vector<std::string> labels;
    if (drawing.test == CullTest::Aabb || drawing.test == CullTest::AabbFast) {
        for (int k = 0; k < 8; ++k) {
            points.push_back(drawing.why.corners[k]);
            colours.push_back(drawing.why.cornerBack[k] ? pointBack : pointFront);
            labels.push_back(std::to_string(k));
        }
    } else {
        for (size_t i = 0; i < drawing.why.vertices.size(); ++i) {
            points.push_back(drawing.why.vertices[i]);
            colours.push_back(drawing.why.vertexBack[i] ? pointBack : pointFront);
        }
    }
    vtkSmartPointer<vtkPolyData> pointData = colouredPoints(points, colours, labels);
    setInput(points_, pointData);
    labelMapper->SetInputData(labels.empty() ? emptyPolyData() : pointData);
    applyVisibility();
}

}  // namespace conescope
