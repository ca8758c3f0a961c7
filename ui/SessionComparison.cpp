// The window's A/B comparison: a pinned snapshot A against the shown one B on the same prepared mesh
// and eyes, through core/Comparison.h. Each side is scored with the test of its own settings.
#include "Session.h"

#include "SceneBinding.h"
#include "TaskGroups.h"

namespace conescope {

void Session::pinAsA() {
    if (!shown_.clusters) return;
    runner_.cancel(taskgroups::comparison);
    const Snapshot a = shown_;
    // Pinned with A against B over the orbit: a Cancel meanwhile leaves nothing pinned.
    runner_.run<std::optional<OrbitComparison>>(
        taskgroups::comparison, tr("Comparing A and B over the orbit"),
        [a](const ProgressCallback& progress) {
            Snapshot b = a;
            return measureSnapshot(b, a, progress);
        },
        [this, a](std::optional<OrbitComparison>& comparison) {
            pin_ = a;
            dropStalePin();                      // another winding repair shown meanwhile
            if (!pin_) return;
            setShownSettings(shown_.settings);  // A is seen from B's eyes
            adoptComparison(comparison);         // none when other clusters were shown meanwhile
            measurePinnedEye();
            setFaceColoring(FaceColoring::Comparison);
            emit comparisonChanged();
            emit notice(tr("Pinned as A: change the settings to make B; X swaps them; Shift+R shows the side where they cull"), 8000);
            completeComparison();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot compare A and B"), error); });
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
    runner_.cancel(taskgroups::comparison);
    const Snapshot a = shown_, b = *pin_;
    // Shown with its scene, its orbit (when A's was measured with other views) and the comparison
    // the other way round; a Cancel meanwhile leaves A and B as they were.
    runner_.run<SceneResult>(
        taskgroups::comparison, tr("Swapping A and B"),
        [a, b](const ProgressCallback& progress) {
            SceneResult result;
            result.snapshot = b;
            result.scene = makeScene(*b.prepared, *b.clusters);
            result.comparison = measureSnapshot(result.snapshot, a, progress);
            return result;
        },
        [this, a, b](SceneResult& result) {
            if (!pin_ || pin_->clusters != b.clusters || shown_.clusters != a.clusters) return;  // changed meanwhile
            pin_ = shown_;
            asked_ = result.snapshot.settings;
            emit settingsChanged(asked_);
            showSceneResult(result, false);
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot swap A and B"), error); });
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


}  // namespace conescope
