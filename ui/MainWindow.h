// The ConeScope window: the observer view with the cluster scene and the cull eye's handle,
// dockable panels (settings, eye, statistics, picked cluster, plots, the eye's own view), menus,
// toolbar and status bar. It creates these and connects them to the Session, which holds the mesh,
// clusters and eye and runs the slow stages; every number comes from the pipeline (src/core calls)
// and every actor from src/scene.
//
// The public functions below the widget plumbing are the window's test interface: they do what the
// matching menu action does, but report the outcome instead of opening dialogs.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include <QMainWindow>
#include <QPoint>

#include "EyeStepTimes.h"
#include "Exports.h"
#include "Session.h"
#include "Slides.h"
#include "core/ClusterRanking.h"
#include "scene/LessonLayer.h"

class QAction;
class QDockWidget;
class QTimer;
class QVTKOpenGLNativeWidget;

namespace conescope {

class CrossSectionView;
class EyePanel;
class EyeView;
class LessonView;
class GranularityPanel;
class LodPanel;
class StepLessonView;
class ObserverView;
class PickedClusterView;
class GaussMapView;
class WorstClustersView;
class PlotsView;
class SettingsPanel;
class StatisticsPanel;
class StatusLine;
class WindowActions;

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

    Settings settings() const { return session_.settings(); }
    // Shows the settings in the panel and recomputes what they change (waitUntilIdle to see it).
    void setSettings(const Settings& settings);
    // The cull eye's position (for an orthographic eye: the point it looks from, towards the centre).
    void setEyePosition(const glm::dvec3& position);
    glm::dvec3 eyePosition() const { return session_.eyePosition(); }
    // The eye the next loaded mesh starts with (command line --eye) instead of startingEyePosition.
    void setInitialEye(const glm::dvec3& position);
    // The measurement of the current eye, or null before a mesh is shown / for an invalid eye.
    const EyeMeasurement* currentStatistics() const { return session_.measurement(); }
    const std::vector<ViewStatistics>& orbitStatistics() const { return session_.orbitRows(); }
    const PreparedMesh* preparedMesh() const { return session_.preparedMesh(); }
    const ClusterSet* clusters() const { return session_.clusters(); }
    const ClusterScene* scene() const { return session_.scene(); }

    // Picks what is under a point of the observer view (widget coordinates), like a click without
    // drag; returns the cluster (also now highlighted and shown in the panel) or -1.
    int pickAt(const QPoint& viewPosition);
    void pickCluster(int cluster);
    int pickedCluster() const { return session_.pickedCluster(); }
    QString clusterReportHtml() const;
    // Where a world point appears in the observer view (widget coordinates).
    QPoint viewPositionOf(const glm::dvec3& world) const;
    void resetCamera();

    // Blocking exports; false (and errorShown) on failure. saveScreenshot: the 3D view;
    // saveWindowScreenshot: the whole window, docks and status bar included.
    bool exportStatistics(const QString& path, StatisticsFormat format, bool orbit);
    bool exportPartition(const QString& path);
    bool saveScreenshot(const QString& path);
    bool saveWindowScreenshot(const QString& path);
    // A line of text over the 3D view (a replay's caption); empty removes it.
    void showCaption(const QString& text);
    // The lesson's figure (writeCrossSectionPng) and its words (Session::exportExplanation); false and
    // errorShown when there is no picked cluster or the file cannot be written.
    bool saveCrossSection(const QString& path);
    bool exportExplanation(const QString& path);
    // The lesson's steps as 16:9 slides in `folder` (slide-01.png ..., 1920x1080, and all of them in
    // slides.pdf; Slides.h): each step's title and words, the 3D view as the step stages it and the
    // cross-section (side by side: both clusters'); the step shown before comes back. False and
    // errorShown on failure.
    bool exportLessonSlides(const QString& folder);
    // Up to eight orbit views, evenly spaced, as slides the same way: the mesh and the eye there, its
    // statistics in words (viewInWords); the eye comes back. False and errorShown on failure.
    bool exportOrbitSlides(const QString& folder);
    // Plays a replay file (a ready-made lesson of File > Examples) in this window; false when it cannot be read.
    bool playReplayFile(const QString& path);

    // Errors always emit errorShown(); with dialogs off no QMessageBox is opened (tests).
    void setErrorDialogsEnabled(bool enabled) { errorDialogs_ = enabled; }
    QString lastError() const { return lastError_; }

    void setLayerVisible(Layer layer, bool visible);
    bool layerVisible(Layer layer) const;
    void setFaceColoring(FaceColoring coloring);

    QVTKOpenGLNativeWidget* observerView() const;
    QVTKOpenGLNativeWidget* eyeView() const;
    SettingsPanel* settingsPanel() const { return settingsPanel_; }
    EyePanel* eyePanel() const { return eyePanel_; }
    StatisticsPanel* statisticsPanel() const { return statisticsPanel_; }
    LodPanel* lodPanel() const { return lodPanel_; }
    StepLessonView* lodLessonView() const { return lodLessonView_; }
    GranularityPanel* granularityPanel() const { return granularityPanel_; }
    StepLessonView* granularityLessonView() const { return granularityLessonView_; }
    // Every action with a shortcut, in menu order (what the help dialog lists).
    QList<QAction*> shortcutActions() const;
    QAction* animateAction() const;
    QAction* followAction() const;
    QStringList recentFiles() const;
    const Session& session() const { return session_; }
    // The actions a click and a replayed step share.
    Session& session() { return session_; }

    // --- What the menus and the eye panel ask for ---------------------------------------------------
    // Puts the cull eye at the observer's camera.
    void lookFromHere();
    void setFollowing(bool follow);
    void setAnimating(bool animate);
    // Renders every view that is on screen.
    void render();
    // A/B: pins the current settings as A and colours the faces by the comparison; clearing goes back
    // to the decision colours.
    void pinAsA();
    void clearPin();
    // What a row of the worst-cluster table does: picks the cluster, frames it and moves the eye to
    // the first orbit view that loses its back faces.
    void chooseCluster(int cluster);
    // chooseCluster for the orbit's worst cluster by `key` (the first row of `conescope-cli clusters
    // --sort KEY`); -1 (nothing chosen) before the orbit is measured.
    int chooseWorstCluster(ClusterSortKey key);
    // A cluster that shows `outcome` (core findExample: culled, drawn, lost to the test or to the
    // partition), picked and framed, the eye at the orbit view that shows it so. -1 (and a notice) when
    // no cluster does or before the orbit is measured.
    int chooseExample(LessonOutcome outcome);
    // Sweeps the eye across the picked cluster's cull boundary (core sweepAcrossCull) in `frames`
    // steps, the lesson at step 5 (its inequality) unless it shows 5 to 7, calling `eachFrame(k)` once
    // each eye is measured and drawn; the eye stays at the last frame. False and errorShown when there
    // is no picked cluster or it has no boundary.
    bool sweepEye(size_t frames, const std::function<void(size_t)>& eachFrame = {});
    // The sweep button: sweepEye animated, one frame every `milliseconds`, or stops one that runs.
    void toggleEyeSweep(size_t frames = 36, int milliseconds = 110);
    bool eyeSweepRunning() const;
    // The lesson's step as a slide (Slides.h), rendered off screen at the slide's sizes; the step must
    // be shown. Throws std::runtime_error without a lesson.
    Slide lessonSlide(int step);
    // Writes the slides as slide-01.png ... and slides.pdf in `folder`; false and errorShown on failure.
    bool writeSlides(const std::vector<Slide>& slides, const QString& folder, const QString& title);
    // The observer looks at the mesh from behind, the side turned away from the cull eye: where its
    // culled clusters are (and where A and B differ).
    void viewFromBehind();
    // --- The lesson -----------------------------------------------------------------------------------
    // Step 1 to kLessonStepCount: shows the layers the step talks about, frames them and raises the
    // lesson dock (the layers and colours before the lesson are kept); 0 ends the lesson and puts them
    // back. Starting without a picked cluster chooses the one the test loses most, once the orbit is
    // measured. False for a step outside 0..kLessonStepCount.
    bool showLessonStep(int step);
    // L: starts the lesson at step 1, or ends it.
    void toggleLesson();
    LessonView* lessonView() const { return lessonView_; }
    CrossSectionView* crossSectionView() const { return crossSection_; }
    WorstClustersView* worstClustersView() const { return worstClusters_; }
    GaussMapView* gaussMapView() const { return gaussMap_; }
    PlotsView* plotsView() const { return plots_; }
    bool progressShown() const;
    // The last eye step's times and their readout in the status bar (View > Show frame times).
    const EyeStepTimes& eyeStepTimes() const { return eyeStepTimes_; }
    void setFrameTimesShown(bool shown);
    QString frameTimesText() const;

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
    void createDocks();
    void sizeDocks();
    void connectSession();
    void connectControls();

    // What the views show when the session has something new.
    void showScene(const ClusterScene* previous, bool newMesh);
    void showEyeMeasurement();
    // The LOD scene in the observer view (or the partition's back), the LOD dock, statistics and pick.
    void showLod(const ClusterScene* previousScene);
    // The granularity report (or none) in its dock, the plots and its lesson.
    void showGranularity();
    void showOrbit();
    void showMultiCones();  // the K-cone record's rows of the statistics panel
    void showMesh(const QString& path, const QString& loadMessage);
    void showError(const QString& title, const QString& message);
    int pickDisplay(const QPoint& display);
    // The layers, colouring, framing, docks and caption of a lesson step (MainWindowLesson.cpp).
    void stageLessonStep(int step);
    // chooseCluster's framing: the picked cluster from where its normals point.
    void framePickedCluster();
    // The 3D scene rendered off screen at `size` from `camera` (or the default observer camera framing
    // the mesh and the eye), its legend fitted to that size.
    QImage renderedView(const QSize& size, const std::optional<CameraPlacement>& camera);

    Session session_;
    ObserverView* view_ = nullptr;
    EyeView* eyeView_ = nullptr;
    PlotsView* plots_ = nullptr;
    PickedClusterView* clusterView_ = nullptr;
    GaussMapView* gaussMap_ = nullptr;
    QDockWidget* gaussMapDock_ = nullptr;
    WorstClustersView* worstClusters_ = nullptr;
    SettingsPanel* settingsPanel_ = nullptr;
    EyePanel* eyePanel_ = nullptr;
    StatisticsPanel* statisticsPanel_ = nullptr;
    QDockWidget* eyeViewDock_ = nullptr;
    QDockWidget* plotsDock_ = nullptr;
    LessonView* lessonView_ = nullptr;
    QDockWidget* lessonDock_ = nullptr;
    CrossSectionView* crossSection_ = nullptr;
    LodPanel* lodPanel_ = nullptr;
    StepLessonView* lodLessonView_ = nullptr;
    GranularityPanel* granularityPanel_ = nullptr;
    StepLessonView* granularityLessonView_ = nullptr;
    QDockWidget* lodDock_ = nullptr;
    QDockWidget* crossSectionDock_ = nullptr;
    // What the window showed before the lesson, put back when it ends.
    std::optional<std::map<Layer, bool>> layersBeforeLesson_;
    FaceColoring coloringBeforeLesson_ = FaceColoring::CullDecision;
    QByteArray docksBeforeLesson_;  // saveState(): which docks were shown, where, how large
    std::array<QDockWidget*, 4> sideDocks_{};  // settings, eye, statistics, picked cluster
    bool docksSized_ = false;
    StatusLine* statusLine_ = nullptr;
    WindowActions* actions_ = nullptr;
    bool errorDialogs_ = true;
    QString lastError_;
    EyeStepTimes eyeStepTimes_;
    QTimer* sweepTimer_ = nullptr;
    std::vector<glm::dvec3> sweepFrames_;  // the animated sweep's eyes still to come
    int sweptCluster_ = -1;                // what they sweep across
    const ClusterScene* sweptScene_ = nullptr;
};

}  // namespace conescope
