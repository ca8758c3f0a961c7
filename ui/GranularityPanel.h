// The granularity dock: measure what each record granularity culls on the clusters shown and what it
// costs (one cone per cluster with every test, 2, 4 and 8 cones, float and compact, per triangle),
// one table row per record as `conescope-cli granularity` writes it, and export it. The report is the
// Session's; the plot of it is in the plots dock and the lesson in its own dock.
#pragma once

#include <QWidget>

#include "core/Granularity.h"

class QLabel;
class QPushButton;
class QTableWidget;

namespace conescope {

class GranularityPanel : public QWidget {
    Q_OBJECT
public:
    explicit GranularityPanel(QWidget* parent = nullptr);
    // The report measured (null: none, or stale) and whether a mesh is shown.
    void showReport(const GranularityReport* report, bool meshLoaded);
    QTableWidget* table() const { return table_; }
    QPushButton* measureButton() const { return measure_; }
    QPushButton* exportButton() const { return export_; }
    QString summary() const;
    // The text of column `column` (record, bytes, bits, efficiency, culled share, tests/view, false culls) for `row`.
    static QString cellText(const GranularityRow& row, int column);
    static constexpr int kColumns = 7;

signals:
    void measureRequested();
    void exportRequested();

private:
    QPushButton* measure_ = nullptr;
    QPushButton* export_ = nullptr;
    QLabel* summary_ = nullptr;
    QTableWidget* table_ = nullptr;
};

}  // namespace conescope
