// The LOD widgets on their own. The plots dock's Levels tab: without a hierarchy it says so and plots
// nothing; with one it plots that hierarchy's levels (a picture of it is saved for looking at). The
// lesson on why coarse clusters cull less: its steps are the core lesson's, Back and Next walk them.
#include <memory>

#include <QApplication>
#include <QDir>
#include <QSurfaceFormat>
#include <QToolButton>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkTable.h>

#include "ElephantLod.h"
#include "StepLessonView.h"
#include "PlotsView.h"
#include "UiTestSupport.h"
#include "core/lod/LodLesson.h"

namespace conescope {

namespace {

const LodStatistics& elephantLevels() {
    static const LodStatistics statistics = testing::elephantLod(16);
    return statistics;
}

}  // namespace

class LodWidgetTests : public QObject {
    Q_OBJECT
private slots:
    void levelsTabShowsTheHierarchyOrSaysThereIsNone() {
        PlotsView plots;
        plots.resize(900, 520);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        int tab = -1;
        for (int i = 0; i < plots.count(); ++i)
            if (plots.tabText(i) == QStringLiteral("Levels")) tab = i;
        QVERIFY(tab >= 0);
        plots.setCurrentIndex(tab);
        QApplication::processEvents();
        QVERIFY(plots.levelsWidget()->isVisible());
        // Nothing built yet.
        QCOMPARE(plots.levelsChart()->GetNumberOfPlots(), vtkIdType(0));
        QVERIFY(plots.levelsCaption().contains(QStringLiteral("No hierarchy built")));

        const LodStatistics& statistics = elephantLevels();
        plots.showLevels(&statistics);
        QCOMPARE(plots.levelsChart()->GetNumberOfPlots(), vtkIdType(4));
        QCOMPARE(plots.levelsChart()->GetPlot(0)->GetInput()->GetNumberOfRows(), vtkIdType(statistics.levels.size()));
        QVERIFY(!plots.levelsCaption().contains(QStringLiteral("No hierarchy built")));
        plots.render();
        QApplication::processEvents();
        const QString output = qEnvironmentVariable("CONESCOPE_UI_TEST_OUTPUT", QDir::tempPath());
        QVERIFY(plots.grab().save(QDir(output).filePath(QStringLiteral("plots-levels.png"))));

        // A closed mesh (or a hierarchy thrown away) empties the tab again.
        plots.showLevels(nullptr);
        QCOMPARE(plots.levelsChart()->GetNumberOfPlots(), vtkIdType(0));
        QVERIFY(plots.levelsCaption().contains(QStringLiteral("No hierarchy built")));
        plots.render();
        QApplication::processEvents();
        QVERIFY(plots.grab().save(QDir(output).filePath(QStringLiteral("plots-levels-none.png"))));
    }

    void lodLessonWalksTheCoreLessonsSteps() {
        std::unique_ptr<StepLessonView> made(makeLodLessonView());
        StepLessonView& view = *made;
        view.resize(520, 420);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        QVERIFY(view.text().contains(QStringLiteral("Build the LOD hierarchy")));
        QVERIFY(!view.nextButton()->isEnabled() && !view.backButton()->isEnabled());
        QVERIFY(!view.showStep(1));
        const LodLesson lesson = makeLodLesson(elephantLevels(), "elephant.off");
        showLodLesson(view, &lesson);
        QCOMPARE(view.step(), 1);
        for (int step = 1; step <= kLodLessonStepCount; ++step) {
            QCOMPARE(view.step(), step);
            QCOMPARE(view.text(), QString::fromStdString(lesson.steps[size_t(step - 1)].text));
            QVERIFY(view.title().contains(QString::fromStdString(lesson.steps[size_t(step - 1)].title)));
            QCOMPARE(view.backButton()->isEnabled(), step > 1);
            QCOMPARE(view.nextButton()->isEnabled(), step < kLodLessonStepCount);
            if (step == 3) {
                const QString output = qEnvironmentVariable("CONESCOPE_UI_TEST_OUTPUT", QDir::tempPath());
                QVERIFY(view.grab().save(QDir(output).filePath(QStringLiteral("lod-lesson-step3.png"))));
            }
            if (step < kLodLessonStepCount) QTest::mouseClick(view.nextButton(), Qt::LeftButton);
        }
        QTest::mouseClick(view.backButton(), Qt::LeftButton);
        QCOMPARE(view.step(), kLodLessonStepCount - 1);
        QVERIFY(!view.showStep(kLodLessonStepCount + 1));
        QCOMPARE(view.step(), kLodLessonStepCount - 1);
        showLodLesson(view, nullptr);
        QCOMPARE(view.step(), 0);
        QVERIFY(view.text().contains(QStringLiteral("Build the LOD hierarchy")));
        // From the statistics directly, as the window gives them: the same lesson; one level is not enough.
        showLodStatistics(view, &elephantLevels(), "elephant.off");
        QCOMPARE(view.step(), 1);
        QCOMPARE(view.text(), QString::fromStdString(lesson.steps[0].text));
        LodStatistics single;
        single.levels.push_back(elephantLevels().levels.front());
        showLodStatistics(view, &single, "elephant.off");
        QCOMPARE(view.step(), 0);
        QVERIFY(view.text().contains(QStringLiteral("single level")));
        showLodStatistics(view, nullptr, {});
        QVERIFY(view.text().contains(QStringLiteral("Build the LOD hierarchy")));
    }
};

}  // namespace conescope

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    conescope::LodWidgetTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "LodWidgetTests.moc"
