// The window's menus, toolbar and keyboard shortcuts. Each action is one line: its text, its key and
// what it calls (a Session or MainWindow function); the File menu's dialogs ask for a path and hand
// it to the same functions the tests call. The help dialog lists shortcutActions() in menu order.
#pragma once

#include <functional>
#include <map>

#include <QList>
#include <QObject>
#include <QStringList>

#include "core/Settings.h"
#include "scene/ClusterScene.h"

class QAction;
class QDockWidget;
class QKeySequence;
class QMenu;

namespace conescope {

class MainWindow;
class Session;

class WindowActions : public QObject {
    Q_OBJECT
public:
    // Adds the menus and the toolbar to `window`. `eyeViewDock`, `plotsDock` and `gaussMapDock` get
    // their own entries (V for the eye's view, G raises the Gauss map); every other dock of the window
    // is listed after them.
    WindowActions(MainWindow* window, Session* session, QDockWidget* eyeViewDock, QDockWidget* plotsDock,
                  QDockWidget* gaussMapDock);

    // Every action with a shortcut, in menu order.
    QList<QAction*> shortcutActions() const { return shortcutActions_; }
    QAction* animateAction() const { return animateAction_; }
    QAction* followAction() const { return followAction_; }
    QAction* layerAction(Layer layer) const { return layerActions_.at(layer); }
    QAction* coloringAction(FaceColoring coloring) const { return coloringActions_.at(coloring); }

    // The meshes opened last, newest first (kept in QSettings), and the menu that lists them.
    static QStringList recentFiles();
    void addRecentFile(const QString& path);

    void showHelp();
    // A page of the help (the glossary, About) in the help dialog.
    void showPage(const QString& title, const QString& html);

private:
    QAction* add(QMenu* menu, const QString& text, const QKeySequence& key, const std::function<void()>& run,
                 const QString& tip = {});
    void changeSettings(Settings (*change)(Settings));
    void createFileMenu();
    void createExamplesMenu(QMenu* examples);
    void createViewMenu(QDockWidget* eyeViewDock, QDockWidget* plotsDock, QDockWidget* gaussMapDock);
    void createEyeMenu();
    void createCullingMenu();
    void createLessonMenu();
    void createToolBar();
    void rebuildRecentMenu();

    // The File menu's questions.
    void openWithDialog();
    void exportStatisticsWithDialog(bool orbit);
    void exportPartitionWithDialog();
    void screenshotWithDialog();
    // Asks for a file and hands it to `write` (which reports its own errors).
    void writeWithDialog(const QString& title, const QString& name, const QString& filter, bool (MainWindow::*write)(const QString&));

    MainWindow* window_;
    Session* session_;
    QMenu* recentMenu_ = nullptr;
    QList<QAction*> shortcutActions_;
    std::map<Layer, QAction*> layerActions_;
    std::map<FaceColoring, QAction*> coloringActions_;
    // The toolbar's actions.
    QAction* open_ = nullptr;
    QAction* exportEye_ = nullptr;
    QAction* screenshot_ = nullptr;
    QAction* reset_ = nullptr;
    QAction* behind_ = nullptr;
    QAction* eyeViewToggle_ = nullptr;
    QAction* look_ = nullptr;
    QAction* followAction_ = nullptr;
    QAction* animateAction_ = nullptr;
    QAction* help_ = nullptr;
};

}  // namespace conescope
