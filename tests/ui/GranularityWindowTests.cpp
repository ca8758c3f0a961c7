// The granularity report in the window: measured in the background from the clusters shown, its rows,
// export, plot and lesson equal to `conescope-cli granularity` with the same settings, dropped when
// the settings change, and nothing shown after a Cancel.
#include <set>
#include <tuple>

#include <QDockWidget>
#include <QPushButton>
#include <QTableWidget>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include "Exports.h"
#include "StepLessonView.h"
#include "core/GranularityLesson.h"
#include "GranularityPanel.h"
#include "MainWindow.h"
#include "PlotsView.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"

namespace conescope::testing {

namespace {

// Every key of every row but the measured times (a granularity row has none today).
nlohmann::json rowsOf(const nlohmann::json& document) { return withoutTimings(document["rows"]); }

}  // namespace

class GranularityWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

    Session& session() { return window_->session(); }

    // `conescope-cli granularity` of the elephant with `arguments`: its JSON, and the lesson it wrote.
    nlohmann::json cliGranularity(const QStringList& arguments, QString* lesson = nullptr) {
        const QString out = temporary_.filePath(QStringLiteral("cli-granularity.json"));
        const QString lessonPath = temporary_.filePath(QStringLiteral("cli-lesson.md"));
        QString errors;
        const int code = runProgram(QStringLiteral(CONESCOPE_CLI_PATH),
                                    QStringList{QStringLiteral("granularity"), datasetPath("elephant.off"), QStringLiteral("--quiet"),
                                                QStringLiteral("-o"), out, QStringLiteral("--write-lesson"), lessonPath} +
                                        arguments,
                                    &errors);
        if (code != 0) qWarning("conescope-cli granularity: %s", qPrintable(errors));
        if (lesson) {
            QFile file(lessonPath);
            if (file.open(QIODevice::ReadOnly)) *lesson = QString::fromUtf8(file.readAll());
        }
        return code == 0 ? readJsonFile(out) : nlohmann::json();
    }

    void measure() {
        QTest::mouseClick(window_->granularityPanel()->measureButton(), Qt::LeftButton);
        window_->waitUntilIdle();
    }

    // The table, the plot and the lesson show `report`'s rows, and the report is the CLI's `document`.
    void checkShown(const nlohmann::json& document) {
        const GranularityReport* report = session().granularity();
        QVERIFY(report);
        QVERIFY(!document.is_null());
        const nlohmann::json fromWindow = rowsOf(granularityToJsonForTest(*report)), fromCli = rowsOf(document);
        QVERIFY2(fromWindow == fromCli, (fromWindow.dump(1) + "\n---\n" + fromCli.dump(1)).substr(0, 4000).c_str());
        QCOMPARE(document["clusters"].get<size_t>(), report->run.clusters);
        QCOMPARE(document["views"].get<size_t>(), report->run.viewCount);
        // The table: one row per record, each cell the row's value.
        QTableWidget* table = window_->granularityPanel()->table();
        QCOMPARE(size_t(table->rowCount()), document["rows"].size());
        for (int r = 0; r < table->rowCount(); ++r) {
            QCOMPARE(table->item(r, 0)->text().toStdString(), document["rows"][size_t(r)]["record"].get<std::string>());
            for (int c = 0; c < GranularityPanel::kColumns; ++c)
                QCOMPARE(table->item(r, c)->text(), GranularityPanel::cellText(report->rows[size_t(r)], c));
        }
        // The plot: every row once, at its bytes and culled share, labelled with its record.
        vtkChartXY* chart = window_->plotsView()->granularityChart();
        std::multiset<std::tuple<std::string, double, double>> expected, labelled, marked;
        for (const nlohmann::json& row : document["rows"])
            expected.insert({row["record"].get<std::string>(), row["bytes_per_cluster"].get<double>(), row["culled_share"].get<double>()});
        size_t labelPlots = 0;
        for (vtkIdType p = 0; p < chart->GetNumberOfPlots(); ++p) {
            vtkPlot* plot = chart->GetPlot(p);
            if (plot->GetLabel() == "the ceiling: every back face") {
                QCOMPARE(plot->GetInput()->GetValueByName(0, "culled share").ToDouble(), report->rows.back().culledShare);
                continue;
            }
            // The labels are a plot of their own, kept out of the legend.
            labelPlots += plot->GetLegendVisibility() ? 0 : 1;
            std::multiset<std::tuple<std::string, double, double>>& into = plot->GetLegendVisibility() ? marked : labelled;
            vtkTable* points = plot->GetInput();
            for (vtkIdType row = 0; row < points->GetNumberOfRows(); ++row)
                into.insert({points->GetValueByName(row, "record").ToString(), points->GetValueByName(row, "bytes per cluster").ToDouble(),
                             points->GetValueByName(row, "culled share").ToDouble()});
        }
        QCOMPARE(labelPlots, size_t(1));
        QCOMPARE(marked.size(), expected.size());
        QVERIFY(marked == expected);
        QVERIFY(labelled == expected);
        // The lesson: its steps are the CLI's lesson, and they quote the rows.
        const GranularityLesson lesson = makeGranularityLesson(*report);
        QVERIFY(shownStepsAre(lesson));
        QCOMPARE(window_->granularityLessonView()->step(), 1);
        QCOMPARE(window_->granularityLessonView()->text().toStdString(), lesson.steps.front().text);
    }

    // The lesson view shows `lesson`'s steps, title and text each.
    bool shownStepsAre(const GranularityLesson& lesson) const {
        const std::vector<LessonStep>& shown = window_->granularityLessonView()->steps();
        if (shown.empty() || shown.size() != lesson.steps.size()) return false;
        for (size_t step = 0; step < shown.size(); ++step)
            if (shown[step].title != lesson.steps[step].title || shown[step].text != lesson.steps[step].text) return false;
        return true;
    }

    static nlohmann::json granularityToJsonForTest(const GranularityReport& report) {
        QTemporaryDir directory;
        const QString path = directory.filePath(QStringLiteral("rows.json"));
        exportGranularity(report, path.toStdString(), StatisticsFormat::Json);
        return readJsonFile(path);
    }

private slots:
    void initTestCase() {
        openWindow();
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
    }
    void cleanupTestCase() { window_.reset(); }

    void nothingBeforeItIsMeasured() {
        QVERIFY(!session().granularity());
        QCOMPARE(window_->granularityPanel()->table()->rowCount(), 0);
        QVERIFY(!window_->granularityPanel()->exportButton()->isEnabled());
        QVERIFY(window_->granularityPanel()->measureButton()->isEnabled());
        QCOMPARE(window_->plotsView()->granularityChart()->GetNumberOfPlots(), vtkIdType(0));
        QVERIFY(window_->granularityLessonView()->steps().empty());
    }

    // A Cancel halfway (in the K-cone records) shows nothing: no rows, no plot, no lesson.
    void cancelLeavesNothingShown() {
        session().cancelAtStage(QStringLiteral("finer records"));
        measure();
        QVERIFY(!session().cancelStageArmed());
        QVERIFY(!session().granularity());
        QCOMPARE(window_->granularityPanel()->table()->rowCount(), 0);
        QCOMPARE(window_->plotsView()->granularityChart()->GetNumberOfPlots(), vtkIdType(0));
        QVERIFY(window_->granularityLessonView()->steps().empty());
        QVERIFY(!window_->granularityPanel()->exportButton()->isEnabled());
    }

    // The rows, the table, the plot, the lesson and the export are the CLI's with the same settings.
    void rowsEqualTheCommandLine() {
        measure();
        QString lesson;
        // The window's default settings are the CLI's defaults: the same command without options...
        const nlohmann::json plain = cliGranularity({}, &lesson);
        checkShown(plain);
        // ... and with the settings the window measured with, spelled out.
        checkShown(cliGranularity(cliSettingsArguments(session().granularityRunSettings())));
        // The lesson is the one the CLI wrote, step for step, and it quotes this mesh's numbers.
        const GranularityLesson shown = makeGranularityLesson(*session().granularity());
        QVERIFY(shownStepsAre(shown));
        QCOMPARE(lesson.toStdString(), granularityLessonMarkdown(shown));
        QVERIFY(lesson.contains(QStringLiteral("elephant.off")));
        for (int step = 1; step <= kGranularityLessonStepCount; ++step) {
            QVERIFY(window_->granularityLessonView()->showStep(step));
            QVERIFY(lesson.contains(window_->granularityLessonView()->text()));
        }
        const nlohmann::json& triangle = plain["rows"].back();
        QVERIFY(window_->granularityLessonView()->text().contains(QString::number(100.0 * triangle["culled_share"].get<double>(), 'f', 1) + '%'));
        window_->granularityLessonView()->showStep(1);
        // The export is the file the CLI writes (JSON and CSV).
        const QString exported = temporary_.filePath(QStringLiteral("window-granularity.json"));
        QVERIFY(session().exportGranularity(exported, StatisticsFormat::Json));
        QVERIFY(withoutTimings(readJsonFile(exported)) == withoutTimings(plain));
        const QString csv = temporary_.filePath(QStringLiteral("window-granularity.csv"));
        QVERIFY(session().exportGranularity(csv, StatisticsFormat::Csv));
        const QString cliCsv = temporary_.filePath(QStringLiteral("cli-granularity.csv"));
        QCOMPARE(runProgram(QStringLiteral(CONESCOPE_CLI_PATH),
                            {QStringLiteral("granularity"), datasetPath("elephant.off"), QStringLiteral("--quiet"), QStringLiteral("-o"), cliCsv}),
                 0);
        QFile a(csv), b(cliCsv);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        QCOMPARE(a.readAll(), b.readAll());
        // The pictures, to look at: the dock with the table and the plot.
        PlotsView* plots = window_->plotsView();
        for (int tab = 0; tab < plots->count(); ++tab)
            if (plots->tabText(tab) == QStringLiteral("Granularity")) plots->setCurrentIndex(tab);
        for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
            if (dock->objectName() == QStringLiteral("granularityDock")) dock->raise();
        QApplication::processEvents();
        plots->render();
        saveRenderWindowPng(plots->granularityWidget()->renderWindow(), QDir(outputDir_).filePath(QStringLiteral("granularity-plot.png")).toStdString());
        saveWindowPicture(QStringLiteral("granularity-window.png"));
        window_->findChild<QDockWidget*>(QStringLiteral("granularityLessonDock"))->raise();
        window_->granularityLessonView()->showStep(3);
        saveWindowPicture(QStringLiteral("granularity-lesson.png"));
        window_->granularityLessonView()->showStep(1);
        // The plot again as large as a user may make its dock.
        QDockWidget* plotsDock = window_->findChild<QDockWidget*>(QStringLiteral("plotsDock"));
        QVERIFY(plotsDock);
        plotsDock->setFloating(true);
        plotsDock->resize(1000, 480);
        QTest::qWait(200);
        plots->render();
        saveRenderWindowPng(plots->granularityWidget()->renderWindow(), QDir(outputDir_).filePath(QStringLiteral("granularity-plot-large.png")).toStdString());
        plotsDock->setFloating(false);
    }

    // Other settings drop the rows at once; measured again they are the CLI's with those settings.
    void aSettingsChangeDropsTheRows() {
        QVERIFY(session().granularity());
        Settings settings = window_->settings();
        settings.views = 24;
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QCOMPARE(session().settings().views, size_t(24));
        QVERIFY(!session().granularity());
        QCOMPARE(window_->granularityPanel()->table()->rowCount(), 0);
        QCOMPARE(window_->plotsView()->granularityChart()->GetNumberOfPlots(), vtkIdType(0));
        QVERIFY(window_->granularityLessonView()->steps().empty());
        measure();
        checkShown(cliGranularity({QStringLiteral("--views"), QStringLiteral("24")}));
        // New clusters drop them too.
        settings.limits.maxTriangles = 64;
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QVERIFY(!session().granularity());
        QCOMPARE(window_->granularityPanel()->table()->rowCount(), 0);
    }
};

}  // namespace conescope::testing

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    conescope::testing::GranularityWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "GranularityWindowTests.moc"
