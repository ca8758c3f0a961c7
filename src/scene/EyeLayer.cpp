#include "scene/EyeLayer.h"

#include <algorithm>
#include <cmath>

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkConeSource.h>
#include <vtkLineSource.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkSphereSource.h>

namespace conescope {

EyeLayer::EyeLayer(const SceneData& data) : SceneLayer(data), marker_(actorFor(plainMapper(emptyPolyData()))) {
    setColour(marker_, SceneColours::eye);
    marker_->GetProperty()->SetLineWidth(2.0f);
}

void EyeLayer::addLegendEntries(FaceColoring, std::vector<LegendEntry>& entries) const {
    entries.push_back({eye_.orthographic ? "cull eye (direction)" : "cull eye", {SceneColours::eye}});
}

void EyeLayer::setEye(const Eye& eye, const glm::dvec3& lookAt) {
    eye_ = eye;
    lookAt_ = lookAt;
    hasEye_ = true;
    const double radius = data_.sceneRadius(), size = 0.06 * radius;
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
        const glm::dvec3 tip = lookAt - direction * (1.15 * radius + glm::distance(lookAt, glm::dvec3(data_.worldBox.center())));
        const glm::dvec3 tail = tip - direction * (0.6 * radius);
        const glm::dvec3 coneCenter = tip - direction * (1.25 * size);
        cone->SetCenter(coneCenter.x, coneCenter.y, coneCenter.z);
        cone->SetDirection(direction.x, direction.y, direction.z);  // apex at the tip
        line->SetPoint1(tail.x, tail.y, tail.z);
        line->SetPoint2(tip.x, tip.y, tip.z);
    }
    append->AddInputConnection(cone->GetOutputPort());
    append->AddInputConnection(line->GetOutputPort());
    append->Update();
    setInput(marker_, append->GetOutput());
    applyVisibility();
}

void EyeLayer::applyToCamera(vtkCamera* camera) const {
    const glm::dvec3 center(data_.worldBox.center());
    const double radius = data_.sceneRadius();
    glm::dvec3 position, focal, direction;
    if (eye_.orthographic) {
        direction = glm::normalize(eye_.direction);
        focal = center;
        position = center - direction * (3.0 * radius);
    } else {
        position = eye_.position;
        focal = glm::length(lookAt_ - position) > 0 ? lookAt_ : center;
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
    if (eye_.orthographic) {
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

}  // namespace conescope
