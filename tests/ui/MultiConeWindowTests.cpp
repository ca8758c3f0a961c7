// K cones per cluster in the window: the setting chosen in the settings panel, the statistics panel's
// K-cone rows, the culled sub-groups from the eye and the picked cluster's sub-groups, each against
// the core; the window's statistics export against conescope-cli stats with the same settings.
#include <QComboBox>
#include <QProcess>
#include <QtTest>

#include <cmath>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>

#include <QTextDocument>

#include "GaussMapView.h"
#include "PickedClusterView.h"
#include "MainWindow.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/MultiConeCulling.h"
#include "core/Pipeline.h"
#include "io/StatisticsIO.h"

using namespace conescope;
using namespace conescope::testing;

class MultiConeWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

private slots:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { window_.reset(); }

    // The combo beside the test sets K; with one cone the K-cone rows are hidden.
    void theChoiceSetsK() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        QCOMPARE(window_->settings().conesPerCluster, 1u);
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("K cones over the orbit")), QStringLiteral("-"));
        chooseInCombo(window_->settingsPanel()->conesPerClusterBox(), "4");
        window_->waitUntilIdle();
        QCOMPARE(window_->settings().conesPerCluster, 4u);
        QVERIFY(window_->session().orbitMultiCones() != nullptr);
    }

    // The panel's numbers, from the eye and over the orbit, are the core's for the shown settings.
    void panelEqualsTheCore() {
        window_->setEyePosition({0.4, 0.6, 1.6});
        window_->waitUntilIdle();
        const PreparedMesh& prepared = *window_->preparedMesh();
        const ClusterBounds& bounds = window_->clusters()->bounds;
        const MultiCones multi = computeMultiCones(prepared.mesh(), prepared.faces, bounds, 4);
        const MultiConeCulling orbit =
            measureMultiConeRun(prepared.mesh(), prepared.world, prepared.faces, bounds, 4, orbitOf(window_->settings(), prepared.box));
        const MultiConeCulling& shown = window_->session().orbitMultiCones()->multiCones;
        QCOMPARE(shown.trianglesCulled, orbit.trianglesCulled);
        QCOMPARE(shown.backFacingTriangles, orbit.backFacingTriangles);
        QCOMPARE(shown.falseCulls, size_t(0));
        QCOMPARE(shown.bytesPerCluster, orbit.bytesPerCluster);
        const QString orbitRow = window_->statisticsPanel()->value(QStringLiteral("K cones over the orbit"));
        QVERIFY2(orbitRow.contains(QStringLiteral("%1 bytes a cluster").arg(orbit.bytesPerCluster)), qPrintable(orbitRow));
        QVERIFY2(orbitRow.contains(QString::number(100.0 * orbit.efficiency, 'f', 1) + QLatin1Char('%')), qPrintable(orbitRow));

        // From the eye: the sub-groups cullSubGroups culls, and the triangles in them.
        const Eye eye = window_->currentStatistics()->eye;
        const std::vector<uint8_t> culled = cullSubGroups(bounds, multi, eye);
        size_t groups = 0, triangles = 0;
        for (size_t g = 0; g < culled.size(); ++g)
            if (culled[g]) ++groups, triangles += multi.groupTriangles[g];
        QVERIFY(groups > 0);
        const std::optional<SubGroupsFromEye> fromEye = window_->session().subGroupsFromEye();
        QVERIFY(fromEye.has_value());
        QCOMPARE(fromEye->counts.groupsCulled, groups);
        QCOMPARE(fromEye->counts.trianglesCulled, triangles);
        QCOMPARE(fromEye->counts.falseCulls, size_t(0));
        const QString eyeRow = window_->statisticsPanel()->value(QStringLiteral("K cones from the eye"));
        QVERIFY2(eyeRow.startsWith(QStringLiteral("%1 of %2 sub-groups,").arg(QLocale().toString(qulonglong(groups)),
                                                                                     QLocale().toString(qulonglong(multi.groupCount())))),
                 qPrintable(eyeRow));
        // Both K-cone rows show their whole text, right under the eye's rows (a value wrapped to three
        // lines was given two, over the next row, below the gap the hidden comparison rows left).
        const QString cut = statisticsLayoutFault(*window_->statisticsPanel());
        // More cones cull at least what one cone culls from this eye on this mesh.
        QVERIFY(triangles >= window_->currentStatistics()->view().trianglesCulled);
        saveWindowPicture(QStringLiteral("multi-cone-window.png"));
    }

    // The picked cluster lists its four sub-groups as the core decides them from the eye.
    void pickedClusterListsItsSubGroups() {
        const PreparedMesh& prepared = *window_->preparedMesh();
        const ClusterBounds& bounds = window_->clusters()->bounds;
        const MultiCones multi = computeMultiCones(prepared.mesh(), prepared.faces, bounds, 4);
        const Eye eye = window_->currentStatistics()->eye;
        const std::vector<uint8_t> culled = cullSubGroups(bounds, multi, eye);
        // A cluster with a culled sub-group and a drawn one, where K cones say more than one.
        int chosen = -1;
        for (uint32_t c = 0; c < bounds.count() && chosen < 0; ++c) {
            bool some = false, all = true;
            for (uint32_t g = 4 * c; g < 4 * c + 4; ++g) some |= culled[g] != 0, all &= culled[g] != 0 || multi.groupTriangles[g] == 0;
            if (some && !all) chosen = int(c);
        }
        QVERIFY(chosen >= 0);
        window_->pickCluster(chosen);
        window_->waitUntilIdle();
        const std::vector<SubGroupVerdict> expected =
            subGroupVerdicts(multi, uint32_t(chosen), culled, classifyFaces(prepared.mesh(), prepared.world, prepared.faces, eye));
        QTextDocument page;
        page.setHtml(window_->clusterReportHtml());
        const QString text = page.toPlainText();
        QVERIFY2(text.contains(QStringLiteral("4 cones: the cluster's sub-groups from the eye")), qPrintable(text));
        const PickedClusterView* view = window_->findChild<PickedClusterView*>();
        QVERIFY(view != nullptr);
        const std::vector<SubGroupVerdict>& shown = view->subGroups();
        QCOMPARE(expected.size(), size_t(4));
        QCOMPARE(shown.size(), expected.size());
        for (size_t i = 0; i < expected.size(); ++i) {
            const SubGroupVerdict& v = expected[i];
            QCOMPARE(shown[i].group, v.group);
            QCOMPARE(shown[i].triangles, v.triangles);
            QCOMPARE(shown[i].halfAngleDegrees, v.halfAngleDegrees);
            QCOMPARE(shown[i].culled, v.culled);
            QCOMPARE(shown[i].allBackFacing, v.allBackFacing);
            // Conservative: a culled sub-group has every face facing away.
            if (v.culled) QVERIFY(v.allBackFacing);
        }
        saveWindowPicture(QStringLiteral("multi-cone-picked.png"));
    }

    // The sub-group colouring draws grey exactly the faces of the sub-groups cullSubGroups culls, and
    // the Gauss map draws the picked cluster's cones, one rim per sub-group with a cone.
    void pictureSaysWhatTheNumbersSay() {
        window_->setFaceColoring(FaceColoring::SubGroup);
        window_->waitUntilIdle();
        const PreparedMesh& prepared = *window_->preparedMesh();
        const ClusterBounds& bounds = window_->clusters()->bounds;
        const MultiCones multi = computeMultiCones(prepared.mesh(), prepared.faces, bounds, 4);
        const Eye eye = window_->currentStatistics()->eye;
        const std::vector<uint8_t> culled = cullSubGroups(bounds, multi, eye);
        std::vector<uint8_t> culledFace(prepared.mesh().faceCount(), 0);
        size_t culledTriangles = 0;
        for (size_t g = 0; g < culled.size(); ++g) {
            if (!culled[g]) continue;
            culledTriangles += multi.groupTriangles[g];
            for (uint32_t i = multi.groupStarts[g]; i < multi.groupStarts[g + 1]; ++i) culledFace[multi.faces[i]] = 1;
        }
        vtkDataArray* colours = window_->scene()->meshPolyData()->GetCellData()->GetArray("sub_group");
        QVERIFY(colours != nullptr);
        const auto grey = [](double c) { return std::lround(c * 255.0); };
        size_t greyFaces = 0;
        for (vtkIdType f = 0; f < colours->GetNumberOfTuples(); ++f) {
            const double* rgb = colours->GetTuple3(f);
            const bool isGrey = rgb[0] == grey(SceneColours::culled[0]) && rgb[1] == grey(SceneColours::culled[1]) &&
                                rgb[2] == grey(SceneColours::culled[2]);
            QCOMPARE(isGrey, culledFace[size_t(f)] != 0);
            greyFaces += isGrey;
        }
        QVERIFY(greyFaces > 0);
        const QString legend = legendText(*window_->scene());
        QVERIFY2(legend.contains(QStringLiteral("sub-groups, 4 a cluster")), qPrintable(legend));
        QVERIFY2(legend.contains(QStringLiteral(", %1 tris").arg(culledTriangles)), qPrintable(legend));
        // The picked cluster's four cones in the Gauss map.
        size_t withCone = 0;
        const uint32_t picked = uint32_t(window_->pickedCluster());
        for (uint32_t g = 4 * picked; g < 4 * picked + 4; ++g) withCone += multi.groupTriangles[g] > 0 && multi.cones[g].cullable;
        QCOMPARE(window_->gaussMapView()->scene().subGroupRimsShown(), withCone);
        QVERIFY(window_->saveWindowScreenshot(QDir(outputDir_).filePath(QStringLiteral("multi-cone-sub-groups.png"))));
        QVERIFY(window_->saveScreenshot(QDir(outputDir_).filePath(QStringLiteral("multi-cone-sub-groups-view.png"))));
    }

    // The window's statistics export is conescope-cli stats with the same settings.
    void exportEqualsTheCli() {
        const Settings settings = window_->settings();
        const QString json = temporary_.filePath(QStringLiteral("orbit.json"));
        QVERIFY(window_->exportStatistics(json, StatisticsFormat::Json, true));
        const nlohmann::json written = readJsonFile(json);
        QVERIFY(written.contains("multi_cone"));
        QCOMPARE(written["settings"]["cones_per_cluster"], nlohmann::json(4));
        const MultiConeCulling& shown = window_->session().orbitMultiCones()->multiCones;
        QCOMPARE(written["multi_cone"]["triangles_culled"].get<size_t>(), shown.trianglesCulled);
        QCOMPARE(written["multi_cone"]["back_facing_triangles"].get<size_t>(), shown.backFacingTriangles);
#ifdef CONESCOPE_CLI_PATH
        const QString cliJson = temporary_.filePath(QStringLiteral("cli.json"));
        QProcess cli;
        QStringList arguments{QStringLiteral("stats"), datasetPath("elephant.off")};
        arguments << cliSettingsArguments(settings) << QStringLiteral("--format") << QStringLiteral("json") << QStringLiteral("-o") << cliJson;
        cli.start(QStringLiteral(CONESCOPE_CLI_PATH), arguments);
        QVERIFY(cli.waitForFinished(120000));
        QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
        const nlohmann::json fromCli = readJsonFile(cliJson);
        QCOMPARE(fromCli["settings"], written["settings"]);
        QCOMPARE(fromCli["multi_cone"], written["multi_cone"]);
        QCOMPARE(fromCli["clusters"], written["clusters"]);
        for (size_t r = 0; r < fromCli["results"].size(); ++r)
            for (const char* key : {"efficiency", "triangles_culled", "back_facing_triangles", "false_culls"})
                QCOMPARE(fromCli["results"][r][key], written["results"][r][key]);
#endif
    }
};

QTEST_MAIN(MultiConeWindowTests)
#include "MultiConeWindowTests.moc"
