// Live numbers: the loaded mesh and its clusters, and for the current eye the culled clusters and
// triangles, efficiency, false culls (always shown; must be 0), degenerate faces and the time per
// test. Formatting only; the numbers come from the pipeline.
#pragma once

#include <QStringList>
#include <QWidget>

#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "core/lod/LodCut.h"

class QFormLayout;
class QLabel;

namespace conescope {

class StatisticsPanel : public QWidget {
    Q_OBJECT
public:
    explicit StatisticsPanel(QWidget* parent = nullptr);

    // The mesh and its clusters, shown with `settings` (the builder, cone and test named).
    void showClusters(const PreparedMesh& prepared, const ClusterSet& clusters, const Settings& settings);
    void showEye(const EyeMeasurement& measurement);
    // The partition's summary over the orbit (measureOrbit); "measuring..." while there is none.
    void showOrbit(const CullTestStatistics* orbit);
    void showEyeError(const QString& message);
    // A against B (the pinned configuration against the current one) for the eye and over the
    // orbit, and the cluster-count warning; `a` null hides the comparison rows.
    void showComparison(const Settings* a, const Comparison* eye, const Comparison* orbit);
    // The K-cone record (cones > 1) from the eye and over the orbit; null: being measured. Hidden for one cone.
    void showMultiCones(uint32_t cones, const MultiConeCulling* orbit, const SubGroupEyeCounts* eye, size_t eyeBackFacing);
    void clear();
    // The LOD hierarchy's cut from the eye and its per-level rows (Session::lodStatistics); null hides them.
    void showLod(const LodStatistics* lod);
    // One level's row as the "LOD levels" value shows it.
    static QString lodLevelLine(const LodLevelStatistics& level);

    // The label text of a row, by its name ("clusters culled", "false culls", ...), for tests.
    QString value(const QString& row) const;
    // What a row means (its tooltip and What's This), and every row's name, for tests.
    QString rowHelp(const QString& row) const;
    QStringList rows() const;

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    struct FitHeightsAfter;
    QLabel* addRow(const QString& name);
    void fitHeight(QLabel* label);
    void fitHeights();
    static QStringList comparisonRows();
    static QStringList multiConeRows();
    static QStringList lodRows();

    QFormLayout* form_ = nullptr;
    std::map<QString, QLabel*> values_;
};

}  // namespace conescope
