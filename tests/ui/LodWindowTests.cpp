// The cluster LOD hierarchy in the window: built from the clusters shown, a level and the cut from the
// cull eye drawn and picked, and the numbers the window shows for the cut and the levels equal to
// `conescope-cli lod --eye` for the same eye and threshold.
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QPushButton>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkChartXY.h>
#include <vtkPlot.h>
#include <vtkTable.h>
#include <vtkVariant.h>

#include "LodPanel.h"
#include "StepLessonView.h"
#include "MainWindow.h"
#include "PlotsView.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/lod/LodFamily.h"

namespace conescope::testing {

class LodWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

    Session& session() { return window_->session(); }

    // Shows `level` (kLodCut, kLodNone or a level) through the dock's chooser, as a user picks it.
    void choose(int level) {
        QComboBox* chooser = window_->lodPanel()->levelChooser();
        const int index = chooser->findData(level);
        QVERIFY(index >= 0);
        chooser->setCurrentIndex(index);
        emit chooser->activated(index);
        QCOMPARE(session().lodLevelShown(), level);
    }

    // `conescope-cli lod` of the elephant from `eye` at `pixels`: its JSON.
    nlohmann::json cliLod(const glm::dvec3& eye, double pixels) {
        const QString out = temporary_.filePath(QStringLiteral("cli-lod.json"));
        QString errors;
        const int code = runProgram(QStringLiteral(CONESCOPE_CLI_PATH),
                                    {QStringLiteral("lod"), datasetPath("elephant.off"), QStringLiteral("--eye"),
                                     QStringLiteral("%1,%2,%3").arg(eye.x, 0, 'g', 17).arg(eye.y, 0, 'g', 17).arg(eye.z, 0, 'g', 17),
                                     QStringLiteral("--threshold"), QString::number(pixels, 'g', 17), QStringLiteral("--quiet"),
                                     QStringLiteral("-o"), out},
                                    &errors);
        if (code != 0) qWarning("conescope-cli lod: %s", qPrintable(errors));
        return code == 0 ? readJsonFile(out) : nlohmann::json();
    }

private slots:
    void initTestCase() {
        openWindow();
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
    }
    void cleanupTestCase() { window_.reset(); }

    void noHierarchyBeforeItIsBuilt() {
        QVERIFY(!session().lodHierarchy());
        QVERIFY(!session().lodStatistics());
        QVERIFY(!session().showLodLevel(0));
        QVERIFY(!window_->lodPanel()->levelChooser()->isEnabled());
        QVERIFY(!window_->statisticsPanel()->findChild<QLabel*>(QStringLiteral("LOD cut"))->isVisibleTo(window_->statisticsPanel()));
    }

    // The window's cut and level numbers from the eye are the CLI's for that eye and threshold.
    void cutNumbersEqualTheCommandLine() {
        const glm::dvec3 eye(0.2, 0.9, 1.6);
        window_->setEyePosition(eye);
        window_->lodPanel()->thresholdBox()->setValue(2.0);
        QCOMPARE(session().lodThreshold().value, 2.0);
        QCOMPARE(session().lodThreshold().screenHeight, 1080.0);
        QCOMPARE(session().lodThreshold().fovDegrees, 60.0);
        QTest::mouseClick(window_->lodPanel()->buildButton(), Qt::LeftButton);
        window_->waitUntilIdle();
        QVERIFY(session().lodHierarchy());
        QVERIFY(session().lodHierarchy()->levels.size() >= 3);
        choose(kLodCut);
        const LodStatistics* shown = session().lodStatistics();
        QVERIFY(shown);
        const nlohmann::json cli = cliLod(eye, 2.0);
        QVERIFY(!cli.is_null());
        const LodCutView& cut = shown->cut.views.front();
        QCOMPARE(cli["cut"]["views"].size(), size_t(1));
        QCOMPARE(cli["cut"]["triangles"].get<double>(), double(cut.triangles));
        QCOMPARE(cli["cut"]["clusters"].get<double>(), double(cut.clusters));
        QCOMPARE(cli["cut"]["triangles_culled"].get<size_t>(), cut.trianglesCulled);
        QCOMPARE(cli["cut"]["back_facing_triangles"].get<size_t>(), cut.backFacingTriangles);
        QCOMPARE(cli["cut"]["false_culls"].get<size_t>(), size_t(0));
        QCOMPARE(cli["cut"]["efficiency"].get<double>(), cut.efficiency);
        QCOMPARE(cli["cut"]["levels_used"].get<std::vector<size_t>>(), shown->cut.levelsUsed);
        QVERIFY(shown->cut.levelsUsed.size() >= 2);
        // What the statistics panel says is those numbers.
        StatisticsPanel* panel = window_->statisticsPanel();
        QCOMPARE(panel->value(QStringLiteral("LOD cut")),
                 QStringLiteral("%1 clusters, %2 triangles").arg(cli["cut"]["clusters"].get<double>()).arg(cli["cut"]["triangles"].get<double>()));
        QCOMPARE(panel->value(QStringLiteral("LOD culled")), QStringLiteral("%1 of %2 back-facing triangles")
                                                                  .arg(cli["cut"]["triangles_culled"].get<size_t>())
                                                                  .arg(cli["cut"]["back_facing_triangles"].get<size_t>()));
        QCOMPARE(panel->value(QStringLiteral("LOD efficiency")), QString::number(100.0 * cli["cut"]["efficiency"].get<double>(), 'f', 1) + '%');
        QCOMPARE(panel->value(QStringLiteral("LOD false culls")), QStringLiteral("0"));
        const QStringList rows = panel->value(QStringLiteral("LOD levels")).split('\n');
        QCOMPARE(size_t(rows.size()), cli["levels"].size());
        for (size_t l = 0; l < cli["levels"].size(); ++l) {
            const nlohmann::json& level = cli["levels"][l];
            QCOMPARE(level["clusters"].get<size_t>(), shown->levels[l].clusters);
            QCOMPARE(level["triangles"].get<size_t>(), shown->levels[l].triangles);
            QCOMPARE(level["efficiency"].get<double>(), shown->levels[l].culling.efficiency);
            QCOMPARE(level["mean_half_angle_deg"].get<double>(), shown->levels[l].meanHalfAngleDegrees);
            QCOMPARE(rows[int(l)], StatisticsPanel::lodLevelLine(shown->levels[l]));
        }
        // The Levels plot draws the CLI's levels, and the LOD lesson quotes them.
        vtkTable* plotted = window_->plotsView()->levelsChart()->GetPlot(0)->GetInput();
        QCOMPARE(size_t(plotted->GetNumberOfRows()), cli["levels"].size());
        for (size_t l = 0; l < cli["levels"].size(); ++l)
            QCOMPARE(plotted->GetValueByName(vtkIdType(l), "efficiency").ToDouble(), cli["levels"][l]["efficiency"].get<double>());
        // The plot as the window's dock shows it at its default size, to look at: no legend covers the bars, the caption names the colours.
        PlotsView* plots = window_->plotsView();
        for (int tab = 0; tab < plots->count(); ++tab)
            if (plots->tabText(tab) == QStringLiteral("Levels")) plots->setCurrentIndex(tab);
        plots->render();
        saveWindowPicture(QStringLiteral("lod-levels-window.png"));
        QVERIFY(window_->lodLessonView()->step() == 1);
        QVERIFY2(window_->lodLessonView()->text().contains(QString::number(cli["levels"][0]["clusters"].get<size_t>())),
                 qPrintable(window_->lodLessonView()->text()));
        // The export is the CLI's document for that eye and threshold (only the build time differs).
        const QString exported = temporary_.filePath(QStringLiteral("window-lod.json"));
        QVERIFY(session().exportLodStatistics(exported, StatisticsFormat::Json));
        nlohmann::json fromWindow = readJsonFile(exported), fromCli = cli;
        fromWindow.erase("build_seconds");
        fromCli.erase("build_seconds");
        QVERIFY2(fromWindow == fromCli, (fromWindow.dump(1) + "\n---\n" + fromCli.dump(1)).substr(0, 3000).c_str());
        // The picture: the cut's scene draws the cut's clusters and culls what the numbers count.
        const LodLevel* drawn = session().lodLevelOnShow();
        QVERIFY(drawn && session().lodScene());
        QCOMPARE(session().lodScene()->clusterCount(), cut.clusters);
        QCOMPARE(drawn->triangles(), cut.triangles);
        QCOMPARE(session().lodMeasurement()->view().trianglesCulled, cut.trianglesCulled);
        QCOMPARE(session().lodMeasurement()->view().backFacingTriangles, cut.backFacingTriangles);
        window_->resetCamera();
        window_->setFaceColoring(FaceColoring::LodLevel);
        QVERIFY(window_->saveScreenshot(QDir(outputDir_).filePath(QStringLiteral("lod-cut-by-level.png"))));
        choose(2);
        QVERIFY(window_->saveScreenshot(QDir(outputDir_).filePath(QStringLiteral("lod-level-2-by-level.png"))));
        choose(kLodCut);
    }

    // A new eye or threshold cuts again, and the numbers follow the CLI's.
    void theCutFollowsTheEyeAndThreshold() {
        const size_t before = session().lodStatistics()->cut.views.front().triangles;
        const glm::dvec3 far(0.5, 2.0, 9.0);
        window_->setEyePosition(far);
        window_->lodPanel()->thresholdBox()->setValue(8.0);
        const LodCutView& cut = session().lodStatistics()->cut.views.front();
        QVERIFY(cut.triangles < before);
        const nlohmann::json cli = cliLod(far, 8.0);
        QCOMPARE(cli["cut"]["triangles"].get<double>(), double(cut.triangles));
        QCOMPARE(cli["cut"]["triangles_culled"].get<size_t>(), cut.trianglesCulled);
        QCOMPARE(cli["cut"]["levels_used"].get<std::vector<size_t>>(), session().lodStatistics()->cut.levelsUsed);
        QCOMPARE(session().lodScene()->clusterCount(), cut.clusters);
    }

    // A level shows its own clusters; picking one shows its group, parents and children.
    void aPickedLevelClusterShowsItsFamily() {
        choose(1);
        const LodLevel& level = session().lodHierarchy()->levels[1];
        QCOMPARE(session().lodScene()->clusterCount(), size_t(level.clusters.partition.clusterCount));
        QCOMPARE(session().lodMeasurement()->view().trianglesCulled, session().lodStatistics()->levels[1].culling.views.front().trianglesCulled);
        session().pickLodCluster(3);
        const std::optional<LodFamily> family = session().lodPick();
        QVERIFY(family);
        const LodFamily expected = lodFamilyOf(*session().lodHierarchy(), {1, 3});
        QCOMPARE(family->parents, expected.parents);
        QCOMPARE(family->children, expected.children);
        QVERIFY(!family->children.empty() && !family->parents.empty());
        const QString html = window_->clusterReportHtml();
        QVERIFY2(html.contains(QStringLiteral("LOD level 1, cluster 3")), qPrintable(html));
        QVERIFY(html.contains(QStringLiteral("Parents (level 2)")));
        QVERIFY(html.contains(QStringLiteral("Children (level 0")));
        window_->resetCamera();
        window_->setFaceColoring(FaceColoring::LodCut);
        QVERIFY(window_->saveScreenshot(QDir(outputDir_).filePath(QStringLiteral("lod-level-1-by-cut.png"))));
        window_->setFaceColoring(FaceColoring::LodGroup);
        QVERIFY(window_->saveScreenshot(QDir(outputDir_).filePath(QStringLiteral("lod-level-1-by-group.png"))));
    }

    // New clusters drop the hierarchy, and the partition is shown again.
    void newClustersDropTheHierarchy() {
        Settings settings = window_->settings();
        settings.limits.maxTriangles = 64;
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QVERIFY(!session().lodHierarchy());
        QVERIFY(!session().lodScene());
        QCOMPARE(session().lodLevelShown(), kLodNone);
        QVERIFY(!window_->lodPanel()->levelChooser()->isEnabled());
    }
};

}  // namespace conescope::testing

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    conescope::testing::LodWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "LodWindowTests.moc"
