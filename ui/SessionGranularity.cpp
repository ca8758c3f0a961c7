// The session's granularity report: measured on request from the shown clusters with the shown
// settings over the orbit's views (as `conescope-cli granularity` measures the mesh), and dropped as
// soon as other clusters or settings are shown, so its numbers are never stale.
#include "Session.h"

#include <algorithm>

#include "TaskGroups.h"
#include "core/SettingsSchema.h"

namespace conescope {

Settings Session::granularityRunSettings() const {
    Settings settings = granularitySettings(exportSettings(shown_.settings, std::nullopt), false);
    // The shown test first: the per-triangle row culls after it, as the window shows it.
    const auto shownTest = std::find(settings.tests.begin(), settings.tests.end(), displayedTest(shown_.settings));
    if (shownTest != settings.tests.end()) std::rotate(settings.tests.begin(), shownTest, shownTest + 1);
    return settings;
}

void Session::measureGranularity() {
    if (!shown_.clusters) {
        emit errorOccurred(tr("Cannot measure the granularity"), tr("No mesh is loaded."));
        return;
    }
    const Snapshot from = shown_;
    const Settings settings = granularityRunSettings();
    using Measured = std::shared_ptr<const GranularityReport>;
    runner_.run<Measured>(
        taskgroups::granularity, tr("Measuring granularity"),
        [from, settings](const ProgressCallback& progress) -> Measured {
            return std::make_shared<const GranularityReport>(conescope::measureGranularity(*from.prepared, *from.clusters, settings, progress));
        },
        [this, from, settings](Measured& report) {
            // Other clusters or settings shown meanwhile: the report is of something no longer shown.
            if (from.clusters != shown_.clusters || !sameSettings(settings, granularityRunSettings())) return;
            granularity_ = report;
            granularityClusters_ = from.clusters;
            granularitySettings_ = settings;
            emit granularityChanged();
        },
        [this](const QString& error) { emit errorOccurred(tr("Cannot measure the granularity"), error); });
}

const GranularityReport* Session::granularity() const {
    if (!granularity_ || granularityClusters_ != shown_.clusters || !sameSettings(granularitySettings_, granularityRunSettings()))
        return nullptr;
    return granularity_.get();
}

void Session::dropStaleGranularity() {
    if (!granularity_ || granularity()) return;
    granularity_.reset();
    granularityClusters_.reset();
    runner_.cancel(taskgroups::granularity);
    emit granularityChanged();
}

bool Session::exportGranularity(const QString& path, StatisticsFormat format) {
    const GranularityReport* report = granularity();
    if (!report) {
        emit errorOccurred(tr("Cannot export the granularity"), tr("Measure the granularity first (Granularity dock)."));
        return false;
    }
    return writeExport(tr("Cannot export the granularity"), path,
                       [&] { conescope::exportGranularity(*report, path.toStdString(), format); });
}

}  // namespace conescope
