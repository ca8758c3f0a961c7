// The window's lesson: what each step shows (scene/LessonLayer.h says which layers, colours and
// camera), the docks it raises, and the layers and colours put back when it ends.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QStatusBar>
#include <QTimer>

#include <vtkImageData.h>

#include "CrossSectionView.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "ObserverView.h"
#include "ReplayPlayer.h"
#include "Slides.h"
#include "core/CrossSection.h"
#include "core/EyeSweep.h"
#include "core/LessonExamples.h"
#include "scene/CrossSectionScene.h"
#include "scene/SceneRendering.h"

namespace conescope {

bool MainWindow::showLessonStep(int step) {
    if (step < 0 || step > kLessonStepCount) return false;
    // A lesson needs a cluster: the one the test loses most, when none is picked.
    if (step > 0 && session_.pickedCluster() < 0) chooseWorstCluster(ClusterSortKey::TestLoss);
    return session_.setLessonStep(step);
}

void MainWindow::toggleLesson() { showLessonStep(session_.lessonStep() > 0 ? 0 : 1); }

void MainWindow::framePickedCluster() {
    if (session_.pickedCluster() < 0) return;
    // Seen from where its normals point (the cone's axis), the cluster shows its faces, not its back.
    const size_t picked = size_t(session_.pickedCluster());
    const ClusterBounds& bounds = session_.clusters()->bounds;
    const glm::dvec3 center(bounds.boxes[picked].center());
    view_->frameBox(bounds.boxes[picked], bounds.cones[picked].cullable ? center + bounds.cones[picked].axis : session_.eyePosition());
}

int MainWindow::chooseWorstCluster(ClusterSortKey key) {
    const CullTestStatistics* orbit = session_.orbitStatistics();
    if (!orbit) return -1;
    const std::vector<uint32_t> worst = rankClusters(*orbit, key, 1);
    if (worst.empty()) return -1;
    chooseCluster(int(worst.front()));
    return int(worst.front());
}

void MainWindow::stageLessonStep(int step) {
    if (step == 0) {
        if (layersBeforeLesson_) {
            for (const auto& [layer, shown] : *layersBeforeLesson_) setLayerVisible(layer, shown);
            session_.setFaceColoring(coloringBeforeLesson_);
            for (QDockWidget* dock : docksHiddenByLesson_) dock->show();
            if (columnBeforeLesson_ > 0) resizeDocks({lessonDock_}, {columnBeforeLesson_}, Qt::Horizontal);
            columnBeforeLesson_ = 0;
            if (!docksHiddenByLesson_.empty()) plotsDock_->raise();
            docksHiddenByLesson_.clear();
            layersBeforeLesson_.reset();
        }
        showCaption({});
        render();
        return;
    }
    if (!layersBeforeLesson_) {
        // The plots and the eye's view make room for the lesson's words and figures (a small screen has
        // none to spare); on a window narrower than a full-HD screen the settings and the eye panel too,
        // and the words get a wider column. All come back when it ends.
        const bool narrow = width() < 1600;
        for (QDockWidget* dock : findChildren<QDockWidget*>()) {
            const Qt::DockWidgetArea area = dockWidgetArea(dock);
            if (!dock->isHidden() && (area == Qt::BottomDockWidgetArea || (narrow && area == Qt::LeftDockWidgetArea))) {
                docksHiddenByLesson_.push_back(dock);
                dock->hide();
            }
        }
        if (narrow) {
            columnBeforeLesson_ = lessonDock_->width();
            resizeDocks({lessonDock_}, {std::max(400, width() * 2 / 5)}, Qt::Horizontal);
        }
        layersBeforeLesson_.emplace();
        for (Layer layer : allLayers()) (*layersBeforeLesson_)[layer] = layerVisible(layer);
        coloringBeforeLesson_ = session_.faceColoring();
    }
    for (const auto& [layer, shown] : lessonLayers(step)) setLayerVisible(layer, shown);
    session_.setFaceColoring(lessonColouring(step));
    lessonDock_->show();
    lessonDock_->raise();
    // Beside the words, the figure the step talks about: the cluster's numbers, its Gauss map, the
    // cross-section of the cone and the view vector.
    QDockWidget* figure = step == 2 || step == 3 ? gaussMapDock_ : step >= 5 ? crossSectionDock_ : sideDocks_[3];
    figure->show();
    figure->raise();
    // The right column shares its height between the words and the figure the same way at every step,
    // so the buttons under the words (Next, Back) never move.
    const int column = lessonDock_->height() + sideDocks_[3]->height();
    const int words = column * 14 / 25;
    if (lessonDock_->height() != words) resizeDocks({lessonDock_, sideDocks_[3]}, {words, column - words}, Qt::Vertical);
    if (const Lesson* lesson = session_.lesson()) {
        view_->placeCamera(lessonCamera(*lesson, step, view_->fittingViewAngle()));
        showCaption(tr("Lesson %1/%2: %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson->steps[size_t(step - 1)].title)));
    }
    render();
}

// --- Examples and the sweep ------------------------------------------------------------------------

int MainWindow::chooseExample(LessonOutcome outcome) {
    const CullTestStatistics* orbit = session_.orbitStatistics();
    if (!orbit || !session_.clusters()) return -1;
    const ClusterExample example = findExample(*session_.preparedMesh(), *session_.clusters(), session_.settings(), *orbit, outcome);
    if (example.cluster < 0) {
        statusBar()->showMessage(tr("No cluster is %1 from any orbit view with these settings")
                                     .arg(QString::fromStdString(toString(outcome))),
                                 8000);
        return -1;
    }
    session_.pickCluster(int(example.cluster));
    session_.moveEyeToOrbitView(example.view);
    // In a lesson the step frames it again; else the view turns to the cluster, as a row of the table does.
    if (session_.lessonStep() > 0) stageLessonStep(session_.lessonStep());
    else framePickedCluster();
    return int(example.cluster);
}

namespace {

// The sweep of the picked cluster from the eye, or the reason there is none.
EyeSweep sweepOf(const Session& session, size_t frames) {
    const Lesson* lesson = session.lesson();
    if (!lesson) throw std::runtime_error("Pick a cluster first: the eye sweeps across the picked cluster's cull boundary.");
    return sweepAcrossCull(*session.preparedMesh(), *session.clusters(), session.settings(), lesson->cluster, session.eyePosition(), frames);
}

}  // namespace

bool MainWindow::sweepEye(size_t frames, const std::function<void(size_t)>& eachFrame) {
    EyeSweep sweep;
    try {
        sweep = sweepOf(session_, frames);
    } catch (const std::exception& error) {
        showError(tr("Cannot sweep the eye"), QString::fromStdString(error.what()));
        return false;
    }
    // The step whose words hold the inequality, unless one that also follows the eye is shown.
    if (session_.lessonStep() < 5) showLessonStep(5);
    for (size_t k = 0; k < sweep.positions.size(); ++k) {
        session_.moveEye(sweep.positions[k], -1);
        QApplication::processEvents();
        if (eachFrame) eachFrame(k);
    }
    return true;
}

void MainWindow::toggleEyeSweep(size_t frames, int milliseconds) {
    if (!sweepTimer_) {
        sweepTimer_ = new QTimer(this);
        connect(sweepTimer_, &QTimer::timeout, this, [this]() {
            if (sweepFrames_.empty()) {
                sweepTimer_->stop();
                lessonView_->showSweeping(false);
                lessonView_->showLesson(session_);
                return;
            }
            const glm::dvec3 next = sweepFrames_.front();
            sweepFrames_.erase(sweepFrames_.begin());
            session_.moveEye(next, -1);
        });
    }
    if (sweepTimer_->isActive()) {
        sweepTimer_->stop();
        sweepFrames_.clear();
        lessonView_->showSweeping(false);
        lessonView_->showLesson(session_);
        return;
    }
    try {
        sweepFrames_ = sweepOf(session_, frames).positions;
    } catch (const std::exception& error) {
        showError(tr("Cannot sweep the eye"), QString::fromStdString(error.what()));
        return;
    }
    if (session_.lessonStep() < 5) showLessonStep(5);
    lessonView_->showSweeping(true);
    sweepTimer_->start(milliseconds);
}

bool MainWindow::eyeSweepRunning() const { return sweepTimer_ && sweepTimer_->isActive(); }

// --- Slides -----------------------------------------------------------------------------------------

QImage MainWindow::renderedView(const QSize& size, const std::optional<CameraPlacement>& camera) {
    RenderOptions options;
    options.width = size.width();
    options.height = size.height();
    if (camera) {
        options.cameraPosition = camera->position;
        options.focalPoint = camera->focalPoint;
        options.viewUp = camera->viewUp;
    } else {
        // The mesh and the eye, from where the window's first view looks.
        const Aabb box = session_.preparedMesh()->box;
        const glm::dvec3 eye = session_.eyePosition();
        const Aabb both = session_.settings().orthographic ? box : computeAabb({box.min, box.max, glm::vec3(eye)});
        const glm::dvec3 centre(both.center());
        options.focalPoint = centre;
        options.cameraPosition = centre + observerDirection(glm::dvec3(box.center()), eye, false) *
                                              (std::max(double(both.halfDiagonal()), 1e-9) / std::sin(glm::radians(options.viewAngleDegrees / 2.0)));
    }
    // Text half as large again as on a screen (the legend, the test's labels), read from the back of a
    // room; the legend sized for the picture, then for the view again.
    constexpr double slideTextRatio = 1.5;
    options.dpi = int(72.0 * slideTextRatio);
    session_.fitLegend(int(size.height() / slideTextRatio), slideTextRatio);
    const vtkSmartPointer<vtkImageData> image = renderToImage(*session_.scene(), options);
    session_.fitLegend(view_->height(), view_->devicePixelRatioF());
    return imageOf(image);
}

Slide MainWindow::lessonSlide(int step) {
    const Lesson* shown = session_.lesson();
    if (!shown || step < 1 || step > kLessonStepCount) throw std::runtime_error("no lesson step to make a slide of");
    const Lesson lesson = *shown;
    Slide slide;
    slide.words.title = tr("%1/%2  %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson.steps[size_t(step - 1)].title));
    slide.words.subtitle = tr("%1, cluster %2, %3, %4 cone")
                               .arg(QString::fromStdString(session_.preparedMesh()->name))
                               .arg(lesson.cluster)
                               .arg(QString::fromStdString(testInWords(lesson.test)), QString::fromStdString(toString(lesson.coneMethod)));
    slide.words.text = QString::fromStdString(lesson.steps[size_t(step - 1)].text);
    // Side by side, both clusters' figures: the culled one first, as the words tell them.
    std::vector<Lesson> sections{lesson};
    if (step == kSideBySideStep && lesson.partner) {
        Lesson partner = makeLesson(*session_.preparedMesh(), *session_.clusters(), lesson.partner->cluster, lesson.eye, lesson.test);
        if (partner.why.culled) sections.insert(sections.begin(), std::move(partner));
        else sections.push_back(std::move(partner));
    }
    slide.layout = layoutSlide(slide.words, int(sections.size()));
    RenderOptions angle;
    slide.picture = renderedView(slide.layout.picture.size(), lessonCamera(lesson, step, angle.viewAngleDegrees));
    for (size_t i = 0; i < sections.size(); ++i) {
        CrossSectionScene figure;
        figure.show(crossSectionOf(sections[i]));
        const QSize size = slide.layout.figures[i].size();
        slide.figures.push_back(imageOf(renderCrossSectionToImage(figure, size.width(), size.height())));
    }
    return slide;
}

bool MainWindow::writeSlides(const std::vector<Slide>& slides, const QString& folder, const QString& title) {
    if (!QDir().mkpath(folder)) {
        showError(title, tr("%1: cannot make the folder").arg(folder));
        return false;
    }
    for (size_t i = 0; i < slides.size(); ++i) {
        const QString path = QDir(folder).filePath(slideFileName(int(i + 1)));
        if (!slideImage(slides[i]).save(path, "PNG")) {
            showError(title, tr("%1: cannot write the PNG").arg(path));
            return false;
        }
    }
    try {
        writeSlidesPdf(slides, QDir(folder).filePath(slidesPdfName()));
    } catch (const std::exception& error) {
        showError(title, QString::fromStdString(error.what()));
        return false;
    }
    statusBar()->showMessage(tr("Wrote %1 slides and %2 to %3").arg(slides.size()).arg(slidesPdfName(), folder), 6000);
    return true;
}

bool MainWindow::exportLessonSlides(const QString& folder) {
    const QString title = tr("Cannot export the lesson slides");
    if (!QDir().mkpath(folder)) {
        showError(title, tr("%1: cannot make the folder").arg(folder));
        return false;
    }
    const int before = session_.lessonStep();
    std::vector<Slide> slides;
    QString failure;
    for (int step = 1; step <= kLessonStepCount && failure.isEmpty(); ++step) {
        if (!showLessonStep(step) || !session_.lesson()) {
            failure = tr("Pick a cluster first (or open a mesh): a lesson is about one cluster.");
            break;
        }
        QApplication::processEvents();
        try {
            slides.push_back(lessonSlide(step));
        } catch (const std::exception& error) {
            failure = QString::fromStdString(error.what());
        }
    }
    showLessonStep(before);
    stageLessonStep(session_.lessonStep());
    if (!failure.isEmpty()) {
        showError(title, failure);
        return false;
    }
    return writeSlides(slides, folder, title);
}

bool MainWindow::exportOrbitSlides(const QString& folder) {
    const QString title = tr("Cannot export the orbit slides");
    if (!session_.clusters() || !session_.preparedMesh()) {
        showError(title, tr("Open a mesh first."));
        return false;
    }
    if (!QDir().mkpath(folder)) {
        showError(title, tr("%1: cannot make the folder").arg(folder));
        return false;
    }
    const glm::dvec3 eyeBefore = session_.eyePosition();
    const long stepBefore = session_.orbitStep();
    const long views = long(session_.settings().views);
    const long count = std::min(views, 8L);
    std::vector<Slide> slides;
    QString failure;
    for (long i = 0; i < count; ++i) {
        const long view = i * views / count;
        session_.moveEyeToOrbitView(view);
        waitUntilIdle();
        const EyeMeasurement* measured = session_.measurement();
        if (!measured) {
            failure = session_.eyeError();
            break;
        }
        Slide slide;
        slide.words.title = tr("Orbit view %1 of %2").arg(view + 1).arg(views);
        slide.words.subtitle = tr("%1, %2 clusters, %3")
                                   .arg(QString::fromStdString(session_.preparedMesh()->name))
                                   .arg(session_.clusters()->bounds.count())
                                   .arg(QString::fromStdString(testInWords(measured->statistics.test)));
        slide.words.text = QString::fromStdString(viewInWords(measured->statistics, session_.clusters()->bounds.count()));
        slide.layout = layoutSlide(slide.words, 0);
        slide.picture = renderedView(slide.layout.picture.size(), std::nullopt);
        slides.push_back(std::move(slide));
    }
    session_.moveEye(eyeBefore, stepBefore);
    if (!failure.isEmpty()) {
        showError(title, failure);
        return false;
    }
    return writeSlides(slides, folder, title);
}

bool MainWindow::playReplayFile(const QString& path) {
    std::vector<ReplayStep> steps;
    try {
        steps = readReplayFile(path);
    } catch (const ReplayError& error) {
        showError(tr("Cannot play the lesson"), QString::fromStdString(error.what()));
        return false;
    }
    auto* player = new ReplayPlayer(*this, this);
    connect(player, &ReplayPlayer::finished, player, &QObject::deleteLater);
    connect(player, &ReplayPlayer::failed, this, [this, player](const QString& message) {
        showError(tr("Cannot play the lesson"), message);
        player->deleteLater();
    });
    player->play(std::move(steps));
    return true;
}

}  // namespace conescope
