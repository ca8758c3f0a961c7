// Teaching with the window: examples of each outcome in one click, the eye swept across the
// cull boundary with the words following it, slides a class can project (1920x1080 PNGs and a 16:9
// PDF), a lesson that fits a 1280x720 projector with Next and Back standing still, a first view that
// shows culled clusters, and words for every choice and every statistics row; the user docs' keys are
// the app's.
#include <QAbstractButton>
#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QFile>
#include <QFormLayout>
#include <QLabel>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSurfaceFormat>
#include <QTextBrowser>
#include <QToolButton>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>

#include "CrossSectionView.h"
#include "Glossary.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "ObserverView.h"
#include "SettingsPanel.h"
#include "Slides.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/CrossSection.h"
#include "core/EyeSweep.h"
#include "core/LessonExamples.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

Lesson coreLesson(MainWindow& window) {
    return makeLesson(*window.preparedMesh(), *window.clusters(), uint32_t(window.pickedCluster()), window.currentStatistics()->eye,
                      displayedTest(window.settings()));
}

ObserverView* observer(MainWindow& window) { return dynamic_cast<ObserverView*>(window.observerView()); }

// Share of the observer view's sampled points (a 48 x 32 grid) on a culled cluster, among those on any
// cluster: how much of what the view shows the test culls.
double culledShareInView(MainWindow& window) {
    ObserverView* view = observer(window);
    const std::vector<uint8_t>& culled = window.currentStatistics()->culled;
    size_t onCluster = 0, onCulled = 0;
    for (int i = 0; i < 48; ++i)
        for (int j = 0; j < 32; ++j) {
            const QPoint at(view->width() * (2 * i + 1) / 96, view->height() * (2 * j + 1) / 64);
            const int cluster = view->clusterAt(*window.scene(), view->displayPointOf(at));
            if (cluster < 0) continue;
            ++onCluster;
            onCulled += culled[size_t(cluster)];
        }
    return onCluster > 0 ? double(onCulled) / double(onCluster) : 0.0;
}

// The PDF's page count and page sizes (points), as its page tree says.
std::pair<int, QStringList> pdfPages(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {-1, {}};
    // The whole file: its title is UTF-16, NUL bytes and all.
    const QByteArray bytes = file.readAll();
    const QString text = QString::fromLatin1(bytes.constData(), bytes.size());
    const QRegularExpressionMatch count = QRegularExpression(QStringLiteral("/Count (\\d+)")).match(text);
    QStringList boxes;
    auto found = QRegularExpression(QStringLiteral("/MediaBox \\[([^\\]]*)\\]")).globalMatch(text);
    while (found.hasNext()) boxes << found.next().captured(1).simplified();
    return {count.hasMatch() ? count.captured(1).toInt() : -1, boxes};
}

// Pixels darker than `below` (grey level) inside `rect` of `image`.
int darkPixels(const QImage& image, const QRect& rect, int below = 100) {
    int dark = 0;
    for (int y = rect.top(); y <= rect.bottom(); ++y)
        for (int x = rect.left(); x <= rect.right(); ++x) dark += qGray(image.pixel(x, y)) < below;
    return dark;
}

QAction* actionNamed(QWidget* window, const QString& text) {
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == text) return action;
    return nullptr;
}

}  // namespace

class TeachingWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

    void showTest(CullTest test) {
        Settings settings = window_->settings();
        settings.tests = {test};
        window_->setSettings(settings);
        window_->waitUntilIdle();
    }
    void openTorusWithTheApexTest() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        showTest(CullTest::Apex);
    }
    // The torus's default settings pinned as A, `b` the test of B.
    void openTorusWithAPinned(CullTest b) {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->pinAsA();
        window_->waitUntilIdle();  // A is pinned once its comparison over the orbit is measured
        showTest(b);
    }

private slots:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { window_.reset(); }

    // One click shows a cluster of each outcome, from the orbit view core findExample names, and starts
    // the lesson on it; its verdict is that outcome.
    void eachExampleButtonShowsItsOutcome() {
        openTorusWithTheApexTest();
        window_->showLessonStep(0);
        for (LessonOutcome outcome : exampleOutcomes()) {
            QToolButton* button = window_->lessonView()->exampleButton(outcome);
            QVERIFY(button && button->isEnabled());
            QVERIFY(!button->toolTip().isEmpty() && !button->whatsThis().isEmpty());
            QTest::mouseClick(button, Qt::LeftButton);
            window_->waitUntilIdle();
            const ClusterExample expected = findExample(*window_->preparedMesh(), *window_->clusters(), window_->settings(),
                                                        *window_->session().orbitStatistics(), outcome);
            QCOMPARE(window_->pickedCluster(), int(expected.cluster));
            QCOMPARE(window_->session().orbitStep(), expected.view);
            QVERIFY(window_->session().lessonStep() >= 1);
            QCOMPARE(int(window_->session().lesson()->outcome), int(outcome));
            QCOMPARE(int(coreLesson(*window_).outcome), int(outcome));
            saveWindowPicture(QStringLiteral("example-%1.png").arg(QString::fromStdString(exampleName(outcome))));
        }
        window_->showLessonStep(0);
    }

    // The eye swept across the boundary: at every frame the words are the core's lesson from that eye,
    // and the inequality turns from holding to failing (or back) once, as the apex test's does.
    void theSweepFlipsTheInequalityOnce() {
        openTorusWithTheApexTest();
        QVERIFY(window_->chooseExample(LessonOutcome::Culled) >= 0);
        const EyeSweep expected = sweepAcrossCull(*window_->preparedMesh(), *window_->clusters(), window_->settings(),
                                                  uint32_t(window_->pickedCluster()), window_->eyePosition(), 10);
        QStringList words, figures;
        std::vector<bool> holds;
        QVERIFY(window_->sweepEye(10, [&](size_t k) {
            QCOMPARE(window_->eyePosition(), expected.positions[k]);
            words << window_->lessonView()->text();
            figures << window_->crossSectionView()->caption();
            QCOMPARE(words.back(), QString::fromStdString(coreLesson(*window_).steps[4].text));
            holds.push_back(words.back().contains(QStringLiteral("so the test holds")));
            QCOMPARE(holds.back(), expected.culled[k] != 0);
        }));
        QCOMPARE(window_->session().lessonStep(), 5);
        QCOMPARE(words.size(), 10);
        size_t flips = 0;
        for (size_t k = 1; k < holds.size(); ++k) flips += holds[k] != holds[k - 1];
        QCOMPARE(flips, size_t(1));
        QVERIFY(words.front() != words.back());
        QVERIFY(figures.front() != figures.back());
        // The button animates it, and stops at the sweep's last eye.
        QAbstractButton* sweep = window_->lessonView()->sweepButton();
        QVERIFY(sweep->isEnabled());
        const EyeSweep back = sweepAcrossCull(*window_->preparedMesh(), *window_->clusters(), window_->settings(),
                                              uint32_t(window_->pickedCluster()), window_->eyePosition(), 36);
        QTest::mouseClick(sweep, Qt::LeftButton);
        QVERIFY(window_->eyeSweepRunning());
        QCOMPARE(sweep->text(), QStringLiteral("Stop"));
        QTRY_VERIFY_WITH_TIMEOUT(!window_->eyeSweepRunning(), 30000);
        QCOMPARE(window_->eyePosition(), back.positions.back());
        QCOMPARE(sweep->text(), QStringLiteral("Sweep eye"));
        window_->showLessonStep(0);
    }

    // A cluster without a cone has no boundary: the button is off and the sweep says why.
    void aClusterWithoutAConeCannotBeSwept() {
        QVERIFY(window_->openMeshBlocking(datasetPath("cube.off")));
        Settings one = window_->settings();
        one.builder = Builder::KMeans;
        one.clusterCount = 1;
        window_->setSettings(one);
        window_->waitUntilIdle();
        window_->pickCluster(0);
        QVERIFY(!window_->session().lesson()->why.cullable);
        QVERIFY(!window_->lessonView()->sweepButton()->isEnabled());
        QVERIFY(!window_->sweepEye(6));
        QVERIFY2(window_->lastError().contains(QStringLiteral("has no cone: its normals span more than a half-space")),
                 qPrintable(window_->lastError()));
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // Lesson > Export the lesson as slides: seven 1920x1080 PNGs and a PDF of seven 16:9 pages, each the
    // step's title, its words at a size read from the back (24 pixels or more), the 3D picture and the
    // cross-section (two side by side); the step shown before comes back.
    void theLessonExportsAsSlides() {
        openTorusWithTheApexTest();
        QVERIFY(window_->chooseExample(LessonOutcome::Culled) >= 0);
        QVERIFY(window_->showLessonStep(3));
        const Lesson lesson = coreLesson(*window_);
        QVERIFY(lesson.partner);
        const QString folder = temporary_.filePath(QStringLiteral("slides"));
        QVERIFY(window_->exportLessonSlides(folder));
        QCOMPARE(window_->session().lessonStep(), 3);
        QVERIFY(observer(*window_)->caption().startsWith(QStringLiteral("Lesson 3/%1").arg(kLessonStepCount)));
        QCOMPARE(QDir(folder).entryList({QStringLiteral("*.png")}, QDir::Files).size(), kLessonStepCount);
        std::vector<QImage> slides;
        for (int step = 1; step <= kLessonStepCount; ++step) {
            slides.emplace_back(QDir(folder).filePath(slideFileName(step)));
            const QImage& slide = slides.back();
            QCOMPARE(slide.size(), QSize(kSlideWidth, kSlideHeight));
            const SlideWords words{QStringLiteral("%1/%2  %3").arg(step).arg(kLessonStepCount).arg(QString::fromStdString(lesson.steps[size_t(step - 1)].title)),
                                   {}, QString::fromStdString(lesson.steps[size_t(step - 1)].text)};
            const SlideLayout layout = layoutSlide(words, step == kSideBySideStep ? 2 : 1);
            QVERIFY2(layout.textPixels >= kSlideTextSmallest, qPrintable(QString::number(layout.textPixels)));
            QVERIFY(layout.text.bottom() < kSlideHeight && layout.picture.height() >= 500);
            // Dark words in the title and the text; the 3D picture on its dark background; the figures white with ink.
            QVERIFY(darkPixels(slide, layout.title) > 2000);
            QVERIFY(darkPixels(slide, layout.text) > 5000);
            QVERIFY(darkPixels(slide, layout.picture, 60) > layout.picture.width() * layout.picture.height() / 3);
            for (const QRect& figure : layout.figures) {
                QVERIFY(darkPixels(slide, figure, 200) > 500);
                QVERIFY(darkPixels(slide, figure, 200) < figure.width() * figure.height() / 2);
            }
        }
        for (size_t a = 0; a < slides.size(); ++a)
            for (size_t b = a + 1; b < slides.size(); ++b) QVERIFY(slides[a] != slides[b]);
        const auto [pages, boxes] = pdfPages(QDir(folder).filePath(slidesPdfName()));
        QCOMPARE(pages, kLessonStepCount);
        QCOMPARE(boxes.size(), kLessonStepCount);
        for (const QString& box : boxes) QCOMPARE(box, QStringLiteral("0 0 960.000000 540.000000"));
        window_->showLessonStep(0);
        QVERIFY(!window_->exportLessonSlides(QStringLiteral("/proc/no/such/folder")));
    }

    // Lesson > Export the orbit as slides: eight views, each a 1920x1080 slide with its words, and the PDF;
    // the eye comes back.
    void theOrbitExportsAsSlides() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->setEyePosition({0.3, 2.5, 0.4});
        window_->waitUntilIdle();
        const QString folder = temporary_.filePath(QStringLiteral("orbit"));
        QVERIFY(window_->exportOrbitSlides(folder));
        QCOMPARE(window_->session().eyePosition(), glm::dvec3(0.3, 2.5, 0.4));
        QCOMPARE(QDir(folder).entryList({QStringLiteral("*.png")}, QDir::Files).size(), 8);
        const QImage first(QDir(folder).filePath(slideFileName(1))), last(QDir(folder).filePath(slideFileName(8)));
        QCOMPARE(first.size(), QSize(kSlideWidth, kSlideHeight));
        QCOMPARE(last.size(), QSize(kSlideWidth, kSlideHeight));
        QVERIFY(first != last);
        QCOMPARE(pdfPages(QDir(folder).filePath(slidesPdfName())).first, 8);
    }

    // At 1280x720 (a projector) every step's words fit their box without scrolling, Next and Back stand
    // still from step to step, and the legend takes at most a quarter of the view's height (and a bit).
    void nextAndBackStandStillAndNothingIsCutAt1280x720() {
        window_->resize(1280, 720);
        QApplication::processEvents();
        struct Case {
            const char* mesh;
            CullTest test;
            LessonOutcome example;
        };
        for (const Case& lessonCase : {Case{"torus.off", CullTest::Apex, LessonOutcome::LostToTest}, Case{"elephant.off", CullTest::Octagon, LessonOutcome::Culled},
                                       Case{"icosphere.off", CullTest::Aabb, LessonOutcome::LostToPartition}}) {
            QVERIFY(window_->openMeshBlocking(datasetPath(lessonCase.mesh)));
            showTest(lessonCase.test);
            QVERIFY(window_->chooseExample(lessonCase.example) >= 0);
            QPoint next, back;
            for (int step = 1; step <= kLessonStepCount; ++step) {
                QVERIFY(window_->showLessonStep(step));
                QApplication::processEvents();
                saveWindowPicture(QStringLiteral("lesson-720-%1-step%2.png").arg(QString::fromLatin1(lessonCase.mesh)).arg(step));
                LessonView* view = window_->lessonView();
                const QPoint nextAt = view->nextButton()->mapTo(window_.get(), QPoint(0, 0));
                const QPoint backAt = view->backButton()->mapTo(window_.get(), QPoint(0, 0));
                if (step == 1) {
                    next = nextAt;
                    back = backAt;
                }
                QCOMPARE(nextAt, next);
                QCOMPARE(backAt, back);
                auto* text = view->findChild<QTextBrowser*>(QStringLiteral("lessonText"));
                QVERIFY2(text->verticalScrollBar()->maximum() == 0,
                         qPrintable(QStringLiteral("%1 step %2: the words scroll").arg(QString::fromLatin1(lessonCase.mesh)).arg(step)));
                // Every button of the dock is inside the window.
                for (QAbstractButton* button : view->findChildren<QAbstractButton*>())
                    QVERIFY(window_->rect().contains(QRect(button->mapTo(window_.get(), QPoint(0, 0)), button->size())));
                const SceneLegend& legend = window_->scene()->legend();
                const double viewHeight = window_->observerView()->height() * window_->observerView()->devicePixelRatioF();
                QVERIFY2(legend.box()[3] - legend.box()[1] <= 0.27 * viewHeight,
                         qPrintable(QStringLiteral("legend %1 of %2").arg(legend.box()[3] - legend.box()[1]).arg(viewHeight)));
            }
            window_->showLessonStep(0);
        }
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
        window_->resize(1280, 960);
        QApplication::processEvents();
    }

    // The first view of a mesh shows culled clusters beside drawn ones (the torus's showed none while
    // its legend counted six); View from behind shows more of them: where A and B differ.
    void theFirstViewShowsCulledClusters() {
        for (const char* mesh : {"torus.off", "elephant.off", "fandisk.off", "icosphere.off"}) {
            QVERIFY(window_->openMeshBlocking(datasetPath(mesh)));
            QApplication::processEvents();
            saveWindowPicture(QStringLiteral("first-view-%1.png").arg(QString::fromLatin1(mesh)));
            // At least half the share the culled clusters have of the mesh's triangles, and drawn ones too.
            const ViewStatistics& seen = window_->currentStatistics()->view();
            const double culledTriangles = double(seen.trianglesCulled) / double(window_->preparedMesh()->triangles);
            const double first = culledShareInView(*window_);
            QVERIFY2(first >= 0.5 * culledTriangles && first > 0.03 && first < 0.9,
                     qPrintable(QStringLiteral("%1: %2 of the view, %3 of the triangles").arg(QString::fromLatin1(mesh)).arg(first).arg(culledTriangles)));
            QAction* behind = actionNamed(window_.get(), QStringLiteral("View from &behind (the culled side)"));
            QVERIFY(behind && !behind->shortcut().isEmpty());
            behind->trigger();
            QApplication::processEvents();
            QVERIFY2(culledShareInView(*window_) > first, qPrintable(QString::fromLatin1(mesh)));
        }
        // A pinned against B: from behind the faces show what either culls.
        openTorusWithAPinned(CullTest::Sphere);
        window_->resetCamera();
        const ViewStatistics& seen = window_->currentStatistics()->view();
        QVERIFY(seen.trianglesCulled > 0);
        // Culled clusters in view (the layout of A's rows moves the torus a little: no ratio here), and
        // more of them from behind.
        const double first = culledShareInView(*window_);
        QVERIFY2(first > 0.03, qPrintable(QStringLiteral("A/B: %1 of the view").arg(first)));
        window_->viewFromBehind();
        QApplication::processEvents();
        saveWindowPicture(QStringLiteral("first-view-ab.png"));
        QVERIFY(culledShareInView(*window_) > first);
        window_->clearPin();
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // A single-choice box says what its chosen item means, in its tooltip and What's This, and never
    // repeats the command line's help for a list ("comma separated").
    void singleChoiceBoxesSayWhatTheChosenItemMeans() {
        const QList<QComboBox*> boxes = window_->settingsPanel()->findChildren<QComboBox*>();
        QCOMPARE(boxes.size(), 7);  // with the cones-per-cluster choice
        for (QComboBox* box : boxes) {
            const QString meaning = box->currentData(Qt::ToolTipRole).toString();
            QVERIFY2(!meaning.isEmpty(), qPrintable(box->currentText()));
            QVERIFY2(box->toolTip().contains(box->currentText().toHtmlEscaped()) && box->toolTip().contains(meaning.toHtmlEscaped()),
                     qPrintable(box->toolTip()));
            QVERIFY(box->whatsThis().contains(QStringLiteral("Chosen: ") + box->currentText()));
            QVERIFY(!box->toolTip().contains(QStringLiteral("comma")) && !box->whatsThis().contains(QStringLiteral("comma")));
        }
        // Another choice, from the box or from the session: the words follow.
        showTest(CullTest::Sphere);
        QComboBox* test = nullptr;
        for (QComboBox* box : boxes)
            if (box->findText(QStringLiteral("octagon")) >= 0) test = box;
        QVERIFY(test);
        QCOMPARE(test->currentText(), QStringLiteral("sphere"));
        QVERIFY(test->toolTip().contains(explain(CullTest::Sphere).toHtmlEscaped()));
        chooseInCombo(test, "apex");
        QVERIFY(test->toolTip().contains(explain(CullTest::Apex).toHtmlEscaped()));
        window_->waitUntilIdle();
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // Every statistics row, its name and its value, says what it means; with A pinned every row shows
    // its whole text (A's cone and test first).
    void everyStatisticsRowSaysWhatItMeans() {
        openTorusWithAPinned(CullTest::Apex);
        QApplication::processEvents();
        StatisticsPanel* panel = window_->statisticsPanel();
        auto* form = panel->findChild<QFormLayout*>();
        QVERIFY(form);
        QVERIFY(panel->rows().size() >= 30);
        for (const QString& row : panel->rows()) {
            QVERIFY2(!panel->rowHelp(row).isEmpty(), qPrintable(row));
            auto* value = panel->findChild<QLabel*>(row);
            QVERIFY(value && !value->whatsThis().isEmpty());
            QWidget* name = form->labelForField(value);
            QVERIFY2(name && !name->toolTip().isEmpty() && !name->whatsThis().isEmpty(), qPrintable(row));
        }
        const QString cut = statisticsLayoutFault(*panel);
        QVERIFY2(cut.isEmpty(), qPrintable(cut));
        QVERIFY(panel->value(QStringLiteral("A (pinned)")).startsWith(QString::fromStdString(toString(kDefaultCone)) + QStringLiteral(" / octagon")));
        window_->clearPin();
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // The user docs name the keys the app has: each "(KEY)" after a control's words is that action's shortcut.
    void theDocumentedKeysAreTheApps() {
        QString docs;
        for (const char* page : {"/docs/user/window.md", "/docs/user/teaching.md"}) {
            QFile file(QStringLiteral(CONESCOPE_SOURCE_DIR) + QLatin1String(page));
            QVERIFY2(file.open(QIODevice::ReadOnly | QIODevice::Text), page);
            docs += QString::fromUtf8(file.readAll()) + QLatin1Char(' ');
        }
        docs = docs.simplified();
        const std::pair<const char*, const char*> keys[] = {
            {"snapped to the observer (", "Put the &eye at the camera (look from here)"},
            {"linked to it (", "&Follow the observer's camera"},
            {"perspective or orthographic (", "Toggle &orthographic eye"},
            {"View from behind (", "View from &behind (the culled side)"},
            {"the one the test loses most (", "Pick the cluster the test loses &most"},
        };
        for (const auto& [words, action] : keys) {
            const int at = docs.indexOf(QLatin1String(words));
            QVERIFY2(at >= 0, words);
            const int start = at + int(qstrlen(words));
            const QString key = docs.mid(start, docs.indexOf(QLatin1Char(')'), start) - start);
            QAction* found = actionNamed(window_.get(), QString::fromLatin1(action));
            QVERIFY2(found, action);
            QCOMPARE(key, found->shortcut().toString());
        }
    }
};

int main(int argc, char** argv) {
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    TeachingWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "TeachingWindowTests.moc"
