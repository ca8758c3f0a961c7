#include "PlotsView.h"

#include <QLabel>
#include <QVBoxLayout>
#include <QVTKOpenGLNativeWidget.h>
#include <cmath>
#include <cstdlib>

#include <vtkAxis.h>
#include <vtkCallbackCommand.h>
#include <vtkChartXY.h>
#include <vtkNew.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include "scene/Charts.h"

namespace conescope {

PlotsView::PlotsView(QWidget* parent) : QTabWidget(parent) {
    efficiency_ = addPlot(tr("Efficiency per view"), "Efficiency per orbit view: triangles culled / back-facing",
                          tr("Share of the back faces culled, per orbit eye; click one to put the eye there."),
                          tr("For each eye position of the orbit: the share of the back-facing triangles the test culled "
                             "(1: as many as checking every triangle would). Click a point to put the cull eye there."));
    histogram_ = addPlot(tr("Cone half-angles"), "Cone half-angles",
                         tr("Clusters per cone half-angle \u03b1: narrow cones are culled from more places."),
                         tr("How many clusters have a cone of each half-angle \u03b1. Narrow cones are culled from more "
                            "places; a cluster whose normals need 90\u00b0 or more can never be culled."));
    levels_ = addPlot(tr("Levels"), "No hierarchy built", QString(),
                      tr("Per level of the LOD hierarchy (0: the finest): the share of the back faces the test culled over the "
                         "views (bars), the share the cones' widths promise, \u03a3 T(1 \u2212 sin \u03b1) / T (dashed), and the "
                         "triangle-weighted mean cone half-angle \u03b1 on the right axis. Coarser clusters cover more surface, "
                         "their normals spread wider and their cones cull from fewer places."));
    showLevels(nullptr);
    granularity_ = addPlot(tr("Granularity"), "Granularity not measured", QString(),
                           tr("For each record measured (Granularity dock): the share of all triangles it culled over the orbit's "
                              "views against the bytes it stores per cluster. One cone per cluster for each test, 2, 4 and 8 cones "
                              "per cluster as float and compact records, and per-triangle culling: every back face, the ceiling."));
    showGranularity(nullptr);
    connect(this, &QTabWidget::currentChanged, this, [this]() { render(); });
    // A click on the efficiency plot moves the eye to that view; a drag still pans the chart. The
    // chart takes the press, so the clicks are watched passively.
    vtkNew<vtkCallbackCommand> click;
    click->SetClientData(this);
    click->SetCallback([](vtkObject* caller, unsigned long event, void* self, void*) {
        auto* plots = static_cast<PlotsView*>(self);
        int position[2];
        static_cast<vtkRenderWindowInteractor*>(caller)->GetEventPosition(position);
        if (event == vtkCommand::LeftButtonPressEvent) {
            plots->pressX_ = position[0], plots->pressY_ = position[1];
            return;
        }
        if (std::abs(position[0] - plots->pressX_) > 3 || std::abs(position[1] - plots->pressY_) > 3) return;
        const long view = plots->viewAtDisplayX(position[0]);
        if (view >= 0) emit plots->viewClicked(view);
    });
    click->PassiveObserverOn();
    efficiency_.widget->interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, click);
    efficiency_.widget->interactor()->AddObserver(vtkCommand::LeftButtonReleaseEvent, click);
}

long PlotsView::viewAtDisplayX(double x) const {
    vtkAxis* axis = efficiency_.chart->GetAxis(vtkAxis::BOTTOM);
    const float* from = axis->GetPoint1();
    const float* to = axis->GetPoint2();
    if (viewCount_ == 0 || !(to[0] > from[0])) return -1;
    const double value = axis->GetMinimum() + (x - from[0]) / (to[0] - from[0]) * (axis->GetMaximum() - axis->GetMinimum());
    const long view = std::lround(value);
    return view >= 0 && size_t(view) < viewCount_ ? view : -1;
}

double PlotsView::displayXOfView(long index) const {
    vtkAxis* axis = efficiency_.chart->GetAxis(vtkAxis::BOTTOM);
    const float* from = axis->GetPoint1();
    const float* to = axis->GetPoint2();
    return from[0] + (double(index) - axis->GetMinimum()) / (axis->GetMaximum() - axis->GetMinimum()) * (to[0] - from[0]);
}

PlotsView::Plot PlotsView::addPlot(const QString& tab, const char* title, const QString& caption, const QString& help) {
    // The context view renders into the widget's window; a line of words under it says what it plots.
    Plot plot;
    auto* page = new QWidget(this);
    plot.widget = new QVTKOpenGLNativeWidget(page);
    auto* words = new QLabel(caption, page);
    words->setWordWrap(true);
    words->setToolTip(help);
    plot.widget->setToolTip(help);
    plot.widget->setWhatsThis(help);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(plot.widget, 1);
    layout->addWidget(words);
    plot.caption = words;
    plot.context = vtkSmartPointer<vtkContextView>::New();
    plot.context->SetRenderWindow(plot.widget->renderWindow());
    plot.context->SetInteractor(plot.widget->interactor());
    plot.context->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    plot.chart = vtkSmartPointer<vtkChartXY>::New();
    plot.context->GetScene()->AddItem(plot.chart);
    plot.chart->SetTitle(title);
    addTab(page, tab);
    return plot;
}

void PlotsView::showOrbit(const std::vector<ViewStatistics>& views, long currentView, const std::vector<double>* pinned) {
    viewCount_ = views.size();
    plotEfficiencyPerView(efficiency_.chart, views, currentView, pinned);
    render(efficiency_);
}

void PlotsView::showHalfAngles(const std::vector<ClusterStatistics>& clusters) {
    plotHalfAngleHistogram(histogram_.chart, clusters);
    render(histogram_);
}

void PlotsView::showLevels(const LodStatistics* statistics) {
    plotLevels(levels_.chart, statistics);
    const bool shown = statistics && !statistics->levels.empty();
    levels_.caption->setText(shown ? tr("Per level (0: the finest): the share of the back faces culled (blue bars), what the cones' "
                                        "widths predict (dark blue, dashed), the share of clusters without a cone (grey, dash-dot), and "
                                        "the mean half-angle of those with one (orange, right axis).")
                                   : tr("No hierarchy built: build the LOD hierarchy to see culling level by level."));
    render(levels_);
}

void PlotsView::showGranularity(const GranularityReport* report) {
    plotGranularity(granularity_.chart, report);
    granularity_.caption->setText(report ? tr("Culled share of all triangles against bytes per cluster. Blue: one cone per cluster "
                                              "(each test); orange: 2, 4, 8 cones; green: the same, compact; purple, dashed: per "
                                              "triangle, the ceiling.")
                                         : tr("Measure the granularity (Granularity dock) to plot what each record culls and costs."));
    render(granularity_);
}

vtkChartXY* PlotsView::granularityChart() const { return granularity_.chart; }

vtkChartXY* PlotsView::levelsChart() const { return levels_.chart; }

QString PlotsView::levelsCaption() const { return levels_.caption->text(); }

void PlotsView::render() {
    render(efficiency_);
    render(histogram_);
    render(levels_);
    render(granularity_);
}

void PlotsView::render(const Plot& plot) {
    if (plot.widget->isVisible()) plot.widget->renderWindow()->Render();
}

}  // namespace conescope
