// The window's files as a user meets them: exports checked against the core and the command-line
// tool, the partition written for the file builder, bad, inside-out and dropped files, cancelled
// loads and screenshots. The view, eye and panels are in MainWindowTests.cpp.
#include <set>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QImage>
#include <QMessageBox>
#include <QMimeData>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QSet>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QTimer>
#include <QUrl>
#include <QtTest>

#include <QVTKOpenGLNativeWidget.h>
#include <vtkRenderWindow.h>

#include "core/meshopt/Meshopt.h"
#include "MainWindow.h"
#include "SettingsPanel.h"
#include "StatisticsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "WorstClustersView.h"
#include "core/Pipeline.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

// The bundled icosphere with every face turned over: consistent, but every normal points in.
QString writeInsideOutSphere(const QTemporaryDir& folder) {
    const Mesh sphere = readMesh(datasetPath("icosphere.off").toStdString());
    QString text = QStringLiteral("OFF\n%1 %2 0\n").arg(sphere.positions.size()).arg(sphere.faceCount());
    for (const glm::vec3& p : sphere.positions) text += QStringLiteral("%1 %2 %3\n").arg(p.x, 0, 'g', 9).arg(p.y, 0, 'g', 9).arg(p.z, 0, 'g', 9);
    for (size_t f = 0; f < sphere.faceCount(); ++f)
        text += QStringLiteral("3 %1 %2 %3\n").arg(sphere.faceBegin(f)[2]).arg(sphere.faceBegin(f)[1]).arg(sphere.faceBegin(f)[0]);
    const QString path = folder.filePath(QStringLiteral("inside-out.off"));
    QFile file(path);
    if (file.open(QIODevice::WriteOnly)) file.write(text.toUtf8());
    return path;
}

// The status bar's Cancel button, as a user presses it.
QPushButton* cancelButton(MainWindow& window) {
    for (QPushButton* button : window.findChildren<QPushButton*>())
        if (button->text() == QStringLiteral("Cancel")) return button;
    return nullptr;
}

}  // namespace

class FileWindowTests : public QObject, private WindowFixture {
    Q_OBJECT

private slots:
    void initTestCase() { openWindow(); }

    void init() { window_->observerView()->setFocus(); }

    void cleanupTestCase() { window_.reset(); }

    void exportsMatchTheCore() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        window_->setEyePosition({0.3, 2.0, 1.5});
        const Settings settings = window_->settings();
        const QString eyeJson = temporary_.filePath(QStringLiteral("eye.json"));
        const QString eyeCsv = temporary_.filePath(QStringLiteral("eye.csv"));
        const QString orbitJson = temporary_.filePath(QStringLiteral("orbit.json"));
        QVERIFY(window_->exportStatistics(eyeJson, StatisticsFormat::Json, false));
        QVERIFY(window_->exportStatistics(eyeCsv, StatisticsFormat::Csv, false));
        QVERIFY(window_->exportStatistics(orbitJson, StatisticsFormat::Json, true));

        Settings eyeSettings = settings;
        eyeSettings.eye = window_->eyePosition();
        const nlohmann::json expectedEye = statisticsToJson(statisticsInProcess(datasetPath("torus.off"), eyeSettings));
        const nlohmann::json expectedOrbit = statisticsToJson(statisticsInProcess(datasetPath("torus.off"), settings));
        const nlohmann::json writtenEye = readJsonFile(eyeJson);
        const nlohmann::json writtenOrbit = readJsonFile(orbitJson);
        for (const auto& [written, expected] : {std::pair{writtenEye, expectedEye}, std::pair{writtenOrbit, expectedOrbit}}) {
            QCOMPARE(written["clusters"], expected["clusters"]);
            QCOMPARE(written["view_count"], expected["view_count"]);
            QCOMPARE(written["settings"], expected["settings"]);
            QCOMPARE(written["mesh"], expected["mesh"]);
            QCOMPARE(written["results"].size(), expected["results"].size());
            for (size_t r = 0; r < expected["results"].size(); ++r)
                for (const char* key : {"cone", "test", "efficiency", "false_culls", "clusters_culled", "triangles_culled",
                                        "back_facing_triangles", "missed_clusters"})
                    QCOMPARE(written["results"][r][key], expected["results"][r][key]);
            QCOMPARE(written["results"][0]["false_culls"], nlohmann::json(0));
        }
        QCOMPARE(writtenEye["view_count"], nlohmann::json(1));
        QCOMPARE(writtenOrbit["view_count"], nlohmann::json(settings.views));
        // The window's efficiency plot shows the same per-view numbers the orbit export holds.
        const nlohmann::json& views = writtenOrbit["results"][0]["views"];
        QCOMPARE(views.size(), window_->orbitStatistics().size());
        for (size_t v = 0; v < views.size(); ++v) {
            QCOMPARE(views[v]["efficiency"].get<double>(), window_->orbitStatistics()[v].efficiency);
            QCOMPARE(views[v]["clusters_culled"].get<size_t>(), window_->orbitStatistics()[v].clustersCulled);
        }
        // The CSV holds the same totals as the JSON.
        // The CSV export is tidy: the totals in the file, the views and clusters beside it, one header each.
        const auto totals = readCsvTable(eyeCsv);
        QCOMPARE(readCsvTable(temporary_.filePath(QStringLiteral("eye.views.csv"))).size(), size_t(1));
        QCOMPARE(readCsvTable(temporary_.filePath(QStringLiteral("eye.clusters.csv"))).size(), window_->clusters()->bounds.count());
        QCOMPARE(totals.size(), size_t(1));
        QCOMPARE(std::stoul(totals[0].at("clusters_culled")), writtenEye["results"][0]["clusters_culled"].get<size_t>());
        QCOMPARE(std::stod(totals[0].at("efficiency")), writtenEye["results"][0]["efficiency"].get<double>());
        QCOMPARE(totals[0].at("false_culls"), std::string("0"));

#ifdef CONESCOPE_CLI_PATH
        // conescope-cli stats with the same settings writes the same numbers.
        for (const auto& [written, eye] : {std::pair{writtenEye, true}, std::pair{writtenOrbit, false}}) {
            const QString cliJson = temporary_.filePath(eye ? QStringLiteral("cli-eye.json") : QStringLiteral("cli-orbit.json"));
            QProcess cli;
            QStringList arguments{QStringLiteral("stats"), datasetPath("torus.off")};
            arguments << cliSettingsArguments(eye ? eyeSettings : settings) << QStringLiteral("--format")
                      << QStringLiteral("json") << QStringLiteral("-o") << cliJson;
            cli.start(QStringLiteral(CONESCOPE_CLI_PATH), arguments);
            QVERIFY(cli.waitForFinished(120000));
            QVERIFY2(cli.exitCode() == 0, cli.readAllStandardError().constData());
            const nlohmann::json fromCli = readJsonFile(cliJson);
            QCOMPARE(fromCli["clusters"], written["clusters"]);
            QCOMPARE(fromCli["view_count"], written["view_count"]);
            QCOMPARE(fromCli["settings"], written["settings"]);
            for (const char* key : {"efficiency", "false_culls", "clusters_culled", "triangles_culled"})
                QCOMPARE(fromCli["results"][0][key], written["results"][0][key]);
        }
#endif
    }

    void exportsThePartitionForTheFileBuilder() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        const uint32_t clusterCount = window_->clusters()->partition.clusterCount;
        const std::vector<uint32_t> clusterOfFace = window_->clusters()->partition.clusterOfFace;
        const QString path = temporary_.filePath(QStringLiteral("torus-clusters.vtp"));
        QVERIFY(window_->exportPartition(path));
        const Mesh written = readMesh(path.toStdString());
        for (const char* name : {"cluster_id", "cone_half_angle_deg", "cone_axis_x", "cone_axis_y", "cone_axis_z",
                                 "sphere_radius", "sphere_center_x", "aabb_min_x", "aabb_max_z", "cull_fraction",
                                 "oracle_fraction", "culled", "back_facing", "loss"})
            QVERIFY2(written.faceArrays.count(name) == 1, name);
        // The eye's arrays are the window's current measurement, face by face.
        const EyeMeasurement& eye = *window_->currentStatistics();
        size_t culledTriangles = 0;
        for (size_t f = 0; f < written.faceCount(); ++f) {
            QCOMPARE(written.faceArrays.at("culled")[f], double(eye.culled[clusterOfFace[f]]));
            culledTriangles += written.faceArrays.at("loss")[f] == double(FaceLoss::Culled) ? written.faceSize(f) - 2 : 0;
        }
        QCOMPARE(culledTriangles, eye.view().trianglesCulled);
        const ClusterBounds& bounds = window_->clusters()->bounds;
        for (size_t f = 0; f < written.faceCount(); ++f) {
            QCOMPARE(written.faceArrays.at("cluster_id")[f], double(clusterOfFace[f]));
            QCOMPARE(written.faceArrays.at("sphere_radius")[f], bounds.spheres[clusterOfFace[f]].radius);
        }
        // The file builder reads the same partition back.
        Settings fileSettings = window_->settings();
        fileSettings.builder = Builder::File;
        window_->setSettings(fileSettings);
        QVERIFY(window_->openMeshBlocking(path));
        QCOMPARE(window_->clusters()->partition.clusterCount, clusterCount);
        // The same grouping of faces; the file builder may number the clusters differently.
        const std::vector<uint32_t>& readBack = window_->clusters()->partition.clusterOfFace;
        QCOMPARE(readBack.size(), clusterOfFace.size());
        std::map<uint32_t, uint32_t> renumbering;
        std::set<uint32_t> used;
        for (size_t f = 0; f < readBack.size(); ++f) {
            auto [entry, added] = renumbering.emplace(clusterOfFace[f], readBack[f]);
            QCOMPARE(entry->second, readBack[f]);
            if (added) QVERIFY(used.insert(readBack[f]).second);
        }
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void fileBuilderFallsBackAndMeshesWithIdsShowTheirOwnPartition() {
        QSignalSpy errors(window_.get(), &MainWindow::errorShown);
        // A mesh carrying cluster_id shows its own partition: the file builder is chosen for it.
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere-clusters.vtp")));
        QVERIFY(window_->settings().builder == Builder::File);
        QCOMPARE(window_->settingsPanel()->builderBox()->currentText(), QStringLiteral("file"));
        QVERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("cluster_id")));
        // With the file builder chosen, a plain mesh still opens, with the default builder and a word why.
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QVERIFY(window_->settings().builder == Settings{}.builder);
        QVERIFY(window_->clusters()->builtWith.builder == Settings{}.builder);
        QCOMPARE(window_->settingsPanel()->builderBox()->currentText(), QString::fromStdString(toString(Settings{}.builder)));
        QVERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("no cluster_id")));
        QCOMPARE(errors.count(), 0);
        // A wrong id file is reported once and does not stick: the default builder takes over.
        const QString ids = temporary_.filePath(QStringLiteral("wrong-ids.txt"));
        QFile file(ids);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("0 1 2\n");
        file.close();
        Settings settings = window_->settings();
        settings.builder = Builder::File;
        settings.clusterFile = ids.toStdString();
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QCOMPARE(errors.count(), 1);
        QVERIFY(window_->settings().builder == Settings{}.builder);
        QVERIFY(window_->settings().clusterFile.empty());
        QVERIFY(window_->settingsPanel()->settings().clusterFile.empty());
        Settings other = window_->settings();
        other.limits.maxTriangles = 64;
        window_->setSettings(other);
        window_->waitUntilIdle();
        QCOMPARE(errors.count(), 1);
        QCOMPARE(window_->clusters()->builtWith.limits.maxTriangles, size_t(64));
        // A good id file: read through io (core reads no file), its clusters shown.
        const QString good = temporary_.filePath(QStringLiteral("ids.txt"));
        QFile goodFile(good);
        QVERIFY(goodFile.open(QIODevice::WriteOnly));
        for (size_t f = 0; f < window_->clusters()->partition.clusterOfFace.size(); ++f) goodFile.write(QByteArray::number(int(f % 5)) + "\n");
        goodFile.close();
        settings = window_->settings();
        settings.builder = Builder::File;
        settings.clusterFile = good.toStdString();
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QCOMPARE(errors.count(), 1);
        QVERIFY(window_->clusters()->builtWith.builder == Builder::File);
        QCOMPARE(window_->clusters()->partition.clusterCount, 5u);
        // Opened with the id file already set (as --cluster-file does), the mesh keeps the file builder.
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QVERIFY(window_->clusters()->builtWith.builder == Builder::File);
        QCOMPARE(window_->settingsPanel()->builderBox()->currentText(), QStringLiteral("file"));
        QCOMPARE(window_->clusters()->partition.clusterCount, 5u);
        QCOMPARE(errors.count(), 1);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // An engine's meshlets in the file builder, its own record scored: a record that culls too much
    // shows its false culls in the statistics panel and first in the worst-cluster table.
    void meshletFileShowsTheEnginesFalseCulls() {
        const std::string mesh = datasetPath("elephant.off").toStdString();
        const Mesh elephant = readMesh(mesh);
        const Partition meshlets = buildMeshoptMeshlets(elephant, {64, 124}, 1.0f);
        const QString path = temporary_.filePath(QStringLiteral("elephant-meshlets.json"));
        writePartitionFile(elephant, meshlets, path.toStdString());
        nlohmann::json json = readJsonFile(path);
        for (nlohmann::json& bounds : json["bounds"]) bounds["cone_cutoff"] = -1.0;  // culls from everywhere
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write(json.dump().c_str());
        file.close();
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        Settings settings = window_->settings();
        settings.builder = Builder::File;
        settings.clusterFile = path.toStdString();
        settings.tests = {CullTest::MeshoptApexF32};
        window_->setSettings(settings);
        window_->waitUntilIdle();
        QCOMPARE(window_->clusters()->partition.clusterCount, meshlets.clusterCount);
        QVERIFY(window_->currentStatistics()->view().falseCulls > 0);
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("false culls")),
                 QLocale().toString(qulonglong(window_->currentStatistics()->view().falseCulls)));
        const CullTestStatistics* orbit = window_->session().orbitStatistics();
        QVERIFY(orbit && orbit->falseCulls > 0);
        WorstClustersView* table = window_->worstClustersView();
        const uint32_t first = uint32_t(table->clusterAt(0));
        size_t most = 0;
        for (const ClusterStatistics& cluster : orbit->clusters) most = std::max(most, cluster.falseCulls);
        QCOMPARE(orbit->clusters.at(first).falseCulls, most);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void badFileKeepsTheMesh() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const std::string before = window_->preparedMesh()->path;
        const QString garbage = temporary_.filePath(QStringLiteral("garbage.off"));
        QFile file(garbage);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("OFF\n3 1 0\n0 0 zero\n1 0 0\n");
        file.close();
        QSignalSpy errors(window_.get(), &MainWindow::errorShown);
        QVERIFY(!window_->openMeshBlocking(garbage));
        QCOMPARE(errors.count(), 1);
        QVERIFY(errors.front().front().toString().contains(QStringLiteral("garbage.off")));
        QCOMPARE(window_->preparedMesh()->path, before);
        QVERIFY(window_->currentStatistics());
        QVERIFY(!window_->openMeshBlocking(temporary_.filePath(QStringLiteral("missing.off"))));
        QCOMPARE(errors.count(), 2);
        QCOMPARE(window_->preparedMesh()->path, before);
    }

    void aBudgetNotMetIsSaidInTheStatusBar() {
        QVERIFY(window_->openMeshBlocking(datasetPath("elephant.off")));
        Settings budget = window_->settings();
        budget.clusterCount = 50;  // below what the limits allow on the elephant
        window_->setSettings(budget);
        window_->waitUntilIdle();
        const size_t made = window_->clusters()->partition.clusterCount;
        QVERIFY(made > 50);
        const QString message = window_->statusBar()->currentMessage();
        QVERIFY2(message.contains(QStringLiteral("asked for 50 clusters, made %1").arg(made), Qt::CaseInsensitive), qPrintable(message));
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    // At --effort best the window says when the best effort kept the balanced search's partition,
    // in the words and figures of a core run with the same settings (emergencySign: 0.311 against 0.310).
    void bestKeepingBalancedIsSaidInTheStatusBar() {
        const QString sign = QStringLiteral(CONESCOPE_TESTDATA_DIR "/props/emergencySign.obj");
        QVERIFY(window_->openMeshBlocking(sign));
        Settings best = window_->settings();
        best.effort = Effort::Best;
        window_->setSettings(best);
        window_->waitUntilIdle();
        const RunStatistics core = statisticsInProcess(sign, window_->settings());
        QVERIFY(core.bestEffort.keptBalanced);
        QCOMPARE(size_t(window_->clusters()->partition.clusterCount), core.clusters);
        const QString said = QString::fromStdString(bestEffortNote(core.bestEffort));
        QVERIFY(said.contains(QStringLiteral("kept the balanced search's partition")));
        const QString message = window_->statusBar()->currentMessage();
        QVERIFY2(message.contains(said, Qt::CaseInsensitive), qPrintable(message));  // the window starts it with a capital
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void insideOutMeshIsWarnedAboutAndRepairedOnRequest() {
        const Mesh sphere = readMesh(datasetPath("icosphere.off").toStdString());
        const QString path = writeInsideOutSphere(temporary_);
        QCheckBox* fix = window_->settingsPanel()->fixWindingBox();
        fix->setChecked(false);
        window_->waitUntilIdle();

        QVERIFY(window_->openMeshBlocking(path));
        QVERIFY2(window_->statusBar()->currentMessage().contains(QStringLiteral("1 closed component turned inside out")),
                 qPrintable(window_->statusBar()->currentMessage()));
        QVERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("Fix winding")));
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("mesh problems")).contains(QStringLiteral("1 inside-out components")));

        fix->setChecked(true);
        window_->waitUntilIdle();
        QCOMPARE(window_->preparedMesh()->windingFixedFaces, sphere.faceCount());
        QVERIFY(window_->statisticsPanel()->value(QStringLiteral("mesh problems")).contains(QStringLiteral("1280 faces flipped")));
        const FaceGeometry& faces = window_->preparedMesh()->faces;
        for (size_t f = 0; f < sphere.faceCount(); ++f) QVERIFY(glm::dot(faces.normals[f], faces.centroids[f]) > 0.0);
        fix->setChecked(false);
        window_->waitUntilIdle();
    }

    void anotherMeshTakesTheWindingWarningAway() {
        window_->settingsPanel()->fixWindingBox()->setChecked(false);
        window_->waitUntilIdle();
        QVERIFY(window_->openMeshBlocking(writeInsideOutSphere(temporary_)));
        QVERIFY(window_->statusBar()->currentMessage().contains(QStringLiteral("inside out")));
        // A mesh with nothing to say: the previous mesh's warning must not stay beside "mesh problems: none".
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QCOMPARE(window_->statisticsPanel()->value(QStringLiteral("mesh problems")), QStringLiteral("none"));
        QVERIFY2(!window_->statusBar()->currentMessage().contains(QStringLiteral("inside out")),
                 qPrintable(window_->statusBar()->currentMessage()));
    }

    void cancelledBuildPutsTheSettingsBack() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        SettingsPanel* panel = window_->settingsPanel();
        const size_t shownLimit = window_->settings().limits.maxTriangles;
        const size_t shownClusters = window_->clusters()->partition.clusterCount;
        QVERIFY(shownLimit != 48);
        // Type 48 and press Cancel while the clusters are built, as a user would.
        panel->maxTrianglesBox()->setValue(48);
        QVERIFY(cancelButton(*window_));
        cancelButton(*window_)->click();
        window_->waitUntilIdle();
        // The clusters shown stay, and so do the settings they were made with: in the box too.
        QCOMPARE(window_->clusters()->partition.clusterCount, shownClusters);
        QCOMPARE(window_->settings().limits.maxTriangles, shownLimit);
        QCOMPARE(size_t(panel->maxTrianglesBox()->value()), shownLimit);
        QCOMPARE(panel->settings().limits.maxTriangles, shownLimit);
        // The export is what the window shows: a core run with the settings in the widgets.
        const QString path = temporary_.filePath(QStringLiteral("after-cancel.json"));
        QVERIFY(window_->exportStatistics(path, StatisticsFormat::Json, true));
        const nlohmann::json exported = readJsonFile(path);
        QCOMPARE(exported["settings"]["max_triangles"].get<size_t>(), shownLimit);
        QCOMPARE(exported["clusters"].get<size_t>(), shownClusters);
        const RunStatistics core = statisticsInProcess(datasetPath("torus.off"), panel->settings());
        QCOMPARE(exported["results"][0]["efficiency"].get<double>(), core.results.front().efficiency);
        QCOMPARE(exported["clusters"].get<size_t>(), core.clusters);
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void progressBarShowsItsWholeText() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        QProgressBar* bar = window_->statusBar()->findChild<QProgressBar*>();
        QVERIFY(bar);
        // Progress as a long orbit reports it.
        Session& session = window_->session();
        emit session.taskStarted(QStringLiteral("Orbit statistics"));
        emit session.progressChanged(0.88, QStringLiteral("orbit statistics"));
        QApplication::processEvents();
        QCOMPARE(bar->text(), QStringLiteral("orbit statistics 88%"));
        const int textWidth = bar->fontMetrics().horizontalAdvance(bar->text());
        QVERIFY2(bar->width() >= textWidth + 12, qPrintable(QStringLiteral("bar %1 px for %2 px of text").arg(bar->width()).arg(textWidth)));
        emit session.progressChanged(0.5, QStringLiteral("Comparing A and B over the orbit"));
        QApplication::processEvents();
        QVERIFY(bar->width() >= bar->fontMetrics().horizontalAdvance(bar->text()) + 12);
        saveWindowPicture(QStringLiteral("window-progress.png"));
        emit session.idle();
    }

    void errorDialogOpensAfterTheProgressBarIsGone() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const QString garbage = temporary_.filePath(QStringLiteral("broken.off"));
        QFile file(garbage);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("OFF\n3 1 0\n0 0 zero\n1 0 0\n");
        file.close();
        window_->setErrorDialogsEnabled(true);
        int dialogs = 0;
        bool progressBehindDialog = false;
        QTimer watcher;
        connect(&watcher, &QTimer::timeout, this, [&]() {
            if (auto* dialog = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) {
                ++dialogs;
                progressBehindDialog = progressBehindDialog || window_->progressShown();
                dialog->close();
            }
        });
        watcher.start(20);
        window_->openMesh(garbage);
        QTRY_COMPARE_WITH_TIMEOUT(dialogs, 1, 5000);
        watcher.stop();
        window_->setErrorDialogsEnabled(false);
        // The closed dialog took the activation: give it back, so the next tests' shortcuts reach the window.
        QApplication::setActiveWindow(window_.get());
        QTRY_COMPARE(QApplication::activeWindow(), window_.get());
        QVERIFY(!progressBehindDialog);
    }

    void cancelledLoadKeepsTheMesh() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        const std::string before = window_->preparedMesh()->path;
        QSignalSpy shown(window_.get(), &MainWindow::meshShown);
        window_->openMesh(datasetPath("torus.off"));
        // The Cancel button of the status bar; the task stops at its next stage.
        QPushButton* cancel = cancelButton(*window_);
        QVERIFY(cancel);
        cancel->click();
        window_->waitUntilIdle();
        QCOMPARE(shown.count(), 0);
        QCOMPARE(window_->preparedMesh()->path, before);
    }

    void screenshotOfTheView() {
        QVERIFY(window_->openMeshBlocking(datasetPath("torus.off")));
        const QString path = temporary_.filePath(QStringLiteral("view.png"));
        QVERIFY(window_->saveScreenshot(path));
        QImage image(path);
        QVERIFY(!image.isNull());
        const int* size = window_->observerView()->renderWindow()->GetSize();
        QCOMPARE(image.width(), size[0]);
        QCOMPARE(image.height(), size[1]);
        // Not a blank picture: the mesh's colours differ from the background's.
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 7)
            for (int x = 0; x < image.width(); x += 7) colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 20);
        image.save(QDir(outputDir_).filePath(QStringLiteral("view-torus.png")));
    }
    void dropOpensAMesh() {
        QVERIFY(window_->openMeshBlocking(datasetPath("icosphere.off")));
        QMimeData text;
        text.setUrls({QUrl::fromLocalFile(temporary_.filePath(QStringLiteral("notes.txt")))});
        QDragEnterEvent refused(QPoint(20, 20), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
        refused.setAccepted(false);
        QApplication::sendEvent(window_.get(), &refused);
        QVERIFY(!refused.isAccepted());

        QMimeData mesh;
        mesh.setUrls({QUrl::fromLocalFile(datasetPath("cube.off"))});
        QDragEnterEvent enter(QPoint(20, 20), Qt::CopyAction, &mesh, Qt::LeftButton, Qt::NoModifier);
        enter.setAccepted(false);
        QApplication::sendEvent(window_.get(), &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(20, 20), Qt::CopyAction, &mesh, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(window_.get(), &drop);
        window_->waitUntilIdle();
        QCOMPARE(QString::fromStdString(window_->preparedMesh()->path), datasetPath("cube.off"));
        QCOMPARE(window_->preparedMesh()->mesh().faceCount(), size_t(12));
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    FileWindowTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "FileWindowTests.moc"
