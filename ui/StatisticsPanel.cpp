#include "StatisticsPanel.h"

#include <algorithm>

#include <QFormLayout>
#include <QLabel>
#include <QLocale>

namespace conescope {

namespace {

QString count(size_t value) { return QLocale().toString(qulonglong(value)); }
QString percent(double fraction) { return QString::number(100.0 * fraction, 'f', 1) + QLatin1Char('%'); }
QString seconds(double value) { return QString::number(1000.0 * value, 'f', 1) + QStringLiteral(" ms"); }

// What the two sides culled, in triangles: only A, only B, both.
QString culledBy(const Comparison& comparison) {
    return QObject::tr("%1 only by A, %2 only by B, %3 by both")
        .arg(count(comparison.trianglesCulledOnlyA), count(comparison.trianglesCulledOnlyB), count(comparison.trianglesCulledBoth));
}

QString efficiencies(const Comparison& comparison) {
    return QObject::tr("A %1, B %2").arg(percent(comparison.efficiencyA), percent(comparison.efficiencyB));
}

QString configuration(const Settings& settings) {
    QString builder = QString::fromStdString(toString(settings.builder));
    // The optimized builder's effort and budget change what it makes at the same count: an
    // explicit budget is searched longer than the default one (README, "Builders").
    if (settings.builder == Builder::Optimized)
        builder += QStringLiteral(" (%1, %2)")
                       .arg(QString::fromStdString(toString(settings.effort)),
                            settings.clusterCount != 0 ? QStringLiteral("budget %1").arg(settings.clusterCount)
                                                       : QStringLiteral("default budget"));
    return QStringLiteral("%1, %2 / %3, %4/%5")
        .arg(builder, QString::fromStdString(toString(displayedCone(settings))), QString::fromStdString(toString(displayedTest(settings))))
        .arg(settings.limits.maxVertices)
        .arg(settings.limits.maxTriangles);
}

}  // namespace

StatisticsPanel::StatisticsPanel(QWidget* parent) : QWidget(parent) {
    form_ = new QFormLayout(this);
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // The current eye's numbers first: they change as the eye moves; the mesh's below.
    for (const char* name : {"eye", "clusters culled", "triangles culled", "back-facing triangles", "efficiency",
                             "false culls", "missed clusters", "time per test"})
        addRow(QString::fromLatin1(name));
    // With a pin, A against B right under the eye's own numbers.
    for (const QString& name : comparisonRows()) addRow(name);
    for (const char* name : {"mesh", "faces", "triangles", "degenerate faces", "mesh problems", "clusters",
                             "uncullable clusters", "builder", "cone / test", "build time", "orbit efficiency",
                             "lost over the orbit", "expected efficiency", "cull / oracle fraction", "cluster fill",
                             "sphere radius"})
        addRow(QString::fromLatin1(name));
    showComparison(nullptr, nullptr, nullptr);
    clear();
}

QLabel* StatisticsPanel::addRow(const QString& name) {
    auto* label = new QLabel(this);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setWordWrap(true);
    label->setObjectName(name);
    form_->addRow(name + QLatin1Char(':'), label);
    values_[name] = label;
    return label;
}

QString StatisticsPanel::value(const QString& row) const {
    auto found = values_.find(row);
    return found == values_.end() ? QString() : found->second->text();
}

void StatisticsPanel::clear() {
    for (auto& [name, label] : values_) label->setText(QStringLiteral("-"));
}

void StatisticsPanel::showClusters(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings) {
    values_["mesh"]->setText(QString::fromStdString(prepared.name));
    values_["faces"]->setText(count(prepared.mesh().faceCount()));
    values_["triangles"]->setText(count(prepared.triangles));
    values_["degenerate faces"]->setText(count(prepared.faces.degenerateCount));
    const MeshReport& report = prepared.report;
    QStringList problems;
    if (report.openEdges) problems << tr("%1 open edges").arg(report.openEdges);
    if (report.nonManifoldEdges) problems << tr("%1 non-manifold edges").arg(report.nonManifoldEdges);
    if (report.inconsistentEdges) problems << tr("%1 inconsistently wound edges").arg(report.inconsistentEdges);
    if (report.insideOutComponents) problems << tr("%1 inside-out components").arg(report.insideOutComponents);
    if (report.duplicateFaces) problems << tr("%1 duplicate faces").arg(report.duplicateFaces);
    if (report.doubleSidedFaces) problems << tr("%1 double-sided").arg(report.doubleSidedFaces);
    if (prepared.windingFixedFaces) problems << tr("%1 faces flipped").arg(prepared.windingFixedFaces);
    values_["mesh problems"]->setText(problems.isEmpty() ? tr("none") : problems.join(QStringLiteral(", ")));
    values_["clusters"]->setText(count(clusters.partition.clusterCount));
    values_["builder"]->setText(QString::fromStdString(toString(settings.builder)));
    values_["cone / test"]->setText(QStringLiteral("%1 / %2").arg(QString::fromStdString(toString(displayedCone(settings))),
                                                                  QString::fromStdString(toString(displayedTest(settings)))));
    values_["build time"]->setText(tr("partition %1, bounds %2")
                                       .arg(seconds(clusters.partitionSeconds), seconds(clusters.boundsSeconds)));
}

void StatisticsPanel::showOrbit(const CullTestStatistics* orbit) {
    const char* rows[] = {"orbit efficiency", "lost over the orbit", "expected efficiency", "cull / oracle fraction",
                          "cluster fill", "sphere radius"};
    if (!orbit) {
        for (const char* row : rows) values_[QString::fromLatin1(row)]->setText(tr("measuring..."));
        return;
    }
    const double back = double(std::max<size_t>(orbit->backFacingTriangles, 1));
    values_["orbit efficiency"]->setText(tr("%1 (mean per view %2)").arg(percent(orbit->efficiency), percent(orbit->meanViewEfficiency)));
    values_["lost over the orbit"]->setText(tr("%1 by the test, %2 by the partition")
                                                .arg(percent(double(orbit->testLossTriangles) / back),
                                                     percent(double(orbit->partitionLossTriangles) / back)));
    values_["expected efficiency"]->setText(percent(orbit->expectedEfficiency));
    values_["cull / oracle fraction"]->setText(QStringLiteral("%1 / %2").arg(orbit->cullFraction, 0, 'f', 3).arg(orbit->oracleFraction, 0, 'f', 3));
    values_["cluster fill"]->setText(tr("%1 triangles, %2 vertices on average")
                                         .arg(orbit->meanClusterTriangles, 0, 'f', 1)
                                         .arg(orbit->meanClusterVertices, 0, 'f', 1));
    values_["sphere radius"]->setText(tr("mean %1, max %2").arg(orbit->meanSphereRadius, 0, 'g', 4).arg(orbit->maxSphereRadius, 0, 'g', 4));
}

void StatisticsPanel::showEye(const EyeMeasurement& measurement) {
    const ViewStatistics& view = measurement.view();
    // The test can change without new clusters: the row says what this measurement used.
    values_["cone / test"]->setText(QStringLiteral("%1 / %2").arg(QString::fromStdString(toString(measurement.statistics.cone)),
                                                                  QString::fromStdString(toString(measurement.statistics.test))));
    const Eye& eye = measurement.eye;
    values_["eye"]->setText(eye.orthographic
                                ? tr("orthographic along (%1, %2, %3)")
                                      .arg(eye.direction.x, 0, 'g', 4).arg(eye.direction.y, 0, 'g', 4).arg(eye.direction.z, 0, 'g', 4)
                                : tr("(%1, %2, %3)")
                                      .arg(eye.position.x, 0, 'g', 5).arg(eye.position.y, 0, 'g', 5).arg(eye.position.z, 0, 'g', 5));
    values_["clusters culled"]->setText(tr("%1 / %2").arg(count(view.clustersCulled), count(measurement.culled.size())));
    values_["triangles culled"]->setText(count(view.trianglesCulled));
    values_["back-facing triangles"]->setText(count(view.backFacingTriangles));
    values_["efficiency"]->setText(percent(view.efficiency));
    values_["missed clusters"]->setText(count(view.missedClusters));
    QLabel* falseCulls = values_["false culls"];
    falseCulls->setText(count(view.falseCulls));
    // A false cull is a bug in a test: make it impossible to overlook.
    falseCulls->setStyleSheet(view.falseCulls ? QStringLiteral("color: white; background: #d00000; font-weight: bold;")
                                              : QStringLiteral("color: #207020;"));
    values_["time per test"]->setText(tr("%1 ns per cluster").arg(view.nanosecondsPerCluster, 0, 'f', 1));
    values_["uncullable clusters"]->setText(count(measurement.statistics.uncullableClusters));
}

QStringList StatisticsPanel::comparisonRows() {
    return {QStringLiteral("A (pinned)"), QStringLiteral("A / B efficiency"), QStringLiteral("A / B culled"),
            QStringLiteral("A / B over the orbit"), QStringLiteral("A / B culled over the orbit"), QStringLiteral("A / B clusters")};
}

void StatisticsPanel::showComparison(const Settings* a, const Comparison* eye, const Comparison* orbit) {
    for (const QString& row : comparisonRows()) {
        values_[row]->setVisible(a != nullptr);
        if (QWidget* label = form_->labelForField(values_[row])) label->setVisible(a != nullptr);
    }
    if (!a) return;
    values_["A (pinned)"]->setText(configuration(*a));
    values_["A / B efficiency"]->setText(eye ? efficiencies(*eye) : QStringLiteral("-"));
    values_["A / B culled"]->setText(eye ? culledBy(*eye) : QStringLiteral("-"));
    values_["A / B over the orbit"]->setText(orbit ? efficiencies(*orbit) : tr("measuring..."));
    values_["A / B culled over the orbit"]->setText(orbit ? culledBy(*orbit) : tr("measuring..."));
    const Comparison* counts = orbit ? orbit : eye;
    QLabel* clusters = values_["A / B clusters"];
    if (!counts) {
        clusters->setText(QStringLiteral("-"));
        return;
    }
    const std::string warning = clusterCountWarning(*counts);
    clusters->setText(tr("A %1, B %2").arg(count(counts->clustersA), count(counts->clustersB)) +
                      (warning.empty() ? QString() : QStringLiteral("<br>") + QString::fromStdString(warning)));
    // Unequal counts make the comparison unfair: say so where it is read.
    clusters->setStyleSheet(warning.empty() ? QString() : QStringLiteral("color: #b05000; font-weight: bold;"));
}

void StatisticsPanel::showEyeError(const QString& message) {
    values_["eye"]->setText(message);
    for (const char* name : {"clusters culled", "triangles culled", "back-facing triangles", "efficiency",
                             "missed clusters", "false culls", "time per test"})
        values_[QString::fromLatin1(name)]->setText(QStringLiteral("-"));
}

}  // namespace conescope
