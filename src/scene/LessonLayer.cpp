#include "scene/LessonLayer.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <vtkActor.h>
#include <vtkArrowSource.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkGlyph3D.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

#include "scene/GaussMapScene.h"
#include "scene/SceneGeometry.h"

namespace conescope {

namespace {

constexpr Rgb gaussColour = SceneColours::gaussSphere;
constexpr Rgb tipColour = SceneColours::normalTip;
constexpr Rgb axisColour = SceneColours::normalTip;
constexpr int rimSegments = 64;

// Arrows from each point along its vector, `length` long, as one polydata (a glyph filter run once).
vtkSmartPointer<vtkPolyData> arrows(const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& along, double length) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto vectors = vtkSmartPointer<vtkFloatArray>::New();
    vectors->SetNumberOfComponents(3);
    for (size_t i = 0; i < from.size(); ++i) {
        points->InsertNextPoint(from[i].x, from[i].y, from[i].z);
        vectors->InsertNextTuple3(along[i].x, along[i].y, along[i].z);
    }
    auto input = vtkSmartPointer<vtkPolyData>::New();
    input->SetPoints(points);
    input->GetPointData()->SetVectors(vectors);
    auto arrow = vtkSmartPointer<vtkArrowSource>::New();
    arrow->SetTipResolution(8);
    arrow->SetShaftResolution(6);
    auto glyphs = vtkSmartPointer<vtkGlyph3D>::New();
    glyphs->SetInputData(input);
    glyphs->SetSourceConnection(arrow->GetOutputPort());
    glyphs->SetVectorModeToUseVector();
    glyphs->OrientOn();
    glyphs->SetScaleModeToDataScalingOff();
    glyphs->SetScaleFactor(length);
    glyphs->Update();
    return glyphs->GetOutput();
}

// The rim of a cone of half-angle `angle` around `axis` from `apex`, `slant` long.
GlyphGeometry rim(const glm::dvec3& apex, const glm::dvec3& axis, double angle, double slant) {
    GlyphGeometry geometry;
    glm::dvec3 u, w;
    orthonormalFrame(axis, u, w);
    for (int k = 0; k < rimSegments; ++k) {
        const double phi = 2.0 * M_PI * k / rimSegments;
        geometry.points.emplace_back(apex + slant * (std::cos(angle) * axis + std::sin(angle) * (std::cos(phi) * u + std::sin(phi) * w)));
    }
    for (int k = 0; k < rimSegments; ++k) geometry.addCell({k, (k + 1) % rimSegments}, 0);
    return geometry;
}

// The cluster's faces as polygons over the mesh's points.
GlyphGeometry clusterFaces(const Mesh& mesh, const uint32_t* faces, size_t count, int cluster) {
    GlyphGeometry geometry;
    for (size_t i = 0; i < count; ++i) {
        const uint32_t* vertices = mesh.faceBegin(faces[i]);
        geometry.connectivity.insert(geometry.connectivity.end(), vertices, vertices + mesh.faceSize(faces[i]));
        geometry.offsets.push_back(int64_t(geometry.connectivity.size()));
        geometry.clusterIds.push_back(cluster);
    }
    return geometry;
}

GlyphGeometry segment(const glm::dvec3& from, const glm::dvec3& to) {
    GlyphGeometry geometry;
    geometry.points = {glm::vec3(from), glm::vec3(to)};
    geometry.addCell({0, 1}, 0);
    return geometry;
}

glm::dvec3 upOf(const Lesson& lesson) {
    return glm::length(lesson.why.axis) > 0.0 ? glm::normalize(lesson.why.axis) : glm::dvec3(0.0, 0.0, 1.0);
}

// The cone beside the displayed one: the average cone beside the minimal, the minimal beside any other.
const ConeOfNormals& otherCone(const Lesson& lesson) {
    return lesson.coneMethod == ConeMethod::Minimal ? lesson.averageCone : lesson.minimalCone;
}
ConeMethod otherMethod(const Lesson& lesson) {
    return lesson.coneMethod == ConeMethod::Minimal ? ConeMethod::Average : ConeMethod::Minimal;
}

std::string degreesText(double radians) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f deg", glm::degrees(radians));
    return text;
}

CameraPlacement lookAt(const glm::dvec3& focus, double radius, const glm::dvec3& from, const glm::dvec3& up, double viewAngle) {
    CameraPlacement camera;
    camera.focalPoint = focus;
    camera.position = focus + glm::normalize(from) * (radius / std::sin(glm::radians(viewAngle) / 2.0));
    camera.viewUp = up;
    return camera;
}

// Where the view vector of a cluster's test aims: the apex for a perspective apex or octagon test
// (a cluster without a cone has none), else the sphere's centre.
glm::dvec3 viewTarget(const CullExplanation& why, CullTest test, const Sphere& sphere, const Eye& eye) {
    const bool apexTest = test == CullTest::Apex || test == CullTest::Octagon || test == CullTest::OctagonCompact;
    return apexTest && why.cullable && !eye.orthographic ? why.apex : sphere.center;
}

// Both clusters and the eye, seen across the line from the eye to their middle, raised towards V1.
CameraPlacement sideBySideCamera(const Lesson& lesson, double viewAngleDegrees) {
    const Sphere& a = lesson.sphere;
    const Sphere& b = lesson.partner->sphere;
    const glm::dvec3 middle = 0.5 * (a.center + b.center);
    const double r = std::max(0.5 * glm::distance(a.center, b.center) + std::max(a.radius, b.radius), 1e-9);
    const glm::dvec3 up = upOf(lesson);
    glm::dvec3 towardsEye = lesson.eye.orthographic ? -lesson.eye.direction : lesson.eye.position - middle;
    if (!(glm::length(towardsEye) > 0.0)) towardsEye = up;
    // The clusters fill the picture; the view vectors come in from the eye's side, the eye itself in
    // the picture only when it is near.
    const double distance = std::min(lesson.eye.orthographic ? 1.6 * r : glm::length(towardsEye), 1.6 * r);
    const glm::dvec3 towards = glm::normalize(towardsEye);
    glm::dvec3 across = glm::cross(towards, up);
    if (glm::length(across) < 1e-6) across = glm::cross(towards, glm::dvec3(1.0, 0.0, 0.0));
    if (glm::length(across) < 1e-6) across = glm::dvec3(0.0, 1.0, 0.0);
    // From outside the surface, where both clusters show their faces (the axes' mean), turned to the
    // side so the view vectors are seen along their length.
    glm::dvec3 outside = up;
    if (lesson.partner->why.cullable) outside += glm::normalize(lesson.partner->why.axis);
    if (glm::length(outside) < 1e-6) outside = up;
    const glm::dvec3 from = glm::normalize(outside) + 0.6 * glm::normalize(across);
    return lookAt(middle + 0.3 * distance * towards, 1.3 * r, from, up, viewAngleDegrees);
}

}  // namespace

double gaussSphereRadius(const Lesson& lesson) { return 0.8 * std::max(lesson.sphere.radius, 1e-9); }

glm::dvec3 gaussSphereCentre(const Lesson& lesson) {
    return lesson.sphere.center + upOf(lesson) * (lesson.sphere.radius + 1.4 * gaussSphereRadius(lesson));
}

std::map<Layer, bool> lessonLayers(int step) {
    std::map<Layer, bool> layers;
    for (Layer layer : allLayers()) layers[layer] = false;
    for (Layer layer : {Layer::Faces, Layer::Borders, Layer::Legend, Layer::Lesson}) layers[layer] = true;
    // The apex lies behind the faces: the bound's step shows the cluster see-through, the mesh as borders.
    if (step == 4) layers[Layer::Faces] = false;
    if (step >= 5) layers[Layer::Eye] = layers[Layer::Test] = true;
    // Side by side, the lesson layer draws both clusters' view vectors; one cluster's region would hide them.
    if (step == kSideBySideStep) layers[Layer::Test] = false;
    return layers;
}

FaceColoring lessonColouring(int step) {
    if (step == kSideBySideStep) return FaceColoring::CullDecision;
    return step >= 6 ? FaceColoring::Loss : step == 5 ? FaceColoring::CullDecision : FaceColoring::Cluster;
}

CameraPlacement lessonCamera(const Lesson& lesson, int step, double viewAngleDegrees) {
    const glm::dvec3 up = upOf(lesson), centre = lesson.sphere.center;
    const double r = std::max(lesson.sphere.radius, 1e-9);
    glm::dvec3 side, other;
    orthonormalFrame(up, side, other);
    // The faces from outside, where their normals point: the arrows (step 1), the faces coloured by
    // what happened to them (step 6).
    if (step <= 1) return lookAt(centre, 1.7 * r, side + 0.8 * up, up, viewAngleDegrees);
    if (step == kSideBySideStep && lesson.partner) return sideBySideCamera(lesson, viewAngleDegrees);
    if (step >= 6) return lookAt(centre, 2.2 * r, side + 0.8 * up, up, viewAngleDegrees);
    if (step <= 3) {
        // The Gauss sphere fills the picture, the cluster's top below it.
        const double radius = gaussSphereRadius(lesson);
        return lookAt(gaussSphereCentre(lesson) - 0.35 * radius * up, 1.7 * radius, side + 0.6 * up, up, viewAngleDegrees);
    }
    if (step == 4) {
        const double reach = lesson.test == CullTest::Apex || lesson.test == CullTest::Octagon
                                 ? glm::distance(lesson.why.apex, centre) + 0.6 * r
                                 : 1.5 * r;
        return lookAt(centre, std::max(1.5 * r, reach), side + 0.5 * up, up, viewAngleDegrees);
    }
    // The cluster and the eye, seen across the plane of V1 and v (the cross-section's plane); a far
    // eye is brought in to twelve radii along its direction, the view vector still coming from it.
    glm::dvec3 towardsEye = lesson.eye.orthographic ? -lesson.eye.direction : lesson.eye.position - centre;
    if (!(glm::length(towardsEye) > 0.0)) towardsEye = side;
    const double distance = lesson.eye.orthographic ? 6.0 * r : std::min(glm::length(towardsEye), 12.0 * r);
    const glm::dvec3 eye = centre + glm::normalize(towardsEye) * distance;
    glm::dvec3 across = glm::cross(glm::normalize(towardsEye), up);
    if (glm::length(across) < 1e-6) across = other;
    // From the side of the plane of V1 and v, raised towards V1 so the cluster shows its faces.
    const glm::dvec3 from = glm::normalize(across) + 0.6 * up;
    return lookAt(0.5 * (centre + eye), 0.5 * distance + 1.3 * r, from, up, viewAngleDegrees);
}

LessonLayer::LessonLayer(const SceneData& data)
    : SceneLayer(data), outline_(lineActor(plainMapper(emptyPolyData()), 3.5)), faces_(actorFor(plainMapper(emptyPolyData()))),
      faceArrows_(actorFor(plainMapper(emptyPolyData()))),
      gaussSphere_(actorFor(plainMapper(emptyPolyData()))), gaussArrows_(actorFor(plainMapper(emptyPolyData()))),
      tips_(pointsActor(tipColour, 7.0)), cone_(actorFor(plainMapper(emptyPolyData()))),
      coneRim_(lineActor(plainMapper(emptyPolyData()), 3.0)), otherRim_(lineActor(plainMapper(emptyPolyData()), 3.0)),
      axis_(lineActor(plainMapper(emptyPolyData()), 3.0)), bound_(lineActor(plainMapper(emptyPolyData()), 2.5)),
      boundPoints_(pointsActor(SceneColours::highlight, 11.0)), partnerOutline_(lineActor(plainMapper(emptyPolyData()), 3.5)),
      views_(lineActor(plainMapper(emptyPolyData()), 2.5)) {
    setColour(partnerOutline_, SceneColours::partner);
    setColour(views_, SceneColours::viewVector);
    setColour(outline_, SceneColours::highlight);
    setColour(faces_, SceneColours::highlight);
    faces_->GetProperty()->SetOpacity(0.45);
    setColour(faceArrows_, SceneColours::lessonNormal);
    setColour(gaussArrows_, SceneColours::lessonNormal);
    setColour(gaussSphere_, gaussColour);
    gaussSphere_->GetProperty()->SetOpacity(0.25);
    gaussSphere_->GetProperty()->BackfaceCullingOn();
    cone_->GetProperty()->SetOpacity(0.45);
    cone_->GetProperty()->BackfaceCullingOff();
    setColour(axis_, axisColour);
    setColour(bound_, SceneColours::highlight);
    applyVisibility();
}

std::vector<vtkActor*> LessonLayer::actors() const {
    return {outline_,  faces_, faceArrows_, gaussSphere_,     gaussArrows_, tips_, cone_, coneRim_,
            otherRim_, axis_,  bound_,      boundPoints_, partnerOutline_, views_};
}

void LessonLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    const Lesson& lesson = *drawing_.lesson;
    const int step = drawing_.step;
    if (step == kSideBySideStep && lesson.partner) {
        entries.push_back({"cluster " + std::to_string(lesson.cluster) + ", " + lesson.verdict(), {SceneColours::highlight}});
        entries.push_back({"cluster " + std::to_string(lesson.partner->cluster) + ", " + (lesson.partner->why.culled ? "culled" : "drawn"),
                           {SceneColours::partner}});
        entries.push_back({"view vector v", {SceneColours::viewVector}});
        if (lesson.why.cullable || lesson.partner->why.cullable) entries.push_back({"cone axis V1", {axisColour}});
        return;
    }
    entries.push_back({"cluster " + std::to_string(lesson.cluster), {SceneColours::highlight}});
    if (step == 1) entries.push_back({"its face normals", {SceneColours::lessonNormal}});
    if (step == 2 || step == 3) entries.push_back({"normals from one point: the Gauss sphere", {SceneColours::lessonNormal, gaussColour}});
    if (step == 3) {
        const ConeOfNormals& other = otherCone(lesson);
        entries.push_back({toString(lesson.coneMethod) + " cone, alpha " + (lesson.why.cullable ? degreesText(glm::radians(lesson.why.halfAngleDegrees)) : "none"),
                           {coneMethodColour(lesson.coneMethod)}});
        if (other.cullable)
            entries.push_back({toString(otherMethod(lesson)) + " cone, alpha " + degreesText(other.halfAngle()), {coneMethodColour(otherMethod(lesson))}});
        if (lesson.why.cullable) entries.push_back({"cone axis V1", {axisColour}});
    }
    if (step >= 4) {
        switch (lesson.test) {
            case CullTest::Apex:
            case CullTest::Octagon:
            case CullTest::OctagonCompact:
                if (lesson.why.cullable) entries.push_back({"apex, behind every face plane", {SceneColours::highlight}});
                break;
            case CullTest::Sphere:
            case CullTest::MeshoptSphere: entries.push_back({"bounding sphere", {SceneColours::highlight}}); break;
            case CullTest::Aabb:
            case CullTest::AabbFast: entries.push_back({"bounding box and its corners", {SceneColours::highlight}}); break;
            case CullTest::Vertices: entries.push_back({"the cluster's vertices", {SceneColours::highlight}}); break;
            case CullTest::Oracle:
            case CullTest::MeshoptApexF32:  // the engines' records hold bounds of their own, told in words
            case CullTest::MeshoptSphereS8:
            case CullTest::CadsceneBoxS8: break;
        }
    }
}

void LessonLayer::setDrawing(const LessonDrawing& drawing) {
    if (drawing.step > 0 && drawing.lesson && drawing.lesson->cluster >= data_.palette.size())
        throw std::out_of_range("setLessonDrawing: cluster " + std::to_string(drawing.lesson->cluster) + " of " +
                                std::to_string(data_.palette.size()));
    drawing_ = drawing;
    for (vtkActor* actor : actors()) setInput(actor, emptyPolyData());
    if (hasContent()) {
        const Lesson& lesson = *drawing.lesson;
        const ClusterBounds& bounds = data_.bounds;
        const uint32_t* faces = bounds.faces.faces.data() + bounds.faces.starts[lesson.cluster];
        const size_t count = bounds.faces.starts[lesson.cluster + 1] - bounds.faces.starts[lesson.cluster];
        setInput(outline_, polyDataFrom(clusterOutline(data_.mesh, faces, count, int(lesson.cluster)), CellKind::Lines, data_.points));
        const double arrowLength = 0.9 * std::max(data_.meanEdge, 1e-9);
        if (drawing.step == 1) setInput(faceArrows_, arrows(lesson.centroids, lesson.normals, arrowLength));
        if (drawing.step == 2 || drawing.step == 3) drawGaussSphere(lesson, drawing.step == 3);
        if (drawing.step == 4) setInput(faces_, polyDataFrom(clusterFaces(data_.mesh, faces, count, int(lesson.cluster)), CellKind::Polygons, data_.points));
        if (drawing.step == kSideBySideStep && lesson.partner) drawSideBySide(lesson);
        else if (drawing.step >= 4) drawBound(lesson);
    }
    applyVisibility();
}

void LessonLayer::drawGaussSphere(const Lesson& lesson, bool withCones) {
    const glm::dvec3 centre = gaussSphereCentre(lesson);
    const double radius = gaussSphereRadius(lesson);
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetCenter(centre.x, centre.y, centre.z);
    sphere->SetRadius(radius);
    sphere->SetThetaResolution(48);
    sphere->SetPhiResolution(24);
    sphere->Update();
    setInput(gaussSphere_, sphere->GetOutput());
    setInput(gaussArrows_, arrows(std::vector<glm::dvec3>(lesson.normals.size(), centre), lesson.normals, radius));
    std::vector<glm::dvec3> tips;
    for (const glm::dvec3& n : lesson.normals) tips.push_back(centre + radius * n);
    setInput(tips_, pointPolyData(tips));
    if (!withCones) return;
    const glm::dvec3 up = upOf(lesson);
    // A cluster without a cone has no axis to draw.
    if (lesson.why.cullable) setInput(axis_, polyDataFrom(segment(centre, centre + 1.5 * radius * up), CellKind::Lines));
    const double slant = 1.15 * radius;
    if (lesson.why.cullable) {
        ConeOfNormals shown;
        shown.axis = up;
        shown.cosHalfAngle = lesson.why.cosHalfAngle;
        shown.sinHalfAngle = std::sqrt(std::max(0.0, 1.0 - shown.cosHalfAngle * shown.cosHalfAngle));
        shown.cullable = true;
        GlyphGeometry cone;
        appendCone(cone, shown, Sphere{centre, slant}, 0, coneSegments, slant);
        setInput(cone_, polyDataFrom(cone, CellKind::Polygons));
        setColour(cone_, coneMethodColour(lesson.coneMethod));
        setInput(coneRim_, polyDataFrom(rim(centre, up, shown.halfAngle(), slant), CellKind::Lines));
        setColour(coneRim_, coneMethodColour(lesson.coneMethod));
    }
    const ConeOfNormals& other = otherCone(lesson);
    if (other.cullable) {
        setInput(otherRim_, polyDataFrom(rim(centre, other.axis, other.halfAngle(), slant), CellKind::Lines));
        setColour(otherRim_, coneMethodColour(otherMethod(lesson)));
    }
}

void LessonLayer::drawBound(const Lesson& lesson) {
    const ClusterBounds& bounds = data_.bounds;
    const uint32_t c = lesson.cluster;
    GlyphGeometry lines;
    std::vector<glm::dvec3> points;
    switch (lesson.test) {
        case CullTest::Apex:
        case CullTest::Octagon:
        case CullTest::OctagonCompact: {
            if (!lesson.why.cullable) break;  // no cone, no apex
            // Lines from the apex to the cluster's outline: every face lies in front of it.
            const uint32_t* faces = bounds.faces.faces.data() + bounds.faces.starts[c];
            const GlyphGeometry outline = clusterOutline(data_.mesh, faces, bounds.faces.starts[c + 1] - bounds.faces.starts[c], int(c));
            lines.points.emplace_back(lesson.why.apex);
            for (size_t i = 0; i < outline.connectivity.size(); i += 2) {
                double p[3];
                data_.points->GetPoint(outline.connectivity[i], p);
                lines.points.emplace_back(glm::dvec3(p[0], p[1], p[2]));
                lines.addCell({0, int64_t(lines.points.size() - 1)}, 0);
            }
            points.push_back(lesson.why.apex);
            break;
        }
        case CullTest::Sphere:
        case CullTest::MeshoptSphere:
            appendSphere(lines, bounds.spheres[c], int(c), sphereSegments);
            points.push_back(bounds.spheres[c].center);
            break;
        case CullTest::Aabb:
        case CullTest::AabbFast:
            appendBox(lines, bounds.boxes[c], int(c));
            points.assign(lesson.why.corners.begin(), lesson.why.corners.end());
            break;
        case CullTest::Vertices:
            for (uint32_t i = bounds.vertexStarts[c]; i < bounds.vertexStarts[c + 1]; ++i) {
                double p[3];
                data_.points->GetPoint(bounds.vertexIds[i], p);
                points.emplace_back(p[0], p[1], p[2]);
            }
            break;
        case CullTest::Oracle:
        case CullTest::MeshoptApexF32:  // the engines' records hold bounds of their own, told in words
        case CullTest::MeshoptSphereS8:
        case CullTest::CadsceneBoxS8: break;
    }
    if (!lines.points.empty()) setInput(bound_, polyDataFrom(lines, CellKind::Lines));
    if (!points.empty()) setInput(boundPoints_, pointPolyData(points));
}

void LessonLayer::drawSideBySide(const Lesson& lesson) {
    const ClusterBounds& bounds = data_.bounds;
    const LessonPartner& partner = *lesson.partner;
    const uint32_t c = partner.cluster;
    const uint32_t* faces = bounds.faces.faces.data() + bounds.faces.starts[c];
    setInput(partnerOutline_, polyDataFrom(clusterOutline(data_.mesh, faces, bounds.faces.starts[c + 1] - bounds.faces.starts[c], int(c)),
                                           CellKind::Lines, data_.points));
    GlyphGeometry views, axes;
    const std::pair<const CullExplanation*, const Sphere*> sides[] = {{&lesson.why, &lesson.sphere}, {&partner.why, &partner.sphere}};
    for (const auto& [why, sphere] : sides) {
        const glm::dvec3 target = viewTarget(*why, lesson.test, *sphere, lesson.eye);
        const double length = 1.5 * std::max(sphere->radius, 1e-9);
        const glm::dvec3 from = lesson.eye.orthographic ? target - lesson.eye.direction * (4.0 * length) : lesson.eye.position;
        const GlyphGeometry view = segment(from, target);
        views.points.insert(views.points.end(), view.points.begin(), view.points.end());
        views.addCell({int64_t(views.points.size() - 2), int64_t(views.points.size() - 1)}, 0);
        if (!why->cullable) continue;
        axes.points.emplace_back(sphere->center);
        axes.points.emplace_back(sphere->center + why->axis * length);
        axes.addCell({int64_t(axes.points.size() - 2), int64_t(axes.points.size() - 1)}, 0);
    }
    setInput(views_, polyDataFrom(views, CellKind::Lines));
    if (!axes.points.empty()) setInput(axis_, polyDataFrom(axes, CellKind::Lines));
}

}  // namespace conescope
