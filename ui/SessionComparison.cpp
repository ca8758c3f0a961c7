// The window's A/B comparison: a pinned snapshot A against the shown one B on the same prepared mesh
// and eyes, through core/Comparison.h. Each side is scored with the test of its own settings.
#include "Session.h"

#include "SceneBinding.h"
#include "TaskGroups.h"

namespace conescope {

void Session::pinAsA() {
    if (!shown_.clusters) return;
    pin_ = shown_;
    measurePinnedEye();
    requestOrbitComparison();
    setFaceColoring(FaceColoring::Comparison);
    emit comparisonChanged();
    emit notice(tr("Pinned as A: change the settings to make B; X swaps them; Shift+R shows the side where they cull"), 8000);
}

void Session::clearPin() {
    dropPin();
    if (coloring_ == FaceColoring::Comparison) setFaceColoring(FaceColoring::CullDecision);
}

void Session::dropPin() {
    if (!pin_) return;
    runner_.cancel(taskgroups::comparison);
    pin_.reset();
    eyeComparison_.reset();
    orbitComparison_.reset();
    if (scene_) scene_->setFaceComparison({});
    emit comparisonChanged();
}

void Session::swapAB() {
    if (!pin_ || !shown_.clusters || pin_->prepared != shown_.prepared) return;
    runner_.cancel(taskgroups::clusters);
    const Snapshot previous = shown_;
    SceneResult result;
    result.snapshot = *pin_;
    result.scene = makeScene(*shown_.prepared, *pin_->clusters);
    pin_ = previous;
    asked_ = result.snapshot.settings;
    emit settingsChanged(asked_);
    showSceneResult(result, false);
}

int Session::pinnedClusterOf(int cluster) const {
    if (!pin_ || !shown_.clusters || cluster < 0 || cluster >= int(shown_.clusters->bounds.count())) return -1;
    const ClusterFaces& rows = shown_.clusters->bounds.faces;
    if (rows.starts[size_t(cluster)] == rows.starts[size_t(cluster) + 1]) return -1;
    return int(pin_->clusters->partition.clusterOfFace[rows.faces[rows.starts[size_t(cluster)]]]);
}

void Session::dropStalePin() {
    if (!pin_ || pin_->prepared == shown_.prepared) return;
    dropPin();
    emit notice(tr("A was pinned for another mesh or winding repair: pin again to compare"), 8000);
}

void Session::measurePinnedEye() {
    eyeComparison_.reset();
    if (!scene_) return;
    if (!pin_ || !measurement_ || !shown_.clusters) {
        scene_->setFaceComparison({});
        return;
    }
    eyeComparison_ = showComparison(*scene_, *shown_.prepared, pin_->configuration(), shown_.configuration(), *measurement_);
}

void Session::requestOrbitComparison() {
    runner_.cancel(taskgroups::comparison);
    orbitComparison_.reset();
    if (!pin_ || !shown_.clusters) return;
    const Snapshot a = *pin_, b = shown_;
    const std::vector<Eye> views = orbitOf(b.settings, b.prepared->box);
    runner_.run<Comparison>(
        taskgroups::comparison, tr("Comparing A and B over the orbit"),
        [a, b, views](const ProgressCallback& progress) {
            return compareClusterSets(*b.prepared, a.configuration(), b.configuration(), views, progress);
        },
        [this, a, b](Comparison& comparison) {
            // Other clusters meanwhile: their own comparison follows. (Other tests or views ask for a
            // new comparison, which cancels this one.)
            if (!pin_ || pin_->clusters != a.clusters || shown_.clusters != b.clusters) return;
            orbitComparison_ = std::move(comparison);
            emit comparisonChanged();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot compare A and B"), error); });
}

}  // namespace conescope
