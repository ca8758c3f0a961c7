#include "EyePanel.h"

#include <cmath>

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace conescope {

EyePanel::EyePanel(QWidget* parent) : QWidget(parent) {
    auto* form = new QFormLayout;
    const char* names[3] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis) {
        auto* box = new QDoubleSpinBox(this);
        box->setRange(-1e9, 1e9);
        box->setDecimals(4);
        box->setKeyboardTracking(false);
        box->setObjectName(QStringLiteral("eye_") + QLatin1String(names[axis]));
        coordinates_[axis] = box;
        box->setToolTip(tr("The cull eye's %1 coordinate, in the mesh's units. Type a value, or drag the magenta handle in "
                           "the view.").arg(QLatin1String(names[axis])));
        box->setWhatsThis(tr("The cull eye is the point the cull decisions are made from. Change a coordinate and every "
                             "cluster's decision, the statistics and the lesson's numbers follow."));
        form->addRow(QStringLiteral("Eye %1").arg(QLatin1String(names[axis])), box);
        connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
                [this, axis](double value) { emit coordinateEdited(axis, value); });
    }
    lookFromHere_ = new QPushButton(tr("Look from here"), this);
    lookFromHere_->setToolTip(tr("Put the cull eye where the observer's camera is (E)"));
    lookFromHere_->setWhatsThis(tr("Moves the cull eye to the observer's camera: the decisions are then made from where you look."));
    follow_ = new QCheckBox(tr("Follow the observer's camera"), this);
    follow_->setToolTip(tr("The cull eye moves with the observer's camera (F)"));
    follow_->setWhatsThis(tr("While checked, every turn of the observer's camera moves the cull eye there: you see the "
                             "decisions change as you move."));
    animate_ = new QPushButton(tr("Animate orbit"), this);
    animate_->setCheckable(true);
    animate_->setToolTip(tr("Step the cull eye along the standard orbit (Space)"));
    animate_->setWhatsThis(tr("Moves the cull eye from one orbit view to the next, around the mesh, until pressed again."));
    orbitStep_ = new QLabel(this);
    orbitStep_->hide();

    auto* buttons = new QHBoxLayout;
    buttons->addWidget(lookFromHere_);
    buttons->addWidget(animate_);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addLayout(buttons);
    layout->addWidget(follow_);
    layout->addWidget(orbitStep_);
    layout->addStretch(1);

    connect(lookFromHere_, &QPushButton::clicked, this, &EyePanel::lookFromHereClicked);
    connect(follow_, &QCheckBox::toggled, this, &EyePanel::followToggled);
    connect(animate_, &QPushButton::toggled, this, &EyePanel::animateToggled);
}

glm::dvec3 EyePanel::position() const {
    return {coordinates_[0]->value(), coordinates_[1]->value(), coordinates_[2]->value()};
}

void EyePanel::showPosition(const glm::dvec3& position) {
    for (int axis = 0; axis < 3; ++axis) {
        const QSignalBlocker blocker(coordinates_[axis]);
        coordinates_[axis]->setValue(position[axis]);
    }
}

void EyePanel::setScale(double meshSize) {
    // Steps of about a hundredth of the mesh and enough decimals to show them.
    const double step = meshSize > 0.0 ? std::pow(10.0, std::floor(std::log10(meshSize / 100.0))) : 0.01;
    const int decimals = std::max(2, int(std::ceil(-std::log10(step))) + 2);
    for (QDoubleSpinBox* box : coordinates_) {
        const QSignalBlocker blocker(box);
        box->setSingleStep(step);
        box->setDecimals(std::min(decimals, 10));
    }
}

void EyePanel::showOrbitStep(int view, int viewCount) {
    orbitStep_->setVisible(view >= 0);
    orbitStep_->setText(tr("Orbit view %1 of %2").arg(view + 1).arg(viewCount));
}

void EyePanel::setFollowing(bool following) {
    const QSignalBlocker blocker(follow_);
    follow_->setChecked(following);
}

void EyePanel::setAnimating(bool animating) {
    const QSignalBlocker blocker(animate_);
    animate_->setChecked(animating);
}

}  // namespace conescope
