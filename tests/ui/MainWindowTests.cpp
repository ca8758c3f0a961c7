// The window driven as a user would (shortcuts, combo boxes, typed coordinates, mouse clicks) and
// through its test interface, with every number checked against the core computed in-process. Its
// files (exports, bad and dropped files, cancelled loads) are in FileWindowTests.cpp.
#include <set>

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDockWidget>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QTextBrowser>
#include <QTimer>
#include <QFile>
#include <QSurfaceFormat>
#include <QTabWidget>
#include <QSpinBox>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>

#include "EyePanel.h"
#include "GaussMapView.h"
#include "MainWindow.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "PlotsView.h"
#include "WorstClustersView.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

// Types a value into a spin box and presses Enter.
void typeInto(QDoubleSpinBox* box, double value) {
    box->setFocus();
    box->selectAll();
    QTest::keyClicks(box, QString::number(value, 'g', 10));
    QTest::keyClick(box, Qt::Key_Return);
}

glm::dvec3 cameraPosition(MainWindow& window) {
    double position[3];
    observerRenderer(window)->GetActiveCamera()->GetPosition(position);
    return {position[0], position[1], position[2]};
}

// The eye's single view as runStatistics gives it for the window's settings.
ViewStatistics expectedView(MainWindow& window) {
    Settings settings = window.settings();
    settings.cones = {settings.cones.front()};
    settings.tests = {settings.tests.front()};
    settings.eye = window.eyePosition();
    const RunStatistics run = statisticsInProcess(QString::fromStdString(window.preparedMesh()->path), settings);
    return run.results.front().views.front();
}

void compareWithCore(MainWindow& window) {
    const EyeMeasurement* measured = window.currentStatistics();
    QVERIFY(measured);
    const ViewStatistics expected = expectedView(window);
    const ViewStatistics& view = measured->view();
    QCOMPARE(view.clustersCulled, expected.clustersCulled);
    QCOMPARE(view.trianglesCulled, expected.trianglesCulled);
    QCOMPARE(view.backFacingTriangles, expected.backFacingTriangles);
    QCOMPARE(view.missedClusters, expected.missedClusters);
    QCOMPARE(view.falseCulls, size_t(0));
    QCOMPARE(view.efficiency, expected.efficiency);
}

}  // namespace

class MainWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

private slots:
    void initTestCase() { openWindow(); }

    void init() { window_->observerView()->setFocus(); }

    void cleanupTestCase() { window_.reset(); }

    void loadsAMesh() {
        const QString path = datasetPath("icosphere.off");
        QVERIFY(window_->openMeshBlocking(path));
        const PreparedMesh* prepared = window_->preparedMesh();
        QVERIFY(prepared);
        QCOMPARE(prepared->mesh().faceCount(), size_t(1280));
        QVERIFY(window_->clusters()->partition.clusterCount > 1);
        QCOMPARE(window_->scene()->clusterCount(), size_t(window_->clusters()->partition.clusterCount));
        QVERIFY(window_->windowTitle().contains(QStringLiteral("icosphere.off")));
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("faces")), QLocale().toString(1280));
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("false culls")), QStringLiteral("0"));
        QVERIFY(window_->recentFiles().contains(QFileInfo(path).absoluteFilePath()));
        compareWithCore(*window_);
        // The orbit measured in the background feeds the efficiency plot: one row per view.
        QCOMPARE(window_->orbitStatistics().size(), window_->settings().views);
        saveWindowPicture(QStringLiteral("window-icosphere.png"));
    }

    void startsWithDefaultSettings() {
        // The lead tunes Settings{}; the window must start on exactly those.
        MainWindow fresh;
        const Settings shown = fresh.settingsPanel()->settings();
        const Settings defaults;
        QVERIFY(shown.builder == defaults.builder);
        QVERIFY(shown.cones.front() == defaults.cones.front());
        QVERIFY(shown.tests.front() == defaults.tests.front());
        QVERIFY(shown.sphere == defaults.sphere);
        QCOMPARE(shown.limits.maxVertices, defaults.limits.maxVertices);
        QCOMPARE(shown.limits.maxTriangles, defaults.limits.maxTriangles);
        QCOMPARE(shown.views, defaults.views);
        QCOMPARE(shown.distance, defaults.distance);
        QCOMPARE(shown.orthographic, defaults.orthographic);
        // A first look a class can read: the faces by decision, the borders and the eye; cones, boxes,
        // normals and spheres wait for their keys.
        for (Layer layer : {Layer::Faces, Layer::Borders, Layer::Eye, Layer::Legend})
            QVERIFY2(fresh.layerVisible(layer), toString(layer).c_str());
        for (Layer layer : {Layer::Cones, Layer::Boxes, Layer::Normals, Layer::Spheres})
            QVERIFY2(!fresh.layerVisible(layer), toString(layer).c_str());
        QCOMPARE(int(fresh.session().faceColoring()), int(FaceColoring::CullDecision));
    }

    void settingsWidgetsRecompute() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        SettingsPanel* panel = window_->settingsPanel();
        std::set<size_t> culledTriangles;
        std::set<uint32_t> clusterCounts;

        chooseInCombo(panel->builderBox(), toString(Builder::KMeans));
        window_->waitUntilIdle();
        QVERIFY(window_->clusters()->builtWith.builder == Builder::KMeans);
        clusterCounts.insert(window_->clusters()->partition.clusterCount);
        compareWithCore(*window_);
        culledTriangles.insert(window_->currentStatistics()->view().trianglesCulled);

        chooseInCombo(panel->builderBox(), toString(Builder::Meshopt));
        window_->waitUntilIdle();
        QVERIFY(window_->clusters()->builtWith.builder == Builder::Meshopt);
        clusterCounts.insert(window_->clusters()->partition.clusterCount);
        compareWithCore(*window_);

        // The effort box is the optimized builder's only: off for the others, and each level rebuilds.
        QVERIFY(!panel->effortBox()->isEnabled());
        chooseInCombo(panel->builderBox(), toString(Builder::Optimized));
        QVERIFY(panel->effortBox()->isEnabled());
        for (Effort effort : allEfforts()) {
            chooseInCombo(panel->effortBox(), toString(effort));
            window_->waitUntilIdle();
            QVERIFY(window_->clusters()->builtWith.effort == effort);
            compareWithCore(*window_);
        }
        chooseInCombo(panel->builderBox(), toString(Builder::Meshopt));
        panel->maxTrianglesBox()->setValue(64);
        window_->waitUntilIdle();
        QCOMPARE(window_->clusters()->builtWith.limits.maxTriangles, size_t(64));
        clusterCounts.insert(window_->clusters()->partition.clusterCount);
        compareWithCore(*window_);
        QVERIFY2(clusterCounts.size() >= 2, "changing the builder and its limits changes the clusters");

        for (ConeMethod cone : allConeMethods()) {
            chooseInCombo(panel->coneBox(), toString(cone));
            window_->waitUntilIdle();
            QVERIFY(window_->clusters()->bounds.coneMethod == cone);
            compareWithCore(*window_);
            culledTriangles.insert(window_->currentStatistics()->view().trianglesCulled);
        }
        for (CullTest test : allCullTests()) {
            chooseInCombo(panel->testBox(), toString(test));
            window_->waitUntilIdle();
            QVERIFY(window_->currentStatistics()->statistics.test == test);
            compareWithCore(*window_);
            culledTriangles.insert(window_->currentStatistics()->view().trianglesCulled);
        }
        QVERIFY2(culledTriangles.size() >= 3, "builders, cones and tests give different culled counts");

        // The T shortcut walks the tests the same way.
        const CullTest before = displayedTest(window_->settings());
        QTest::keyClick(window_.get(), Qt::Key_T);
        window_->waitUntilIdle();
        QVERIFY(displayedTest(window_->settings()) != before);
        QCOMPARE(panel->testBox()->currentText(), QString::fromStdString(toString(displayedTest(window_->settings()))));
        compareWithCore(*window_);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void typedEyeChangesCulling() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        EyePanel* eye = window_->eyePanel();
        typeInto(eye->coordinateBox(0), 0.0);
        typeInto(eye->coordinateBox(1), 0.0);
        typeInto(eye->coordinateBox(2), 4.0);
        QCOMPARE(window_->eyePosition(), glm::dvec3(0.0, 0.0, 4.0));
        compareWithCore(*window_);
        const std::vector<uint8_t> fromFront = window_->currentStatistics()->culled;
        QVERIFY(window_->currentStatistics()->view().clustersCulled > 0);

        typeInto(eye->coordinateBox(2), -4.0);
        QCOMPARE(window_->eyePosition(), glm::dvec3(0.0, 0.0, -4.0));
        compareWithCore(*window_);
        const std::vector<uint8_t> fromBehind = window_->currentStatistics()->culled;
        QVERIFY2(fromFront != fromBehind, "moving the eye to the other side culls other clusters");
        // Clusters on the far side from one eye face the other eye: culled from one side only.
        size_t culledFromFrontOnly = 0;
        for (size_t c = 0; c < fromFront.size(); ++c) culledFromFrontOnly += fromFront[c] && !fromBehind[c];
        QVERIFY(culledFromFrontOnly > 0);
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("clusters culled")),
                 QStringLiteral("%1 / %2").arg(QLocale().toString(qulonglong(window_->currentStatistics()->view().clustersCulled)),
                                               QLocale().toString(qulonglong(fromBehind.size()))));

        // Orthographic: the eye becomes a direction towards the centre; the core agrees.
        // (shown with its orbit, once that is measured).
        chooseInCombo(window_->settingsPanel()->projectionBox(), "orthographic");
        window_->waitUntilIdle();
        QVERIFY(window_->currentStatistics()->eye.orthographic);
        compareWithCore(*window_);
        QTest::keyClick(window_.get(), Qt::Key_O);
        window_->waitUntilIdle();
        QVERIFY(!window_->settings().orthographic);
        QVERIFY(!window_->currentStatistics()->eye.orthographic);
        window_->waitUntilIdle();
    }

    void lookFromHereAndFollow() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        window_->activateWindow();
        window_->observerView()->setFocus();
        QTest::keyClick(window_.get(), Qt::Key_E);
        QCOMPARE(window_->eyePosition(), cameraPosition(*window_));
        compareWithCore(*window_);

        QTest::keyClick(window_.get(), Qt::Key_F);
        QVERIFY(window_->followAction()->isChecked());
        QVERIFY(window_->eyePanel()->followBox()->isChecked());
        vtkCamera* camera = observerRenderer(*window_)->GetActiveCamera();
        camera->Azimuth(70.0);
        camera->Elevation(20.0);
        QTRY_COMPARE(window_->eyePosition(), cameraPosition(*window_));
        QTRY_VERIFY(window_->currentStatistics()->eye.position == cameraPosition(*window_));
        compareWithCore(*window_);
        QTest::keyClick(window_.get(), Qt::Key_F);
        QVERIFY(!window_->followAction()->isChecked());
        const glm::dvec3 kept = window_->eyePosition();
        camera->Azimuth(40.0);
        QTest::qWait(50);
        QCOMPARE(window_->eyePosition(), kept);
    }

    void orbitAnimationFollowsTheStandardViews() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const std::vector<Eye> views = orbitOf(window_->settings(), window_->preparedMesh()->box);
        // The eye starts off the orbit: N goes on from the orbit view nearest to it.
        const size_t nearest = nearestOrbitView(window_->settings(), window_->preparedMesh()->box, window_->eyePosition());
        QTest::keyClick(window_.get(), Qt::Key_N);
        QCOMPARE(window_->eyePosition(), views[(nearest + 1) % views.size()].position);
        QTest::keyClick(window_.get(), Qt::Key_N);
        const size_t second = (nearest + 2) % views.size();
        QCOMPARE(window_->eyePosition(), views[second].position);
        compareWithCore(*window_);
        // The window's orbit rows are runStatistics' views rows for the same settings.
        QCOMPARE(window_->currentStatistics()->view().trianglesCulled, window_->orbitStatistics()[second].trianglesCulled);

        QTest::keyClick(window_.get(), Qt::Key_Space);
        QVERIFY(window_->animateAction()->isChecked());
        const glm::dvec3 start = window_->eyePosition();
        QTRY_VERIFY_WITH_TIMEOUT(window_->eyePosition() != start, 3000);
        QTest::keyClick(window_.get(), Qt::Key_Space);
        QVERIFY(!window_->animateAction()->isChecked());
        const glm::dvec3 stopped = window_->eyePosition();
        QVERIFY(std::find_if(views.begin(), views.end(), [&](const Eye& eye) { return eye.position == stopped; }) != views.end());
        QTest::qWait(400);
        QCOMPARE(window_->eyePosition(), stopped);
    }

    void worstClustersTableRanksAndShowsWhereAClusterIsLost() {
        QVERIFY(window_->openMeshBlocking(datasetPath("fandisk.off")));
        window_->waitUntilIdle();
        WorstClustersView* table = window_->worstClustersView();
        const CullTestStatistics* orbit = window_->session().orbitStatistics();
        QVERIFY(orbit);
        QCOMPARE(size_t(table->rowCount()), window_->clusters()->partition.clusterCount);
        // The partition's summary over the orbit, in the statistics panel.
        const QString efficiency = QString::number(100.0 * orbit->efficiency, 'f', 1) + QLatin1Char('%');
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("orbit efficiency")).startsWith(efficiency));
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("lost over the orbit")).contains(QStringLiteral("by the partition")));
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("cull / oracle fraction"))
                    .startsWith(QString::number(orbit->cullFraction, 'f', 3)));
        // Worst test loss first, as measureOrbit counted it.
        size_t worst = 0;
        for (const ClusterStatistics& cluster : orbit->clusters) worst = std::max(worst, cluster.testLossTriangles);
        QVERIFY(worst > 0);
        QCOMPARE(orbit->clusters.at(size_t(table->clusterAt(0))).testLossTriangles, worst);
        for (int row = 1; row < table->rowCount(); ++row)
            QVERIFY(orbit->clusters.at(size_t(table->clusterAt(row - 1))).testLossTriangles >=
                    orbit->clusters.at(size_t(table->clusterAt(row))).testLossTriangles);
        // Sorting by another column re-orders by that number.
        table->sortByColumn(8, Qt::DescendingOrder);  // radius
        QCOMPARE(orbit->clusters.at(size_t(table->clusterAt(0))).sphereRadius,
                 std::max_element(orbit->clusters.begin(), orbit->clusters.end(), [](const auto& a, const auto& b) {
                     return a.sphereRadius < b.sphereRadius;
                 })->sphereRadius);
        table->sortByColumn(1, Qt::DescendingOrder);

        // A click on the worst row picks that cluster and puts the eye where the test misses it.
        auto* dock = qobject_cast<QDockWidget*>(table->parentWidget());
        QVERIFY(dock);
        dock->raise();
        QApplication::processEvents();
        const int cluster = table->clusterAt(0);
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualItemRect(table->item(0, 0)).center());
        window_->waitUntilIdle();
        QCOMPARE(window_->pickedCluster(), cluster);
        QVERIFY(window_->currentStatistics());
        const ClusterStatistics& now = window_->currentStatistics()->statistics.clusters.at(size_t(cluster));
        QCOMPARE(now.timesMissed, size_t(1));
        QCOMPARE(now.timesCulled, size_t(0));
        QVERIFY(window_->session().orbitStep() >= 0);
        QVERIFY(window_->clusterReportHtml().contains(QStringLiteral("%1").arg(cluster)));
        saveWindowPicture(QStringLiteral("window-worst-clusters.png"));
    }

    void boxesShowAndExportOnlyWhatIsChosen() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        SettingsPanel* panel = window_->settingsPanel();
        for (CullTest test : {CullTest::Sphere, CullTest::Aabb, CullTest::Apex}) {
            chooseInCombo(panel->testBox(), toString(test));
            window_->waitUntilIdle();
            // The statistics name the test this eye was measured with, though the clusters stayed.
            QVERIFY2(window_->statisticsPanel()->value(QStringLiteral("cone / test")).endsWith(QString::fromStdString(toString(test))),
                     qPrintable(window_->statisticsPanel()->value(QStringLiteral("cone / test"))));
        }
        // Earlier choices are not kept as hidden extra results: an export has the one test shown.
        QVERIFY(window_->settings().tests == std::vector<CullTest>{CullTest::Apex});
        const QString path = QDir(temporary_.path()).filePath(QStringLiteral("one-test.json"));
        QVERIFY(window_->exportStatistics(path, StatisticsFormat::Json, false));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QCOMPARE(nlohmann::json::parse(file.readAll().toStdString())["results"].size(), size_t(1));
    }

    void followingHidesTheEyeMarker() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QVERIFY(window_->layerVisible(Layer::Eye));
        window_->setFollowing(true);
        QVERIFY2(!window_->session().layerVisible(Layer::Eye), "the marker would sit on the camera");
        QVERIFY(!window_->scene()->layerVisible(Layer::Eye));
        window_->setFollowing(false);
        QVERIFY(window_->session().layerVisible(Layer::Eye));
        QVERIFY(window_->scene()->layerVisible(Layer::Eye));
    }

    void clickingTheEfficiencyPlotMovesTheEyeToThatView() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->waitUntilIdle();
        PlotsView* plots = window_->plotsView();
        auto* dock = qobject_cast<QDockWidget*>(plots->parentWidget());
        QVERIFY(dock);
        dock->raise();
        plots->setCurrentIndex(0);
        QApplication::processEvents();
        window_->render();
        QWidget* widget = plots->efficiencyWidget();
        QVERIFY(widget->isVisible());
        const long target = 37;
        const double x = plots->displayXOfView(target);
        QCOMPARE(plots->viewAtDisplayX(x), target);
        const double ratio = widget->devicePixelRatioF();
        QTest::mouseClick(widget, Qt::LeftButton, {}, QPoint(int(std::lround(x / ratio)), widget->height() / 2));
        window_->waitUntilIdle();
        QCOMPARE(window_->session().orbitStep(), target);
        const std::vector<Eye> views = orbitOf(window_->settings(), window_->preparedMesh()->box);
        QCOMPARE(window_->eyePosition(), views[size_t(target)].position);
    }

    void clickPicksACluster() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        window_->setEyePosition({0.0, 0.0, 4.0});
        // Cones and the eye marker would hide the face behind them: the cones are off at first, the eye
        // is switched off with its key (and the cones' key toggles them on and off again).
        const int conesKey = Qt::Key_1 + int(std::find(allLayers().begin(), allLayers().end(), Layer::Cones) - allLayers().begin());
        const int eyeKey = Qt::Key_1 + int(std::find(allLayers().begin(), allLayers().end(), Layer::Eye) - allLayers().begin());
        QVERIFY(!window_->layerVisible(Layer::Cones));
        QTest::keyClick(window_.get(), Qt::Key(conesKey));
        QVERIFY(window_->layerVisible(Layer::Cones));
        QTest::keyClick(window_.get(), Qt::Key(conesKey));
        QTest::keyClick(window_.get(), Qt::Key(eyeKey));
        QVERIFY(!window_->layerVisible(Layer::Cones));
        QVERIFY(!window_->layerVisible(Layer::Eye));
        window_->resetCamera();

        // The face turned most towards the camera: its centroid is certainly visible.
        const PreparedMesh& prepared = *window_->preparedMesh();
        const glm::dvec3 camera = cameraPosition(*window_);
        size_t best = 0;
        double bestFacing = -2.0;
        for (size_t f = 0; f < prepared.mesh().faceCount(); ++f) {
            const double facing = glm::dot(prepared.faces.normals[f], glm::normalize(camera - prepared.faces.centroids[f]));
            if (facing > bestFacing) bestFacing = facing, best = f;
        }
        const int expected = int(window_->clusters()->partition.clusterOfFace[best]);
        const QPoint where = window_->viewPositionOf(prepared.faces.centroids[best]);
        QVERIFY(window_->observerView()->rect().contains(where));
        QTest::mouseClick(window_->observerView(), Qt::LeftButton, Qt::NoModifier, where);
        QCOMPARE(window_->pickedCluster(), expected);
        QCOMPARE(window_->scene()->highlightedCluster(), expected);

        // The panel shows the core's numbers for this cluster and eye.
        const ClusterBounds& bounds = window_->clusters()->bounds;
        const CullExplanation why = explainCull(cullingInput(prepared, *window_->clusters()), uint32_t(expected),
                                                window_->currentStatistics()->eye, displayedTest(window_->settings()));
        const QString report = window_->clusterReportHtml();
        QVERIFY(report.contains(QStringLiteral("Cluster %1").arg(expected)));
        QVERIFY(report.contains(QString::number(bounds.triangles[size_t(expected)])));
        QVERIFY(report.contains(QString::number(why.halfAngleDegrees, 'f', 3)));
        QVERIFY(report.contains(QString::number(bounds.spheres[size_t(expected)].radius, 'g', 7)));
        QVERIFY(report.contains(QStringLiteral("front-facing faces")));
        QVERIFY(report.contains(QString::fromStdString(toString(displayedTest(window_->settings())))));
        saveWindowPicture(QStringLiteral("window-picked.png"));

        // Escape clears the pick; a drag rotates the camera instead of picking.
        QTest::keyClick(window_.get(), Qt::Key_Escape);
        QCOMPARE(window_->pickedCluster(), -1);
        QTest::mousePress(window_->observerView(), Qt::LeftButton, Qt::NoModifier, where);
        QTest::mouseRelease(window_->observerView(), Qt::LeftButton, Qt::NoModifier, where + QPoint(40, 25));
        QCOMPARE(window_->pickedCluster(), -1);
        window_->resetCamera();
        QCOMPARE(window_->pickAt(where), expected);
        window_->pickCluster(-1);
        QTest::keyClick(window_.get(), Qt::Key(conesKey));
        QTest::keyClick(window_.get(), Qt::Key(eyeKey));
        QVERIFY(window_->layerVisible(Layer::Cones));
    }

    void explainsEveryTest() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->pickCluster(0);
        for (CullTest test : allCullTests()) {
            chooseInCombo(window_->settingsPanel()->testBox(), toString(test));
            window_->waitUntilIdle();
            const QString report = window_->clusterReportHtml();
            QVERIFY(report.contains(QStringLiteral("Cluster 0")));
            QVERIFY(report.contains(QStringLiteral("decision")));
            const bool culled = window_->currentStatistics()->culled[0] != 0;
            QVERIFY(report.contains(culled ? QStringLiteral("culled") : QStringLiteral("drawn")));
        }
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
        window_->pickCluster(-1);
    }


    void colouringKeysSwitchTheFaceColours() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::CullDecision));
        QTest::keyClick(window_.get(), Qt::Key_3, Qt::ControlModifier);
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::FaceFacing));
        // The oracle's facing per face reached the scene: front/back for every face, none unclassified.
        const std::vector<Facing> expected = classifyFaces(window_->preparedMesh()->mesh(), window_->preparedMesh()->world,
                                                           window_->preparedMesh()->faces, window_->currentStatistics()->eye);
        vtkDataArray* facing = window_->scene()->meshPolyData()->GetCellData()->GetArray(facingArrayName);
        QVERIFY(facing);
        QCOMPARE(size_t(facing->GetNumberOfTuples()), expected.size());
        for (size_t f = 0; f < expected.size(); ++f) QCOMPARE(facing->GetTuple1(vtkIdType(f)), double(expected[f]));
        // Moving the eye updates the facing too.
        window_->setEyePosition({0.0, 0.0, -3.0});
        const std::vector<Facing> moved = classifyFaces(window_->preparedMesh()->mesh(), window_->preparedMesh()->world,
                                                        window_->preparedMesh()->faces, window_->currentStatistics()->eye);
        for (size_t f = 0; f < moved.size(); ++f) QCOMPARE(facing->GetTuple1(vtkIdType(f)), double(moved[f]));
        auto* plots = window_->findChild<QTabWidget*>();
        QVERIFY(plots);
        plots->setCurrentIndex(1);
        saveWindowPicture(QStringLiteral("window-facing-histogram.png"));
        plots->setCurrentIndex(0);
        QTest::keyClick(window_.get(), Qt::Key_1, Qt::ControlModifier);
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::Cluster));
        QTest::keyClick(window_.get(), Qt::Key_2, Qt::ControlModifier);
        QCOMPARE(int(window_->scene()->faceColoring()), int(FaceColoring::CullDecision));
    }

    void eyeHandleDragMovesTheEye() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        window_->setEyePosition({1.5, 1.0, 2.5});
        window_->resetCamera();
        const glm::dvec3 before = window_->eyePosition();
        const QPoint start = window_->viewPositionOf(before);
        QVERIFY(window_->observerView()->rect().contains(start));
        QWidget* view = window_->observerView();
        QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, start);
        for (int step = 1; step <= 5; ++step) {
            const QPoint at = start + QPoint(-8 * step, 6 * step);
            QMouseEvent move(QEvent::MouseMove, at, view->mapToGlobal(at), Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
            QApplication::sendEvent(view, &move);
        }
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, start + QPoint(-40, 30));
        QTRY_VERIFY(window_->eyePosition() != before);
        QTRY_VERIFY(window_->currentStatistics()->eye.position == window_->eyePosition());
        // The handle moves the eye across the screen, towards the lower left.
        const QPoint after = window_->viewPositionOf(window_->eyePosition());
        QVERIFY(after.x() < start.x() - 20);
        QVERIFY(after.y() > start.y() + 15);
        // The typed-coordinates boxes show the new place (rounded to their decimals).
        for (int axis = 0; axis < 3; ++axis)
            QVERIFY(std::abs(window_->eyePanel()->position()[axis] - window_->eyePosition()[axis]) < 1e-3);
        compareWithCore(*window_);
    }

    void nextViewAfterDraggingTheEyeGoesOnFromWhereItWas() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const std::vector<Eye> views = orbitOf(window_->settings(), window_->preparedMesh()->box);
        const long onView = 5;
        for (size_t press = 0; press < views.size() && window_->session().orbitStep() != onView; ++press)
            QTest::keyClick(window_.get(), Qt::Key_N);
        QCOMPARE(window_->session().orbitStep(), onView);
        window_->resetCamera();  // the eye and its handle in the picture
        // The handle dragged a few pixels: the eye leaves the orbit, still nearest view 5.
        QWidget* view = window_->observerView();
        const QPoint start = window_->viewPositionOf(window_->eyePosition());
        QVERIFY(view->rect().contains(start));
        QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, start);
        QMouseEvent move(QEvent::MouseMove, start + QPoint(-4, 3), view->mapToGlobal(start + QPoint(-4, 3)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(view, &move);
        QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, start + QPoint(-4, 3));
        QTRY_VERIFY(window_->eyePosition() != views[size_t(onView)].position);
        QCOMPARE(window_->session().orbitStep(), -1L);
        const glm::dvec3 center(window_->preparedMesh()->box.center());
        const glm::dvec3 direction = glm::normalize(window_->eyePosition() - center);
        size_t nearest = 0;
        for (size_t v = 0; v < views.size(); ++v)
            if (glm::dot(direction, glm::normalize(views[v].position - center)) >
                glm::dot(direction, glm::normalize(views[nearest].position - center)))
                nearest = v;
        QCOMPARE(long(nearest), onView);
        // N: the view after it, not the first; P from there goes back.
        QTest::keyClick(window_.get(), Qt::Key_N);
        QCOMPARE(window_->session().orbitStep(), onView + 1);
        QCOMPARE(window_->eyePosition(), views[size_t(onView + 1)].position);
        QTest::keyClick(window_.get(), Qt::Key_P);
        QCOMPARE(window_->session().orbitStep(), onView);
    }

    void f1HelpListsEveryShortcut() {
        // The dialog F1 opens, read while it is open, then closed.
        QString shown;
        QTimer reader;
        connect(&reader, &QTimer::timeout, this, [&]() {
            auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            if (auto* browser = dialog->findChild<QTextBrowser*>()) shown = browser->toPlainText();
            dialog->reject();
        });
        reader.start(20);
        QTest::keyClick(window_.get(), Qt::Key_F1);
        QTRY_VERIFY(!shown.isEmpty());
        reader.stop();
        QApplication::setActiveWindow(window_.get());
        QTRY_COMPARE(QApplication::activeWindow(), window_.get());
        for (const char* key : {"Ctrl+O", "Ctrl+S", "Ctrl+Shift+S", "F1", "Space"}) QVERIFY2(shown.contains(QLatin1String(key)), key);
        for (const char* text : {"Put the eye at the camera", "Start or end the lesson", "Reset camera", "Animate along the orbit", "Show faces", "Pin as A",
                                 "Swap A and B", "Show the Gauss map"})
            QVERIFY2(shown.contains(QLatin1String(text)), text);
        // Every shortcut the window answers to is in the list.
        for (QAction* action : window_->findChildren<QAction*>()) {
            if (action->shortcut().isEmpty()) continue;
            QString text = action->text();
            text.remove(QLatin1Char('&'));
            QVERIFY2(shown.contains(text), qPrintable(text + " " + action->shortcut().toString()));
        }
    }

    void resetKeyLooksAtTheMesh() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        vtkCamera* camera = observerRenderer(*window_)->GetActiveCamera();
        camera->SetFocalPoint(10.0, 10.0, 10.0);
        camera->SetPosition(20.0, 10.0, 10.0);
        QTest::keyClick(window_.get(), Qt::Key_R);
        double focal[3];
        camera->GetFocalPoint(focal);
        const glm::dvec3 center(window_->preparedMesh()->box.center());
        // ResetCamera centres on everything shown (mesh, cones and eye marker): near the mesh centre.
        QVERIFY(glm::length(glm::dvec3(focal[0], focal[1], focal[2]) - center) < 2.0 * window_->preparedMesh()->box.halfDiagonal());
        QVERIFY(glm::length(glm::dvec3(focal[0], focal[1], focal[2]) - glm::dvec3(10.0)) > 5.0);
    }

};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    MainWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "MainWindowTests.moc"
