// Live numbers: the loaded mesh and its clusters, and for the current eye the culled clusters and
// triangles, efficiency, false culls (always shown; must be 0), degenerate faces and the time per
// test. Formatting only; the numbers come from the pipeline.
#pragma once

#include <QWidget>

#include "core/Pipeline.h"

class QFormLayout;
class QLabel;

namespace conescope {

class StatisticsPanel : public QWidget {
    Q_OBJECT
public:
    explicit StatisticsPanel(QWidget* parent = nullptr);

    void showClusters(const PreparedMesh& prepared, const ClusterSet& clusters);
    void showEye(const EyeMeasurement& measurement);
    // The partition's summary over the orbit (measureOrbit); "measuring..." while there is none.
    void showOrbit(const TestStatistics* orbit);
    void showEyeError(const QString& message);
    void clear();

    // The label text of a row, by its name ("clusters culled", "false culls", ...), for tests.
    QString value(const QString& row) const;

private:
    QLabel* addRow(const QString& name);

    QFormLayout* form_ = nullptr;
    std::map<QString, QLabel*> values_;
};

}  // namespace conescope
