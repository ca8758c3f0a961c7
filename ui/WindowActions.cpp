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
#include <QWhatsThis>

#include "Datasets.h"
#include "Glossary.h"
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
    createLessonMenu();
    QMenu* help = window_->menuBar()->addMenu(tr("&Help"));
    help_ = add(help, tr("&Shortcuts and controls"), QKeySequence::HelpContents, [this]() { showHelp(); });
    add(help, tr("&Glossary"), {}, [this]() { showPage(tr("ConeScope glossary"), glossaryHtml()); },
        tr("What cluster, normal cone, alpha, B, apex, the tests, the fractions and the losses mean"));
    QAction* whatsThis = QWhatsThis::createAction(this);
    whatsThis->setShortcut(QKeySequence(tr("Shift+F1")));
    help->addAction(whatsThis);
    window_->addAction(whatsThis);
    shortcutActions_ << whatsThis;
    help->addSeparator();
    add(help, tr("&About ConeScope"), {}, [this]() { showPage(tr("About ConeScope"), aboutHtml()); });
    createToolBar();
}

QAction* WindowActions::add(QMenu* menu, const QString& text, const QKeySequence& key, const std::function<void()>& run,
                            const QString& tip) {
    QAction* action = menu->addAction(text);
    if (!key.isEmpty()) {
        action->setShortcut(key);
        shortcutActions_ << action;
    }
    if (!tip.isEmpty()) {
        action->setStatusTip(tip);
        action->setToolTip(tip);
        action->setWhatsThis(tip);
    }
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
    createExamplesMenu(file->addMenu(tr("&Examples")));
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

void WindowActions::createExamplesMenu(QMenu* examples) {
    // Small meshes whose clusters a class reads at a glance, then ready-made lessons on them.
    for (const auto& [label, file] : exampleMeshes()) {
        const QString path = findDataset(file);
        QAction* action = add(examples, label, {}, [this, path]() { window_->openMesh(path); },
                              tr("Open %1, a small teaching mesh").arg(file));
        action->setEnabled(!path.isEmpty());
    }
    examples->addSeparator();
    for (const QString& path : lessonFiles())
        add(examples, tr("Lesson: %1").arg(QFileInfo(path).completeBaseName().replace(QLatin1Char('-'), QLatin1Char(' '))), {},
            [this, path]() { window_->playReplayFile(path); }, tr("Plays %1: a mesh, an eye and a cluster, the lesson at its first step").arg(path));
}

void WindowActions::createViewMenu(QDockWidget* eyeViewDock, QDockWidget* plotsDock, QDockWidget* gaussMapDock) {
    QMenu* view = window_->menuBar()->addMenu(tr("&View"));
    reset_ = add(view, tr("&Reset camera"), QKeySequence(tr("R")), [this]() { window_->resetCamera(); },
                 tr("The first view: the whole mesh and the eye, turned past the eye's side so culled clusters show beside drawn ones"));
    behind_ = add(view, tr("View from &behind (the culled side)"), QKeySequence(tr("Shift+R")), [this]() { window_->viewFromBehind(); },
                  tr("Looks at the mesh from behind, the side turned away from the cull eye: where its culled clusters are, "
                     "and where A and B differ"));
    QMenu* layers = view->addMenu(tr("&Layers"));
    int number = 1;
    for (Layer layer : allLayers()) {
        // 1 .. 9, then 0 for the tenth, as on the keyboard.
        const QKeySequence key = number <= 10 ? QKeySequence(Qt::Key_0 + number % 10) : QKeySequence();
        QAction* action = add(layers, tr("Show %1").arg(QString::fromStdString(toString(layer))), key, {}, explain(layer));
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
    // Ctrl+1 .. Ctrl+9 in the order of allFaceColorings.
    int key = 1;
    for (FaceColoring mode : allFaceColorings()) {
        // The last LOD colouring is in the menu and the LOD dock only.
        const QKeySequence shortcut = key <= 9 ? QKeySequence(tr("Ctrl+%1").arg(key)) : QKeySequence();
        ++key;
        QAction* action = add(coloring, tr("Colour by %1").arg(QString::fromStdString(toString(mode))), shortcut,
                              [this, mode = mode]() { session_->setFaceColoring(mode); }, explain(mode));
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
    QAction* frameTimes = add(view, tr("Show &frame times"), {}, {},
                              tr("Where each eye step's time goes: the cull and scene update, the panels, each view drawn"));
    frameTimes->setCheckable(true);
    connect(frameTimes, &QAction::toggled, window_, &MainWindow::setFrameTimesShown);
    // Beside the picked cluster's numbers: its normals and cones on the unit sphere.
    add(view, tr("Show the &Gauss map"), QKeySequence(tr("G")), [gaussMapDock]() {
        gaussMapDock->show();
        gaussMapDock->raise();
    }, explain(QStringLiteral("gauss sphere")));
    for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
        if (dock != eyeViewDock && dock != plotsDock) view->addAction(dock->toggleViewAction());
}

void WindowActions::createEyeMenu() {
    QMenu* eye = window_->menuBar()->addMenu(tr("&Eye"));
    look_ = add(eye, tr("Put the &eye at the camera (look from here)"), QKeySequence(tr("E")), [this]() { window_->lookFromHere(); },
                tr("Put the cull eye where the observer's camera is"));
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

void WindowActions::createLessonMenu() {
    QMenu* lesson = window_->menuBar()->addMenu(tr("&Lesson"));
    add(lesson, tr("Start or end the &lesson"), QKeySequence(tr("L")), [this]() { window_->toggleLesson(); },
        tr("Seven steps through the picked cluster's cull decision, in words, with its numbers"));
    add(lesson, tr("&Next lesson step"), QKeySequence(Qt::Key_PageDown), [this]() {
        if (session_->lessonStep() > 0) window_->showLessonStep(std::min(session_->lessonStep() + 1, kLessonStepCount));
    });
    add(lesson, tr("&Previous lesson step"), QKeySequence(Qt::Key_PageUp), [this]() {
        if (session_->lessonStep() > 0) window_->showLessonStep(std::max(session_->lessonStep() - 1, 1));
    });
    add(lesson, tr("Pick the cluster the test loses &most"), QKeySequence(tr("M")),
        [this]() { window_->chooseWorstCluster(ClusterSortKey::TestLoss); },
        tr("The cluster whose back faces the test draws most over the orbit, seen from where it draws them"));
    lesson->addSeparator();
    add(lesson, tr("Export the &explanation..."), {}, [this]() { writeWithDialog(tr("Export the explanation"), QStringLiteral("explanation.json"),
                                                                                tr("JSON (*.json)"), &MainWindow::exportExplanation); },
        tr("The lesson's steps and numbers as JSON"));
    add(lesson, tr("Save the &cross-section..."), {}, [this]() { writeWithDialog(tr("Save the cross-section"), QStringLiteral("cross-section.png"),
                                                                                tr("PNG (*.png)"), &MainWindow::saveCrossSection); },
        tr("Seed 000's figure of the picked cluster as a picture, and beside it (X.json) what it drew"));
    add(lesson, tr("Export the lesson as &slides..."), {}, [this]() {
        const QString folder = QFileDialog::getExistingDirectory(window_, tr("Folder for the lesson slides"));
        if (!folder.isEmpty()) window_->exportLessonSlides(folder);
    }, tr("The seven steps as 1920x1080 slides (slide-01.png ...) and slides.pdf: title, 3D view, cross-section, words"));
    add(lesson, tr("Export the &orbit as slides..."), {}, [this]() {
        const QString folder = QFileDialog::getExistingDirectory(window_, tr("Folder for the orbit slides"));
        if (!folder.isEmpty()) window_->exportOrbitSlides(folder);
    }, tr("Eight orbit views as 1920x1080 slides and slides.pdf, each with that eye's statistics in words"));
}

void WindowActions::writeWithDialog(const QString& title, const QString& name, const QString& filter,
                                    bool (MainWindow::*write)(const QString&)) {
    const QString path = QFileDialog::getSaveFileName(window_, title, name, filter);
    if (!path.isEmpty()) (window_->*write)(path);
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
        {behind_, QStyle::SP_CustomBase, tr("View from behind")},
        {look_, QStyle::SP_ArrowForward, tr("Eye at camera")},
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

void WindowActions::showPage(const QString& title, const QString& html) {
    HelpDialog dialog(title, html, window_);
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
