#include "WindowActions.h"

#include <algorithm>

#include <QAction>
#include <QActionGroup>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QSettings>
#include <QStyle>
#include <QToolBar>

#include "HelpDialog.h"
#include "MainWindow.h"
#include "Session.h"
#include "io/MeshReader.h"

namespace conescope {

namespace {

const char* const recentFilesKey = "recentFiles";
constexpr int maxRecentFiles = 8;

// The entry after `current`, wrapping around: what a cycling key switches to.
template <typename Enum>
Enum nextOf(const std::vector<Enum>& all, Enum current) {
    auto found = std::find(all.begin(), all.end(), current);
    return found == all.end() || std::next(found) == all.end() ? all.front() : *std::next(found);
}

Settings withNextTest(Settings settings) {
    settings.tests = {nextOf(allCullTests(), displayedTest(settings))};
    return settings;
}

Settings withNextCone(Settings settings) {
    settings.cones = {nextOf(allConeMethods(), displayedCone(settings))};
    return settings;
}

Settings withNextBuilder(Settings settings) {
    settings.builder = nextOf(allBuilders(), settings.builder);
    return settings;
}

Settings withOtherProjection(Settings settings) {
    settings.orthographic = !settings.orthographic;
    return settings;
}

}  // namespace

WindowActions::WindowActions(MainWindow* window, Session* session, QDockWidget* eyeViewDock, QDockWidget* plotsDock,
                             QDockWidget* gaussMapDock)
    : QObject(window), window_(window), session_(session) {
    createFileMenu();
    createViewMenu(eyeViewDock, plotsDock, gaussMapDock);
    createEyeMenu();
    createCullingMenu();
    QMenu* help = window_->menuBar()->addMenu(tr("&Help"));
    help_ = add(help, tr("&Shortcuts and controls"), QKeySequence::HelpContents, [this]() { showHelp(); });
    createToolBar();
}

QAction* WindowActions::add(QMenu* menu, const QString& text, const QKeySequence& key, const std::function<void()>& run,
                            const QString& tip) {
    QAction* action = menu->addAction(text);
    if (!key.isEmpty()) {
        action->setShortcut(key);
        shortcutActions_ << action;
    }
    if (!tip.isEmpty()) action->setStatusTip(tip);
    if (run) connect(action, &QAction::triggered, this, run);
    // Shortcuts work wherever the focus is in the window, also when the menu bar is hidden.
    window_->addAction(action);
    return action;
}

// From what the widgets show: while a build runs, the settings asked for.
void WindowActions::changeSettings(Settings (*change)(Settings)) { session_->applySettings(change(session_->askedSettings())); }

void WindowActions::createFileMenu() {
    QMenu* file = window_->menuBar()->addMenu(tr("&File"));
    open_ = add(file, tr("&Open mesh..."), QKeySequence::Open, [this]() { openWithDialog(); },
                tr("Open a mesh (OFF, PLY, OBJ, STL, glTF, GLB, VTP, VTK)"));
    recentMenu_ = file->addMenu(tr("Open &recent"));
    rebuildRecentMenu();
    file->addSeparator();
    exportEye_ = add(file, tr("Export &statistics for the current eye..."), QKeySequence(tr("Ctrl+S")),
                     [this]() { exportStatisticsWithDialog(false); });
    add(file, tr("Export statistics for the &orbit..."), QKeySequence(tr("Ctrl+Shift+E")), [this]() { exportStatisticsWithDialog(true); });
    add(file, tr("Export &partition..."), QKeySequence(tr("Ctrl+Shift+P")), [this]() { exportPartitionWithDialog(); },
        tr("The mesh with cluster_id and cone/bound arrays per face"));
    screenshot_ = add(file, tr("Save screens&hot..."), QKeySequence(tr("Ctrl+Shift+S")), [this]() { screenshotWithDialog(); });
    file->addSeparator();
    add(file, tr("&Quit"), QKeySequence(tr("Ctrl+Q")), [this]() { window_->close(); });
}

void WindowActions::createViewMenu(QDockWidget* eyeViewDock, QDockWidget* plotsDock, QDockWidget* gaussMapDock) {
    QMenu* view = window_->menuBar()->addMenu(tr("&View"));
    reset_ = add(view, tr("&Reset camera"), QKeySequence(tr("R")), [this]() { window_->resetCamera(); });
    QMenu* layers = view->addMenu(tr("&Layers"));
    int number = 1;
    for (Layer layer : allLayers()) {
        // 1 .. 9, then 0 for the tenth, as on the keyboard.
        const QKeySequence key = number <= 10 ? QKeySequence(Qt::Key_0 + number % 10) : QKeySequence();
        QAction* action = add(layers, tr("Show %1").arg(QString::fromStdString(toString(layer))), key, {});
        action->setCheckable(true);
        action->setChecked(session_->layerVisible(layer));
        connect(action, &QAction::toggled, this, [this, layer](bool visible) {
            session_->setLayerVisible(layer, visible);
            window_->render();
        });
        layerActions_[layer] = action;
        ++number;
    }
    QMenu* coloring = view->addMenu(tr("&Colour faces by"));
    auto* coloringGroup = new QActionGroup(this);
    // Ctrl+1 .. Ctrl+6 in the order of allFaceColorings.
    int key = 1;
    for (FaceColoring mode : allFaceColorings()) {
        QAction* action = add(coloring, tr("Colour by %1").arg(QString::fromStdString(toString(mode))),
                              QKeySequence(tr("Ctrl+%1").arg(key++)),
                              [this, mode = mode]() { session_->setFaceColoring(mode); });
        action->setCheckable(true);
        action->setChecked(mode == session_->faceColoring());
        coloringGroup->addAction(action);
        coloringActions_[mode] = action;
    }
    view->addSeparator();
    eyeViewToggle_ = eyeViewDock->toggleViewAction();
    eyeViewToggle_->setShortcut(QKeySequence(tr("V")));
    view->addAction(eyeViewToggle_);
    shortcutActions_ << eyeViewToggle_;
    view->addAction(plotsDock->toggleViewAction());
    // Beside the picked cluster's numbers: its normals and cones on the unit sphere.
    add(view, tr("Show the &Gauss map"), QKeySequence(tr("G")), [gaussMapDock]() {
        gaussMapDock->show();
        gaussMapDock->raise();
    });
    for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
        if (dock != eyeViewDock && dock != plotsDock) view->addAction(dock->toggleViewAction());
}

void WindowActions::createEyeMenu() {
    QMenu* eye = window_->menuBar()->addMenu(tr("&Eye"));
    look_ = add(eye, tr("&Look from here"), QKeySequence(tr("L")), [this]() { window_->lookFromHere(); },
                tr("Put the cull eye at the observer's camera"));
    followAction_ = add(eye, tr("&Follow the observer's camera"), QKeySequence(tr("F")), {});
    followAction_->setCheckable(true);
    connect(followAction_, &QAction::toggled, window_, &MainWindow::setFollowing);
    animateAction_ = add(eye, tr("&Animate along the orbit"), QKeySequence(Qt::Key_Space), {});
    animateAction_->setCheckable(true);
    connect(animateAction_, &QAction::toggled, window_, &MainWindow::setAnimating);
    add(eye, tr("&Next orbit view"), QKeySequence(tr("N")), [this]() { session_->stepOrbit(1); });
    add(eye, tr("&Previous orbit view"), QKeySequence(tr("P")), [this]() { session_->stepOrbit(-1); });
    add(eye, tr("Eye to its &starting place"), QKeySequence(Qt::Key_Home), [this]() { session_->moveEyeToStart(); });
    add(eye, tr("Toggle &orthographic eye"), QKeySequence(tr("O")), [this]() { changeSettings(withOtherProjection); });
}

void WindowActions::createCullingMenu() {
    QMenu* culling = window_->menuBar()->addMenu(tr("&Culling"));
    add(culling, tr("Next cull &test"), QKeySequence(tr("T")), [this]() { changeSettings(withNextTest); });
    add(culling, tr("Next &cone method"), QKeySequence(tr("C")), [this]() { changeSettings(withNextCone); });
    add(culling, tr("Next &builder"), QKeySequence(tr("B")), [this]() { changeSettings(withNextBuilder); });
    add(culling, tr("Clear the picked cluster"), QKeySequence(Qt::Key_Escape), [this]() { window_->pickCluster(-1); });
    culling->addSeparator();
    // A/B: pin what is shown as A, change the settings (B), compare; X swaps them.
    add(culling, tr("&Pin as A (compare with what comes next)"), QKeySequence(tr("A")), [this]() { session_->pinAsA(); },
        tr("Keep these clusters and settings as A; the faces show what A and B cull"));
    add(culling, tr("Swap A and B"), QKeySequence(tr("X")), [this]() { session_->swapAB(); });
    add(culling, tr("Clear A"), QKeySequence(tr("Shift+A")), [this]() { session_->clearPin(); });
}

void WindowActions::createToolBar() {
    // Short labels for the toolbar; the menus keep the full text. A null action is a separator.
    const struct {
        QAction* action;
        QStyle::StandardPixmap icon;  // SP_CustomBase: none
        QString text;
    } tools[] = {
        {open_, QStyle::SP_DialogOpenButton, tr("Open")},
        {exportEye_, QStyle::SP_DialogSaveButton, tr("Export statistics")},
        {screenshot_, QStyle::SP_DesktopIcon, tr("Screenshot")},
        {nullptr, QStyle::SP_CustomBase, {}},
        {reset_, QStyle::SP_BrowserReload, tr("Reset camera")},
        {look_, QStyle::SP_ArrowForward, tr("Look from here")},
        {followAction_, QStyle::SP_CustomBase, tr("Follow camera")},
        {animateAction_, QStyle::SP_MediaPlay, tr("Animate orbit")},
        {nullptr, QStyle::SP_CustomBase, {}},
        {eyeViewToggle_, QStyle::SP_CustomBase, tr("Eye view")},
        {help_, QStyle::SP_DialogHelpButton, tr("Help")},
    };
    QToolBar* toolBar = window_->addToolBar(tr("Main"));
    toolBar->setObjectName(QStringLiteral("mainToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    for (const auto& tool : tools) {
        if (!tool.action) {
            toolBar->addSeparator();
            continue;
        }
        if (tool.icon != QStyle::SP_CustomBase) tool.action->setIcon(window_->style()->standardIcon(tool.icon));
        tool.action->setIconText(tool.text);
        toolBar->addAction(tool.action);
    }
}

void WindowActions::showHelp() {
    HelpDialog dialog(shortcutActions_, window_);
    dialog.exec();
}

// --- Recent files ----------------------------------------------------------------------------------

QStringList WindowActions::recentFiles() { return QSettings().value(QLatin1String(recentFilesKey)).toStringList(); }

void WindowActions::addRecentFile(const QString& path) {
    QStringList files = recentFiles();
    files.removeAll(path);
    files.prepend(path);
    while (files.size() > maxRecentFiles) files.removeLast();
    QSettings().setValue(QLatin1String(recentFilesKey), files);
    rebuildRecentMenu();
}

void WindowActions::rebuildRecentMenu() {
    recentMenu_->clear();
    const QStringList files = recentFiles();
    for (const QString& path : files) {
        QAction* action = recentMenu_->addAction(QFileInfo(path).fileName());
        action->setToolTip(path);
        action->setStatusTip(path);
        connect(action, &QAction::triggered, window_, [this, path]() { window_->openMesh(path); });
    }
    recentMenu_->setEnabled(!files.isEmpty());
}

// --- The File menu's dialogs -------------------------------------------------------------------------

void WindowActions::openWithDialog() {
    const PreparedMesh* prepared = session_->preparedMesh();
    const QString folder = prepared ? QFileInfo(QString::fromStdString(prepared->path)).absolutePath() : QString();
    const QString path = QFileDialog::getOpenFileName(window_, tr("Open mesh"), folder, QString::fromStdString(meshFileFilter()));
    if (!path.isEmpty()) window_->openMesh(path);
}

void WindowActions::exportStatisticsWithDialog(bool orbit) {
    const PreparedMesh* prepared = session_->preparedMesh();
    if (!prepared) return;
    QString selectedFilter;
    const QString base = QFileInfo(QString::fromStdString(prepared->name)).completeBaseName() +
                         (orbit ? QStringLiteral("-orbit") : QStringLiteral("-eye"));
    const QString path = QFileDialog::getSaveFileName(window_, orbit ? tr("Export orbit statistics") : tr("Export statistics for the eye"),
                                                      base + QStringLiteral(".json"), tr("JSON (*.json);;CSV (*.csv)"),
                                                      &selectedFilter);
    if (path.isEmpty()) return;
    // In the background: the window stays usable while a large orbit is measured.
    session_->startStatisticsExport(path, statisticsFormatOf(path.toStdString()), orbit, [](bool) {});
}

void WindowActions::exportPartitionWithDialog() {
    const PreparedMesh* prepared = session_->preparedMesh();
    if (!prepared) return;
    const QString base = QFileInfo(QString::fromStdString(prepared->name)).completeBaseName() + QStringLiteral("-clusters.vtp");
    const QString path = QFileDialog::getSaveFileName(window_, tr("Export partition"), base,
                                                      tr("VTK XML PolyData (*.vtp);;VTK legacy (*.vtk)"));
    if (!path.isEmpty()) window_->exportPartition(path);
}

void WindowActions::screenshotWithDialog() {
    const QString path = QFileDialog::getSaveFileName(window_, tr("Save screenshot"), QStringLiteral("conescope.png"), tr("PNG (*.png)"));
    if (!path.isEmpty()) window_->saveScreenshot(path);
}

}  // namespace conescope
