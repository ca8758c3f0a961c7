#include "LodPanel.h"

#include <cmath>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>

#include "Session.h"

namespace conescope {

namespace {

// The slider runs over 0 to 64 pixels in quarter pixels; the spin box takes any value.
constexpr int sliderSteps = 256;
constexpr double sliderPixels = 64.0;

QDoubleSpinBox* spinBox(double low, double high, double value, int decimals, const QString& suffix, QWidget* parent) {
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(low, high);
    box->setDecimals(decimals);
    box->setValue(value);
    box->setSuffix(suffix);
    box->setKeyboardTracking(false);
    return box;
}

}  // namespace

LodPanel::LodPanel(QWidget* parent) : QWidget(parent) {
    const LodThreshold defaults;
    auto* form = new QFormLayout(this);
    build_ = new QPushButton(tr("Build LOD hierarchy"), this);
    build_->setToolTip(tr("Groups neighbouring clusters, simplifies each group to about half and splits it again, level after "
                          "level, as engines build cluster LOD (the clusters shown are level 0)."));
    form->addRow(build_);
    summary_ = new QLabel(tr("No hierarchy yet."), this);
    summary_->setWordWrap(true);
    form->addRow(summary_);
    level_ = new QComboBox(this);
    level_->setToolTip(tr("What the 3D view shows: the partition, one level of the hierarchy with its cones, or the clusters the cut "
                          "from the cull eye draws."));
    form->addRow(tr("Show"), level_);
    slider_ = new QSlider(Qt::Horizontal, this);
    slider_->setRange(0, sliderSteps);
    pixels_ = spinBox(0.0, 10000.0, defaults.value, 2, tr(" px"), this);
    pixels_->setSingleStep(0.25);
    const QString thresholdHelp = tr("The largest simplification error the cut draws, in pixels on the screen below: a cluster is drawn "
                                     "when its error seen from the eye is within it and its group's is not.");
    slider_->setToolTip(thresholdHelp);
    pixels_->setToolTip(thresholdHelp);
    form->addRow(tr("Threshold"), pixels_);
    form->addRow(slider_);
    screenHeight_ = spinBox(1.0, 100000.0, defaults.screenHeight, 0, tr(" px"), this);
    screenHeight_->setToolTip(tr("The screen's height the threshold is measured on."));
    form->addRow(tr("Screen height"), screenHeight_);
    fov_ = spinBox(1.0, 179.0, defaults.fovDegrees, 1, tr(" deg"), this);
    fov_->setToolTip(tr("The vertical field of view the screen covers."));
    form->addRow(tr("Field of view"), fov_);
    coloring_ = new QComboBox(this);
    for (FaceColoring coloring : {FaceColoring::LodLevel, FaceColoring::LodGroup, FaceColoring::LodCut, FaceColoring::CullDecision})
        coloring_->addItem(QString::fromStdString(toString(coloring)), int(coloring));
    coloring_->setToolTip(tr("Colour the clusters by their level, their group, or whether the cut from the eye draws them (or a coarser "
                             "or finer level there); decision: as the test decides."));
    form->addRow(tr("Colour by"), coloring_);
    export_ = new QPushButton(tr("Export LOD statistics..."), this);
    export_->setToolTip(tr("The levels and the cut from the cull eye as conescope-cli lod --eye writes them (JSON, or CSV by the extension)."));
    form->addRow(export_);
    showHierarchy(nullptr, kLodNone, FaceColoring::CullDecision, false);

    connect(build_, &QPushButton::clicked, this, &LodPanel::buildRequested);
    connect(export_, &QPushButton::clicked, this, &LodPanel::exportRequested);
    connect(level_, qOverload<int>(&QComboBox::activated), this, [this](int index) { emit levelChosen(level_->itemData(index).toInt()); });
    connect(coloring_, qOverload<int>(&QComboBox::activated), this,
            [this](int index) { emit coloringChosen(FaceColoring(coloring_->itemData(index).toInt())); });
    connect(slider_, &QSlider::valueChanged, this, [this](int step) {
        const QSignalBlocker blocker(pixels_);
        pixels_->setValue(sliderPixels * step / sliderSteps);
        emit thresholdChanged(threshold());
    });
    for (QDoubleSpinBox* box : {pixels_, screenHeight_, fov_})
        connect(box, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this]() {
            const QSignalBlocker blocker(slider_);
            slider_->setValue(int(std::lround(std::min(pixels_->value(), sliderPixels) / sliderPixels * sliderSteps)));
            emit thresholdChanged(threshold());
        });
}

LodThreshold LodPanel::threshold() const {
    LodThreshold threshold;
    threshold.value = pixels_->value();
    threshold.screenHeight = screenHeight_->value();
    threshold.fovDegrees = fov_->value();
    return threshold;
}

void LodPanel::showLod(const Session& session) {
    showHierarchy(session.lodHierarchy(), session.lodLevelShown(), session.faceColoring(), session.clusters() != nullptr);
}

void LodPanel::showHierarchy(const ClusterHierarchy* hierarchy, int shown, FaceColoring coloring, bool meshLoaded) {
    {
        const QSignalBlocker blocker(level_);
        level_->clear();
        level_->addItem(tr("Partition (no LOD)"), kLodNone);
        if (hierarchy) {
            level_->addItem(tr("Cut from the eye"), kLodCut);
            for (size_t l = 0; l < hierarchy->levels.size(); ++l)
                level_->addItem(tr("Level %1 (%2 clusters)").arg(l).arg(hierarchy->levels[l].clusters.partition.clusterCount), int(l));
        }
        level_->setCurrentIndex(std::max(0, level_->findData(shown)));
    }
    level_->setEnabled(hierarchy != nullptr);
    coloring_->setEnabled(hierarchy != nullptr);
    export_->setEnabled(hierarchy != nullptr);
    {
        const QSignalBlocker blocker(coloring_);
        coloring_->setCurrentIndex(std::max(0, coloring_->findData(int(coloring))));
    }
    if (!hierarchy) {
        summary_->setText(meshLoaded ? tr("No hierarchy yet: build it from the clusters shown.") : tr("No mesh loaded."));
        return;
    }
    summary_->setText(tr("%1 levels, %2 to %3 triangles, built in %4 s.")
                          .arg(hierarchy->levels.size())
                          .arg(hierarchy->levels.front().triangles())
                          .arg(hierarchy->levels.back().triangles())
                          .arg(hierarchy->buildSeconds, 0, 'f', 2));
}

}  // namespace conescope
