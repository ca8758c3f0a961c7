#include "PlotsView.h"

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "scene/Charts.h"

namespace conescope {

PlotsView::PlotsView(QWidget* parent) : QTabWidget(parent) {
    efficiency_ = addPlot(tr("Efficiency per view"), "Efficiency per orbit view: triangles culled / back-facing");
    histogram_ = addPlot(tr("Cone half-angles"), "Cone half-angles");
    connect(this, &QTabWidget::currentChanged, this, [this]() { render(); });
}

PlotsView::Plot PlotsView::addPlot(const QString& tab, const char* title) {
    // The context view renders into the widget's window.
    Plot plot;
    plot.widget = new QVTKOpenGLNativeWidget(this);
    plot.context = vtkSmartPointer<vtkContextView>::New();
    plot.context->SetRenderWindow(plot.widget->renderWindow());
    plot.context->SetInteractor(plot.widget->interactor());
    plot.context->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    plot.chart = vtkSmartPointer<vtkChartXY>::New();
    plot.context->GetScene()->AddItem(plot.chart);
    plot.chart->SetTitle(title);
    addTab(plot.widget, tab);
    return plot;
}

void PlotsView::showOrbit(const std::vector<ViewStatistics>& views, long currentView) {
    plotEfficiencyPerView(efficiency_.chart, views, currentView);
    render(efficiency_);
}

void PlotsView::showHalfAngles(const std::vector<ClusterStatistics>& clusters) {
    plotHalfAngleHistogram(histogram_.chart, clusters);
    render(histogram_);
}

void PlotsView::render() {
    render(efficiency_);
    render(histogram_);
}

void PlotsView::render(const Plot& plot) {
    if (plot.widget->isVisible()) plot.widget->renderWindow()->Render();
}

}  // namespace conescope
