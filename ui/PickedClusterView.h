// The "Picked cluster" dock: the picked cluster's numbers for the current eye (ClusterReport's
// page, from core explainCull), or what to do to pick one.
#pragma once

#include <QTextBrowser>

namespace conescope {

class Session;

class PickedClusterView : public QTextBrowser {
    Q_OBJECT
public:
    explicit PickedClusterView(QWidget* parent = nullptr);

    // The session's picked cluster explained for its current eye and displayed test.
    void showPick(const Session& session);
};

}  // namespace conescope
