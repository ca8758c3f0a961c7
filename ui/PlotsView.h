// The plots dock: efficiency per orbit view (with the view the eye is at) and the histogram of
// cone half-angles, each a vtkChartXY in its own GL widget, one tab each. The charts come from
// scene/Charts.h; the rows from the session.
#pragma once

#include <vector>

#include <QTabWidget>

#include <vtkSmartPointer.h>

#include "core/Statistics.h"

class QVTKOpenGLNativeWidget;
class vtkChartXY;
class vtkContextView;

namespace conescope {

class PlotsView : public QTabWidget {
    Q_OBJECT
public:
    explicit PlotsView(QWidget* parent = nullptr);

    void showOrbit(const std::vector<ViewStatistics>& views, long currentView);
    void showHalfAngles(const std::vector<ClusterStatistics>& clusters);
    // Renders the plot on screen, if any.
    void render();

private:
    struct Plot {
        QVTKOpenGLNativeWidget* widget = nullptr;
        vtkSmartPointer<vtkContextView> context;
        vtkSmartPointer<vtkChartXY> chart;
    };
    Plot addPlot(const QString& tab, const char* title);
    static void render(const Plot& plot);

    Plot efficiency_;
    Plot histogram_;
};

}  // namespace conescope
