// The side panel that edits conescope::Settings: builder, its limits and effort, cone method, cull test,
// sphere method, projection, orbit. It only maps widgets to fields; the window decides what to
// recompute when settingsChanged() arrives.
#pragma once

#include <QWidget>

#include "core/Settings.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace conescope {

class SettingsPanel : public QWidget {
    Q_OBJECT
public:
    explicit SettingsPanel(QWidget* parent = nullptr);

    Settings settings() const;
    // Shows `settings` without emitting settingsChanged. Only the first cone and test are shown.
    void setSettings(const Settings& settings);

    // The widgets, for tests that drive them.
    QComboBox* builderBox() const { return builder_; }
    QComboBox* coneBox() const { return cone_; }
    QComboBox* testBox() const { return test_; }
    QComboBox* conesPerClusterBox() const { return conesPerCluster_; }
    QComboBox* projectionBox() const { return projection_; }
    QSpinBox* maxTrianglesBox() const { return maxTriangles_; }
    QComboBox* effortBox() const { return effort_; }
    QCheckBox* fixWindingBox() const { return fixWinding_; }

signals:
    void settingsChanged(const conescope::Settings& settings);

private:
    void emitChanged();
    void enableForBuilder();
    // Tooltips and What's This for every control, from the settings schema and the glossary.
    void describeWidgets();
    // A single-choice box's tooltip and What's This: what the box is for and what its chosen item means.
    void describeChoice(QComboBox* box);
    void browseClusterFile();

    // Fields the panel does not edit (extra cones/tests, the eye) pass through unchanged.
    Settings base_;
    QComboBox* builder_ = nullptr;
    QSpinBox* maxVertices_ = nullptr;
    QSpinBox* maxTriangles_ = nullptr;
    QSpinBox* clusterCount_ = nullptr;
    QComboBox* effort_ = nullptr;
    QLineEdit* clusterFile_ = nullptr;
    QPushButton* browseClusterFile_ = nullptr;
    QDoubleSpinBox* normalWeight_ = nullptr;
    QDoubleSpinBox* coneWeight_ = nullptr;
    QComboBox* cone_ = nullptr;
    QComboBox* test_ = nullptr;
    QComboBox* sphere_ = nullptr;
    QComboBox* conesPerCluster_ = nullptr;
    QComboBox* projection_ = nullptr;
    QCheckBox* fixWinding_ = nullptr;
    QSpinBox* views_ = nullptr;
    QDoubleSpinBox* distance_ = nullptr;
};

}  // namespace conescope
