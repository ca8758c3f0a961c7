// The plots dock: efficiency per orbit view (with the view the eye is at), the histogram of cone
// half-angles and culling per level of an LOD hierarchy, each a vtkChartXY in its own GL widget, one
// tab each. The charts come from
// scene/Charts.h; the rows from the session.
#pragma once

#include <vector>

#include <QTabWidget>

#include <vtkSmartPointer.h>

#include "core/Granularity.h"
#include "core/Statistics.h"
#include "core/lod/LodCut.h"

class QLabel;
class QVTKOpenGLNativeWidget;
class vtkCallbackCommand;
class vtkChartXY;
class vtkContextView;

namespace conescope {

class PlotsView : public QTabWidget {
    Q_OBJECT
public:
    explicit PlotsView(QWidget* parent = nullptr);

    // `pinned`: the pinned configuration A's efficiency per view, drawn as a second curve.
    void showOrbit(const std::vector<ViewStatistics>& views, long currentView, const std::vector<double>* pinned = nullptr);
    void showHalfAngles(const std::vector<ClusterStatistics>& clusters);
    // The "Levels" tab: efficiency and mean cone half-angle per level of a measured hierarchy
    // (plotLevels); null empties it and says that no hierarchy is built.
    void showLevels(const LodStatistics* statistics);
    // The "Granularity" tab: culled share against bytes per cluster of each record (plotGranularity);
    // null empties it and says that nothing is measured.
    void showGranularity(const GranularityReport* report);
    vtkChartXY* granularityChart() const;
    QVTKOpenGLNativeWidget* granularityWidget() const { return granularity_.widget; }
    // Renders the plot on screen, if any.
    void render();
    // The orbit view under a point of the efficiency plot (VTK display coordinates, x from the
    // left), or -1 outside its bottom axis' range; for a click and for tests.
    long viewAtDisplayX(double x) const;
    // Where view `index` is on the efficiency plot's bottom axis (display x), for tests.
    double displayXOfView(long index) const;
    QVTKOpenGLNativeWidget* efficiencyWidget() const { return efficiency_.widget; }
    QVTKOpenGLNativeWidget* levelsWidget() const { return levels_.widget; }
    vtkChartXY* levelsChart() const;
    QString levelsCaption() const;

signals:
    // A click (not a drag) on the efficiency plot at this orbit view.
    void viewClicked(long view);

private:
    struct Plot {
        QVTKOpenGLNativeWidget* widget = nullptr;
        vtkSmartPointer<vtkContextView> context;
        vtkSmartPointer<vtkChartXY> chart;
        QLabel* caption = nullptr;
    };
    Plot addPlot(const QString& tab, const char* title, const QString& caption, const QString& help);
    static void render(const Plot& plot);

    Plot efficiency_;
    Plot histogram_;
    Plot levels_;
    Plot granularity_;
    size_t viewCount_ = 0;
    int pressX_ = 0, pressY_ = 0;
};

}  // namespace conescope
