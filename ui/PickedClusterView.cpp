#include "PickedClusterView.h"

#include <QAbstractTextDocumentLayout>
#include <QScrollBar>

#include "ClusterReport.h"
#include "Session.h"

namespace conescope {

PickedClusterView::PickedClusterView(QWidget* parent) : QTextBrowser(parent) {
    setObjectName(QStringLiteral("clusterReport"));
    setOpenLinks(false);
    setHtml(emptyClusterReportHtml());
}

namespace {

QString clusterList(const std::vector<uint32_t>& clusters) {
    if (clusters.empty()) return QObject::tr("none");
    QStringList ids;
    for (uint32_t c : clusters) ids << QString::number(c);
    return ids.join(QStringLiteral(", "));
}

// Where a LOD cluster sits: its level and group, the group's other clusters, its parents and children.
QString familyHtml(const LodFamily& family, size_t levelCount) {
    const size_t level = family.cluster.level;
    QString html = QObject::tr("<h3>LOD level %1, cluster %2</h3><p>").arg(level).arg(family.cluster.cluster);
    html += family.group == kNoGroup ? QObject::tr("Top level: in no group.<br>")
                                     : QObject::tr("Group %1, with clusters %2.<br>").arg(family.group).arg(clusterList(family.groupMates));
    if (level + 1 < levelCount) html += QObject::tr("Parents (level %1): %2.<br>").arg(level + 1).arg(clusterList(family.parents));
    if (level > 0)
        html += QObject::tr("Children (level %1, group %2): %3.").arg(level - 1).arg(family.sourceGroup).arg(clusterList(family.children));
    else
        html += QObject::tr("Level 0: the partition's own cluster.");
    return html + QStringLiteral("</p>");
}

}  // namespace

void PickedClusterView::showPick(const Session& session) {
    if (session.lodScene()) {
        showLodPick(session);
        return;
    }
    const int picked = session.pickedCluster();
    const EyeMeasurement* measurement = session.measurement();
    if (picked < 0 || !session.clusters() || !measurement) {
        subGroups_.clear();
        showPage(-1, picked < 0 ? emptyClusterReportHtml() : tr("<p>Cluster %1: no valid eye to explain.</p>").arg(picked));
        return;
    }
    ClusterReportInput input;
    input.cluster = uint32_t(picked);
    input.bounds = &session.clusters()->bounds;
    input.eye = measurement->eye;
    input.test = displayedTest(session.settings());
    input.explanation = explainCull(cullingInput(*session.preparedMesh(), *session.clusters()), input.cluster, input.eye, input.test);
    // With a pin, the same faces under A: the A cluster that holds this cluster's first face.
    QString underA;
    const int aCluster = session.pinnedClusterOf(picked);
    if (aCluster >= 0) {
        ClusterReportInput a;
        a.cluster = uint32_t(aCluster);
        a.bounds = &session.pinnedClusters()->bounds;
        a.eye = input.eye;
        a.test = displayedTest(*session.pinnedSettings());
        a.explanation = explainCull(cullingInput(*session.preparedMesh(), *session.pinnedClusters()), a.cluster, a.eye, a.test);
        underA = pinnedClusterHtml(a);
    }
    // With K cones per cluster, each sub-group of the cluster from the same eye.
    subGroups_.clear();
    if (const std::optional<SubGroupsFromEye> fromEye = session.subGroupsFromEye()) {
        subGroups_ = subGroupVerdicts(*fromEye->multi, input.cluster, fromEye->culled, fromEye->facing);
        underA = subGroupsHtml(subGroups_) + underA;
    }
    showPage(picked, clusterReportHtml(input, underA));
}

void PickedClusterView::showLodPick(const Session& session) {
    const std::optional<LodFamily> family = session.lodPick();
    const LodLevel* level = session.lodLevelOnShow();
    const EyeMeasurement* measurement = session.lodMeasurement();
    if (!family || !level || !measurement) {
        showPage(-1, tr("<p>Click a cluster of the LOD level or cut shown to see its group, parents and children.</p>"));
        return;
    }
    ClusterReportInput input;
    input.cluster = uint32_t(session.lodPickedCluster());
    input.bounds = &level->clusters.bounds;
    input.eye = measurement->eye;
    input.test = measurement->statistics.test;
    input.explanation = explainCull(cullingInput(level->prepared, level->clusters), input.cluster, input.eye, input.test);
    showPage(int(input.cluster), familyHtml(*family, session.lodHierarchy()->levels.size()) + clusterReportHtml(input, QString()));
}

void PickedClusterView::showPage(int cluster, const QString& html) {
    // The same cluster from another eye: the reader keeps their place (the margin while the eye is
    // dragged); another cluster starts at the top.
    const bool samePage = cluster >= 0 && cluster == shownCluster_;
    const int vertical = verticalScrollBar()->value(), horizontal = horizontalScrollBar()->value();
    setHtml(html);
    shownCluster_ = cluster;
    if (!samePage) return;
    document()->documentLayout()->documentSize();  // lays the page out, so the scroll bars have their range
    verticalScrollBar()->setValue(vertical);
    horizontalScrollBar()->setValue(horizontal);
}

}  // namespace conescope
