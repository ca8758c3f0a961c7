#include "GranularityPanel.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace conescope {

GranularityPanel::GranularityPanel(QWidget* parent) : QWidget(parent) {
    setObjectName(QStringLiteral("granularityPanel"));
    measure_ = new QPushButton(tr("Measure granularity"), this);
    measure_->setToolTip(tr("Culls the clusters shown from the orbit's views with one cone per cluster (every test), 2, 4 and 8 "
                            "cones per cluster (float and compact records) and per triangle, in the background."));
    export_ = new QPushButton(tr("Export granularity..."), this);
    export_->setToolTip(tr("The rows as conescope-cli granularity writes them with the same settings (JSON, or CSV by the extension)."));
    summary_ = new QLabel(this);
    summary_->setWordWrap(true);
    table_ = new QTableWidget(0, kColumns, this);
    table_->setHorizontalHeaderLabels({tr("record"), tr("bytes/cluster"), tr("bits/triangle"), tr("efficiency"), tr("culled share"),
                                       tr("tests/view"), tr("false culls")});
    table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->setWhatsThis(tr("Efficiency: triangles culled / back-facing triangles. Culled share: of all triangles. Tests per view: "
                            "cluster, sub-group and triangle tests made from one eye. triangle: every triangle tested after the "
                            "cluster test, the ceiling."));
    auto* buttons = new QHBoxLayout;
    buttons->addWidget(measure_);
    buttons->addWidget(export_);
    buttons->addStretch(1);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(buttons);
    layout->addWidget(summary_);
    layout->addWidget(table_, 1);
    connect(measure_, &QPushButton::clicked, this, &GranularityPanel::measureRequested);
    connect(export_, &QPushButton::clicked, this, &GranularityPanel::exportRequested);
    showReport(nullptr, false);
}

QString GranularityPanel::cellText(const GranularityRow& row, int column) {
    switch (column) {
    case 0: return QString::fromStdString(row.record);
    case 1: return QString::number(row.bytesPerCluster);
    case 2: return QString::number(row.bitsPerTriangle, 'f', 2);
    case 3: return QString::number(100.0 * row.efficiency, 'f', 1) + '%';
    case 4: return QString::number(100.0 * row.culledShare, 'f', 1) + '%';
    case 5: return QString::number(row.testsPerView, 'f', 0);
    default: return QString::number(row.falseCulls);
    }
}

void GranularityPanel::showReport(const GranularityReport* report, bool meshLoaded) {
    measure_->setEnabled(meshLoaded);
    export_->setEnabled(report != nullptr);
    table_->setRowCount(report ? int(report->rows.size()) : 0);
    if (!report) {
        summary_->setText(meshLoaded ? tr("Not measured for the clusters and settings shown: press Measure granularity.")
                                     : tr("No mesh loaded."));
        return;
    }
    const RunStatistics& run = report->run;
    summary_->setText(tr("%1: %2 clusters, %3 triangles, %4 views; triangle: every triangle tested after the %5/%6 cluster test.")
                          .arg(QString::fromStdString(run.meshName))
                          .arg(run.clusters)
                          .arg(run.triangles)
                          .arg(run.viewCount)
                          .arg(QString::fromStdString(toString(displayedCone(run.settings))))
                          .arg(QString::fromStdString(toString(displayedTest(run.settings)))));
    for (int r = 0; r < int(report->rows.size()); ++r)
        for (int c = 0; c < kColumns; ++c) {
            auto* item = new QTableWidgetItem(cellText(report->rows[size_t(r)], c));
            item->setTextAlignment(c == 0 ? Qt::AlignLeft | Qt::AlignVCenter : Qt::AlignRight | Qt::AlignVCenter);
            table_->setItem(r, c, item);
        }
}

QString GranularityPanel::summary() const { return summary_->text(); }

}  // namespace conescope
