// The plots dock's Levels tab on its own: without a hierarchy it says so and plots nothing; with one
// it plots that hierarchy's levels, and a picture of it is saved for looking at.
#include <QApplication>
#include <QDir>
#include <QSurfaceFormat>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkRenderWindow.h>
#include <vtkTable.h>

#include "PlotsView.h"
#include "UiTestSupport.h"
#include "core/lod/LodCut.h"
#include "io/MeshReader.h"

namespace conescope {

class PlotsViewTests : public QObject {
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

        Settings settings;
        settings.views = 16;
        const LodStatistics statistics =
            lodOfMesh(readMesh(testing::datasetPath("elephant.off").toStdString()), "elephant.off", settings, LodThreshold{});
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
};

}  // namespace conescope

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    conescope::PlotsViewTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "PlotsViewTests.moc"
