// The "Picked cluster" dock: the picked cluster's numbers for the current eye (ClusterReport's
// page, from core explainCull), or what to do to pick one.
#pragma once

#include <vector>

#include <QTextBrowser>

#include "core/MultiConeCulling.h"

namespace conescope {

class Session;

class PickedClusterView : public QTextBrowser {
    Q_OBJECT
public:
    explicit PickedClusterView(QWidget* parent = nullptr);

    // The session's picked cluster explained for its current eye and displayed test; the page keeps
    // its scroll position while the same cluster is shown.
    void showPick(const Session& session);
    // The picked cluster's sub-groups the page lists (K cones per cluster), empty otherwise.
    const std::vector<SubGroupVerdict>& subGroups() const { return subGroups_; }

private:
    void showPage(int cluster, const QString& html);
    // A cluster of the LOD level or cut shown: its family, then its report for the eye.
    void showLodPick(const Session& session);

    int shownCluster_ = -1;
    std::vector<SubGroupVerdict> subGroups_;
};

}  // namespace conescope
