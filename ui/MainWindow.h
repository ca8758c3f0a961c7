// The ConeScope window: the observer view (QVTKOpenGLNativeWidget) with the cluster scene and the
// cull eye's handle, dockable panels (settings, eye, statistics, picked cluster, plots, the eye's own
// view), menus, toolbar and status bar. It keeps the current mesh, clusters and eye, runs the slow
// stages through a TaskRunner and takes every number from the pipeline (src/core calls) and every
// actor from src/scene.
//
// The public functions below the widget plumbing are the window's test interface: they do what the
// matching menu action does, but report the outcome instead of opening dialogs.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <optional>

#include <QMainWindow>
#include <QPoint>
#include <QTimer>

#include <vtkSmartPointer.h>

#include "Exports.h"
#include "core/Pipeline.h"
#include "TaskRunner.h"
#include "scene/ClusterScene.h"

class QAction;
class QActionGroup;
class QDockWidget;
class QLabel;
class QMenu;
class QProgressBar;
class QPushButton;
class QTextBrowser;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkCallbackCommand;
class vtkCellPicker;
class vtkChartXY;
class vtkContextView;
class vtkGenericOpenGLRenderWindow;
class vtkHandleWidget;
class vtkObject;
class vtkPointHandleRepresentation3D;
class vtkRenderer;

namespace conescope {

class EyePanel;
class SettingsPanel;
class StatisticsPanel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // --- Test interface -------------------------------------------------------------------------
    // Loads (off the UI thread) and waits until the mesh and everything after it are shown. False
    // when the file could not be read or clustered: the previous mesh stays, errorShown() fired.
    bool openMeshBlocking(const QString& path);
    // Starts loading and returns; the status bar shows progress.
    void openMesh(const QString& path);
    // Waits until no background task is queued or running.
    void waitUntilIdle();

    Settings settings() const { return settings_; }
    // Shows the settings in the panel and recomputes what they change (waitUntilIdle to see it).
    void setSettings(const Settings& settings);
    // The cull eye's position (for an orthographic eye: the point it looks from, towards the centre).
    void setEyePosition(const glm::dvec3& position);
    glm::dvec3 eyePosition() const { return eyePosition_; }
    // The eye the next loaded mesh starts with (command line --eye) instead of startingEyePosition.
    void setInitialEye(const glm::dvec3& position);
    // The measurement of the current eye, or null before a mesh is shown / for an invalid eye.
    const EyeMeasurement* currentStatistics() const { return measurement_ ? &*measurement_ : nullptr; }
    const std::vector<ViewStatistics>& orbitStatistics() const { return orbitRows_; }
    const PreparedMesh* preparedMesh() const { return prepared_.get(); }
    const ClusterSet* clusters() const { return clusters_.get(); }
    const ClusterScene* scene() const { return scene_.get(); }

    // Picks what is under a point of the observer view (widget coordinates), like a click without
    // drag; returns the cluster (also now highlighted and shown in the panel) or -1.
    int pickAt(const QPoint& viewPosition);
    void pickCluster(int cluster);
    int pickedCluster() const { return picked_; }
    QString clusterReportHtml() const;
    // Where a world point appears in the observer view (widget coordinates).
    QPoint viewPositionOf(const glm::dvec3& world) const;
    void resetCamera();

    // Blocking exports; false (and errorShown) on failure.
    bool exportStatistics(const QString& path, StatisticsFormat format, bool orbit);
    bool exportPartition(const QString& path);
    bool saveScreenshot(const QString& path);

    // Errors always emit errorShown(); with dialogs off no QMessageBox is opened (tests).
    void setErrorDialogsEnabled(bool enabled) { errorDialogs_ = enabled; }
    QString lastError() const { return lastError_; }

    void setLayerVisible(Layer layer, bool visible);
    bool layerVisible(Layer layer) const;
    void setFaceColoring(FaceColoring coloring);

    QVTKOpenGLNativeWidget* observerView() const { return view_; }
    QVTKOpenGLNativeWidget* eyeView() const { return eyeView_; }
    SettingsPanel* settingsPanel() const { return settingsPanel_; }
    EyePanel* eyePanel() const { return eyePanel_; }
    StatisticsPanel* statisticsPanel() const { return statisticsPanel_; }
    // Every action with a shortcut, in menu order (what the help dialog lists).
    QList<QAction*> shortcutActions() const { return shortcutActions_; }
    QAction* animateAction() const { return animateAction_; }
    QAction* followAction() const { return followAction_; }
    QStringList recentFiles() const;

signals:
    void errorShown(const QString& message);
    void meshShown(const QString& path);
    void eyeMeasured();

protected:
    void dragEnterEvent(QDragEnterEvent* event) override;
    void dropEvent(QDropEvent* event) override;
    void closeEvent(QCloseEvent* event) override;
    void showEvent(QShowEvent* event) override;

private:
    struct SceneResult;

    // Construction, one part each.
    void createViews();
    void createDocks();
    void createActions();
    void createStatusBar();
    void createEyeHandle();
    void sizeDocks();
    QAction* addAction(QMenu* menu, const QString& text, const QKeySequence& shortcut, const QString& tip = {});

    // Background stages and what they deliver.
    void requestClusters(bool reprepare);
    void requestOrbit();
    void showSceneResult(SceneResult& result, bool newMesh);

    // Reactions.
    void applySettings(const Settings& settings);
    void updateEye();
    void scheduleEyeUpdate();
    void showEyeInScene();
    void updateClusterPanel();
    void updateEfficiencyPlot();
    void updateHistogram();
    void updateStatusText();
    void render();
    void showError(const QString& title, const QString& message);
    void addRecentFile(const QString& path);
    void rebuildRecentMenu();
    void showHelp();
    void lookFromHere();
    void setFollowing(bool follow);
    void setAnimating(bool animate);
    void stepOrbit(int step);
    void moveEye(const glm::dvec3& position, long orbitStep);
    void cycleTest();
    void cycleCone();
    void cycleBuilder();

    // Actions of the File menu that ask for a path.
    void openWithDialog();
    void exportStatisticsWithDialog(bool orbit);
    void startStatisticsExport(const QString& path, StatisticsFormat format, bool orbit,
                               const std::function<void(bool)>& finished);
    void exportPartitionWithDialog();
    void screenshotWithDialog();

    // VTK observers.
    void onLeftButtonPress();
    void onLeftButtonRelease();
    void onCameraModified(vtkObject* caller, unsigned long event, void* data);
    void onHandleMoved(vtkObject* caller, unsigned long event, void* data);
    int pickDisplay(int x, int y);

    // Views.
    QVTKOpenGLNativeWidget* view_ = nullptr;
    vtkSmartPointer<vtkGenericOpenGLRenderWindow> renderWindow_;
    vtkSmartPointer<vtkRenderer> renderer_;
    QVTKOpenGLNativeWidget* eyeView_ = nullptr;
    vtkSmartPointer<vtkRenderer> eyeRenderer_;
    vtkSmartPointer<vtkActor> eyeViewActor_;
    QVTKOpenGLNativeWidget* efficiencyView_ = nullptr;
    vtkSmartPointer<vtkContextView> efficiencyContext_;
    vtkSmartPointer<vtkChartXY> efficiencyChart_;
    QVTKOpenGLNativeWidget* histogramView_ = nullptr;
    vtkSmartPointer<vtkContextView> histogramContext_;
    vtkSmartPointer<vtkChartXY> histogramChart_;
    vtkSmartPointer<vtkHandleWidget> eyeHandle_;
    vtkSmartPointer<vtkPointHandleRepresentation3D> eyeHandleRepresentation_;
    vtkSmartPointer<vtkCellPicker> picker_;
    vtkSmartPointer<vtkCallbackCommand> clickObserver_;
    unsigned long cameraObserver_ = 0;
    int pressPosition_[2] = {0, 0};

    // Panels and bars.
    SettingsPanel* settingsPanel_ = nullptr;
    EyePanel* eyePanel_ = nullptr;
    StatisticsPanel* statisticsPanel_ = nullptr;
    QTextBrowser* clusterBrowser_ = nullptr;
    QDockWidget* eyeViewDock_ = nullptr;
    QDockWidget* plotsDock_ = nullptr;
    std::array<QDockWidget*, 4> sideDocks_{};  // settings, eye, statistics, picked cluster
    bool docksSized_ = false;
    QLabel* statusText_ = nullptr;
    QProgressBar* progressBar_ = nullptr;
    QPushButton* cancelButton_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QList<QAction*> shortcutActions_;
    std::map<Layer, QAction*> layerActions_;
    std::map<FaceColoring, QAction*> coloringActions_;
    QAction* animateAction_ = nullptr;
    QAction* followAction_ = nullptr;

    // State.
    TaskRunner runner_;
    Settings settings_;
    std::shared_ptr<const PreparedMesh> prepared_;
    std::shared_ptr<const ClusterSet> clusters_;
    std::unique_ptr<ClusterScene> scene_;
    std::optional<EyeMeasurement> measurement_;
    double eyeSeconds_ = 0.0;
    std::vector<ViewStatistics> orbitRows_;
    glm::dvec3 eyePosition_{0.0, 0.0, 3.0};
    bool eyeGiven_ = false;  // the next mesh keeps eyePosition_ instead of the starting position
    int picked_ = -1;
    FaceColoring coloring_ = FaceColoring::CullDecision;
    bool errorDialogs_ = true;
    QString lastError_;
    bool following_ = false;
    QTimer animationTimer_;
    long orbitStep_ = -1;
    bool eyeUpdateScheduled_ = false;
};

}  // namespace conescope
