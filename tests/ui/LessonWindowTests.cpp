// The lesson in the window (issue 33): L starts it on the cluster the test loses most, each step shows
// the layers it talks about and the core's words, the words follow the eye, the end puts the window
// back; and words everywhere: every control has a tooltip and What's This, every legend entry and
// glossary term an explanation.
#include <set>

#include <QAbstractButton>
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QSurfaceFormat>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>

#include "core/Choices.h"

#include "CrossSectionView.h"
#include "Datasets.h"
#include "EyeStepTimes.h"
#include "EyePanel.h"
#include "Glossary.h"
#include "LessonView.h"
#include "MainWindow.h"
#include "PlotsView.h"
#include "Multisampling.h"
#include "ObserverView.h"
#include "ReplayPlayer.h"
#include "Slides.h"
#include "SettingsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/ClusterRanking.h"
#include "core/CrossSection.h"
#include "io/LessonIO.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

// The lesson the core makes for what the window shows: the one the dock must show.
Lesson coreLesson(MainWindow& window) {
    const EyeMeasurement* measured = window.currentStatistics();
    return makeLesson(*window.preparedMesh(), *window.clusters(), uint32_t(window.pickedCluster()), measured->eye,
                      displayedTest(window.settings()));
}

// The window's action whose menu text is `text`; nullptr when there is none.
QAction* actionNamed(QWidget* window, const QString& text) {
    for (QAction* action : window->findChildren<QAction*>())
        if (action->text() == text) return action;
    return nullptr;
}

// Every input control below `widget` (the ones a user changes).
QList<QWidget*> controlsOf(QWidget* widget) {
    QList<QWidget*> controls;
    for (QWidget* child : widget->findChildren<QWidget*>())
        if (qobject_cast<QComboBox*>(child) || qobject_cast<QAbstractSpinBox*>(child) || qobject_cast<QAbstractButton*>(child) ||
            qobject_cast<QLineEdit*>(child))
            // Not the parts Qt builds into a control (a line edit's clear button, a spin box's editor).
            if (!child->objectName().startsWith(QLatin1String("qt_")) && child->parent() && !qobject_cast<QAbstractSpinBox*>(child->parent()) &&
                !qobject_cast<QComboBox*>(child->parent()) && !qobject_cast<QLineEdit*>(child->parent()))
                controls << child;
    return controls;
}

}  // namespace

class LessonWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

private slots:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { window_.reset(); }

    void lKeyStartsOnTheCostliestClusterAndEachStepShowsItsLayers() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        window_->setLayerVisible(Layer::Boxes, true);
        window_->observerView()->setFocus();
        QCOMPARE(window_->pickedCluster(), -1);
        QTest::keyClick(window_.get(), Qt::Key_L);
        window_->waitUntilIdle();
        const std::vector<uint32_t> worst = rankClusters(*window_->session().orbitStatistics(), ClusterSortKey::TestLoss, 1);
        QCOMPARE(window_->pickedCluster(), int(worst.front()));
        QCOMPARE(window_->session().lessonStep(), 1);
        for (int step = 1; step <= kLessonStepCount; ++step) {
            if (step > 1) QTest::keyClick(window_.get(), Qt::Key_PageDown);
            QCOMPARE(window_->session().lessonStep(), step);
            for (const auto& [layer, shown] : lessonLayers(step)) QCOMPARE(window_->layerVisible(layer), shown);
            QCOMPARE(int(window_->session().faceColoring()), int(lessonColouring(step)));
            const Lesson expected = coreLesson(*window_);
            QCOMPARE(window_->lessonView()->text(), QString::fromStdString(expected.steps[size_t(step - 1)].text));
            QVERIFY(window_->lessonView()->title().endsWith(QString::fromStdString(expected.steps[size_t(step - 1)].title)));
            QCOMPARE(window_->scene()->lessonDrawing().step, step);
            saveWindowPicture(QStringLiteral("lesson-step%1.png").arg(step));
        }
        QVERIFY(window_->crossSectionView()->isVisible());
        // The dock's figure as drawn: labels that each have a place of their own.
        const std::vector<CrossSectionLabel>& drawn = window_->crossSectionView()->drawnLabels();
        QVERIFY(drawn.size() >= 3);
        for (size_t a = 0; a < drawn.size(); ++a)
            for (size_t b = a + 1; b < drawn.size(); ++b) {
                const auto& p = drawn[a].box;
                const auto& q = drawn[b].box;
                QVERIFY2(!(p[0] < q[2] && q[0] < p[2] && p[1] < q[3] && q[1] < p[3]), (drawn[a].text + " / " + drawn[b].text).c_str());
            }
        QCOMPARE(window_->crossSectionView()->caption(), 
                 QString::fromStdString(crossSectionOf(coreLesson(*window_), cullingInput(*window_->preparedMesh(), *window_->clusters())).caption));
        QTest::keyClick(window_.get(), Qt::Key_PageDown);  // past the last step: stays
        QCOMPARE(window_->session().lessonStep(), kLessonStepCount);
        QTest::keyClick(window_.get(), Qt::Key_PageUp);
        QCOMPARE(window_->session().lessonStep(), kLessonStepCount - 1);
        // L again ends it: the layers and colours from before come back.
        QTest::keyClick(window_.get(), Qt::Key_L);
        QCOMPARE(window_->session().lessonStep(), 0);
        QVERIFY(window_->layerVisible(Layer::Boxes));
        QVERIFY(!window_->layerVisible(Layer::Lesson) || window_->scene()->lessonDrawing().step == 0);
        QCOMPARE(int(window_->session().faceColoring()), int(FaceColoring::CullDecision));
        QVERIFY(!window_->showLessonStep(kLessonStepCount + 1));
    }

    // A lesson step hides the bottom docks and the view grows: the frame drawn at the new size has the
    // legend fitted to it, not the small one the short view had (the last frame stays until the next draw).
    void theLegendIsFittedBeforeTheGrownViewIsDrawn() {
        window_->resize(1280, 720);  // the view short enough for the smallest legend
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QApplication::processEvents();
        const ClusterScene* scene = window_->scene();
        QVERIFY(window_->observerView()->height() <= 450);
        QCOMPARE(scene->legend().scale(), legendScaleFor(450));
        std::pair<const ClusterScene*, double> drawn{scene, 0.0};
        vtkNew<vtkCallbackCommand> record;
        record->SetClientData(&drawn);
        record->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
            auto* last = static_cast<std::pair<const ClusterScene*, double>*>(data);
            last->second = last->first->legend().scale();
        });
        vtkRenderWindow* renderWindow = window_->observerView()->renderWindow();
        const unsigned long tag = renderWindow->AddObserver(vtkCommand::StartEvent, record);
        window_->pickCluster(3);
        QVERIFY(window_->showLessonStep(1));
        QApplication::processEvents();
        renderWindow->RemoveObserver(tag);
        QCOMPARE(window_->scene(), scene);
        QVERIFY(window_->observerView()->height() > 600);
        QCOMPARE(scene->legend().scale(), 1.0);
        QCOMPARE(drawn.second, 1.0);
        window_->showLessonStep(0);
        window_->resize(1280, 960);
        QApplication::processEvents();
    }

    void theWordsFollowTheEye() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->pickCluster(3);
        QVERIFY(window_->showLessonStep(5));
        const QString before = window_->lessonView()->text();
        const QString figureBefore = window_->crossSectionView()->caption();
        window_->setEyePosition({0.3, 2.5, 0.4});
        window_->waitUntilIdle();
        QVERIFY(window_->lessonView()->text() != before);
        QVERIFY(window_->lessonView()->text().contains(QStringLiteral("e = (0.300, 2.500, 0.400)")));
        QCOMPARE(window_->lessonView()->text(), QString::fromStdString(coreLesson(*window_).steps[4].text));
        QVERIFY(window_->crossSectionView()->caption() != figureBefore);
        // Another test: the words are that test's.
        Settings sphere = window_->settings();
        sphere.tests = {CullTest::Sphere};
        window_->setSettings(sphere);
        window_->waitUntilIdle();
        QVERIFY(window_->lessonView()->text().contains(QStringLiteral("asin(r/d)")));
        QCOMPARE(window_->lessonView()->text(), QString::fromStdString(coreLesson(*window_).steps[4].text));
        window_->showLessonStep(0);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void theExplanationExportIsTheCoresLesson() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const QString path = temporary_.filePath(QStringLiteral("explanation.json"));
        QVERIFY(!window_->exportExplanation(path));  // nothing picked: refused, said why
        QVERIFY(window_->lastError().contains(QStringLiteral("Pick a cluster")));
        window_->pickCluster(7);
        QVERIFY(window_->exportExplanation(path));
        QCOMPARE(readJsonFile(path), lessonToJson(coreLesson(*window_)));
        const QString png = temporary_.filePath(QStringLiteral("cross-section.png"));
        QVERIFY(window_->saveCrossSection(png));
        QCOMPARE(QImage(png).size(), QSize(960, 720));
    }

    void everyControlHasATooltipAndWhatsThis() {
        QList<QWidget*> controls = controlsOf(window_->settingsPanel()) + controlsOf(window_->eyePanel()) +
                                   controlsOf(window_->lessonView());
        QVERIFY(controls.size() >= 20);
        for (QWidget* control : controls) {
            const QString name = control->metaObject()->className() + QStringLiteral(" ") + control->objectName() +
                                 QStringLiteral(" ") + control->property("text").toString();
            QVERIFY2(!control->toolTip().isEmpty(), qPrintable(name));
            QVERIFY2(!control->whatsThis().isEmpty(), qPrintable(name));
        }
        // Each choice of a combo box says what it is too.
        for (QComboBox* box : window_->settingsPanel()->findChildren<QComboBox*>())
            for (int i = 0; i < box->count(); ++i)
                if (box->count() > 3) QVERIFY2(!box->itemData(i, Qt::ToolTipRole).toString().isEmpty(), qPrintable(box->itemText(i)));
        // Every layer and colouring action explains itself.
        for (QAction* action : window_->findChildren<QAction*>())
            if (action->text().startsWith(QStringLiteral("Show ")) || action->text().startsWith(QStringLiteral("Colour by ")))
                QVERIFY2(!action->toolTip().isEmpty() && !action->whatsThis().isEmpty(), qPrintable(action->text()));
    }

    void everyLegendEntryAndGlossaryTermIsExplained() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->pickCluster(2);
        for (Layer layer : allLayers()) window_->setLayerVisible(layer, true);
        for (int step : {0, 3, 4}) {
            window_->showLessonStep(step);
            for (FaceColoring coloring : allFaceColorings()) {
                if (coloring == FaceColoring::Comparison) continue;
                window_->setFaceColoring(coloring);
                for (const LegendEntry& entry : window_->scene()->legend().entries())
                    QVERIFY2(!explainLegendLabel(entry.label).isEmpty(), entry.label.c_str());
            }
        }
        window_->showLessonStep(0);
        for (const char* term : {"cluster", "face normal", "normal cone", "alpha", "angle b", "apex", "bounding sphere",
                                 "bounding box", "cull fraction", "oracle fraction", "test loss", "partition loss", "efficiency"})
            QVERIFY2(!explain(QString::fromLatin1(term)).isEmpty(), term);
        for (CullTest test : allCullTests()) QVERIFY(!explain(test).isEmpty());
        // The glossary's tests and cones are exactly the descriptor tables' rows, in their order.
        QStringList tests, cones, expectedTests, expectedCones;
        for (const GlossaryEntry& entry : glossary()) {
            // The choices' entries (a term such as "test loss" shares the prefix, not the title).
            if (entry.term.startsWith(QStringLiteral("Test: "))) tests << entry.key.mid(5);
            if (entry.term.startsWith(QStringLiteral("Cone: "))) cones << entry.key.mid(5);
        }
        for (const CullTestDescriptor& row : cullTestDescriptors()) expectedTests << QString::fromUtf8(row.name);
        for (const ConeDescriptor& row : coneDescriptors()) expectedCones << QString::fromUtf8(row.name);
        QCOMPARE(tests, expectedTests);
        QCOMPARE(cones, expectedCones);
        QVERIFY(glossaryHtml().contains(QStringLiteral("Partition loss")));
        window_->setFaceColoring(FaceColoring::CullDecision);
    }

    // View > Show frame times: the readout is the last eye step's parts, the first of them the session's own time.
    void frameTimesReadoutSplitsAnEyeStep() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QVERIFY(window_->frameTimesText().isEmpty());
        QAction* show = actionNamed(window_.get(), QStringLiteral("Show &frame times"));
        QVERIFY(show);
        show->trigger();
        window_->setEyePosition({0.4, 2.8, 0.6});
        window_->waitUntilIdle();
        const EyeStepTimes& times = window_->eyeStepTimes();
        QCOMPARE(times.cullAndScene, window_->session().eyeSeconds());
        QVERIFY(times.cullAndScene > 0.0 && times.observerView > 0.0);
        QCOMPARE(window_->frameTimesText(), describe(times));
        QVERIFY(window_->frameTimesText().startsWith(QStringLiteral("Eye step ")));
        show->trigger();
        QVERIFY(window_->frameTimesText().isEmpty());
    }

    // A dragged eye redraws the views that show it, not the orbit's plots, and keeps the scene and
    // clusters it had: no pipeline runs again.
    void anEyeMoveRedrawsOnlyWhatItChanges() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->plotsView()->parentWidget()->show();
        QApplication::processEvents();
        int plotDraws = 0, viewDraws = 0;
        vtkNew<vtkCallbackCommand> countPlot, countView;
        countPlot->SetClientData(&plotDraws);
        countView->SetClientData(&viewDraws);
        for (vtkCallbackCommand* count : {countPlot.Get(), countView.Get()})
            count->SetCallback([](vtkObject*, unsigned long, void* counter, void*) { ++*static_cast<int*>(counter); });
        window_->plotsView()->efficiencyWidget()->renderWindow()->AddObserver(vtkCommand::EndEvent, countPlot);
        window_->observerView()->renderWindow()->AddObserver(vtkCommand::EndEvent, countView);
        const ClusterScene* scene = window_->scene();
        const ClusterSet* clusters = window_->clusters();
        for (double x : {2.5, -2.5}) {
            window_->session().moveEyeSoon({x, 0.3, 0.4});
            QApplication::processEvents();
        }
        window_->waitUntilIdle();
        QVERIFY(viewDraws >= 2);
        QCOMPARE(plotDraws, 0);
        QCOMPARE(window_->scene(), scene);
        QCOMPARE(window_->clusters(), clusters);
        QCOMPARE(window_->session().eyePosition(), glm::dvec3(-2.5, 0.3, 0.4));
        // The counter sees the plots drawn when the window draws everything.
        QVERIFY(window_->plotsView()->efficiencyWidget()->isVisible());
        window_->render();
        QVERIFY(plotDraws > 0);
        window_->plotsView()->efficiencyWidget()->renderWindow()->RemoveObserver(countPlot);
        window_->observerView()->renderWindow()->RemoveObserver(countView);
    }

    // Mesa's llvmpipe (what Xvfb gives the tests) pays for every sample: the views ask for none; the
    // variable overrides.
    void aSoftwareRendererGetsNoMultisampling() {
        QCOMPARE(viewMultisamples(), 0);
        qputenv("CONESCOPE_SAMPLES", "4");
        QCOMPARE(viewMultisamples(), 4);
        qunsetenv("CONESCOPE_SAMPLES");
    }

    // File > Examples: the four teaching meshes open, and every ready-made lesson plays to its first step
    // on the cluster its ranking names, with the core's words; among them a culled cluster for the box,
    // the sphere and the apex test each.
    void examplesOpenAndTheReadyMadeLessonsPlay() {
        for (const auto& [label, file] : exampleMeshes()) {
            QAction* open = actionNamed(window_.get(), label);
            QVERIFY2(open && open->isEnabled(), qPrintable(file));
            open->trigger();
            window_->waitUntilIdle();
            QCOMPARE(QString::fromStdString(window_->preparedMesh()->name), file);
        }
        const QStringList lessons = lessonFiles();
        QVERIFY(lessons.size() >= 7);
        std::set<CullTest> culledBy;  // the tests a ready-made lesson shows culling its cluster
        for (const QString& path : lessons) {
            QVERIFY2(actionNamed(window_.get(), QStringLiteral("Lesson: ") + QFileInfo(path).completeBaseName().replace('-', ' ')),
                     qPrintable(path));
            window_->showLessonStep(0);
            window_->pickCluster(-1);
            ReplayPlayer player(*window_);
            QCOMPARE(player.playBlocking(readReplayFile(path)), QString());
            QCOMPARE(window_->session().lessonStep(), 1);
            QVERIFY(window_->pickedCluster() >= 0);
            QCOMPARE(window_->lessonView()->text(), QString::fromStdString(coreLesson(*window_).steps[0].text));
            if (coreLesson(*window_).outcome == LessonOutcome::Culled) culledBy.insert(displayedTest(window_->settings()));
        }
        // A culled cluster for each of seed 000's tests: the box, the sphere and the apex.
        for (CullTest test : {CullTest::Aabb, CullTest::Sphere, CullTest::Apex})
            QVERIFY2(culledBy.count(test), toString(test).c_str());
        window_->showLessonStep(0);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    LessonWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "LessonWindowTests.moc"
