#include "MainWindow.h"

#include <algorithm>
#include <chrono>

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGuiApplication>
#include <QScreen>
#include <QLabel>
#include <QMessageBox>
#include <QMimeData>
#include <QScrollArea>
#include <QScrollBar>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>
#include <QVBoxLayout>

#include "CrossSectionView.h"
#include "EyePanel.h"
#include "EyeView.h"
#include "ObserverView.h"
#include "GaussMapView.h"
#include "Glossary.h"
#include "LessonView.h"
#include "StepLessonView.h"
#include "GranularityPanel.h"
#include "LodPanel.h"
#include "PickedClusterView.h"
#include "WorstClustersView.h"
#include "PlotsView.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "StatusLine.h"
#include "WindowActions.h"
#include "io/MeshReader.h"

namespace conescope {

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("ConeScope"));
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    view_ = new ObserverView(this);
    setCentralWidget(view_);
    createDocks();
    actions_ = new WindowActions(this, &session_, eyeViewDock_, plotsDock_, gaussMapDock_);
    statusLine_ = new StatusLine(statusBar(), &session_);
    settingsPanel_->setSettings(session_.settings());
    connectSession();
    connectControls();
    // At most the screen: a 1280x720 projector shows the whole window.
    const QRect screen = QGuiApplication::primaryScreen() ? QGuiApplication::primaryScreen()->availableGeometry() : QRect(0, 0, 1400, 900);
    resize(std::min(1400, screen.width()), std::min(900, screen.height()));
}

MainWindow::~MainWindow() = default;

// --- Construction --------------------------------------------------------------------------------

// Long panels scroll rather than forcing their height on the other docks.
static QScrollArea* scrolledPanel(QWidget* panel, QWidget* parent) {
    auto* area = new QScrollArea(parent);
    area->setWidget(panel);
    area->setWidgetResizable(true);
    area->setFrameShape(QFrame::NoFrame);
    area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    area->setMinimumWidth(panel->sizeHint().width() + area->verticalScrollBar()->sizeHint().width());
    return area;
}

// A picture with a line of words under it.
static QWidget* captionedPicture(QWidget* picture, const QString& words, const QString& help, QWidget* parent) {
    auto* page = new QWidget(parent);
    auto* caption = new QLabel(words, page);
    caption->setWordWrap(true);
    caption->setToolTip(help);
    picture->setToolTip(help);
    picture->setWhatsThis(help);
    auto* layout = new QVBoxLayout(page);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(picture, 1);
    layout->addWidget(caption);
    return page;
}

void MainWindow::createDocks() {
    // The left column runs the full height; the plots and the eye's view share the bottom with
    // the observer view and the right column.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::TopLeftCorner, Qt::LeftDockWidgetArea);
    auto dock = [this](const QString& title, const char* name, QWidget* content, Qt::DockWidgetArea area) {
        auto* widget = new QDockWidget(title, this);
        widget->setObjectName(QLatin1String(name));
        widget->setWidget(content);
        addDockWidget(area, widget);
        return widget;
    };
    auto scrolled = [this](QWidget* panel) { return scrolledPanel(panel, this); };
    auto captioned = [this](QWidget* picture, const QString& words, const QString& help) {
        return captionedPicture(picture, words, help, this);
    };
    settingsPanel_ = new SettingsPanel(this);
    eyePanel_ = new EyePanel(this);
    statisticsPanel_ = new StatisticsPanel(this);
    clusterView_ = new PickedClusterView(this);
    gaussMap_ = new GaussMapView(this);
    sideDocks_ = {dock(tr("Settings"), "settingsDock", scrolled(settingsPanel_), Qt::LeftDockWidgetArea),
                  dock(tr("Cull eye"), "eyeDock", eyePanel_, Qt::LeftDockWidgetArea),
                  dock(tr("Statistics"), "statisticsDock", scrolled(statisticsPanel_), Qt::RightDockWidgetArea),
                  dock(tr("Picked cluster"), "clusterDock", clusterView_, Qt::RightDockWidgetArea)};
    // Beside the picked cluster's numbers: its normals and cones on the unit sphere (G raises it), and
    // seed 000's figure of them in the plane of V1 and v.
    gaussMapDock_ = dock(tr("Gauss map"), "gaussMapDock", captioned(gaussMap_, tr("Dots: face normals. Circles: cones. Turquoise: v and its horizon."), tr(
        "Each white dot is a face normal of the picked cluster, drawn from the centre of a sphere of radius 1. The "
        "circles are the cones of the four methods (the one in use filled). The turquoise line is the view vector v and "
        "its circle the horizon: every face turns away when all dots lie beyond it, on v's side.")), Qt::RightDockWidgetArea);
    tabifyDockWidget(sideDocks_[3], gaussMapDock_);
    crossSection_ = new CrossSectionView(this);
    crossSectionDock_ = dock(tr("Cross-section"), "crossSectionDock", crossSection_, Qt::RightDockWidgetArea);
    tabifyDockWidget(gaussMapDock_, crossSectionDock_);
    sideDocks_[3]->raise();
    connect(gaussMapDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) gaussMap_->render();
    });
    connect(crossSectionDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) crossSection_->showLesson(session_);
    });
    // The lesson's words over the statistics: L starts it.
    lessonView_ = new LessonView(this);
    lessonDock_ = dock(tr("Lesson"), "lessonDock", lessonView_, Qt::RightDockWidgetArea);
    tabifyDockWidget(sideDocks_[2], lessonDock_);
    // Why coarse clusters cull less, with the built hierarchy's own numbers.
    lodLessonView_ = makeLodLessonView(this);
    tabifyDockWidget(sideDocks_[2], dock(tr("LOD lesson"), "lodLessonDock", lodLessonView_, Qt::RightDockWidgetArea));
    // What each record granularity culls and costs, and why, behind the statistics.
    granularityPanel_ = new GranularityPanel(this);
    tabifyDockWidget(sideDocks_[2], dock(tr("Granularity"), "granularityDock", granularityPanel_, Qt::RightDockWidgetArea));
    granularityLessonView_ = makeGranularityLessonView(this);
    tabifyDockWidget(sideDocks_[2], dock(tr("Granularity lesson"), "granularityLessonDock", granularityLessonView_, Qt::RightDockWidgetArea));
    sideDocks_[2]->raise();

    // The LOD hierarchy's controls behind the settings (its numbers go to the statistics).
    lodPanel_ = new LodPanel(this);
    lodDock_ = dock(tr("LOD hierarchy"), "lodDock", scrolled(lodPanel_), Qt::LeftDockWidgetArea);
    tabifyDockWidget(sideDocks_[0], lodDock_);
    sideDocks_[0]->raise();

    plots_ = new PlotsView(this);
    plotsDock_ = dock(tr("Plots"), "plotsDock", plots_, Qt::BottomDockWidgetArea);
    eyeView_ = new EyeView(this);
    eyeViewDock_ = dock(tr("Eye view (culled clusters removed)"), "eyeViewDock", eyeView_, Qt::BottomDockWidgetArea);
    splitDockWidget(plotsDock_, eyeViewDock_, Qt::Horizontal);
    worstClusters_ = new WorstClustersView(this);
    // Behind the plots: the table of what each cluster costs over the orbit.
    tabifyDockWidget(plotsDock_, dock(tr("Worst clusters"), "worstClustersDock", worstClusters_, Qt::BottomDockWidgetArea));
    plotsDock_->raise();
    connect(eyeViewDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) eyeView_->render();
    });
}

void MainWindow::connectSession() {
    connect(&session_, &Session::sceneReplaced, this, &MainWindow::showScene);
    connect(&session_, &Session::eyeMoved, this, [this]() {
        eyePanel_->showPosition(session_.eyePosition());
        eyePanel_->showOrbitStep(int(session_.orbitStep()), int(session_.settings().views));
        if (session_.scene()) view_->placeEyeHandle(session_.eyePosition());
    });
    connect(&session_, &Session::eyeMeasured, this, &MainWindow::showEyeMeasurement);
    connect(&session_, &Session::orbitChanged, this, &MainWindow::showOrbit);
    connect(&session_, &Session::comparisonChanged, this, [this]() {
        showOrbit();
        clusterView_->showPick(session_);
        render();
    });
    connect(&session_, &Session::pickChanged, this, [this]() {
        clusterView_->showPick(session_);
        gaussMap_->showPick(session_, true);
        render();
    });
    connect(&session_, &Session::lessonChanged, this, [this]() {
        lessonView_->showLesson(session_);
        crossSection_->showLesson(session_);
    });
    connect(&session_, &Session::lessonStepChanged, this, &MainWindow::stageLessonStep);
    connect(&session_, &Session::meshShown, this, &MainWindow::showMesh);
    connect(&session_, &Session::settingsChanged, settingsPanel_, &SettingsPanel::setSettings);
    connect(&session_, &Session::faceColoringChanged, this, [this](FaceColoring coloring) {
        actions_->coloringAction(coloring)->setChecked(true);
        if (session_.scene()) render();
    });
    connect(&session_, &Session::lodChanged, this, &MainWindow::showLod);
    connect(&session_, &Session::granularityChanged, this, &MainWindow::showGranularity);
    connect(&session_, &Session::errorOccurred, this, &MainWindow::showError);
    connect(&session_, &Session::notice, statusBar(), &QStatusBar::showMessage);
}

void MainWindow::connectControls() {
    connect(settingsPanel_, &SettingsPanel::settingsChanged, &session_, &Session::applySettings);
    connect(eyePanel_, &EyePanel::coordinateEdited, this, [this](int axis, double value) {
        glm::dvec3 position = session_.eyePosition();
        position[axis] = value;
        session_.moveEye(position, -1);
    });
    connect(eyePanel_, &EyePanel::lookFromHereClicked, this, &MainWindow::lookFromHere);
    connect(eyePanel_, &EyePanel::followToggled, this, &MainWindow::setFollowing);
    connect(eyePanel_, &EyePanel::animateToggled, this, &MainWindow::setAnimating);
    connect(view_, &ObserverView::clicked, this, &MainWindow::pickDisplay);
    connect(view_, &ObserverView::resized, this, [this]() { session_.fitLegend(view_->height(), view_->devicePixelRatioF()); });
    // Over the legend, each entry says what it means.
    view_->setToolTipSource([this](const QPoint& display) -> QString {
        if (!session_.scene() || !layerVisible(Layer::Legend)) return {};
        const SceneLegend& legend = session_.scene()->legend();
        const SceneLegend::Rectangle box = legend.box();
        if (display.x() < box[0] || display.x() > box[2]) return {};
        for (const SceneLegend::Placed& text : legend.texts())
            if (display.y() >= text.box[1] - 2 && display.y() <= text.box[3] + 2) return explainLegendLabel(text.text);
        return {};
    });
    connect(lodPanel_, &LodPanel::buildRequested, &session_, &Session::buildLodHierarchy);
    connect(lodPanel_, &LodPanel::exportRequested, this, [this]() {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export LOD statistics"), QString(), tr("JSON (*.json);;CSV (*.csv)"));
        if (!path.isEmpty()) session_.exportLodStatistics(path, statisticsFormatOf(path.toStdString()));
    });
    connect(granularityPanel_, &GranularityPanel::measureRequested, &session_, &Session::measureGranularity);
    connect(granularityPanel_, &GranularityPanel::exportRequested, this, [this]() {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export granularity"), QString(), tr("JSON (*.json);;CSV (*.csv)"));
        if (!path.isEmpty()) session_.exportGranularity(path, statisticsFormatOf(path.toStdString()));
    });
    connect(lodPanel_, &LodPanel::levelChosen, &session_, &Session::showLodLevel);
    connect(lodPanel_, &LodPanel::thresholdChanged, &session_, &Session::setLodThreshold);
    connect(lodPanel_, &LodPanel::coloringChosen, &session_, &Session::setFaceColoring);
    connect(worstClusters_, &WorstClustersView::clusterChosen, this, &MainWindow::chooseCluster);
    connect(lessonView_, &LessonView::stepRequested, this, &MainWindow::showLessonStep);
    connect(lessonView_, &LessonView::exampleRequested, this, [this](LessonOutcome outcome) {
        if (chooseExample(outcome) >= 0 && session_.lessonStep() == 0) showLessonStep(1);
    });
    connect(lessonView_, &LessonView::sweepRequested, this, [this]() { toggleEyeSweep(); });
    connect(plots_, &PlotsView::viewClicked, &session_, &Session::moveEyeToOrbitView);
    connect(view_, &ObserverView::cameraMoved, &session_, &Session::followCamera);
    connect(view_, &ObserverView::eyeHandleMoved, &session_, &Session::moveEyeSoon);
}

// --- What the session delivers ---------------------------------------------------------------------

void MainWindow::showScene(const ClusterScene* previous, bool newMesh) {
    const ClusterScene& scene = *session_.scene();
    view_->showScene(previous, scene);
    eyeView_->showScene(scene);
    if (newMesh) {
        eyePanel_->setScale(2.0 * double(session_.preparedMesh()->box.halfDiagonal()));
        view_->placeEyeHandle(session_.eyePosition(), true);
    }
    statisticsPanel_->showClusters(*session_.preparedMesh(), *session_.clusters(), session_.settings());
    const EyeMeasurement* measurement = session_.measurement();
    plots_->showHalfAngles(measurement ? measurement->statistics.clusters : std::vector<ClusterStatistics>{});
    showOrbit();
    showGranularity();
}

void MainWindow::showGranularity() {
    const GranularityReport* report = session_.granularity();
    granularityPanel_->showReport(report, session_.clusters() != nullptr);
    plots_->showGranularity(report);
    showGranularityLesson(*granularityLessonView_, report);
}

void MainWindow::showLod(const ClusterScene* previousScene) {
    // The observer view shows the LOD scene in place of the partition's while a level or cut is shown.
    const ClusterScene* lodScene = session_.lodScene();
    if (session_.scene() && (previousScene || lodScene)) {
        view_->showScene(previousScene, *session_.scene());
        if (lodScene) view_->showScene(session_.scene(), *lodScene);
    }
    lodPanel_->showLod(session_);
    statisticsPanel_->showLod(session_.lodStatistics());
    plots_->showLevels(session_.lodStatistics());
    showLodStatistics(*lodLessonView_, session_.lodStatistics(), session_.preparedMesh() ? session_.preparedMesh()->name : std::string());
    clusterView_->showPick(session_);
    view_->render();
}

void MainWindow::showEyeMeasurement() {
    // Only what an eye move changes is redone and drawn: the plots are the orbit's (showOrbit).
    using Clock = std::chrono::steady_clock;
    const auto seconds = [](Clock::time_point from) { return std::chrono::duration<double>(Clock::now() - from).count(); };
    EyeStepTimes times;
    times.cullAndScene = session_.eyeSeconds();
    auto start = Clock::now();
    const EyeMeasurement* measurement = session_.measurement();
    statisticsPanel_->showComparison(session_.pinnedSettings(), session_.eyeComparison(), session_.orbitComparison());
    if (measurement) {
        statisticsPanel_->showEye(*measurement);
        showMultiCones();
        eyeView_->showEye(*session_.scene());
        statusLine_->showSummary(session_);
    } else {
        statisticsPanel_->showEyeError(session_.eyeError());
    }
    clusterView_->showPick(session_);
    times.panels = seconds(start);
    start = Clock::now();
    gaussMap_->showPick(session_, false);
    times.gaussMap = seconds(start);
    start = Clock::now();
    view_->render();
    times.observerView = seconds(start);
    start = Clock::now();
    eyeView_->render();
    times.eyeView = seconds(start);
    eyeStepTimes_ = times;
    statusLine_->showEyeStepTimes(times);
    if (measurement) emit eyeMeasured();
}

void MainWindow::showOrbit() {
    // With a pin, A's efficiency per orbit view is the plot's second curve.
    std::vector<double> pinned;
    if (const Comparison* comparison = session_.orbitComparison())
        for (const ViewComparison& view : comparison->views) pinned.push_back(view.efficiencyA);
    plots_->showOrbit(session_.orbitRows(), session_.orbitStep(), pinned.empty() ? nullptr : &pinned);
    statisticsPanel_->showComparison(session_.pinnedSettings(), session_.eyeComparison(), session_.orbitComparison());
    worstClusters_->showOrbit(session_.orbitStatistics());
    statisticsPanel_->showOrbit(session_.orbitStatistics());
    showMultiCones();
    statusLine_->showSummary(session_);
}

void MainWindow::showMultiCones() {
    const OrbitMeasurement* orbit = session_.orbitMultiCones();
    const std::optional<SubGroupsFromEye> eye = session_.subGroupsFromEye();
    const EyeMeasurement* measurement = session_.measurement();
    statisticsPanel_->showMultiCones(session_.settings().conesPerCluster, orbit ? &orbit->multiCones : nullptr,
                                     eye ? &eye->counts : nullptr, measurement ? measurement->view().backFacingTriangles : 0);
    clusterView_->showPick(session_);
    gaussMap_->showPick(session_, false);
}

void MainWindow::showMesh(const QString& path, const QString& loadMessage) {
    // A new mesh is looked at from the side of its eye, once the eye is measured and drawn.
    resetCamera();
    // The previous mesh's message goes with it, so it is never read as this one's.
    if (loadMessage.isEmpty()) statusBar()->clearMessage();
    else statusBar()->showMessage(loadMessage, 30000);
    actions_->addRecentFile(QFileInfo(path).absoluteFilePath());
    setWindowTitle(tr("ConeScope - %1").arg(QFileInfo(path).fileName()));
    emit meshShown(path);
}

void MainWindow::showError(const QString& title, const QString& message) {
    lastError_ = message;
    statusBar()->showMessage(title, 8000);
    emit errorShown(message);
    // Once the failed task has ended and the progress bar is gone, not over it.
    if (errorDialogs_) QTimer::singleShot(0, this, [this, title, message]() { QMessageBox::critical(this, title, message); });
}

bool MainWindow::progressShown() const { return statusLine_->progressShown(); }

void MainWindow::setFrameTimesShown(bool shown) { statusLine_->setEyeStepTimesShown(shown); }

QString MainWindow::frameTimesText() const { return statusLine_->eyeStepTimesText(); }

void MainWindow::render() {
    view_->render();
    eyeView_->render();
    plots_->render();
}

// --- Test interface ----------------------------------------------------------------------------------

void MainWindow::openMesh(const QString& path) { session_.openMesh(path); }

bool MainWindow::openMeshBlocking(const QString& path) {
    bool shown = false;
    const QMetaObject::Connection connection = connect(this, &MainWindow::meshShown, this, [&shown]() { shown = true; });
    session_.openMesh(path);
    session_.waitUntilIdle();
    disconnect(connection);
    return shown;
}

void MainWindow::waitUntilIdle() { session_.waitUntilIdle(); }

void MainWindow::setSettings(const Settings& settings) { session_.applySettings(settings); }

void MainWindow::setEyePosition(const glm::dvec3& position) { session_.moveEye(position, -1); }

void MainWindow::setInitialEye(const glm::dvec3& position) { session_.setInitialEye(position); }

int MainWindow::pickDisplay(const QPoint& display) {
    if (!session_.scene()) return -1;
    if (const ClusterScene* lodScene = session_.lodScene()) {
        const int cluster = view_->clusterAt(*lodScene, display);
        session_.pickLodCluster(cluster);
        return cluster;
    }
    const int cluster = view_->clusterAt(*session_.scene(), display);
    pickCluster(cluster);
    return cluster;
}

int MainWindow::pickAt(const QPoint& viewPosition) { return pickDisplay(view_->displayPointOf(viewPosition)); }

void MainWindow::pickCluster(int cluster) { session_.pickCluster(cluster); }

QString MainWindow::clusterReportHtml() const { return clusterView_->toHtml(); }

QPoint MainWindow::viewPositionOf(const glm::dvec3& world) const { return view_->viewPositionOf(world); }

void MainWindow::pinAsA() { session_.pinAsA(); }

void MainWindow::clearPin() { session_.clearPin(); }

void MainWindow::chooseCluster(int cluster) {
    session_.showClusterWhereItIsLost(cluster);
    framePickedCluster();
}

void MainWindow::resetCamera() {
    if (!session_.scene()) return;
    view_->lookAtMesh(glm::dvec3(session_.preparedMesh()->box.center()), session_.eyePosition());
    view_->placeEyeHandle(session_.eyePosition());
    render();
}

void MainWindow::viewFromBehind() {
    if (!session_.scene()) return;
    view_->lookAtMesh(glm::dvec3(session_.preparedMesh()->box.center()), session_.eyePosition(), true);
    view_->placeEyeHandle(session_.eyePosition());
    render();
}

bool MainWindow::exportStatistics(const QString& path, StatisticsFormat format, bool orbit) {
    return session_.exportStatistics(path, format, orbit);
}

bool MainWindow::exportPartition(const QString& path) { return session_.exportPartition(path); }

bool MainWindow::saveWindowScreenshot(const QString& path) {
    QApplication::processEvents();
    if (!grab().save(path, "PNG")) {
        showError(tr("Cannot save the screenshot"), tr("%1: cannot write the PNG").arg(path));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1").arg(path), 6000);
    return true;
}

void MainWindow::showCaption(const QString& text) {
    view_->setCaption(text);
    view_->render();
}

bool MainWindow::saveCrossSection(const QString& path) {
    try {
        writeCrossSectionPng(session_, path);
    } catch (const std::exception& error) {
        showError(tr("Cannot save the cross-section"), QString::fromStdString(error.what()));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1").arg(path), 6000);
    return true;
}

bool MainWindow::exportExplanation(const QString& path) { return session_.exportExplanation(path); }

bool MainWindow::saveScreenshot(const QString& path) {
    try {
        view_->render();
        saveRenderWindowPng(view_->renderWindow(), path.toStdString());
    } catch (const std::exception& error) {
        showError(tr("Cannot save the screenshot"), QString::fromStdString(error.what()));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1").arg(path), 6000);
    return true;
}

void MainWindow::setLayerVisible(Layer layer, bool visible) { actions_->layerAction(layer)->setChecked(visible); }

bool MainWindow::layerVisible(Layer layer) const { return actions_->layerAction(layer)->isChecked(); }

void MainWindow::setFaceColoring(FaceColoring coloring) { session_.setFaceColoring(coloring); }

QVTKOpenGLNativeWidget* MainWindow::observerView() const { return view_; }
QVTKOpenGLNativeWidget* MainWindow::eyeView() const { return eyeView_; }
QList<QAction*> MainWindow::shortcutActions() const { return actions_->shortcutActions(); }
QAction* MainWindow::animateAction() const { return actions_->animateAction(); }
QAction* MainWindow::followAction() const { return actions_->followAction(); }
QStringList MainWindow::recentFiles() const { return WindowActions::recentFiles(); }

// --- The eye's modes -------------------------------------------------------------------------------

void MainWindow::lookFromHere() { session_.moveEye(view_->cameraPosition(), -1); }

void MainWindow::setFollowing(bool follow) {
    view_->setFollowing(follow);
    // The eye's marker would sit on the camera: hidden while following, back as the Eye layer says.
    session_.setLayerVisible(Layer::Eye, !follow && layerVisible(Layer::Eye));
    eyePanel_->setFollowing(follow);
    {
        const QSignalBlocker blocker(actions_->followAction());
        actions_->followAction()->setChecked(follow);
    }
    if (follow) lookFromHere();
}

void MainWindow::setAnimating(bool animate) {
    eyePanel_->setAnimating(animate);
    {
        const QSignalBlocker blocker(actions_->animateAction());
        actions_->animateAction()->setChecked(animate);
    }
    session_.setAnimating(animate);
}

// --- Window events -----------------------------------------------------------------------------------

void MainWindow::dragEnterEvent(QDragEnterEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (!urls.isEmpty() && urls.front().isLocalFile() && hasSupportedMeshExtension(urls.front().toLocalFile().toStdString()))
        event->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* event) {
    const QList<QUrl> urls = event->mimeData()->urls();
    if (urls.isEmpty() || !urls.front().isLocalFile()) return;
    event->acceptProposedAction();
    openMesh(urls.front().toLocalFile());
}

void MainWindow::showEvent(QShowEvent* event) {
    QMainWindow::showEvent(event);
    if (docksSized_) return;
    docksSized_ = true;
    // After the first layout pass, or the docks' own size hints win.
    QTimer::singleShot(0, this, &MainWindow::sizeDocks);
}

void MainWindow::sizeDocks() {
    // Dock sizes only take once the window has its size: a third of the width for the two side
    // columns together, a quarter of the height for the plots.
    const int side = std::clamp(width() / 4, 260, 380);
    resizeDocks({sideDocks_[0], sideDocks_[2]}, {side, side + 30}, Qt::Horizontal);
    resizeDocks({sideDocks_[0], sideDocks_[1]}, {height() * 3 / 4, height() / 4}, Qt::Vertical);
    resizeDocks({plotsDock_}, {std::max(220, height() / 4)}, Qt::Vertical);
    const int statisticsHeight = statisticsPanel_->sizeHint().height() + 30;
    resizeDocks({sideDocks_[2], sideDocks_[3]}, {statisticsHeight, std::max(200, height() - statisticsHeight)}, Qt::Vertical);
    resizeDocks({plotsDock_, eyeViewDock_}, {width() * 2 / 5, width() / 3}, Qt::Horizontal);
}

void MainWindow::closeEvent(QCloseEvent* event) {
    setAnimating(false);
    session_.cancelAll();
    QMainWindow::closeEvent(event);
}

}  // namespace conescope
