// The window's non-widget parts: the pipeline against runStatistics, the partition arrays, the
// command line, the chart binning, the cluster report, and `conescope --screenshot` end to end.
#include <set>

#include <QImage>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "core/meshopt/Meshopt.h"
#include "ClusterReport.h"
#include "CommandLine.h"
#include "Datasets.h"
#include "core/CullMap.h"
#include "core/Pipeline.h"
#include "MeshLoading.h"
#include "UiTestSupport.h"
#include "scene/Charts.h"

using namespace conescope;
using namespace conescope::testing;

class PipelineTests : public QObject {
    Q_OBJECT

private:
    QTemporaryDir temporary_;

    // Runs the application binary; returns the exit code, stderr in `errors`.
    int runApplication(const QStringList& arguments, QString* errors = nullptr) {
        QProcess process;
        process.start(QStringLiteral(CONESCOPE_APP_PATH), arguments);
        if (!process.waitForFinished(120000)) return -1;
        if (errors) *errors = QString::fromLocal8Bit(process.readAllStandardError());
        return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    }

private slots:
    void eyeMeasurementIsRunStatisticsForOneEye() {
        for (Builder builder : {Builder::Meshlet, Builder::KMeans, Builder::Meshopt}) {
            Settings settings;
            settings.builder = builder;
            const PreparedMesh prepared = loadMesh(datasetPath("torus.off").toStdString(), Settings{});
            const ClusterSet clusters = buildClusters(prepared, settings);
            for (const glm::dvec3& position : {glm::dvec3(0.0, 0.0, 3.0), glm::dvec3(2.0, -1.0, 0.5)}) {
                for (CullTest test : allCullTests()) {
                    const EyeMeasurement measured = measureEye(prepared, clusters, eyeAt(settings, position, prepared.box), test);
                    Settings single = settings;
                    single.tests = {test};
                    single.eye = position;
                    const RunStatistics run = statisticsInProcess(datasetPath("torus.off"), single);
                    const ViewStatistics& expected = run.results.front().views.front();
                    QCOMPARE(measured.view().clustersCulled, expected.clustersCulled);
                    QCOMPARE(measured.view().trianglesCulled, expected.trianglesCulled);
                    QCOMPARE(measured.view().efficiency, expected.efficiency);
                    QCOMPARE(measured.view().falseCulls, size_t(0));
                    size_t culled = 0;
                    for (uint8_t flag : measured.culled) culled += flag;
                    QCOMPARE(culled, expected.clustersCulled);
                    QVERIFY(measured.culled == cullClusters(cullingInput(prepared, clusters), measured.eye, test));
                }
            }
        }
    }

    void orbitRowsAreRunStatisticsViews() {
        Settings settings;
        settings.views = 37;  // not a multiple of the slice size
        settings.tests = {CullTest::Aabb};
        const PreparedMesh prepared = loadMesh(datasetPath("icosphere.off").toStdString(), Settings{});
        const ClusterSet clusters = buildClusters(prepared, settings);
        const std::vector<ViewStatistics> rows = measureOrbit(prepared, clusters, settings).views;
        const RunStatistics run = statisticsInProcess(datasetPath("icosphere.off"), settings);
        const std::vector<ViewStatistics>& expected = run.results.front().views;
        QCOMPARE(rows.size(), expected.size());
        for (size_t v = 0; v < rows.size(); ++v) {
            QCOMPARE(rows[v].view, expected[v].view);
            QCOMPARE(rows[v].eye.position, expected[v].eye.position);
            QCOMPARE(rows[v].clustersCulled, expected[v].clustersCulled);
            QCOMPARE(rows[v].efficiency, expected[v].efficiency);
        }
    }

    // Loading for the window builds the optimized builder's start while the mesh is prepared: the
    // same meshlets, the same clusters; a builder that starts elsewhere gets none.
    void loadingBuildsTheStartMeanwhile() {
        const std::string torus = datasetPath("torus.off").toStdString();
        std::shared_ptr<MeshletStream> start;
        const PreparedMesh prepared = loadMesh(torus, Settings{}, {}, &start);
        QVERIFY(start);
        QVERIFY(start->whole().clusterOfFace == buildMeshoptMeshlets(prepared.mesh(), Settings{}.limits, 1.0f).clusterOfFace);
        QVERIFY(buildClusters(prepared, Settings{}, nullptr, {}, start.get()).partition.clusterOfFace ==
                buildClusters(prepared, Settings{}).partition.clusterOfFace);
        Settings best;
        best.effort = Effort::Best;
        std::shared_ptr<MeshletStream> none;
        loadMesh(torus, best, {}, &none);
        QVERIFY(!none);
    }

    void cancellingStopsBetweenStages() {
        int calls = 0;
        const ProgressCallback refuse = [&calls](double, const std::string&) { return ++calls < 2; };
        QVERIFY_EXCEPTION_THROWN(loadMesh(datasetPath("torus.off").toStdString(), Settings{}, refuse), OperationCancelled);
        QCOMPARE(calls, 2);
    }

    void partitionChangesAreDetected() {
        const Settings base;
        Settings cone = base;
        cone.cones = {ConeMethod::Average};
        QVERIFY(!partitionChanged(base, cone));
        QVERIFY(boundsChanged(base, cone));
        Settings test = base;
        test.tests = {CullTest::Sphere};
        QVERIFY(!boundsChanged(base, test));
        Settings limits = base;
        limits.limits.maxTriangles = base.limits.maxTriangles / 2;
        QVERIFY(partitionChanged(base, limits));
        // Reusing the partition when only the cone changes gives the same clusters as building anew.
        const PreparedMesh prepared = loadMesh(datasetPath("torus.off").toStdString(), Settings{});
        const ClusterSet first = buildClusters(prepared, base);
        const ClusterSet reused = buildClusters(prepared, cone, &first);
        const ClusterSet fresh = buildClusters(prepared, cone);
        QCOMPARE(reused.partition.clusterOfFace, fresh.partition.clusterOfFace);
        QVERIFY(reused.bounds.coneMethod == ConeMethod::Average);
        for (size_t c = 0; c < fresh.bounds.count(); ++c) QCOMPARE(reused.bounds.cones[c].axis, fresh.bounds.cones[c].axis);
    }

    void partitionArraysSpreadClusterValues() {
        const PreparedMesh prepared = loadMesh(datasetPath("icosphere.off").toStdString(), Settings{});
        const ClusterSet clusters = buildClusters(prepared, Settings{});
        const auto arrays = partitionFaceArrays(prepared, clusters, CullTest::Apex);
        for (const auto& [name, values] : arrays) QCOMPARE(values.size(), prepared.mesh().faceCount());
        for (size_t f = 0; f < prepared.mesh().faceCount(); f += 17) {
            const uint32_t c = clusters.partition.clusterOfFace[f];
            QCOMPARE(arrays.at("cluster_id")[f], double(c));
            QCOMPARE(arrays.at("cone_axis_y")[f], clusters.bounds.cones[c].axis.y);
            QCOMPARE(arrays.at("cone_half_angle_deg")[f], glm::degrees(clusters.bounds.cones[c].halfAngle()));
            QCOMPARE(arrays.at("aabb_max_z")[f], double(clusters.bounds.boxes[c].max.z));
            // The fraction of the test asked for, not of the one the clusters were built under.
            QCOMPARE(arrays.at("cull_fraction")[f], cullFraction(clusters.cullMap, c, CullTest::Apex));
        }
    }

    void commandLineGivesSettings() {
        const CommandLineResult result = parseCommandLine(
            {QStringLiteral("conescope"), QStringLiteral("--builder"), QStringLiteral("kmeans"), QStringLiteral("--clusters"),
             QStringLiteral("12"), QStringLiteral("--cone"), QStringLiteral("average,minimal"), QStringLiteral("--test"),
             QStringLiteral("sphere"), QStringLiteral("--ortho"), QStringLiteral("--eye=-1,2.5,3"), QStringLiteral("--screenshot"),
             QStringLiteral("out.png"), QStringLiteral("--size"), QStringLiteral("320x200"), QStringLiteral("mesh.off")});
        QCOMPARE(int(result.action), int(CommandLineResult::Action::Run));
        const AppOptions& options = result.options;
        QVERIFY(options.settings.builder == Builder::KMeans);
        QCOMPARE(options.settings.clusterCount, size_t(12));
        QVERIFY((options.settings.cones == std::vector<ConeMethod>{ConeMethod::Average, ConeMethod::Minimal}));
        QVERIFY(options.settings.tests == std::vector<CullTest>{CullTest::Sphere});
        QVERIFY(options.settings.orthographic);
        QCOMPARE(*options.eye, glm::dvec3(-1.0, 2.5, 3.0));
        QCOMPARE(options.screenshot, QStringLiteral("out.png"));
        QCOMPARE(options.size, QSize(320, 200));
        QCOMPARE(options.mesh, QStringLiteral("mesh.off"));
        // Untouched fields keep Settings{}.
        QCOMPARE(options.settings.limits.maxTriangles, Settings{}.limits.maxTriangles);
        QVERIFY(!options.layers);
        // `all` and repeated list options, as the CLI takes them.
        const CommandLineResult all = parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--cone"), QStringLiteral("all"),
                                                        QStringLiteral("--test"), QStringLiteral("sphere"), QStringLiteral("--test"),
                                                        QStringLiteral("apex")});
        QCOMPARE(int(all.action), int(CommandLineResult::Action::Run));
        QVERIFY(all.options.settings.cones == allConeMethods());
        QVERIFY((all.options.settings.tests == std::vector<CullTest>{CullTest::Sphere, CullTest::Apex}));
        const CommandLineResult layered =
            parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--layers"), QStringLiteral("boxes, spheres,faces")});
        QCOMPARE(int(layered.action), int(CommandLineResult::Action::Run));
        QVERIFY((layered.options.layers == std::vector<Layer>{Layer::Boxes, Layer::Spheres, Layer::Faces}));
        const CommandLineResult unknownLayer =
            parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--layers"), QStringLiteral("faces,clouds")});
        QCOMPARE(int(unknownLayer.action), int(CommandLineResult::Action::ExitFailure));
        QVERIFY(unknownLayer.message.contains(QStringLiteral("clouds")));
        QVERIFY(unknownLayer.message.contains(QStringLiteral("spheres")));

        for (const QStringList& bad :
             {QStringList{QStringLiteral("conescope"), QStringLiteral("--builder"), QStringLiteral("nope")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("--eye"), QStringLiteral("1,2")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("--screenshot"), QStringLiteral("a.png"), QStringLiteral("--size"),
                          QStringLiteral("12")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("--unknown")},
              // The CLI's domains (the settings schema): a cluster needs 3 vertices, an orbit a view.
              QStringList{QStringLiteral("conescope"), QStringLiteral("--max-verts"), QStringLiteral("0")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("--views"), QStringLiteral("0")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("--distance"), QStringLiteral("-1")},
              QStringList{QStringLiteral("conescope"), QStringLiteral("a.off"), QStringLiteral("b.off")}}) {
            const CommandLineResult failed = parseCommandLine(bad);
            QCOMPARE(int(failed.action), int(CommandLineResult::Action::ExitFailure));
            QVERIFY(!failed.message.isEmpty());
        }
    }

    void loadMessagesAreSentences() {
        // A reader's note that ends its sentence, then the winding warning: not "faces.; warning:".
        PreparedMesh prepared = loadMesh(datasetPath("icosphere.off").toStdString(), Settings{});
        prepared.readerNotes = {"Skipped 2 primitives of points or lines: they have no faces.", "merged 3 vertices into others"};
        prepared.report.inconsistentEdges = 4;
        const QString message = QString::fromStdString(loadMessage(prepared));
        QVERIFY2(!message.contains(QStringLiteral(".;")) && !message.contains(QStringLiteral("; warning")), qPrintable(message));
        QVERIFY2(message.startsWith(QStringLiteral("Skipped 2 primitives of points or lines: they have no faces. Merged 3 vertices into "
                                                   "others. Warning: the mesh has 4 edges")),
                 qPrintable(message));
        QVERIFY(message.endsWith(QStringLiteral("tick 'Fix winding' in Settings to repair.")));
        QCOMPARE(QString::fromStdString(joinSentences({"", "one", "two!", "  "})), QStringLiteral("One. Two!"));
    }

    void bundledMeshIsFound() {
        const QString path = defaultMeshPath();
        QVERIFY(!path.isEmpty());
        QVERIFY(QFileInfo(path).isFile());
    }

    void histogramCountsEveryCluster() {
        const PreparedMesh prepared = loadMesh(datasetPath("torus.off").toStdString(), Settings{});
        const ClusterSet clusters = buildClusters(prepared, Settings{});
        const EyeMeasurement measured =
            measureEye(prepared, clusters, eyeAt(Settings{}, {0.0, 0.0, 3.0}, prepared.box), CullTest::Vertices);
        const HalfAngleHistogram histogram = halfAngleHistogram(measured.statistics.clusters, 10.0);
        QCOMPARE(histogram.counts.size(), size_t(9));
        size_t total = histogram.uncullable;
        for (size_t count : histogram.counts) total += count;
        QCOMPARE(total, size_t(clusters.partition.clusterCount));
        QCOMPARE(histogram.uncullable, measured.statistics.uncullableClusters);
        // A cluster of 30 degrees lands in the bin [30, 40).
        ClusterStatistics thirty;
        thirty.cullable = true;
        thirty.halfAngleDegrees = 30.0;
        QCOMPARE(halfAngleHistogram({thirty}, 10.0).counts[3], size_t(1));
    }

    void reportShowsTheTestsNumbers() {
        const PreparedMesh prepared = loadMesh(datasetPath("icosphere.off").toStdString(), Settings{});
        const ClusterSet clusters = buildClusters(prepared, Settings{});
        const Eye eye = Eye::perspective({0.0, 0.0, 3.0});
        for (CullTest test : {CullTest::Sphere, CullTest::Aabb, CullTest::Apex}) {
            ClusterReportInput input;
            input.cluster = 1;
            input.bounds = &clusters.bounds;
            input.eye = eye;
            input.test = test;
            input.explanation = explainCull(cullingInput(prepared, clusters), 1, eye, test);
            const QString html = clusterReportHtml(input);
            QVERIFY(html.contains(QStringLiteral("Cluster 1")));
            QVERIFY(html.contains(QString::number(input.explanation.threshold, 'g', 7)));
            // v·V1 against the threshold is the decision of the sphere and (the default) apex tests.
            QVERIFY(html.contains(QString::number(input.explanation.viewDotAxis, 'g', 7)) || test == CullTest::Aabb);
            if (test == CullTest::Apex) QVERIFY(html.contains(QStringLiteral("v&middot;V1")));
            if (test == CullTest::Sphere) QVERIFY(html.contains(QStringLiteral("asin(r/d)")));
            if (test == CullTest::Aabb)
                for (int corner = 0; corner < 8; ++corner)
                    QVERIFY(html.contains(QString::number(input.explanation.cornerDotAxis[corner], 'g', 7)));
            QVERIFY(html.contains(QStringLiteral("front-facing faces")));
        }
    }

    void headlessScreenshot() {
        QVERIFY(temporary_.isValid());
        const QString path = temporary_.filePath(QStringLiteral("shot.png"));
        QString errors;
        QCOMPARE(runApplication({QStringLiteral("--screenshot"), path, QStringLiteral("--size"), QStringLiteral("320x240"),
                                 QStringLiteral("--eye=0,0,3"), QStringLiteral("--test"), QStringLiteral("aabb"),
                                 datasetPath("icosphere.off")},
                                &errors),
                 0);
        QImage image(path);
        QVERIFY2(!image.isNull(), qPrintable(errors));
        QCOMPARE(image.size(), QSize(320, 240));
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 3)
            for (int x = 0; x < image.width(); x += 3) colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 10);

        // The eye's own view, orthographic, another builder.
        const QString fromEye = temporary_.filePath(QStringLiteral("eye.png"));
        QCOMPARE(runApplication({QStringLiteral("--screenshot"), fromEye, QStringLiteral("--size"), QStringLiteral("200x150"),
                                 QStringLiteral("--from-eye"), QStringLiteral("--ortho"), QStringLiteral("--builder"),
                                 QStringLiteral("meshopt"), datasetPath("torus.off")}),
                 0);
        QCOMPARE(QImage(fromEye).size(), QSize(200, 150));

        // --layers: only the layers named are drawn, so each set gives its own image, and none is
        // the default set (faces, borders, eye, highlight, test, legend).
        auto shot = [&](const QString& name, const QStringList& layers) {
            const QString file = temporary_.filePath(name);
            QStringList arguments{QStringLiteral("--screenshot"), file, QStringLiteral("--size"), QStringLiteral("240x180"),
                                  QStringLiteral("--eye=0,0,3"), datasetPath("torus.off")};
            if (!layers.isEmpty()) arguments << QStringLiteral("--layers") << layers.join(QLatin1Char(','));
            return runApplication(arguments) == 0 ? QImage(file) : QImage();
        };
        const QImage defaults = shot(QStringLiteral("defaults.png"), {});
        const QImage faces = shot(QStringLiteral("faces.png"), {QStringLiteral("faces")});
        const QImage facesAndBoxes = shot(QStringLiteral("faces-boxes.png"), {QStringLiteral("faces"), QStringLiteral("boxes")});
        const QImage boxes = shot(QStringLiteral("boxes.png"), {QStringLiteral("boxes")});
        QVERIFY(!defaults.isNull() && !faces.isNull() && !facesAndBoxes.isNull() && !boxes.isNull());
        QVERIFY(faces != facesAndBoxes && faces != boxes && boxes != facesAndBoxes);
        QVERIFY(defaults != faces && defaults != facesAndBoxes && defaults != boxes);
        QCOMPARE(shot(QStringLiteral("faces-again.png"), {QStringLiteral("faces")}), faces);
        // Headless starts with the window's first-look layers.
        QCOMPARE(defaults, shot(QStringLiteral("window-layers.png"),
                                {QStringLiteral("faces"), QStringLiteral("borders"), QStringLiteral("eye"), QStringLiteral("highlight"),
                                 QStringLiteral("test"), QStringLiteral("legend"), QStringLiteral("lesson")}));
    }

    void headlessScreenshotPicksACluster() {
        // --pick highlights a cluster; an id the mesh does not have is refused with the range.
        auto shot = [&](const QString& name, const QStringList& extra, QString* errors = nullptr) {
            const QString file = temporary_.filePath(name);
            QStringList arguments{QStringLiteral("--screenshot"), file, QStringLiteral("--size"), QStringLiteral("240x180"),
                                  QStringLiteral("--eye=0,0,3"), datasetPath("torus.off")};
            arguments << extra;
            return runApplication(arguments, errors) == 0 ? QImage(file) : QImage();
        };
        const QImage plain = shot(QStringLiteral("plain.png"), {});
        const QImage picked = shot(QStringLiteral("picked.png"), {QStringLiteral("--pick"), QStringLiteral("3")});
        QVERIFY(!plain.isNull() && !picked.isNull());
        QVERIFY(plain != picked);
        QString errors;
        QVERIFY(shot(QStringLiteral("none.png"), {QStringLiteral("--pick"), QStringLiteral("100000")}, &errors).isNull());
        QVERIFY2(errors.contains(QStringLiteral("clusters (0 to")), qPrintable(errors));
    }

    void headlessScreenshotDrawsTheGaussMapAndAComparison() {
        auto run = [&](const QStringList& extra, QString* errors = nullptr) {
            QStringList arguments{QStringLiteral("--size"), QStringLiteral("240x180"), datasetPath("elephant.off")};
            return runApplication(arguments + extra, errors);
        };
        // --gauss-map writes the picked cluster's Gauss map beside the screenshot; it needs --pick.
        const QString shot = temporary_.filePath(QStringLiteral("pick.png")), gauss = temporary_.filePath(QStringLiteral("gauss.png"));
        QCOMPARE(run({QStringLiteral("--screenshot"), shot, QStringLiteral("--pick"), QStringLiteral("2"), QStringLiteral("--gauss-map"), gauss}), 0);
        QVERIFY(!QImage(shot).isNull());
        QCOMPARE(QImage(gauss).size(), QSize(240, 180));
        QString errors;
        QCOMPARE(run({QStringLiteral("--screenshot"), shot, QStringLiteral("--gauss-map"), gauss}, &errors), 1);
        QVERIFY2(errors.contains(QStringLiteral("--gauss-map needs")), qPrintable(errors));
        // --compare: the diff colouring; unequal cluster counts are warned about; a bad K=V is refused.
        const QString compared = temporary_.filePath(QStringLiteral("compare.png")), decided = temporary_.filePath(QStringLiteral("decide.png"));
        QCOMPARE(run({QStringLiteral("--screenshot"), compared, QStringLiteral("--compare"), QStringLiteral("builder=meshopt")}, &errors), 0);
        QCOMPARE(run({QStringLiteral("--screenshot"), decided}), 0);
        QVERIFY(!QImage(compared).isNull() && QImage(compared) != QImage(decided));
        QCOMPARE(run({QStringLiteral("--screenshot"), compared, QStringLiteral("--compare"), QStringLiteral("max-tris=24,max-verts=24")}, &errors), 0);
        QVERIFY2(errors.contains(QStringLiteral("warning: A has")), qPrintable(errors));
        QCOMPARE(run({QStringLiteral("--screenshot"), compared, QStringLiteral("--compare"), QStringLiteral("views=3")}, &errors), 1);
        QVERIFY2(errors.contains(QStringLiteral("shared by both sides")), qPrintable(errors));
    }

    void headlessScreenshotErrors() {
        const QString garbage = temporary_.filePath(QStringLiteral("garbage.off"));
        QFile file(garbage);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("not a mesh\n");
        file.close();
        const QString path = temporary_.filePath(QStringLiteral("never.png"));
        QString errors;
        QCOMPARE(runApplication({QStringLiteral("--screenshot"), path, garbage}, &errors), 1);
        QVERIFY(errors.contains(QStringLiteral("garbage.off")));
        QVERIFY(!QFileInfo::exists(path));
        QCOMPARE(runApplication({QStringLiteral("--screenshot"), path, QStringLiteral("--eye"), QStringLiteral("1,2"),
                                 datasetPath("torus.off")},
                                &errors),
                 1);
        QVERIFY(errors.contains(QStringLiteral("eye")));
        QCOMPARE(runApplication({QStringLiteral("--help")}), 0);
    }
};

QTEST_GUILESS_MAIN(PipelineTests)
#include "PipelineTests.moc"
