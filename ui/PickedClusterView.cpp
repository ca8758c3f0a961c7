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

void PickedClusterView::showPick(const Session& session) {
    const int picked = session.pickedCluster();
    const EyeMeasurement* measurement = session.measurement();
    if (picked < 0 || !session.clusters() || !measurement) {
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
    showPage(picked, clusterReportHtml(input, underA));
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
