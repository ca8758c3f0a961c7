#include "WorstClustersView.h"

#include <QColor>
#include <QHeaderView>

namespace conescope {

namespace {

// A number the table sorts by its value, not its text: "10" after "9", decimals as numbers.
class NumberItem : public QTableWidgetItem {
public:
    NumberItem(double value, int decimals) {
        setData(Qt::DisplayRole, decimals < 0 ? QVariant(qulonglong(value)) : QVariant(QString::number(value, 'f', decimals)));
        setData(Qt::UserRole, value);
        setData(Qt::TextAlignmentRole, int(Qt::AlignRight | Qt::AlignVCenter));
    }
    bool operator<(const QTableWidgetItem& other) const override {
        return data(Qt::UserRole).toDouble() < other.data(Qt::UserRole).toDouble();
    }
};

struct ColumnSpec {
    const char* title;
    const char* tip;
    int decimals;  // -1: a count
    double (*value)(const ClusterStatistics&);
};

const ColumnSpec columns[] = {
    {"cluster", "Cluster id", -1, [](const ClusterStatistics& c) { return double(c.cluster); }},
    {"test loss", "Back-facing triangles the test drew although the whole cluster faced away, over the orbit", -1,
     [](const ClusterStatistics& c) { return double(c.testLossTriangles); }},
    {"partition loss", "Back-facing triangles drawn because the cluster also held a visible face, over the orbit", -1,
     [](const ClusterStatistics& c) { return double(c.partitionLossTriangles); }},
    {"missed", "Orbit views from which every face faced away and the test drew it", -1,
     [](const ClusterStatistics& c) { return double(c.timesMissed); }},
    {"culled", "Orbit views from which the test culled it", -1, [](const ClusterStatistics& c) { return double(c.timesCulled); }},
    {"tris", "Triangles", -1, [](const ClusterStatistics& c) { return double(c.triangles); }},
    {"verts", "Vertices", -1, [](const ClusterStatistics& c) { return double(c.vertices); }},
    {"alpha", "Half-angle of the cone of normals in degrees (90: never cullable)", 1,
     [](const ClusterStatistics& c) { return c.halfAngleDegrees; }},
    {"radius", "Bounding-sphere radius", 4, [](const ClusterStatistics& c) { return c.sphereRadius; }},
    {"cull", "Share of view directions from which the test culls it: (1 - sin alpha)/2", 3,
     [](const ClusterStatistics& c) { return c.cullFraction; }},
    {"oracle", "Share of view directions from which every face faces away: the most any test could reach", 3,
     [](const ClusterStatistics& c) { return c.oracleFraction; }},
    {"false culls", "Orbit views from which the test culled it while it held a visible face: only an engine's own record does", -1,
     [](const ClusterStatistics& c) { return double(c.falseCulls); }},
    {"quant loss", "Back-facing triangles the quantised record drew and its float original culls, over the orbit", -1,
     [](const ClusterStatistics& c) { return double(c.quantisationLossTriangles); }},
};

}  // namespace

WorstClustersView::WorstClustersView(QWidget* parent) : QTableWidget(parent) {
    setObjectName(QStringLiteral("worstClusters"));
    setColumnCount(int(std::size(columns)));
    for (int k = 0; k < columnCount(); ++k) {
        auto* header = new QTableWidgetItem(tr(columns[k].title));
        header->setToolTip(tr(columns[k].tip));
        setHorizontalHeaderItem(k, header);
    }
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setSelectionMode(QAbstractItemView::SingleSelection);
    verticalHeader()->hide();
    horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    setSortingEnabled(true);
    sortByColumn(1, Qt::DescendingOrder);
    connect(this, &QTableWidget::cellClicked, this, [this](int row, int) { emit clusterChosen(clusterAt(row)); });
    connect(this, &QTableWidget::cellActivated, this, [this](int row, int) { emit clusterChosen(clusterAt(row)); });
}

void WorstClustersView::showOrbit(const CullTestStatistics* orbit) {
    // The session also says orbitChanged when the eye steps along the orbit: the rows stay.
    const void* rows = orbit ? static_cast<const void*>(orbit->clusters.data()) : nullptr;
    if (rows == shownRows_ && (!orbit || size_t(rowCount()) == orbit->clusters.size())) return;
    shownRows_ = rows;
    int sortColumn = horizontalHeader()->sortIndicatorSection();
    Qt::SortOrder order = horizontalHeader()->sortIndicatorOrder();
    // An engine's record that culls visible faces: those clusters first, they are its bug.
    if (orbit && orbit->falseCulls > 0) sortColumn = int(std::size(columns)) - 2, order = Qt::DescendingOrder;
    setSortingEnabled(false);
    clearContents();
    setRowCount(orbit ? int(orbit->clusters.size()) : 0);
    if (orbit) {
        int row = 0;
        for (const ClusterStatistics& cluster : orbit->clusters) {
            for (int k = 0; k < columnCount(); ++k) setItem(row, k, new NumberItem(columns[k].value(cluster), columns[k].decimals));
            if (cluster.falseCulls > 0) markFalseCulls(row);
            ++row;
        }
    }
    setSortingEnabled(true);
    sortByColumn(sortColumn, order);
}

void WorstClustersView::markFalseCulls(int row) {
    // A false cull is an engine bug (a visible face culled): the row stands out.
    for (int k = 0; k < columnCount(); ++k) item(row, k)->setForeground(QColor(200, 0, 0));
}

int WorstClustersView::clusterAt(int row) const {
    const QTableWidgetItem* cell = item(row, 0);
    return cell ? int(cell->data(Qt::UserRole).toDouble()) : -1;
}

}  // namespace conescope
