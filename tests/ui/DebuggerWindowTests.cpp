// The window as a debugger: the picked cluster's test drawn with its margin and Gauss map, the
// fraction and loss colourings, the A/B comparison, and a second mesh with its own scale.
#include <cmath>

#include <QComboBox>
#include <QFile>
#include <QScrollBar>
#include <QTextBrowser>
#include <QLabel>
#include <QLocale>
#include <QTextStream>

#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>

#include "GaussMapView.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "MeshLoading.h"
#include "core/Comparison.h"

using namespace conescope;
using namespace conescope::testing;

class DebuggerWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

    // The elephant at the defaults over 32 views (the A/B tests' start), the eye in front of it.
    void openElephantWithFewViews() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        Settings few = window_->settings();
        few.views = 32;
        window_->setSettings(few);
        window_->waitUntilIdle();
        window_->setEyePosition({0.6, 0.3, 1.4});
    }

    void unpinAndResetSettings() {
        QTest::keyClick(window_.get(), Qt::Key_A, Qt::ShiftModifier);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

private slots:
    void initTestCase() { openWindow(); }
    void init() { window_->observerView()->setFocus(); }
    void cleanupTestCase() { window_.reset(); }

    void pickDrawsTheTestTheMarginAndTheGaussMap() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->setEyePosition({0.4, -2.2, 1.3});
        QVERIFY(window_->layerVisible(Layer::Test));
        const ClusterScene& scene = *window_->scene();
        QCOMPARE(scene.testDrawing().cluster, -1);
        QVERIFY(!scene.actor(Layer::Test)->GetVisibility());
        QVERIFY(!window_->gaussMapView()->scene().hasMap());
        const Eye eye = window_->currentStatistics()->eye;
        const CullingInput input = cullingInput(*window_->preparedMesh(), *window_->clusters());
        const CullTest test = displayedTest(window_->settings());
        // Every cluster: the drawing and the margin are the core's for this eye and test.
        size_t culled = 0, drawn = 0;
        for (uint32_t c = 0; c < window_->clusters()->bounds.count(); ++c) {
            window_->pickCluster(int(c));
            const CullExplanation why = explainCull(input, c, eye, test);
            QCOMPARE(window_->scene()->testDrawing().cluster, int(c));
            QCOMPARE(window_->scene()->testDrawing().why.margin, why.margin);
            QVERIFY(window_->scene()->actor(Layer::Test)->GetVisibility());
            QVERIFY(window_->gaussMapView()->scene().hasMap());
            const QString report = window_->clusterReportHtml();
            if (std::isnan(why.margin)) continue;
            QVERIFY(report.contains(why.margin > 0.0 ? QStringLiteral("passes by") : QStringLiteral("short by")));
            (why.culled ? culled : drawn)++;
        }
        QVERIFY(culled > 0 && drawn > 0);
        // The drawing follows the eye.
        const double before = window_->scene()->testDrawing().why.margin;
        window_->setEyePosition({-1.0, 2.5, -1.5});
        QVERIFY(window_->scene()->testDrawing().why.margin != before);
        QCOMPARE(window_->scene()->testDrawing().eye.position, window_->currentStatistics()->eye.position);
        QTest::keyClick(window_.get(), Qt::Key_G);
        saveWindowPicture(QStringLiteral("window-gauss-map.png"));
        window_->pickCluster(-1);
        QCOMPARE(window_->scene()->testDrawing().cluster, -1);
        QVERIFY(!window_->gaussMapView()->scene().hasMap());
    }

    void fractionAndLossColourings() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        const ClusterSet& clusters = *window_->clusters();
        // Ctrl+4: cull fraction, one entry per cluster on the ramp, uncullable clusters apart and counted.
        QTest::keyClick(window_.get(), Qt::Key_4, Qt::ControlModifier);
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::CullFraction));
        size_t uncullable = 0;
        for (const ConeOfNormals& cone : clusters.bounds.cones) uncullable += !cone.cullable;
        QVERIFY(uncullable > 0);
        QVERIFY(legendText(*window_->scene()).contains(QStringLiteral("uncullable: no cone (%1)").arg(uncullable)));
        // Ctrl+6: the loss class of every face is the core's for the current eye.
        QTest::keyClick(window_.get(), Qt::Key_6, Qt::ControlModifier);
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::Loss));
        const PreparedMesh& prepared = *window_->preparedMesh();
        const std::vector<FaceLoss> expected = faceLosses(
            clusters, *window_->currentStatistics(),
            classifyFaces(prepared.mesh(), prepared.world, prepared.faces, window_->currentStatistics()->eye));
        vtkDataArray* loss = window_->scene()->meshPolyData()->GetCellData()->GetArray(lossArrayName);
        QVERIFY(loss);
        size_t testLoss = 0;
        for (size_t f = 0; f < expected.size(); ++f) {
            QCOMPARE(loss->GetTuple1(vtkIdType(f)), double(expected[f]));
            testLoss += expected[f] == FaceLoss::Test;
        }
        QVERIFY(legendText(*window_->scene()).contains(QStringLiteral("lost to the test (%1)").arg(testLoss)));
        saveWindowPicture(QStringLiteral("window-loss.png"));
        QTest::keyClick(window_.get(), Qt::Key_2, Qt::ControlModifier);
    }

    void pinnedAComparesWithTheCurrentSettings() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        window_->setEyePosition({0.6, 0.3, 1.4});
        QVERIFY(!window_->session().hasPin());
        QVERIFY(!window_->statisticsPanel()->findChild<QLabel*>(QStringLiteral("A (pinned)"))->isVisibleTo(window_->statisticsPanel()));
        // A: the default builder. B: meshoptimizer's builder. A is pinned with its comparison.
        QTest::keyClick(window_.get(), Qt::Key_A);
        window_->waitUntilIdle();
        QVERIFY(window_->session().hasPin());
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::Comparison));
        Settings b = window_->settings();
        b.builder = Builder::Meshopt;
        window_->setSettings(b);
        window_->waitUntilIdle();
        QVERIFY(window_->settings().builder == Builder::Meshopt);
        QVERIFY(window_->session().pinnedSettings()->builder == Builder::Optimized);

        // The scene's per-face diff is the core's for the eye, and the legend counts its triangles.
        const PreparedMesh& prepared = *window_->preparedMesh();
        const ClusterSet& a = *window_->session().pinnedClusters();
        const ClusterSet& current = *window_->clusters();
        const Eye eye = window_->currentStatistics()->eye;
        const Settings& settingsA = *window_->session().pinnedSettings();
        const std::vector<FaceDiff> diff = faceDiff(a, measureEye(prepared, a, eye, displayedTest(settingsA)).culled, current,
                                                    window_->currentStatistics()->culled);
        vtkDataArray* shown = window_->scene()->meshPolyData()->GetCellData()->GetArray(comparisonArrayName);
        QVERIFY(shown);
        size_t onlyA = 0;
        for (size_t f = 0; f < diff.size(); ++f) {
            QCOMPARE(shown->GetTuple1(vtkIdType(f)), double(diff[f]));
            onlyA += diff[f] == FaceDiff::OnlyA;
        }
        QVERIFY(legendText(*window_->scene()).contains(QStringLiteral("culled by A only (%1 tris)").arg(onlyA)));
        // The paired statistics over the orbit are the core's comparison.
        QTRY_VERIFY(window_->session().orbitComparison());
        const Comparison expected = compareClusterSets(prepared, {a, settingsA}, {current, window_->settings()},
                                                       orbitOf(window_->settings(), prepared.box));
        const Comparison& orbit = *window_->session().orbitComparison();
        QCOMPARE(orbit.trianglesCulledOnlyA, expected.trianglesCulledOnlyA);
        QCOMPARE(orbit.trianglesCulledOnlyB, expected.trianglesCulledOnlyB);
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("A / B culled over the orbit"))
                    .contains(QLocale().toString(qulonglong(expected.trianglesCulledOnlyA))));
        QVERIFY(window_->statisticsPanel()->findChild<QLabel*>(QStringLiteral("A (pinned)"))->isVisibleTo(window_->statisticsPanel()));
        // A's summary says its cone and test first (what A and B differ in), then its effort and budget:
        // an explicit budget is searched longer.
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("A (pinned)")),
                 QString::fromStdString(toString(kDefaultCone)) + QStringLiteral(" / octagon, optimized (balanced, default budget), 64/124"));
        // The picked cluster is shown under A too.
        window_->pickCluster(0);
        QVERIFY(window_->clusterReportHtml().contains(QStringLiteral("Under A (pinned): cluster %1").arg(window_->session().pinnedClusterOf(0))));
        saveWindowPicture(QStringLiteral("window-compare.png"));

        // X swaps: the current settings are A's, A is what was current; nothing is rebuilt.
        const ClusterSet* clustersOfA = &a;
        QTest::keyClick(window_.get(), Qt::Key_X);
        window_->waitUntilIdle();
        QVERIFY(window_->settings().builder == Builder::Optimized);
        QVERIFY(window_->session().pinnedSettings()->builder == Builder::Meshopt);
        QCOMPARE(window_->clusters(), clustersOfA);
        QVERIFY(window_->settingsPanel()->settings().builder == Builder::Optimized);
        QTRY_VERIFY(window_->session().orbitComparison());
        QCOMPARE(window_->session().orbitComparison()->trianglesCulledOnlyA, expected.trianglesCulledOnlyB);
        // Unequal cluster counts are said in the panel.
        const std::string warning = clusterCountWarning(*window_->session().orbitComparison());
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("A / B clusters")).contains(QStringLiteral("more than 5%")), !warning.empty());

        // Another winding repair makes another prepared mesh: A was made for the old one and goes.
        Settings repaired = window_->settings();
        repaired.fixWinding = true;
        window_->setSettings(repaired);
        window_->waitUntilIdle();
        QVERIFY(!window_->session().hasPin());
        QTest::keyClick(window_.get(), Qt::Key_A);
        window_->waitUntilIdle();
        QVERIFY(window_->session().hasPin());
        // Shift+A clears the pin and goes back to the decision colours; a new mesh clears it too.
        QTest::keyClick(window_.get(), Qt::Key_A, Qt::ShiftModifier);
        QVERIFY(!window_->session().hasPin());
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::CullDecision));
        QTest::keyClick(window_.get(), Qt::Key_A);
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QVERIFY(!window_->session().hasPin());
        window_->pickCluster(-1);
        window_->setFaceColoring(FaceColoring::CullDecision);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void pinAfterATestOnlyChangeFindsNoDifference() {
        openElephantWithFewViews();
        // Only the Test box changes: no new clusters. A is then exactly what B is.
        chooseInCombo(window_->settingsPanel()->testBox(), "apex");
        window_->waitUntilIdle();
        QTest::keyClick(window_.get(), Qt::Key_A);
        window_->waitUntilIdle();
        QVERIFY(window_->session().hasPin());
        const Comparison* eye = window_->session().eyeComparison();
        QVERIFY(eye);
        QCOMPARE(eye->trianglesCulledOnlyA, size_t(0));
        QCOMPARE(eye->trianglesCulledOnlyB, size_t(0));
        QCOMPARE(eye->efficiencyA, eye->efficiencyB);
        QCOMPARE(eye->efficiencyB, window_->currentStatistics()->view().efficiency);
        QTRY_VERIFY(window_->session().orbitComparison());
        const Comparison& orbit = *window_->session().orbitComparison();
        QCOMPARE(orbit.trianglesCulledOnlyA, size_t(0));
        QCOMPARE(orbit.trianglesCulledOnlyB, size_t(0));
        // Both sides scored with the apex test: the orbit's efficiency for apex on these clusters.
        const PreparedMesh& prepared = *window_->preparedMesh();
        const double apex = measureCulling(cullingInput(prepared, *window_->clusters()), orbitOf(window_->settings(), prepared.box),
                                           CullTest::Apex)
                                .efficiency;
        QCOMPARE(orbit.efficiencyA, apex);
        QCOMPARE(orbit.efficiencyB, apex);
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("A / B culled over the orbit")).startsWith(QStringLiteral("0 only by A, 0 only by B")));
        unpinAndResetSettings();
    }

    void eachPinnedSideIsScoredWithItsOwnTest() {
        openElephantWithFewViews();
        // meshoptimizer's pipeline through the boxes, one at a time, as a user sets it; pinned; the
        // defaults back.
        SettingsPanel* panel = window_->settingsPanel();
        for (const auto& [box, name] : {std::pair{panel->builderBox(), "meshopt"}, {panel->coneBox(), "meshopt"}, {panel->testBox(), "apex"}}) {
            chooseInCombo(box, name);
            window_->waitUntilIdle();
        }
        QTest::keyClick(window_.get(), Qt::Key_A);
        for (const auto& [box, name] : {std::pair{panel->testBox(), "octagon"}, {panel->coneBox(), "minimal"}, {panel->builderBox(), "optimized"}}) {
            chooseInCombo(box, name);
            window_->waitUntilIdle();
        }
        QTRY_VERIFY(window_->session().orbitComparison());
        // Each side on its own, from the file: meshopt/meshopt culled by apex, the defaults by octagon.
        Settings settingsA = window_->settings();
        settingsA.builder = Builder::Meshopt, settingsA.cones = {ConeMethod::Meshopt}, settingsA.tests = {CullTest::Apex};
        const Settings settingsB = window_->settings();
        const PreparedMesh prepared = loadMesh(datasetPath("elephant.off").toStdString(), settingsB);
        const std::vector<Eye> views = orbitOf(settingsB, prepared.box);
        const ClusterSet a = buildClusters(prepared, settingsA), b = buildClusters(prepared, settingsB);
        const CullTestStatistics expectedA = measureCulling(cullingInput(prepared, a), views, CullTest::Apex);
        const CullTestStatistics expectedB = measureCulling(cullingInput(prepared, b), views, CullTest::Octagon);
        const Comparison& orbit = *window_->session().orbitComparison();
        QCOMPARE(orbit.efficiencyA, expectedA.efficiency);
        QCOMPARE(orbit.efficiencyB, expectedB.efficiency);
        QCOMPARE(orbit.trianglesCulledOnlyA + orbit.trianglesCulledBoth, expectedA.trianglesCulled);
        QCOMPARE(orbit.trianglesCulledOnlyB + orbit.trianglesCulledBoth, expectedB.trianglesCulled);
        // The eye's pair as well.
        const EyeMeasurement eyeA = measureEye(prepared, a, window_->currentStatistics()->eye, CullTest::Apex);
        QCOMPARE(window_->session().eyeComparison()->efficiencyA, eyeA.view().efficiency);
        unpinAndResetSettings();
    }

    void measurementsInFlightSurviveAChangeThatDoesNotConcernThem() {
        openElephantWithFewViews();
        Settings meshopt = window_->settings();
        meshopt.builder = Builder::Meshopt;
        window_->setSettings(meshopt);
        window_->waitUntilIdle();
        QTest::keyClick(window_.get(), Qt::Key_A);
        // New views start the orbit and the comparison; the builder's effort, which meshoptimizer's
        // builder does not use, changes before either is delivered.
        Settings more = window_->settings();
        more.views = 40;
        window_->setSettings(more);
        more.effort = Effort::Fast;
        window_->setSettings(more);
        window_->waitUntilIdle();
        QVERIFY(window_->session().orbitStatistics());
        QCOMPARE(window_->orbitStatistics().size(), size_t(40));
        QVERIFY(window_->session().orbitComparison());
        QCOMPARE(window_->session().orbitComparison()->views.size(), size_t(40));
        unpinAndResetSettings();
    }

    void pickedClusterPageKeepsItsPlaceWhileTheEyeMoves() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->setEyePosition({0.4, -2.2, 1.3});
        auto* page = window_->findChild<QTextBrowser*>(QStringLiteral("clusterReport"));
        QVERIFY(page);
        // A short page view, so the report of the octagon test (eight edges) scrolls.
        page->setFixedHeight(120);
        QApplication::processEvents();
        window_->pickCluster(3);
        QApplication::processEvents();
        QScrollBar* scroll = page->verticalScrollBar();
        QVERIFY(scroll->maximum() > 40);
        scroll->setValue(scroll->maximum() / 2);
        const int place = scroll->value();
        QVERIFY(place > 0);
        // The eye dragged, N pressed: the reader stays where the margin is.
        window_->setEyePosition({0.5, -2.1, 1.4});
        QApplication::processEvents();
        QCOMPARE(scroll->value(), place);
        QTest::keyClick(window_.get(), Qt::Key_N);
        QApplication::processEvents();
        QCOMPARE(scroll->value(), place);
        // Another cluster starts at its top.
        window_->pickCluster(4);
        QApplication::processEvents();
        QCOMPARE(scroll->value(), 0);
        window_->pickCluster(-1);
        page->setMinimumHeight(0);
        page->setMaximumHeight(QWIDGETSIZE_MAX);
    }

    void secondMeshGetsItsOwnScale() {
        // A mesh a thousand times larger, then the unit cube: the camera, the eye handle and the eye
        // marker must follow the cube's size, and Reset must frame the cube.
        const QString large = temporary_.filePath(QStringLiteral("large-cube.off"));
        {
            QFile file(large);
            QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Text));
            QTextStream out(&file);
            out << "OFF\n8 12 0\n";
            for (int i = 0; i < 8; ++i) out << ((i & 1) ? 500 : -500) << ' ' << ((i & 2) ? 500 : -500) << ' ' << ((i & 4) ? 500 : -500) << '\n';
            const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                                      {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
            for (const auto& face : faces) out << "3 " << face[0] << ' ' << face[1] << ' ' << face[2] << '\n';
        }
        QVERIFY(window_->openMeshBlocking(large));
        QVERIFY(window_->openMeshBlocking(datasetPath("cube.off")));
        auto cameraDistance = [this]() {
            vtkCamera* camera = observerRenderer(*window_)->GetActiveCamera();
            return camera->GetDistance();
        };
        const double size = 2.0 * window_->preparedMesh()->box.halfDiagonal();
        QVERIFY2(cameraDistance() < 20.0 * size, qPrintable(QString::number(cameraDistance())));
        QVERIFY(glm::length(window_->eyePosition()) < 10.0 * size);
        // Every prop the observer shows, the eye handle too, is within reach of the cube: nothing sized
        // for the large mesh.
        vtkPropCollection* props = observerRenderer(*window_)->GetViewProps();
        props->InitTraversal();
        while (vtkProp* prop = props->GetNextProp()) {
            const double* bounds = prop->GetVisibility() ? prop->GetBounds() : nullptr;
            for (int i = 0; bounds && i < 6; ++i)
                QVERIFY2(std::abs(bounds[i]) < 10.0 * size, qPrintable(QString::fromLatin1(prop->GetClassName()) + " " + QString::number(bounds[i])));
        }
        vtkCamera* camera = observerRenderer(*window_)->GetActiveCamera();
        camera->SetPosition(0.0, 0.0, 5000.0);
        QTest::keyClick(window_.get(), Qt::Key_R);
        QVERIFY2(cameraDistance() < 20.0 * size, qPrintable(QString::number(cameraDistance())));
        saveWindowPicture(QStringLiteral("window-second-mesh.png"));
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    DebuggerWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "DebuggerWindowTests.moc"
