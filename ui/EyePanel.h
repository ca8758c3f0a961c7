// The cull eye's controls: typed coordinates, "look from here", follow the observer, orbit
// animation. It holds no eye of its own: the window owns the eye and shows it here.
#pragma once

#include <QWidget>

#include <glm/glm.hpp>

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace conescope {

class EyePanel : public QWidget {
    Q_OBJECT
public:
    explicit EyePanel(QWidget* parent = nullptr);

    glm::dvec3 position() const;
    // Shows the position without emitting positionEdited.
    void showPosition(const glm::dvec3& position);
    // Sets how many digits and what step suit a mesh of this size.
    void setScale(double meshSize);
    void showOrbitStep(int view, int viewCount);  // view < 0 hides it
    void setFollowing(bool following);
    void setAnimating(bool animating);

    QDoubleSpinBox* coordinateBox(int axis) const { return coordinates_[axis]; }
    QCheckBox* followBox() const { return follow_; }

signals:
    // One typed coordinate; the others keep their exact values (the boxes show them rounded).
    void coordinateEdited(int axis, double value);
    void lookFromHereClicked();
    void followToggled(bool follow);
    void animateToggled(bool animate);

private:
    QDoubleSpinBox* coordinates_[3] = {nullptr, nullptr, nullptr};
    QPushButton* lookFromHere_ = nullptr;
    QCheckBox* follow_ = nullptr;
    QPushButton* animate_ = nullptr;
    QLabel* orbitStep_ = nullptr;
};

}  // namespace conescope
