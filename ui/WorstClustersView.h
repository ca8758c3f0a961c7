// The "Worst clusters" dock: every cluster of the displayed test over the orbit, with what it costs
// (triangles lost to the test and to the partition, misses) and why (half-angle, sphere radius,
// cull and oracle fractions), worst test loss first and sortable by any column. Choosing a row asks
// the window to pick the cluster, frame it and put the eye where it is lost. The numbers are the
// session's orbit statistics (core measureOrbit): the table computes nothing.
#pragma once

#include <QTableWidget>

#include "core/Statistics.h"

namespace conescope {

class WorstClustersView : public QTableWidget {
    Q_OBJECT
public:
    explicit WorstClustersView(QWidget* parent = nullptr);

    // Shows the orbit's clusters (or an empty table while the orbit is measured), keeping the sort.
    void showOrbit(const CullTestStatistics* orbit);
    // The cluster of a row as it is sorted now.
    int clusterAt(int row) const;

signals:
    void clusterChosen(int cluster);

private:
    void markFalseCulls(int row);
    const void* shownRows_ = nullptr;  // the orbit statistics shown, to skip rebuilding the same rows
};

}  // namespace conescope
