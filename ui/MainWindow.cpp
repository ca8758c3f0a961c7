#include "MainWindow.h"
#include "MeshLoading.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QShowEvent>
#include <QStyle>
#include <QStatusBar>
#include <QTabWidget>
#include <QTextBrowser>
#include <QToolBar>
#include <QUrl>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkHandleWidget.h>
#include <vtkPointHandleRepresentation3D.h>
#include <vtkProperty.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>

#include "ClusterReport.h"
#include "EyePanel.h"
#include "HelpDialog.h"
#include "ObserverStyle.h"
#include "SceneBinding.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "io/MeshReader.h"
#include "scene/Charts.h"

namespace conescope {

namespace {

const char* const recentFilesKey = "recentFiles";
constexpr int maxRecentFiles = 8;
// A press and release closer than this (pixels) is a click: pick instead of rotate.
constexpr int clickTolerance = 3;
constexpr int animationIntervalMs = 150;

const QString loadGroup = QStringLiteral("load");
const QString clustersGroup = QStringLiteral("clusters");
const QString orbitGroup = QStringLiteral("orbit");
const QString exportGroup = QStringLiteral("export");

// Maps a stage's progress into [from, to] of the whole task.
ProgressCallback scaled(const ProgressCallback& progress, double from, double to) {
    return [progress, from, to](double fraction, const std::string& stage) {
        return progress(from + (to - from) * fraction, stage);
    };
}

QString milliseconds(double seconds) { return QString::number(1000.0 * seconds, 'f', 1) + QStringLiteral(" ms"); }

// A chart in its own GL widget: the context view renders into the widget's window.
void setUpChart(QVTKOpenGLNativeWidget* widget, vtkSmartPointer<vtkContextView>& context, vtkSmartPointer<vtkChartXY>& chart) {
    context = vtkSmartPointer<vtkContextView>::New();
    context->SetRenderWindow(widget->renderWindow());
    context->SetInteractor(widget->interactor());
    context->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    chart = vtkSmartPointer<vtkChartXY>::New();
    context->GetScene()->AddItem(chart);
}

}  // namespace

struct MainWindow::SceneResult {
    std::shared_ptr<const PreparedMesh> prepared;
    std::shared_ptr<const ClusterSet> clusters;
    std::unique_ptr<ClusterScene> scene;
};

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
    setWindowTitle(tr("ConeScope"));
    setAcceptDrops(true);
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks);
    createViews();
    createDocks();
    createActions();
    createStatusBar();
    createEyeHandle();
    statisticsPanel_->clear();
    clusterBrowser_->setHtml(emptyClusterReportHtml());
    settingsPanel_->setSettings(settings_);

    connect(settingsPanel_, &SettingsPanel::settingsChanged, this, &MainWindow::applySettings);
    connect(eyePanel_, &EyePanel::coordinateEdited, this, [this](int axis, double value) {
        glm::dvec3 position = eyePosition_;
        position[axis] = value;
        moveEye(position, -1);
    });
    connect(eyePanel_, &EyePanel::lookFromHereClicked, this, &MainWindow::lookFromHere);
    connect(eyePanel_, &EyePanel::followToggled, this, &MainWindow::setFollowing);
    connect(eyePanel_, &EyePanel::animateToggled, this, &MainWindow::setAnimating);
    animationTimer_.setInterval(animationIntervalMs);
    connect(&animationTimer_, &QTimer::timeout, this, [this]() { stepOrbit(1); });

    connect(&runner_, &TaskRunner::taskStarted, this, [this](const QString& title) {
        progressBar_->setValue(0);
        progressBar_->setFormat(title + QStringLiteral(" %p%"));
        progressBar_->show();
        cancelButton_->show();
    });
    connect(&runner_, &TaskRunner::progressChanged, this, [this](double fraction, const QString& stage) {
        progressBar_->setValue(int(std::lround(100.0 * fraction)));
        progressBar_->setFormat(stage + QStringLiteral(" %p%"));
    });
    connect(&runner_, &TaskRunner::idle, this, [this]() {
        progressBar_->hide();
        cancelButton_->hide();
    });
    resize(1400, 900);
}

MainWindow::~MainWindow() {
    animationTimer_.stop();
    runner_.cancelAll();
    if (eyeHandle_) eyeHandle_->Off();
    if (cameraObserver_) renderer_->GetActiveCamera()->RemoveObserver(cameraObserver_);
    view_->interactor()->RemoveObserver(clickObserver_);
}

// --- Construction --------------------------------------------------------------------------------

void MainWindow::createViews() {
    view_ = new QVTKOpenGLNativeWidget(this);
    view_->setObjectName(QStringLiteral("observerView"));
    renderWindow_ = vtkGenericOpenGLRenderWindow::SafeDownCast(view_->renderWindow());
    renderer_ = vtkSmartPointer<vtkRenderer>::New();
    renderer_->SetBackground(0.12, 0.13, 0.16);
    renderer_->SetBackground2(0.28, 0.30, 0.36);
    renderer_->GradientBackgroundOn();
    view_->renderWindow()->AddRenderer(renderer_);
    vtkNew<ObserverStyle> style;
    view_->interactor()->SetInteractorStyle(style);
    setCentralWidget(view_);

    picker_ = vtkSmartPointer<vtkCellPicker>::New();
    picker_->SetTolerance(0.0005);
    // The trackball style grabs the focus on a press, after which only focus holders and passive
    // observers hear the release: watch the clicks passively (they never change the event's course).
    clickObserver_ = vtkSmartPointer<vtkCallbackCommand>::New();
    clickObserver_->SetClientData(this);
    clickObserver_->SetCallback([](vtkObject*, unsigned long event, void* window, void*) {
        auto* self = static_cast<MainWindow*>(window);
        if (event == vtkCommand::LeftButtonPressEvent)
            self->onLeftButtonPress();
        else
            self->onLeftButtonRelease();
    });
    clickObserver_->PassiveObserverOn();
    view_->interactor()->AddObserver(vtkCommand::LeftButtonPressEvent, clickObserver_);
    view_->interactor()->AddObserver(vtkCommand::LeftButtonReleaseEvent, clickObserver_);
    cameraObserver_ = renderer_->GetActiveCamera()->AddObserver(vtkCommand::ModifiedEvent, this, &MainWindow::onCameraModified);

    eyeView_ = new QVTKOpenGLNativeWidget(this);
    eyeView_->setObjectName(QStringLiteral("eyeView"));
    eyeRenderer_ = vtkSmartPointer<vtkRenderer>::New();
    eyeRenderer_->SetBackground(0.10, 0.10, 0.12);
    eyeView_->renderWindow()->AddRenderer(eyeRenderer_);
    // The eye's view is what the eye sees: no camera interaction of its own.
    eyeView_->interactor()->SetInteractorStyle(nullptr);

    efficiencyView_ = new QVTKOpenGLNativeWidget(this);
    setUpChart(efficiencyView_, efficiencyContext_, efficiencyChart_);
    efficiencyChart_->SetTitle("Efficiency per orbit view: triangles culled / back-facing");
    histogramView_ = new QVTKOpenGLNativeWidget(this);
    setUpChart(histogramView_, histogramContext_, histogramChart_);
    histogramChart_->SetTitle("Cone half-angles");
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
    settingsPanel_ = new SettingsPanel(this);
    eyePanel_ = new EyePanel(this);
    statisticsPanel_ = new StatisticsPanel(this);
    clusterBrowser_ = new QTextBrowser(this);
    clusterBrowser_->setObjectName(QStringLiteral("clusterReport"));
    clusterBrowser_->setOpenLinks(false);

    // Long panels scroll rather than forcing their height on the other docks.
    auto scrolled = [this](QWidget* panel) {
        auto* area = new QScrollArea(this);
        area->setWidget(panel);
        area->setWidgetResizable(true);
        area->setFrameShape(QFrame::NoFrame);
        area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        area->setMinimumWidth(panel->sizeHint().width() + area->verticalScrollBar()->sizeHint().width());
        return area;
    };
    QDockWidget* settingsDock = dock(tr("Settings"), "settingsDock", scrolled(settingsPanel_), Qt::LeftDockWidgetArea);
    QDockWidget* eyeDock = dock(tr("Cull eye"), "eyeDock", eyePanel_, Qt::LeftDockWidgetArea);
    QDockWidget* statisticsDock = dock(tr("Statistics"), "statisticsDock", scrolled(statisticsPanel_), Qt::RightDockWidgetArea);
    QDockWidget* clusterDock = dock(tr("Picked cluster"), "clusterDock", clusterBrowser_, Qt::RightDockWidgetArea);

    auto* plots = new QTabWidget(this);
    plots->addTab(efficiencyView_, tr("Efficiency per view"));
    plots->addTab(histogramView_, tr("Cone half-angles"));
    connect(plots, &QTabWidget::currentChanged, this, [this]() { render(); });
    plotsDock_ = dock(tr("Plots"), "plotsDock", plots, Qt::BottomDockWidgetArea);
    eyeViewDock_ = dock(tr("Eye view (culled clusters removed)"), "eyeViewDock", eyeView_, Qt::BottomDockWidgetArea);
    splitDockWidget(plotsDock_, eyeViewDock_, Qt::Horizontal);
    connect(eyeViewDock_, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) render();
    });
    sideDocks_ = {settingsDock, eyeDock, statisticsDock, clusterDock};
}

QAction* MainWindow::addAction(QMenu* menu, const QString& text, const QKeySequence& shortcut, const QString& tip) {
    QAction* action = menu->addAction(text);
    if (!shortcut.isEmpty()) {
        action->setShortcut(shortcut);
        shortcutActions_ << action;
    }
    if (!tip.isEmpty()) action->setStatusTip(tip);
    // Shortcuts work wherever the focus is in the window, also when the menu bar is hidden.
    QMainWindow::addAction(action);
    return action;
}

void MainWindow::createActions() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* open = addAction(file, tr("&Open mesh..."), QKeySequence::Open, tr("Open a mesh (OFF, PLY, OBJ, STL, VTP, VTK)"));
    connect(open, &QAction::triggered, this, &MainWindow::openWithDialog);
    recentMenu_ = file->addMenu(tr("Open &recent"));
    rebuildRecentMenu();
    file->addSeparator();
    QAction* exportEye = addAction(file, tr("Export &statistics for the current eye..."), QKeySequence(tr("Ctrl+S")));
    connect(exportEye, &QAction::triggered, this, [this]() { exportStatisticsWithDialog(false); });
    QAction* exportOrbit = addAction(file, tr("Export statistics for the &orbit..."), QKeySequence(tr("Ctrl+Shift+E")));
    connect(exportOrbit, &QAction::triggered, this, [this]() { exportStatisticsWithDialog(true); });
    QAction* exportPartitionAction = addAction(file, tr("Export &partition..."), QKeySequence(tr("Ctrl+Shift+P")),
                                               tr("The mesh with cluster_id and cone/bound arrays per face"));
    connect(exportPartitionAction, &QAction::triggered, this, &MainWindow::exportPartitionWithDialog);
    QAction* screenshot = addAction(file, tr("Save screens&hot..."), QKeySequence(tr("Ctrl+Shift+S")));
    connect(screenshot, &QAction::triggered, this, &MainWindow::screenshotWithDialog);
    file->addSeparator();
    QAction* quit = addAction(file, tr("&Quit"), QKeySequence(tr("Ctrl+Q")));
    connect(quit, &QAction::triggered, this, &QWidget::close);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    QAction* reset = addAction(view, tr("&Reset camera"), QKeySequence(tr("R")));
    connect(reset, &QAction::triggered, this, &MainWindow::resetCamera);
    QMenu* layers = view->addMenu(tr("&Layers"));
    int number = 1;
    for (Layer layer : allLayers()) {
        const QKeySequence key = number <= 9 ? QKeySequence(Qt::Key_0 + number) : QKeySequence();
        QAction* action = addAction(layers, tr("Show %1").arg(QString::fromStdString(toString(layer))), key);
        action->setCheckable(true);
        // A first look shows clusters, cones and boxes; normals and spheres crowd the view, so
        // they wait for their keys. Every new scene takes these states when it is shown.
        action->setChecked(layer != Layer::Normals && layer != Layer::Spheres);
        connect(action, &QAction::toggled, this, [this, layer](bool visible) {
            if (scene_) scene_->setLayerVisible(layer, visible);
            render();
        });
        layerActions_[layer] = action;
        ++number;
    }
    QMenu* coloring = view->addMenu(tr("&Colour faces by"));
    auto* coloringGroup = new QActionGroup(this);
    const std::pair<FaceColoring, QString> colorings[] = {{FaceColoring::Cluster, tr("Ctrl+1")},
                                                          {FaceColoring::CullDecision, tr("Ctrl+2")},
                                                          {FaceColoring::FaceFacing, tr("Ctrl+3")}};
    for (const auto& [mode, key] : colorings) {
        QAction* action = addAction(coloring, tr("Colour by %1").arg(QString::fromStdString(toString(mode))), QKeySequence(key));
        action->setCheckable(true);
        action->setChecked(mode == coloring_);
        coloringGroup->addAction(action);
        connect(action, &QAction::triggered, this, [this, mode = mode]() { setFaceColoring(mode); });
        coloringActions_[mode] = action;
    }
    view->addSeparator();
    QAction* eyeViewToggle = eyeViewDock_->toggleViewAction();
    eyeViewToggle->setShortcut(QKeySequence(tr("V")));
    view->addAction(eyeViewToggle);
    shortcutActions_ << eyeViewToggle;
    view->addAction(plotsDock_->toggleViewAction());
    for (QDockWidget* dock : findChildren<QDockWidget*>())
        if (dock != eyeViewDock_ && dock != plotsDock_) view->addAction(dock->toggleViewAction());

    QMenu* eye = menuBar()->addMenu(tr("&Eye"));
    QAction* look = addAction(eye, tr("&Look from here"), QKeySequence(tr("L")), tr("Put the cull eye at the observer's camera"));
    connect(look, &QAction::triggered, this, &MainWindow::lookFromHere);
    followAction_ = addAction(eye, tr("&Follow the observer's camera"), QKeySequence(tr("F")));
    followAction_->setCheckable(true);
    connect(followAction_, &QAction::toggled, this, &MainWindow::setFollowing);
    animateAction_ = addAction(eye, tr("&Animate along the orbit"), QKeySequence(Qt::Key_Space));
    animateAction_->setCheckable(true);
    connect(animateAction_, &QAction::toggled, this, &MainWindow::setAnimating);
    QAction* next = addAction(eye, tr("&Next orbit view"), QKeySequence(tr("N")));
    connect(next, &QAction::triggered, this, [this]() { stepOrbit(1); });
    QAction* previous = addAction(eye, tr("&Previous orbit view"), QKeySequence(tr("P")));
    connect(previous, &QAction::triggered, this, [this]() { stepOrbit(-1); });
    QAction* startingEye = addAction(eye, tr("Eye to its &starting place"), QKeySequence(Qt::Key_Home));
    connect(startingEye, &QAction::triggered, this, [this]() {
        if (prepared_) moveEye(startingEyePosition(prepared_->box, settings_), -1);
    });
    QAction* projection = addAction(eye, tr("Toggle &orthographic eye"), QKeySequence(tr("O")));
    connect(projection, &QAction::triggered, this, [this]() {
        Settings next = settings_;
        next.orthographic = !next.orthographic;
        setSettings(next);
    });

    QMenu* culling = menuBar()->addMenu(tr("&Culling"));
    QAction* test = addAction(culling, tr("Next cull &test"), QKeySequence(tr("T")));
    connect(test, &QAction::triggered, this, &MainWindow::cycleTest);
    QAction* cone = addAction(culling, tr("Next &cone method"), QKeySequence(tr("C")));
    connect(cone, &QAction::triggered, this, &MainWindow::cycleCone);
    QAction* builder = addAction(culling, tr("Next &builder"), QKeySequence(tr("B")));
    connect(builder, &QAction::triggered, this, &MainWindow::cycleBuilder);
    QAction* clear = addAction(culling, tr("Clear the picked cluster"), QKeySequence(Qt::Key_Escape));
    connect(clear, &QAction::triggered, this, [this]() { pickCluster(-1); });

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    QAction* shortcuts = addAction(help, tr("&Shortcuts and controls"), QKeySequence::HelpContents);
    connect(shortcuts, &QAction::triggered, this, &MainWindow::showHelp);

    open->setIcon(style()->standardIcon(QStyle::SP_DialogOpenButton));
    exportEye->setIcon(style()->standardIcon(QStyle::SP_DialogSaveButton));
    screenshot->setIcon(style()->standardIcon(QStyle::SP_DesktopIcon));
    reset->setIcon(style()->standardIcon(QStyle::SP_BrowserReload));
    look->setIcon(style()->standardIcon(QStyle::SP_ArrowForward));
    animateAction_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    shortcuts->setIcon(style()->standardIcon(QStyle::SP_DialogHelpButton));

    QToolBar* tools = addToolBar(tr("Main"));
    tools->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    // Short labels for the toolbar; the menus keep the full text.
    open->setIconText(tr("Open"));
    exportEye->setIconText(tr("Export statistics"));
    screenshot->setIconText(tr("Screenshot"));
    reset->setIconText(tr("Reset camera"));
    look->setIconText(tr("Look from here"));
    followAction_->setIconText(tr("Follow camera"));
    animateAction_->setIconText(tr("Animate orbit"));
    eyeViewToggle->setIconText(tr("Eye view"));
    shortcuts->setIconText(tr("Help"));
    tools->setObjectName(QStringLiteral("mainToolBar"));
    tools->addAction(open);
    tools->addAction(exportEye);
    tools->addAction(screenshot);
    tools->addSeparator();
    tools->addAction(reset);
    tools->addAction(look);
    tools->addAction(followAction_);
    tools->addAction(animateAction_);
    tools->addSeparator();
    tools->addAction(eyeViewToggle);
    tools->addAction(shortcuts);
}

void MainWindow::createStatusBar() {
    statusText_ = new QLabel(tr("No mesh"), this);
    progressBar_ = new QProgressBar(this);
    progressBar_->setRange(0, 100);
    progressBar_->setMaximumWidth(320);
    progressBar_->setTextVisible(true);
    progressBar_->hide();
    cancelButton_ = new QPushButton(tr("Cancel"), this);
    cancelButton_->hide();
    connect(cancelButton_, &QPushButton::clicked, this, [this]() {
        runner_.cancelAll();
        statusBar()->showMessage(tr("Cancelled: the mesh and clusters shown before stay"), 5000);
    });
    // A normal widget: messages (errors, files written) replace it for a few seconds.
    statusBar()->addWidget(statusText_, 1);
    statusBar()->addPermanentWidget(progressBar_);
    statusBar()->addPermanentWidget(cancelButton_);
}

void MainWindow::createEyeHandle() {
    eyeHandleRepresentation_ = vtkSmartPointer<vtkPointHandleRepresentation3D>::New();
    eyeHandleRepresentation_->AllOff();
    eyeHandleRepresentation_->SetHandleSize(40);
    eyeHandleRepresentation_->GetProperty()->SetColor(SceneColours::eye[0], SceneColours::eye[1], SceneColours::eye[2]);
    eyeHandleRepresentation_->GetProperty()->SetLineWidth(2.0);
    eyeHandleRepresentation_->GetSelectedProperty()->SetColor(SceneColours::highlight[0], SceneColours::highlight[1],
                                                              SceneColours::highlight[2]);
    eyeHandleRepresentation_->GetSelectedProperty()->SetLineWidth(3.0);
    eyeHandle_ = vtkSmartPointer<vtkHandleWidget>::New();
    eyeHandle_->SetInteractor(view_->interactor());
    eyeHandle_->SetRepresentation(eyeHandleRepresentation_);
    eyeHandle_->AddObserver(vtkCommand::InteractionEvent, this, &MainWindow::onHandleMoved);
}

// --- Loading and recomputing ---------------------------------------------------------------------

void MainWindow::openMesh(const QString& path) {
    // A new mesh replaces whatever was being computed for the old one.
    runner_.cancelAll();
    const std::string file = path.toStdString();
    const Settings settings = settings_;
    runner_.run<SceneResult>(
        loadGroup, tr("Loading %1").arg(QFileInfo(path).fileName()),
        [file, settings](const ProgressCallback& progress) {
            SceneResult result;
            auto prepared = std::make_shared<PreparedMesh>(loadMesh(file, settings.fixWinding, scaled(progress, 0.0, 0.4)));
            auto clusters = std::make_shared<ClusterSet>(buildClusters(*prepared, settings, nullptr, scaled(progress, 0.4, 0.9)));
            progress(0.9, "scene");
            result.scene = makeScene(*prepared, *clusters);
            result.prepared = prepared;
            result.clusters = clusters;
            return result;
        },
        [this, path](SceneResult& result) {
            showSceneResult(result, true);
            const std::string message = loadMessage(*prepared_);
            if (!message.empty()) statusBar()->showMessage(QString::fromStdString(message), 30000);
            addRecentFile(QFileInfo(path).absoluteFilePath());
            setWindowTitle(tr("ConeScope - %1").arg(QFileInfo(path).fileName()));
            emit meshShown(path);
        },
        [this, path](const QString& error) {
            showError(tr("Cannot open %1").arg(QFileInfo(path).fileName()),
                      prepared_ ? error + tr("\n\nThe mesh shown before stays loaded.") : error);
        });
}

bool MainWindow::openMeshBlocking(const QString& path) {
    bool shown = false;
    const QMetaObject::Connection connection = connect(this, &MainWindow::meshShown, this, [&shown]() { shown = true; });
    openMesh(path);
    runner_.waitUntilIdle();
    disconnect(connection);
    return shown;
}

void MainWindow::waitUntilIdle() { runner_.waitUntilIdle(); }

void MainWindow::requestClusters(bool reprepare) {
    // A mesh still loading picks the current settings up when it arrives.
    if (!prepared_ || runner_.busy(loadGroup)) return;
    runner_.cancel(clustersGroup);
    runner_.cancel(orbitGroup);
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> previous = reprepare ? nullptr : clusters_;
    const Settings settings = settings_;
    runner_.run<SceneResult>(
        clustersGroup, tr("Building clusters"),
        [prepared, previous, settings, reprepare](const ProgressCallback& progress) {
            SceneResult result;
            result.prepared = prepared;
            if (reprepare) {
                PreparedMesh again = prepareMesh(prepared->original, prepared->path, settings.fixWinding, scaled(progress, 0.0, 0.3));
                again.readerNotes = prepared->readerNotes;
                result.prepared = std::make_shared<PreparedMesh>(std::move(again));
            }
            auto clusters = std::make_shared<ClusterSet>(
                buildClusters(*result.prepared, settings, previous.get(), scaled(progress, reprepare ? 0.3 : 0.0, 0.9)));
            progress(0.9, "scene");
            result.scene = makeScene(*result.prepared, *clusters);
            result.clusters = clusters;
            return result;
        },
        [this](SceneResult& result) { showSceneResult(result, false); },
        [this](const QString& error) { showError(tr("Cannot build the clusters"), error); });
}

void MainWindow::requestOrbit() {
    if (!prepared_ || !clusters_) return;
    runner_.cancel(orbitGroup);
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> clusters = clusters_;
    const Settings settings = settings_;
    runner_.run<std::vector<ViewStatistics>>(
        orbitGroup, tr("Orbit statistics"),
        [prepared, clusters, settings](const ProgressCallback& progress) {
            return measureOrbit(*prepared, *clusters, settings, progress);
        },
        [this, clusters](std::vector<ViewStatistics>& rows) {
            if (clusters != clusters_) return;  // the clusters changed meanwhile; their own orbit follows
            orbitRows_ = std::move(rows);
            updateEfficiencyPlot();
            updateStatusText();
        },
        [this](const QString& error) { showError(tr("Cannot measure the orbit"), error); });
}

void MainWindow::showSceneResult(SceneResult& result, bool newMesh) {
    const bool samePartition = !newMesh && clusters_ && result.prepared == prepared_ &&
                               !partitionChanged(clusters_->settings, result.clusters->settings);
    if (scene_) scene_->removeFrom(renderer_);
    if (eyeViewActor_) eyeRenderer_->RemoveActor(eyeViewActor_);
    prepared_ = result.prepared;
    clusters_ = result.clusters;
    scene_ = std::move(result.scene);
    scene_->addTo(renderer_);
    for (const auto& [layer, action] : layerActions_) scene_->setLayerVisible(layer, action->isChecked());
    scene_->setFaceColoring(coloring_);
    eyeViewActor_ = scene_->makeVisibleClustersActor();
    eyeRenderer_->AddActor(eyeViewActor_);
    if (!samePartition || picked_ >= int(clusters_->partition.clusterCount)) picked_ = -1;
    scene_->setHighlightedCluster(picked_);
    orbitRows_.clear();
    if (newMesh) {
        if (!eyeGiven_) eyePosition_ = startingEyePosition(prepared_->box, settings_);
        eyeGiven_ = false;
        orbitStep_ = -1;
        eyePanel_->setScale(2.0 * double(prepared_->box.halfDiagonal()));
        eyeHandleRepresentation_->SetWorldPosition(&eyePosition_[0]);
        eyeHandle_->On();
    }
    statisticsPanel_->showClusters(*prepared_, *clusters_);
    updateEye();
    if (newMesh) resetCamera();
    updateHistogram();
    updateEfficiencyPlot();
    // The settings may have moved on while this was computed.
    if (prepared_->fixWindingAsked != settings_.fixWinding || boundsChanged(clusters_->settings, settings_))
        requestClusters(prepared_->fixWindingAsked != settings_.fixWinding);
    else
        requestOrbit();
}

void MainWindow::setSettings(const Settings& settings) {
    settingsPanel_->setSettings(settings);
    applySettings(settingsPanel_->settings());
}

void MainWindow::applySettings(const Settings& settings) {
    const Settings before = settings_;
    settings_ = settings;
    if (!prepared_ || !clusters_) return;
    const bool reprepare = prepared_->fixWindingAsked != settings.fixWinding;
    if (reprepare || boundsChanged(clusters_->settings, settings)) {
        requestClusters(reprepare);
        return;
    }
    // Back to what is built: nothing queued is needed any more.
    runner_.cancel(clustersGroup);
    const bool eyeChanged = displayedTest(before) != displayedTest(settings) || before.orthographic != settings.orthographic;
    const bool orbitChanged = eyeChanged || before.views != settings.views || before.distance != settings.distance;
    if (eyeChanged) updateEye();
    if (orbitChanged) {
        orbitRows_.clear();
        updateEfficiencyPlot();
        requestOrbit();
    }
}

// --- The eye ---------------------------------------------------------------------------------------

void MainWindow::setEyePosition(const glm::dvec3& position) { moveEye(position, -1); }

void MainWindow::setInitialEye(const glm::dvec3& position) {
    eyePosition_ = position;
    eyeGiven_ = true;
}

void MainWindow::moveEye(const glm::dvec3& position, long orbitStep) {
    eyePosition_ = position;
    orbitStep_ = orbitStep;
    updateEye();
    updateEfficiencyPlot();
}

void MainWindow::scheduleEyeUpdate() {
    if (eyeUpdateScheduled_) return;
    eyeUpdateScheduled_ = true;
    QTimer::singleShot(0, this, [this]() {
        eyeUpdateScheduled_ = false;
        updateEye();
    });
}

void MainWindow::updateEye() {
    eyePanel_->showPosition(eyePosition_);
    eyePanel_->showOrbitStep(int(orbitStep_), int(settings_.views));
    if (!prepared_ || !clusters_ || !scene_) return;
    eyeHandleRepresentation_->SetWorldPosition(&eyePosition_[0]);
    const auto start = std::chrono::steady_clock::now();
    try {
        const Eye eye = eyeAt(settings_, eyePosition_, prepared_->box);
        measurement_ = measureEye(*prepared_, *clusters_, eye, displayedTest(settings_));
    } catch (const std::exception& error) {
        // An orthographic eye at the mesh centre has no direction: say so and show no decision.
        measurement_.reset();
        statisticsPanel_->showEyeError(QString::fromStdString(error.what()));
        scene_->clearClusterDecisions();
        updateClusterPanel();
        render();
        return;
    }
    showMeasurement(*scene_, *prepared_, *measurement_);
    if (coloring_ == FaceColoring::FaceFacing) showFaceFacing(*scene_, *prepared_, measurement_->eye);
    eyeSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    statisticsPanel_->showEye(*measurement_);
    scene_->applyEyeToCamera(eyeRenderer_->GetActiveCamera());
    eyeRenderer_->ResetCameraClippingRange();
    updateClusterPanel();
    updateStatusText();
    render();
    emit eyeMeasured();
}

void MainWindow::lookFromHere() {
    double position[3];
    renderer_->GetActiveCamera()->GetPosition(position);
    moveEye({position[0], position[1], position[2]}, -1);
}

void MainWindow::setFollowing(bool follow) {
    following_ = follow;
    eyePanel_->setFollowing(follow);
    {
        const QSignalBlocker blocker(followAction_);
        followAction_->setChecked(follow);
    }
    if (follow) lookFromHere();
}

void MainWindow::setAnimating(bool animate) {
    eyePanel_->setAnimating(animate);
    {
        const QSignalBlocker blocker(animateAction_);
        animateAction_->setChecked(animate);
    }
    if (animate)
        animationTimer_.start();
    else
        animationTimer_.stop();
}

void MainWindow::stepOrbit(int step) {
    if (!prepared_) return;
    const std::vector<Eye> views = orbitOf(settings_, prepared_->box);
    if (views.empty()) return;
    const long count = long(views.size());
    const long next = orbitStep_ < 0 ? (step > 0 ? 0 : count - 1) : ((orbitStep_ + step) % count + count) % count;
    moveEye(views[size_t(next)].position, next);
}

// --- Cycling settings from the keyboard ------------------------------------------------------------

namespace {
template <typename Enum>
Enum nextOf(const std::vector<Enum>& all, Enum current) {
    auto found = std::find(all.begin(), all.end(), current);
    return found == all.end() || std::next(found) == all.end() ? all.front() : *std::next(found);
}
}  // namespace

void MainWindow::cycleTest() {
    Settings next = settings_;
    next.tests = {nextOf(allCullTests(), displayedTest(settings_))};
    setSettings(next);
}

void MainWindow::cycleCone() {
    Settings next = settings_;
    next.cones = {nextOf(allConeMethods(), displayedCone(settings_))};
    setSettings(next);
}

void MainWindow::cycleBuilder() {
    Settings next = settings_;
    next.builder = nextOf(allBuilders(), settings_.builder);
    setSettings(next);
}

// --- Picking ---------------------------------------------------------------------------------------

void MainWindow::onLeftButtonPress() {
    view_->interactor()->GetEventPosition(pressPosition_);
}

void MainWindow::onLeftButtonRelease() {
    int position[2];
    view_->interactor()->GetEventPosition(position);
    if (std::abs(position[0] - pressPosition_[0]) > clickTolerance || std::abs(position[1] - pressPosition_[1]) > clickTolerance)
        return;
    pickDisplay(position[0], position[1]);
}

int MainWindow::pickDisplay(int x, int y) {
    if (!scene_) return -1;
    int cluster = -1;
    if (picker_->Pick(x, y, 0.0, renderer_)) cluster = scene_->clusterOfCell(picker_->GetActor(), picker_->GetCellId());
    pickCluster(cluster);
    return cluster;
}

int MainWindow::pickAt(const QPoint& viewPosition) {
    // Qt's widget coordinates (top-left origin, logical pixels) to VTK's display coordinates, as
    // QVTKInteractorAdapter converts mouse events.
    const double ratio = view_->devicePixelRatioF();
    const int height = view_->renderWindow()->GetSize()[1];
    return pickDisplay(int(std::lround(viewPosition.x() * ratio)), height - int(std::lround(viewPosition.y() * ratio)) - 1);
}

QPoint MainWindow::viewPositionOf(const glm::dvec3& world) const {
    renderer_->SetWorldPoint(world.x, world.y, world.z, 1.0);
    renderer_->WorldToDisplay();
    double display[3];
    renderer_->GetDisplayPoint(display);
    const double ratio = view_->devicePixelRatioF();
    const int height = view_->renderWindow()->GetSize()[1];
    return {int(std::lround(display[0] / ratio)), int(std::lround((height - 1 - display[1]) / ratio))};
}

void MainWindow::pickCluster(int cluster) {
    if (!scene_ || cluster < -1 || cluster >= int(scene_->clusterCount())) cluster = -1;
    picked_ = cluster;
    if (scene_) scene_->setHighlightedCluster(cluster);
    updateClusterPanel();
    render();
}

void MainWindow::updateClusterPanel() {
    if (picked_ < 0 || !clusters_ || !measurement_) {
        clusterBrowser_->setHtml(picked_ < 0 ? emptyClusterReportHtml()
                                             : tr("<p>Cluster %1: no valid eye to explain.</p>").arg(picked_));
        return;
    }
    ClusterReportInput input;
    input.cluster = uint32_t(picked_);
    input.bounds = &clusters_->bounds;
    input.eye = measurement_->eye;
    input.test = displayedTest(settings_);
    input.explanation = explainCull(cullingInput(*prepared_, *clusters_), input.cluster, input.eye, input.test);
    clusterBrowser_->setHtml(conescope::clusterReportHtml(input));
}

QString MainWindow::clusterReportHtml() const { return clusterBrowser_->toHtml(); }

// --- Camera observers --------------------------------------------------------------------------------

void MainWindow::onCameraModified(vtkObject*, unsigned long, void*) {
    if (!following_ || !prepared_) return;
    double position[3];
    renderer_->GetActiveCamera()->GetPosition(position);
    // Rendering touches the camera too (clipping range): only a new position moves the eye.
    if (glm::dvec3(position[0], position[1], position[2]) == eyePosition_) return;
    eyePosition_ = {position[0], position[1], position[2]};
    orbitStep_ = -1;
    scheduleEyeUpdate();
}

void MainWindow::onHandleMoved(vtkObject*, unsigned long, void*) {
    double position[3];
    eyeHandleRepresentation_->GetWorldPosition(position);
    eyePosition_ = {position[0], position[1], position[2]};
    orbitStep_ = -1;
    scheduleEyeUpdate();
}

void MainWindow::resetCamera() {
    if (!scene_) return;
    // Look at the mesh from the side of the eye, a little turned, so the eye marker and both the
    // culled and the drawn side are in the picture.
    vtkCamera* camera = renderer_->GetActiveCamera();
    const glm::dvec3 center(prepared_->box.center());
    glm::dvec3 direction = eyePosition_ - center;
    if (!(glm::length(direction) > 0.0)) direction = {0.0, 0.0, 1.0};
    direction = glm::normalize(direction);
    const glm::dvec3 side = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), direction) + glm::dvec3(1e-9));
    const glm::dvec3 from = center + glm::normalize(direction * 0.6 - side * 0.8 + glm::dvec3(0.0, 0.3, 0.0));
    camera->SetFocalPoint(center.x, center.y, center.z);
    camera->SetPosition(from.x, from.y, from.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    renderer_->ResetCamera();
    render();
}

// --- Layers and colours --------------------------------------------------------------------------------

void MainWindow::setLayerVisible(Layer layer, bool visible) {
    layerActions_.at(layer)->setChecked(visible);
}

bool MainWindow::layerVisible(Layer layer) const { return layerActions_.at(layer)->isChecked(); }

void MainWindow::setFaceColoring(FaceColoring coloring) {
    coloring_ = coloring;
    coloringActions_.at(coloring)->setChecked(true);
    if (!scene_) return;
    scene_->setFaceColoring(coloring);
    if (coloring == FaceColoring::FaceFacing && measurement_) showFaceFacing(*scene_, *prepared_, measurement_->eye);
    render();
}

// --- Plots, status, rendering ----------------------------------------------------------------------------

void MainWindow::updateEfficiencyPlot() {
    plotEfficiencyPerView(efficiencyChart_, orbitRows_, orbitStep_);
    if (efficiencyView_->isVisible()) efficiencyView_->renderWindow()->Render();
}

void MainWindow::updateHistogram() {
    plotHalfAngleHistogram(histogramChart_, measurement_ ? measurement_->statistics.clusters : std::vector<ClusterStatistics>{});
    if (histogramView_->isVisible()) histogramView_->renderWindow()->Render();
}

void MainWindow::updateStatusText() {
    if (!prepared_ || !clusters_) {
        statusText_->setText(tr("No mesh"));
        return;
    }
    QString text = tr("%1: %2 triangles, %3 clusters (%4, %5, %6) | load %7, partition %8, bounds %9, eye %10")
                       .arg(QString::fromStdString(prepared_->name))
                       .arg(QLocale().toString(qulonglong(prepared_->triangles)))
                       .arg(clusters_->partition.clusterCount)
                       .arg(QString::fromStdString(toString(clusters_->settings.builder)),
                            QString::fromStdString(toString(displayedCone(clusters_->settings))),
                            QString::fromStdString(toString(displayedTest(settings_))))
                       .arg(milliseconds(prepared_->prepareSeconds), milliseconds(clusters_->partitionSeconds),
                            milliseconds(clusters_->boundsSeconds), milliseconds(eyeSeconds_));
    if (!orbitRows_.empty()) text += tr(" | orbit of %1 views measured").arg(orbitRows_.size());
    statusText_->setText(text);
}

void MainWindow::render() {
    view_->renderWindow()->Render();
    if (eyeViewDock_->isVisible()) eyeView_->renderWindow()->Render();
    if (efficiencyView_->isVisible()) efficiencyView_->renderWindow()->Render();
    if (histogramView_->isVisible()) histogramView_->renderWindow()->Render();
}

// --- Errors, files, dialogs ------------------------------------------------------------------------------

void MainWindow::showError(const QString& title, const QString& message) {
    lastError_ = message;
    statusBar()->showMessage(title, 8000);
    emit errorShown(message);
    if (errorDialogs_) QMessageBox::critical(this, title, message);
}

QStringList MainWindow::recentFiles() const { return QSettings().value(QLatin1String(recentFilesKey)).toStringList(); }

void MainWindow::addRecentFile(const QString& path) {
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > maxRecentFiles) files.removeLast();
    QSettings().setValue(QLatin1String(recentFilesKey), files);
    rebuildRecentMenu();
}

void MainWindow::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = recentFiles();
    for (const QString& path : files) {
        QAction* action = recentMenu_->addAction(QFileInfo(path).fileName());
        action->setToolTip(path);
        action->setStatusTip(path);
        connect(action, &QAction::triggered, this, [this, path]() { openMesh(path); });
    }
    recentMenu_->setEnabled(!files.isEmpty());
}

void MainWindow::openWithDialog() {
    const QString folder = prepared_ ? QFileInfo(QString::fromStdString(prepared_->path)).absolutePath() : QString();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open mesh"), folder, QString::fromStdString(meshFileFilter()));
    if (!path.isEmpty()) openMesh(path);
}

void MainWindow::startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                                       const std::function<void(bool)>& finished) {
    if (!prepared_) {
        showError(tr("Cannot export statistics"), tr("No mesh is loaded."));
        finished(false);
        return;
    }
    const std::shared_ptr<const PreparedMesh> prepared = prepared_;
    const std::shared_ptr<const ClusterSet> clusters = clusters_;
    const Settings settings = exportSettings(settings_, orbit ? std::nullopt : std::optional<glm::dvec3>(eyePosition_));
    const std::string file = path.toStdString();
    runner_.run<RunStatistics>(
        exportGroup, tr("Exporting statistics"),
        [prepared, clusters, settings, file, format](const ProgressCallback& progress) {
            return conescope::exportStatistics(*prepared, *clusters, settings, file, format, progress);
        },
        [this, path, finished](RunStatistics& run) {
            statusBar()->showMessage(tr("Wrote %1 (%2 views)").arg(path).arg(run.viewCount), 6000);
            finished(true);
        },
        [this, finished](const QString& error) {
            showError(tr("Cannot export statistics"), error);
            finished(false);
        });
}

bool MainWindow::exportStatistics(const QString& path, StatisticsFormat format, bool orbit) {
    auto written = std::make_shared<bool>(false);
    startStatisticsExport(path, format, orbit, [written](bool success) { *written = success; });
    runner_.waitUntilIdle();
    return *written;
}

void MainWindow::exportStatisticsWithDialog(bool orbit) {
    if (!prepared_) return;
    QString selectedFilter;
    const QString base = QFileInfo(QString::fromStdString(prepared_->name)).completeBaseName() +
                         (orbit ? QStringLiteral("-orbit") : QStringLiteral("-eye"));
    const QString path = QFileDialog::getSaveFileName(this, orbit ? tr("Export orbit statistics") : tr("Export statistics for the eye"),
                                                      base + QStringLiteral(".json"), tr("JSON (*.json);;CSV (*.csv)"),
                                                      &selectedFilter);
    if (path.isEmpty()) return;
    // In the background: the window stays usable while a large orbit is measured.
    startStatisticsExport(path, statisticsFormatOf(path.toStdString()), orbit, [](bool) {});
}

bool MainWindow::exportPartition(const QString& path) {
    if (!prepared_ || !clusters_) {
        showError(tr("Cannot export the partition"), tr("No mesh is loaded."));
        return false;
    }
    try {
        conescope::exportPartition(*prepared_, *clusters_, path.toStdString());
    } catch (const std::exception& error) {
        showError(tr("Cannot export the partition"), QString::fromStdString(error.what()));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1").arg(path), 6000);
    return true;
}

void MainWindow::exportPartitionWithDialog() {
    if (!prepared_) return;
    const QString base = QFileInfo(QString::fromStdString(prepared_->name)).completeBaseName() + QStringLiteral("-clusters.vtp");
    const QString path = QFileDialog::getSaveFileName(this, tr("Export partition"), base,
                                                      tr("VTK XML PolyData (*.vtp);;VTK legacy (*.vtk)"));
    if (!path.isEmpty()) exportPartition(path);
}

bool MainWindow::saveScreenshot(const QString& path) {
    try {
        view_->renderWindow()->Render();
        saveRenderWindowPng(view_->renderWindow(), path.toStdString());
    } catch (const std::exception& error) {
        showError(tr("Cannot save the screenshot"), QString::fromStdString(error.what()));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1").arg(path), 6000);
    return true;
}

void MainWindow::screenshotWithDialog() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Save screenshot"), QStringLiteral("conescope.png"), tr("PNG (*.png)"));
    if (!path.isEmpty()) saveScreenshot(path);
}

void MainWindow::showHelp() {
    HelpDialog dialog(shortcutActions_, this);
    dialog.exec();
}

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
    runner_.cancelAll();
    QMainWindow::closeEvent(event);
}

}  // namespace conescope
