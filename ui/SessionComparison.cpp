// The window's A/B comparison: a pinned configuration A against the current one B on the same
// prepared mesh and eyes, through core/Comparison.h.
#include "Session.h"

#include "SceneBinding.h"
#include "TaskGroups.h"

namespace conescope {

void Session::pinAsA() {
    if (!prepared_ || !clusters_) return;
    pin_ = Pin{settings_, clusters_, prepared_};
    measurePinnedEye();
    requestOrbitComparison();
    emit comparisonChanged();
    emit notice(tr("Pinned as A: change the settings to make B; X swaps them"), 6000);
}

void Session::clearPin() {
    if (!pin_) return;
    runner_.cancel(taskgroups::comparison);
    pin_.reset();
    eyeComparison_.reset();
    orbitComparison_.reset();
    if (scene_) scene_->setFaceComparison({});
    emit comparisonChanged();
}

void Session::swapAB() {
    if (!pin_ || !prepared_ || !clusters_ || pin_->prepared != prepared_) return;
    runner_.cancel(taskgroups::clusters);
    const Pin previous{settings_, clusters_, prepared_};
    settings_ = pin_->settings;
    SceneResult result;
    result.prepared = prepared_;
    result.clusters = pin_->clusters;
    result.scene = makeScene(*prepared_, *pin_->clusters);
    pin_ = previous;
    emit settingsAdjusted(settings_);
    showSceneResult(result, false);
}

int Session::pinnedClusterOf(int cluster) const {
    if (!pin_ || !clusters_ || cluster < 0 || cluster >= int(clusters_->bounds.count())) return -1;
    const ClusterFaces& rows = clusters_->bounds.faces;
    if (rows.starts[size_t(cluster)] == rows.starts[size_t(cluster) + 1]) return -1;
    return int(pin_->clusters->partition.clusterOfFace[rows.faces[rows.starts[size_t(cluster)]]]);
}

void Session::dropStalePin() {
    if (!pin_ || pin_->prepared == prepared_) return;
    clearPin();
    emit notice(tr("A was pinned for another mesh or winding repair: pin again to compare"), 8000);
}

void Session::measurePinnedEye() {
    eyeComparison_.reset();
    if (!scene_) return;
    if (!pin_ || !measurement_ || !prepared_ || !clusters_) {
        scene_->setFaceComparison({});
        return;
    }
    eyeComparison_ = showComparison(*scene_, *prepared_, *pin_->clusters, *clusters_, *measurement_);
}

void Session::requestOrbitComparison() {
    runner_.cancel(taskgroups::comparison);
    orbitComparison_.reset();
    if (!pin_ || !prepared_ || !clusters_) return;
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> a = pin_->clusters, b = clusters_;
    const std::vector<Eye> views = orbitOf(settings_, prepared_->box);
    runner_.run<Comparison>(
        taskgroups::comparison, tr("Comparing A and B over the orbit"),
        [prepared, a, b, views](const ProgressCallback& progress) { return compareClusterSets(*prepared, *a, *b, views, progress); },
        [this, a, b](Comparison& comparison) {
            if (!pin_ || pin_->clusters != a || clusters_ != b) return;  // A or B changed meanwhile
            orbitComparison_ = std::move(comparison);
            emit comparisonChanged();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot compare A and B"), error); });
}

}  // namespace conescope
