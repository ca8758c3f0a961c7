#include "StatisticsPanel.h"

#include <algorithm>

#include <QEvent>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>

#include "Glossary.h"

namespace conescope {

namespace {

// Above and below each row's name and value: the rows' spacing (the form's own is 0).
constexpr int kRowMargin = 3;

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
    // explicit budget is searched longer than the default one (docs/user/what-is-computed.md, "Builders").
    if (settings.builder == Builder::Optimized)
        builder += QStringLiteral(" (%1, %2)")
                       .arg(QString::fromStdString(toString(settings.effort)),
                            settings.clusterCount != 0 ? QStringLiteral("budget %1").arg(settings.clusterCount)
                                                       : QStringLiteral("default budget"));
    // The cone and test first: what A and B most often differ in must not be the part that wraps away.
    return QStringLiteral("%1 / %2, %3, %4/%5")
        .arg(QString::fromStdString(toString(displayedCone(settings))), QString::fromStdString(toString(displayedTest(settings))), builder)
        .arg(settings.limits.maxVertices)
        .arg(settings.limits.maxTriangles);
}

}  // namespace

StatisticsPanel::StatisticsPanel(QWidget* parent) : QWidget(parent) {
    form_ = new QFormLayout(this);
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    // The space between rows is each row's own margin: Qt 5's form keeps its spacing for hidden rows,
    // which left a gap where the comparison's rows are hidden.
    form_->setVerticalSpacing(0);
    // The current eye's numbers first: they change as the eye moves; the mesh's below.
    for (const char* name : {"eye", "clusters culled", "triangles culled", "back-facing triangles", "efficiency",
                             "false culls", "missed clusters", "time per test"})
        addRow(QString::fromLatin1(name));
    // With a pin, A against B right under the eye's own numbers.
    for (const QString& name : comparisonRows()) addRow(name);
    // With K cones per cluster, that record beside the one-cone test.
    for (const QString& name : multiConeRows()) addRow(name);
    for (const char* name : {"mesh", "faces", "triangles", "degenerate faces", "mesh problems", "clusters",
                             "uncullable clusters", "builder", "cone / test", "build time", "orbit efficiency",
                             "lost over the orbit", "expected efficiency", "cull / oracle fraction", "cluster fill",
                             "sphere radius"})
        addRow(QString::fromLatin1(name));
    // The LOD hierarchy's cut from the eye and its levels (LOD dock), last: shown once it is built.
    for (const QString& name : lodRows()) addRow(name);
    showComparison(nullptr, nullptr, nullptr);
    showMultiCones(0, nullptr, nullptr, 0);
    showLod(nullptr);
    clear();
}

// Fits the values' heights to their new texts when a show function returns (however it returns).
struct StatisticsPanel::FitHeightsAfter {
    explicit FitHeightsAfter(StatisticsPanel& panel) : panel(panel) {}
    ~FitHeightsAfter() { panel.fitHeights(); }
    StatisticsPanel& panel;
};

namespace {

// What each row says, for its tooltip and What's This.
QString aboutRow(const QString& row) {
    static const std::map<QString, QString> about = {
        {"eye", QObject::tr("Where the cull eye is (or, orthographic, the direction it looks along): every number above the "
                            "mesh's is for this eye.")},
        {"clusters culled", QObject::tr("Clusters the test skips from this eye, of all clusters.")},
        {"triangles culled", QObject::tr("Triangles in the culled clusters: what culling saves from this eye.")},
        {"back-facing triangles", QObject::tr("Triangles whose face turns away from this eye (the oracle's count): the most any "
                                              "culling could save.")},
        {"efficiency", explain(QStringLiteral("efficiency"))},
        {"false culls", explain(QStringLiteral("false cull")) + QObject::tr(" Always 0 for ConeScope's own tests.")},
        {"missed clusters", explain(QStringLiteral("missed cull")) + QObject::tr(" The count from this eye.")},
        {"K cones from the eye", QObject::tr("Each cluster split into K sub-groups with a cone and an apex each: "
                                             "sub-groups culled from this eye, the triangles in them and their share of the "
                                             "back-facing triangles, beside the one-cone test above.")},
        {"K cones over the orbit", QObject::tr("The K-cone record over every orbit eye: efficiency, false culls and the bytes "
                                               "a cluster's record takes (what the statistics export's multi_cone says).")},
        {"time per test", QObject::tr("How long one cluster's test takes, measured over all clusters for this eye.")},
        {"A (pinned)", QObject::tr("The settings pinned as A: cone / test first (what A and B most often differ in), then the "
                                   "builder and the limits. The current settings are B.")},
        {"A / B efficiency", QObject::tr("Efficiency from this eye with A's settings and with B's.")},
        {"A / B culled", QObject::tr("Triangles culled from this eye by A only, by B only and by both (the colours of the faces).")},
        {"A / B over the orbit", QObject::tr("Efficiency over the whole orbit with A's settings and with B's.")},
        {"A / B culled over the orbit", QObject::tr("Triangles culled over the orbit by A only, by B only and by both.")},
        {"A / B clusters", QObject::tr("How many clusters A and B have: compare partitions only at equal counts (within 5%), "
                                       "smaller clusters cull more for free.")},
        {"mesh", QObject::tr("The file shown.")},
        {"faces", QObject::tr("Faces of the mesh as read (a polygon counts once).")},
        {"triangles", QObject::tr("Triangles of the mesh: a polygon of n corners counts n - 2.")},
        {"degenerate faces", QObject::tr("Faces without area, so without a normal: they never decide a cull.")},
        {"mesh problems", QObject::tr("Open, non-manifold or inconsistently wound edges, inside-out pieces, duplicate and "
                                      "double-sided faces: what can make a face's normal point the wrong way.")},
        {"clusters", explain(QStringLiteral("cluster")) + QObject::tr(" How many the builder made.")},
        {"uncullable clusters", QObject::tr("Clusters without a cone: their normals span more than a half-space, so no cone test "
                                            "can cull them from any eye.")},
        {"builder", QObject::tr("How the faces were grouped into clusters (Settings > Builder).")},
        {"cone / test", QObject::tr("The cone of normals and the cull test the numbers are for.")},
        {"build time", QObject::tr("How long making the clusters and their cones and bounds took.")},
        {"orbit efficiency", QObject::tr("Efficiency over every orbit eye together (triangles culled / back-facing, summed), "
                                         "and the views' efficiencies averaged.")},
        {"lost over the orbit", explain(QStringLiteral("test loss")) + QStringLiteral(" ") + explain(QStringLiteral("partition loss"))},
        {"expected efficiency", QObject::tr("What the cones promise from random far eyes: the sum of T (1 - sin alpha) / 2 over "
                                            "the clusters, over half the triangles.")},
        {"cull / oracle fraction", explain(QStringLiteral("cull fraction")) + QStringLiteral(" ") + explain(QStringLiteral("oracle fraction"))},
        {"cluster fill", QObject::tr("How full the clusters are on average, against the limits (Max vertices, Max triangles).")},
        {"LOD cut", QObject::tr("The clusters and triangles the LOD hierarchy's cut from this eye draws: per region the "
                                "coarsest level whose error, seen from the eye, is within the threshold.")},
        {"LOD levels used", QObject::tr("The levels the cut draws clusters from, with how many of each.")},
        {"LOD culled", QObject::tr("Of the cut's triangles: those in clusters the test culls, and those facing away from the eye.")},
        {"LOD efficiency", QObject::tr("The cut's triangles culled / its back-facing triangles: how much of what the hierarchy draws "
                                       "the cone test still skips.")},
        {"LOD false culls", QObject::tr("Culled clusters of the cut holding a front-facing face: must be 0.")},
        {"LOD levels", QObject::tr("Per level from this eye: clusters, triangles, the mean cone half-angle (triangle-weighted) "
                                   "and the test's efficiency on the whole level.")},
        {"sphere radius", QObject::tr("The clusters' bounding spheres: how far a cluster sprawls (what frustum and occlusion "
                                      "culling see).")},
    };
    const auto found = about.find(row);
    return found == about.end() ? QString() : found->second;
}

}  // namespace

QLabel* StatisticsPanel::addRow(const QString& name) {
    auto* label = new QLabel(this);
    label->setTextInteractionFlags(Qt::TextSelectableByMouse);
    label->setWordWrap(true);
    label->setObjectName(name);
    // The form sizes its rows from a wrapped value's height at another width than the one it gets
    // (two lines where three are needed): without height-for-width, fitHeight's minimum holds.
    QSizePolicy policy = label->sizePolicy();
    policy.setHeightForWidth(false);
    label->setSizePolicy(policy);
    auto* title = new QLabel(name + QLatin1Char(':'), this);
    // The row's name and its value both say what it means.
    for (QLabel* part : {title, label}) {
        part->setToolTip(aboutRow(name));
        part->setWhatsThis(aboutRow(name));
        part->setContentsMargins(0, kRowMargin, 0, kRowMargin);
    }
    form_->addRow(title, label);
    values_[name] = label;
    label->installEventFilter(this);
    return label;
}

bool StatisticsPanel::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::Resize) fitHeight(static_cast<QLabel*>(watched));
    return QWidget::eventFilter(watched, event);
}

void StatisticsPanel::fitHeight(QLabel* label) {
    // A form lays its rows out from their size hints, not from the height a wrapped text needs at the
    // width it gets: each value takes that height itself, or its last lines are cut away.
    const int needed = label->heightForWidth(label->width());
    if (needed > 0 && (needed != label->minimumHeight() || needed != label->maximumHeight())) label->setFixedHeight(needed);
}

void StatisticsPanel::fitHeights() {
    for (auto& [name, label] : values_) fitHeight(label);
}

QString StatisticsPanel::rowHelp(const QString& row) const {
    const auto found = values_.find(row);
    return found == values_.end() ? QString() : found->second->toolTip();
}

QStringList StatisticsPanel::rows() const {
    QStringList names;
    for (const auto& [name, label] : values_) names << name;
    return names;
}

QString StatisticsPanel::value(const QString& row) const {
    auto found = values_.find(row);
    return found == values_.end() ? QString() : found->second->text();
}

QStringList StatisticsPanel::lodRows() {
    return {QStringLiteral("LOD cut"), QStringLiteral("LOD levels used"), QStringLiteral("LOD culled"), QStringLiteral("LOD efficiency"),
            QStringLiteral("LOD false culls"), QStringLiteral("LOD levels")};
}

QString StatisticsPanel::lodLevelLine(const LodLevelStatistics& level) {
    return tr("level %1: %2 clusters, %3 triangles, mean half-angle %4 deg, efficiency %5")
        .arg(level.level)
        .arg(level.clusters)
        .arg(level.triangles)
        .arg(level.meanHalfAngleDegrees, 0, 'f', 1)
        .arg(percent(level.culling.efficiency));
}

void StatisticsPanel::showLod(const LodStatistics* lod) {
    const FitHeightsAfter fit(*this);
    for (const QString& row : lodRows()) {
        values_[row]->setVisible(lod != nullptr);
        form_->labelForField(values_[row])->setVisible(lod != nullptr);
    }
    if (!lod || lod->cut.views.empty()) return;
    const LodCutView& cut = lod->cut.views.front();
    values_["LOD cut"]->setText(tr("%1 clusters, %2 triangles").arg(cut.clusters).arg(cut.triangles));
    QStringList used;
    for (size_t l = 0; l < cut.clustersPerLevel.size(); ++l)
        if (cut.clustersPerLevel[l]) used << tr("%1 (%2)").arg(l).arg(cut.clustersPerLevel[l]);
    values_["LOD levels used"]->setText(used.join(QStringLiteral(", ")));
    values_["LOD culled"]->setText(tr("%1 of %2 back-facing triangles").arg(cut.trianglesCulled).arg(cut.backFacingTriangles));
    values_["LOD efficiency"]->setText(percent(cut.efficiency));
    values_["LOD false culls"]->setText(QString::number(cut.falseCulls));
    QStringList levels;
    for (const LodLevelStatistics& level : lod->levels) levels << lodLevelLine(level);
    values_["LOD levels"]->setText(levels.join(QLatin1Char('\n')));
}

void StatisticsPanel::clear() {
    const FitHeightsAfter fit(*this);
    for (auto& [name, label] : values_) label->setText(QStringLiteral("-"));
}

void StatisticsPanel::showClusters(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings) {
    const FitHeightsAfter fit(*this);
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
    const FitHeightsAfter fit(*this);
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
    const FitHeightsAfter fit(*this);
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
    // The share too, and why it matters when most clusters can never be culled (the note as its tooltip).
    const CullTestStatistics& shown = measurement.statistics;
    QLabel* uncullable = values_["uncullable clusters"];
    uncullable->setText(tr("%1 of %2 (%3)").arg(count(shown.uncullableClusters), count(shown.clusters.size()),
                                               percent(uncullableShare(shown.uncullableClusters, shown.clusters.size()))));
    const QString note = QString::fromStdString(uncullableNote(shown.uncullableClusters, shown.clusters.size()));
    const QString about = aboutRow(QStringLiteral("uncullable clusters"));
    uncullable->setToolTip(note.isEmpty() ? about : about + QStringLiteral("\n\n") + note);
    uncullable->setStyleSheet(note.isEmpty() ? QString() : QStringLiteral("color: #a0400a; font-weight: bold;"));
}

QStringList StatisticsPanel::multiConeRows() {
    return {QStringLiteral("K cones from the eye"), QStringLiteral("K cones over the orbit")};
}

void StatisticsPanel::showMultiCones(uint32_t cones, const MultiConeCulling* orbit, const SubGroupEyeCounts* eye, size_t eyeBackFacing) {
    const FitHeightsAfter fit(*this);
    for (const QString& row : multiConeRows()) {
        values_[row]->setVisible(cones > 1);
        if (auto* label = qobject_cast<QLabel*>(form_->labelForField(values_[row]))) {
            label->setText(QString(row).replace(QLatin1Char('K'), QString::number(cones)));
            label->setVisible(cones > 1);
        }
    }
    if (cones <= 1) return;
    values_["K cones from the eye"]->setText(
        eye ? tr("%1 of %2 sub-groups, %3 triangles (%4), false culls %5")
                  .arg(count(eye->groupsCulled), count(eye->groups), count(eye->trianglesCulled),
                       percent(cullEfficiency(eye->trianglesCulled, eyeBackFacing)), count(eye->falseCulls))
            : tr("measuring..."));
    values_["K cones over the orbit"]->setText(
        orbit ? tr("%1 (%2 of %3), false culls %4, %5 bytes a cluster")
                    .arg(percent(orbit->efficiency), count(orbit->trianglesCulled), count(orbit->backFacingTriangles),
                         count(orbit->falseCulls), count(orbit->bytesPerCluster))
              : tr("measuring..."));
}

QStringList StatisticsPanel::comparisonRows() {
    return {QStringLiteral("A (pinned)"), QStringLiteral("A / B efficiency"), QStringLiteral("A / B culled"),
            QStringLiteral("A / B over the orbit"), QStringLiteral("A / B culled over the orbit"), QStringLiteral("A / B clusters")};
}

void StatisticsPanel::showComparison(const Settings* a, const Comparison* eye, const Comparison* orbit) {
    const FitHeightsAfter fit(*this);
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
    const FitHeightsAfter fit(*this);
    values_["eye"]->setText(message);
    for (const char* name : {"clusters culled", "triangles culled", "back-facing triangles", "efficiency",
                             "missed clusters", "false culls", "time per test"})
        values_[QString::fromLatin1(name)]->setText(QStringLiteral("-"));
}

}  // namespace conescope
