// The cluster LOD hierarchy's controls: build it, show one level or the cut from the cull eye, the
// cut's error threshold in pixels (with the screen it is measured on) and the LOD colourings. The
// numbers go to the statistics panel; the hierarchy itself is the Session's.
#pragma once

#include <QWidget>

#include "core/lod/LodCut.h"
#include "scene/SceneTypes.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSlider;

namespace conescope {

class Session;

class LodPanel : public QWidget {
    Q_OBJECT
public:
    explicit LodPanel(QWidget* parent = nullptr);
    // The session's hierarchy, what it shows and its threshold.
    void showLod(const Session& session);
    // The threshold the controls show.
    LodThreshold threshold() const;
    QComboBox* levelChooser() const { return level_; }
    QDoubleSpinBox* thresholdBox() const { return pixels_; }
    QPushButton* buildButton() const { return build_; }

signals:
    void buildRequested();
    void exportRequested();
    void levelChosen(int level);  // kLodNone, kLodCut or a level
    void thresholdChanged(const conescope::LodThreshold& threshold);
    void coloringChosen(conescope::FaceColoring coloring);

private:
    void showHierarchy(const ClusterHierarchy* hierarchy, int shown, FaceColoring coloring, bool meshLoaded);

    QPushButton* build_ = nullptr;
    QPushButton* export_ = nullptr;
    QLabel* summary_ = nullptr;
    QComboBox* level_ = nullptr;
    QComboBox* coloring_ = nullptr;
    QSlider* slider_ = nullptr;
    QDoubleSpinBox* pixels_ = nullptr;
    QDoubleSpinBox* screenHeight_ = nullptr;
    QDoubleSpinBox* fov_ = nullptr;
};

}  // namespace conescope
