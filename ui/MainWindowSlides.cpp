// The window's slides (Slides.h): each lesson step, each of eight orbit views, rendered off screen at
// the slide's sizes (the 3D view as the step stages it, the cross-sections) and written as PNGs and one
// PDF.
#include <algorithm>
#include <cmath>

#include <QApplication>
#include <QDir>
#include <QStatusBar>

#include <vtkImageData.h>

#include "MainWindow.h"
#include "ObserverView.h"
#include "Slides.h"
#include "core/CrossSection.h"
#include "core/Pipeline.h"
#include "scene/CrossSectionScene.h"
#include "scene/SceneRendering.h"

namespace conescope {

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
        figure.show(crossSectionOf(sections[i], cullingInput(*session_.preparedMesh(), *session_.clusters())));
        const QSize size = slide.layout.figures[i].size();
        // Its labels as large as the slide's legend, read from the back of the room.
        slide.figures.push_back(imageOf(renderCrossSectionToImage(figure, size.width(), size.height(), 108)));
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

}  // namespace conescope
