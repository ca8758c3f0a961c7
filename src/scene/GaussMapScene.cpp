#include "scene/GaussMapScene.h"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkImageData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkWindowToImageFilter.h>

#include "core/Choices.h"
#include "scene/SceneGeometry.h"
#include "scene/SceneLayer.h"
#include "scene/SceneLegend.h"
#include "scene/SceneRendering.h"

namespace conescope {

namespace {

constexpr Rgb sphereColour = SceneColours::gaussSphere;
constexpr Rgb normalColour = SceneColours::normalTip;
constexpr Rgb octagonColour{1.00, 0.90, 0.20};
constexpr int circleSegments = 96;

// Two unit vectors perpendicular to `axis` and to each other.
void basis(const glm::dvec3& axis, glm::dvec3& u, glm::dvec3& w) {
    const glm::dvec3 other = std::abs(axis.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u = glm::normalize(glm::cross(axis, other));
    w = glm::cross(axis, u);
}

// The circle at angle `angle` from `axis` on a sphere of radius `radius`: a cap's rim (angle pi/2
// is the great circle perpendicular to axis).
GlyphGeometry circleOnSphere(const glm::dvec3& axis, double angle, double radius) {
    GlyphGeometry geometry;
    glm::dvec3 u, w;
    basis(axis, u, w);
    for (int k = 0; k < circleSegments; ++k) {
        const double phi = 2.0 * M_PI * k / circleSegments;
        geometry.points.emplace_back(radius * (std::cos(angle) * axis + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * w)));
    }
    for (int k = 0; k < circleSegments; ++k) geometry.addCell({k, (k + 1) % circleSegments}, 0);
    return geometry;
}

// The cap itself as a fan of rings, slightly above the sphere so it is not hidden by it.
GlyphGeometry capSurface(const glm::dvec3& axis, double angle, double radius) {
    GlyphGeometry geometry;
    glm::dvec3 u, w;
    basis(axis, u, w);
    constexpr int rings = 12, segments = 48;
    geometry.points.emplace_back(radius * axis);
    for (int r = 1; r <= rings; ++r) {
        const double a = angle * r / rings;
        for (int k = 0; k < segments; ++k) {
            const double phi = 2.0 * M_PI * k / segments;
            geometry.points.emplace_back(radius * (std::cos(a) * axis + std::sin(a) * (std::cos(phi) * u + std::sin(phi) * w)));
        }
    }
    for (int k = 0; k < segments; ++k) geometry.addCell({0, 1 + k, 1 + (k + 1) % segments}, 0);
    for (int r = 1; r < rings; ++r)
        for (int k = 0; k < segments; ++k) {
            const int64_t a = 1 + int64_t(r - 1) * segments, b = a + segments, next = (k + 1) % segments;
            geometry.addCell({a + k, a + next, b + next, b + k}, 0);
        }
    return geometry;
}

// The octagon on the sphere: great-circle arcs between its neighbouring edges.
GlyphGeometry octagonOnSphere(const OctagonCone& octagon, double radius) {
    GlyphGeometry geometry;
    constexpr int steps = 12;
    for (size_t k = 0; k < 8; ++k) {
        const glm::dvec3 &a = octagon.edges[k], &b = octagon.edges[(k + 1) % 8];
        for (int i = 0; i < steps; ++i) {
            const double t = double(i) / steps;
            const glm::dvec3 p = (1.0 - t) * a + t * b;
            geometry.points.emplace_back(radius * (glm::length(p) > 0.0 ? glm::normalize(p) : a));
        }
    }
    const int64_t count = int64_t(geometry.points.size());
    for (int64_t i = 0; i < count; ++i) geometry.addCell({i, (i + 1) % count}, 0);
    return geometry;
}

std::string degreesText(double radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f deg", radians * 180.0 / M_PI);
    return text;
}

}  // namespace

Rgb coneMethodColour(ConeMethod method) { return descriptor(method).colour; }

Rgb subGroupCapColour(size_t index) {
    static const Rgb hues[] = {{1.00, 0.45, 0.45}, {0.45, 0.85, 1.00}, {1.00, 0.85, 0.35}, {0.65, 1.00, 0.55},
                               {0.95, 0.55, 1.00}, {1.00, 0.65, 0.25}, {0.55, 0.65, 1.00}, {0.85, 0.85, 0.85}};
    return hues[index % 8];
}

struct GaussMapScene::Impl {
    vtkSmartPointer<vtkActor> sphere = actorFor(plainMapper(emptyPolyData()));
    vtkSmartPointer<vtkActor> normals = pointsActor(normalColour, 7.0);
    std::vector<vtkSmartPointer<vtkActor>> rims;  // one per cone method, in allConeMethods() order
    vtkSmartPointer<vtkActor> cap = actorFor(plainMapper(emptyPolyData()));
    vtkSmartPointer<vtkActor> octagon = lineActor(plainMapper(emptyPolyData()), 2.5);
    vtkSmartPointer<vtkActor> view = lineActor(plainMapper(emptyPolyData()), 3.0);
    vtkSmartPointer<vtkActor> viewTip = pointsActor(SceneColours::viewVector, 12.0);
    vtkSmartPointer<vtkActor> horizon = lineActor(plainMapper(emptyPolyData()), 2.0);
    std::vector<vtkSmartPointer<vtkActor>> subGroupRims;  // K cones per cluster: one per sub-group
    SceneLegend legend;
    std::vector<LegendEntry> entries;  // what show() put in the legend
    std::optional<GaussMap> map;
    ConeMethod displayed = ConeMethod::Minimal;

    std::vector<vtkActor*> actors() const {
        std::vector<vtkActor*> all = {sphere, cap, octagon, horizon, view, viewTip, normals};
        for (const auto& rim : rims) all.push_back(rim);
        for (const auto& rim : subGroupRims) all.push_back(rim);
        return all;
    }
};

GaussMapScene::GaussMapScene() : impl_(std::make_unique<Impl>()) {
    auto source = vtkSmartPointer<vtkSphereSource>::New();
    source->SetRadius(1.0);
    source->SetThetaResolution(64);
    source->SetPhiResolution(32);
    source->Update();
    setInput(impl_->sphere, source->GetOutput());
    setColour(impl_->sphere, sphereColour);
    impl_->sphere->GetProperty()->SetOpacity(0.25);
    impl_->sphere->GetProperty()->BackfaceCullingOn();
    impl_->cap->GetProperty()->SetOpacity(0.35);
    impl_->cap->GetProperty()->LightingOff();
    setColour(impl_->view, SceneColours::viewVector);
    setColour(impl_->horizon, SceneColours::viewVector);
    setColour(impl_->octagon, octagonColour);
    for (size_t i = 0; i < allConeMethods().size(); ++i) impl_->rims.push_back(lineActor(plainMapper(emptyPolyData()), 3.0));
    for (size_t i = 0; i < 8; ++i) {
        impl_->subGroupRims.push_back(lineActor(plainMapper(emptyPolyData()), 2.0));
        setColour(impl_->subGroupRims.back(), subGroupCapColour(i));
    }
    impl_->legend.setVisible(true);
    show(std::nullopt, ConeMethod::Minimal);
}

GaussMapScene::~GaussMapScene() = default;

void GaussMapScene::show(const std::optional<GaussMap>& map, ConeMethod displayed, int cluster) {
    impl_->map = map;
    impl_->displayed = displayed;
    for (vtkActor* actor : impl_->actors()) actor->SetVisibility(map.has_value());
    for (const auto& rim : impl_->subGroupRims) rim->SetVisibility(false);
    if (!map) {
        impl_->legend.show({{"pick a cluster to see its normals", {sphereColour}}});
        return;
    }
    std::vector<LegendEntry> entries;
    entries.push_back({"cluster " + std::to_string(cluster) + ": " + std::to_string(map->normals.size()) + " face normals", {normalColour}});
    setInput(impl_->normals, pointPolyData(map->normals, 1.004));
    impl_->cap->SetVisibility(false);
    for (size_t i = 0; i < map->cones.size() && i < impl_->rims.size(); ++i) {
        const auto& [method, cone] = map->cones[i];
        vtkActor* rim = impl_->rims[i];
        setColour(rim, coneMethodColour(method));
        const std::string name = toString(method) + (method == displayed ? " (shown)" : "");
        if (!cone.cullable) {
            rim->SetVisibility(false);
            entries.push_back({name + ": no cone", {coneMethodColour(method)}});
            continue;
        }
        setInput(rim, polyDataFrom(circleOnSphere(cone.axis, cone.halfAngle(), 1.006), CellKind::Lines));
        entries.push_back({name + ": " + degreesText(cone.halfAngle()), {coneMethodColour(method)}});
        if (method == displayed) {
            setInput(impl_->cap, polyDataFrom(capSurface(cone.axis, cone.halfAngle(), 1.003), CellKind::Polygons));
            setColour(impl_->cap, coneMethodColour(method));
            impl_->cap->SetVisibility(true);
        }
    }
    // The octagon test's cone, around the displayed method's axis: tighter than the cap where the
    // normals spread one way.
    impl_->octagon->SetVisibility(map->octagon.cullable);
    if (map->octagon.cullable) {
        setInput(impl_->octagon, polyDataFrom(octagonOnSphere(map->octagon, 1.007), CellKind::Lines));
        char share[64];
        std::snprintf(share, sizeof share, "octagon: culled from %.1f%% of views", 100.0 * octagonCullShare(map->octagon));
        entries.push_back({share, {octagonColour}});
    }
    // v from the centre to the sphere, and its horizon: the normals of a back-facing cluster lie on v's side.
    GlyphGeometry line;
    line.points = {glm::vec3(0.0f), glm::vec3(map->view * 1.35)};
    line.addCell({0, 1}, 0);
    setInput(impl_->view, polyDataFrom(line, CellKind::Lines));
    setInput(impl_->viewTip, pointPolyData({map->view}, 1.35));
    setInput(impl_->horizon, polyDataFrom(circleOnSphere(map->view, M_PI / 2.0, 1.002), CellKind::Lines));
    entries.push_back({"view vector v and its horizon", {SceneColours::viewVector}});
    impl_->legend.show(entries);
    impl_->entries = std::move(entries);
}

void GaussMapScene::showSubGroups(const std::vector<SubGroupCap>& caps) {
    if (!impl_->map) return;
    std::vector<LegendEntry> entries = impl_->entries;
    for (size_t i = 0; i < impl_->subGroupRims.size(); ++i) {
        vtkActor* rim = impl_->subGroupRims[i];
        const bool drawn = i < caps.size() && caps[i].triangles > 0 && caps[i].cone.cullable;
        rim->SetVisibility(drawn);
        if (i >= caps.size() || caps[i].triangles == 0) continue;
        const SubGroupCap& cap = caps[i];
        if (drawn) setInput(rim, polyDataFrom(circleOnSphere(cap.cone.axis, cap.cone.halfAngle(), 1.008), CellKind::Lines));
        entries.push_back({"sub-group " + std::to_string(i + 1) + ": " + (cap.cone.cullable ? degreesText(cap.cone.halfAngle()) : "no cone") +
                               ", " + std::to_string(cap.triangles) + " tris, " + (cap.culled ? "culled" : "drawn"),
                           {subGroupCapColour(i)}});
    }
    impl_->legend.show(entries);
}

size_t GaussMapScene::subGroupRimsShown() const {
    size_t shown = 0;
    for (const auto& rim : impl_->subGroupRims) shown += rim->GetVisibility() ? 1 : 0;
    return shown;
}

bool GaussMapScene::hasMap() const { return impl_->map.has_value(); }

void GaussMapScene::addTo(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->actors()) renderer->AddActor(actor);
    renderer->AddViewProp(impl_->legend.prop());
}

void GaussMapScene::removeFrom(vtkRenderer* renderer) const {
    for (vtkActor* actor : impl_->actors()) renderer->RemoveActor(actor);
    renderer->RemoveViewProp(impl_->legend.prop());
}

void GaussMapScene::placeCamera(vtkCamera* camera) const {
    glm::dvec3 towards(0.0, 0.0, 1.0), up(0.0, 1.0, 0.0);
    if (impl_->map) {
        // 45 degrees from the displayed cap's axis towards v: the cap in front, v and its horizon at a
        // slant (through the translucent sphere when v points away).
        const glm::dvec3 view = impl_->map->view;
        glm::dvec3 axis = view;
        for (const auto& [method, cone] : impl_->map->cones)
            if (method == impl_->displayed && cone.cullable) axis = cone.axis;
        glm::dvec3 u, w;
        basis(axis, u, w);
        glm::dvec3 side = view - glm::dot(view, axis) * axis;
        side = glm::length(side) > 1e-6 ? glm::normalize(side) : u;
        towards = glm::normalize(axis + side);
        up = glm::cross(towards, glm::cross(axis, side));
        if (glm::length(up) < 1e-6) up = w;
    }
    const glm::dvec3 position = towards * 4.6;
    camera->ParallelProjectionOff();
    camera->SetViewAngle(30.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(position.x, position.y, position.z);
    camera->SetViewUp(up.x, up.y, up.z);
    camera->OrthogonalizeViewUp();
    camera->SetClippingRange(0.5, 10.0);
}

const SceneLegend& GaussMapScene::legend() const { return impl_->legend; }

void GaussMapScene::fitLegend(int viewHeight, double pixelRatio) {
    impl_->legend.fitTo(viewHeight, pixelRatio);
}

vtkSmartPointer<vtkImageData> renderGaussMapToImage(const GaussMapScene& scene, int width, int height) {
    requireDisplay();
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetBackground(0.12, 0.13, 0.16);
    scene.addTo(renderer);
    scene.placeCamera(renderer->GetActiveCamera());
    vtkSmartPointer<vtkImageData> image = renderOffScreen(renderer, width, height);
    scene.removeFrom(renderer);
    return image;
}

}  // namespace conescope
