// Replay files: read and refused naming the step, played in the window (relative paths, captions,
// screenshots), and `conescope --replay` run as a user runs it, its exports checked against
// `conescope-cli compare` (issue 29's "done when").
#include <QFile>
#include <QImage>
#include <QSurfaceFormat>
#include <QtTest>

#include "CommandLine.h"
#include "ObserverView.h"
#include "ReplayPlayer.h"
#include "ReplaySteps.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/Lesson.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

void writeFile(const QString& path, const QByteArray& text) {
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(text);
}

// The message parseReplay refuses `json` with.
QString refusal(const char* json) {
    try {
        parseReplay(json, QDir::tempPath());
    } catch (const ReplayError& error) {
        return QString::fromStdString(error.what());
    }
    return {};
}

}  // namespace

class ReplayTests : public QObject, private WindowFixture {
    Q_OBJECT

    // `conescope --replay` on a file of these steps in the temporary folder; the exit code, stderr in `errors`.
    int replay(const QString& name, const QByteArray& steps, QString* errors = nullptr) {
        const QString path = temporary_.filePath(name);
        writeFile(path, steps);
        return runProgram(QStringLiteral(CONESCOPE_APP_PATH), {QStringLiteral("--replay"), path}, errors);
    }

    // `conescope-cli compare` of the elephant at 64 views, distance 3: its JSON.
    nlohmann::json cliCompare(const QString& a, const QString& b) {
        const QString out = temporary_.filePath(QStringLiteral("cli-compare.json"));
        QString errors;
        const int code = runProgram(QStringLiteral(CONESCOPE_CLI_PATH),
                                    {QStringLiteral("compare"), datasetPath("elephant.off"), QStringLiteral("--a"), a, QStringLiteral("--b"), b,
                                     QStringLiteral("--views"), QStringLiteral("64"), QStringLiteral("--distance"), QStringLiteral("3"),
                                     QStringLiteral("--quiet"), QStringLiteral("-o"), out},
                                    &errors);
        if (code != 0) qWarning("conescope-cli compare: %s", qPrintable(errors));
        return code == 0 ? readJsonFile(out) : nlohmann::json();
    }

private slots:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { window_.reset(); }

    void readingRefusesWhatCannotBePlayedNamingTheStep() {
        QVERIFY(refusal("[{\"open\": ").startsWith(QStringLiteral("not JSON")));
        QVERIFY(refusal("{\"steps\": 3}").contains(QStringLiteral("a replay is a list of steps")));
        const QString unknown = refusal("[{\"open\": \"a.off\"}, {\"fly\": true}]");
        QVERIFY2(unknown.startsWith(QStringLiteral("step 2 {\"fly\":true}: unknown step 'fly' (expected one of: open, set,")), qPrintable(unknown));
        const QString key = refusal("[{\"set\": {\"tset\": \"apex\"}}]");
        QVERIFY2(key.startsWith(QStringLiteral("step 1 {\"set\":{\"tset\":\"apex\"}}: 'set' unknown key 'tset'")), qPrintable(key));
        QVERIFY(refusal("[{\"set\": {\"eye\": \"1,2,3\"}}]").contains(QStringLiteral("unknown key 'eye'")));
        const QString value = refusal("[{\"set\": {\"views\": 64}}, {\"set\": {\"test\": \"apx\"}}]");
        QVERIFY2(value.startsWith(QStringLiteral("step 2 ")) && value.contains(QStringLiteral("apx")), qPrintable(value));
        QVERIFY(refusal("[{\"set\": {\"views\": 0}}]").startsWith(QStringLiteral("step 1 ")));
        QVERIFY(refusal("[{\"eye\": [1, 2]}]").contains(QStringLiteral("takes a point [x, y, z]")));
        QVERIFY(refusal("[{\"orbit-view\": -1}]").contains(QStringLiteral("takes an orbit view")));
        QVERIFY(refusal("[{\"pin\": \"B\"}]").contains(QStringLiteral("takes \"A\"")));
        QVERIFY(refusal("[{\"swap\": false}]").contains(QStringLiteral("takes true")));
        QVERIFY(refusal("[{\"open\": \"a.off\", \"pin\": \"A\"}]").contains(QStringLiteral("one member")));
        QVERIFY(refusal("[{\"caption\": 3}]").contains(QStringLiteral("takes a text")));
        QVERIFY(refusal("[{\"lesson-step\": 8}]").contains(QStringLiteral("takes a lesson step, 1 to 7")));
        QVERIFY(refusal("[{\"example\": \"visible\"}]").contains(QStringLiteral("culled, drawn, test-loss, partition-loss")));
        QVERIFY(refusal("[{\"example\": 3}]").contains(QStringLiteral("'example' takes one of")));
        QVERIFY(refusal("[{\"sweep-eye\": 1}]").contains(QStringLiteral("a number of frames")));
        QVERIFY(refusal("[{\"sweep-eye\": {\"frame\": 4}}]").contains(QStringLiteral("unknown key 'frame'")));
        QVERIFY(refusal("[{\"sweep-eye\": {\"slides\": \"s\"}}]").contains(QStringLiteral("takes a number of frames")));
        QVERIFY(refusal("[{\"lesson-step\": -1}]").contains(QStringLiteral("takes a lesson step")));
        QVERIFY(refusal("[{\"choose\": \"worst\"}]").contains(QStringLiteral("test-loss")));
        QVERIFY(refusal("[{\"cross-section\": \"\"}]").contains(QStringLiteral("takes a file path")));
        QVERIFY(refusal("[{\"cancel-at-stage\": true}]").contains(QStringLiteral("takes the name of a stage")));
        try {
            readReplayFile(temporary_.filePath(QStringLiteral("no-such-replay.json")));
            QFAIL("a missing file was read");
        } catch (const ReplayError& error) {
            QVERIFY(QString::fromLatin1(error.what()).contains(QStringLiteral("cannot read the replay file")));
        }
        // Every kind reads.
        const std::vector<ReplayStep> steps = parseReplay(
            R"([{"open": "m.off"}, {"set": {"builder": "meshopt", "max-tris": 64, "test": ["apex", "sphere"], "ortho": true}},
                {"eye": [1, 2, 3.5]}, {"orbit-view": 3}, {"pick": -1}, {"pin": "A"}, {"swap": true}, {"drop-pin": true},
                {"cancel-next-build": true}, {"cancel-at-stage": "scene"}, {"screenshot": "a.png"}, {"window-screenshot": "b.png"}, {"export": "c.json"},
                {"export-eye": "d.csv"}, {"caption": "text"}, {"choose": 3}, {"choose": "test-loss"}, {"lesson-step": 2},
                {"cross-section": "e.png"}, {"export-explanation": "f.json"}, {"slides": "g"},
                {"orbit-slides": "h"}, {"example": "culled"}, {"sweep-eye": 12}, {"sweep-eye": {"frames": 4, "slides": "i"}}])",
            QDir::tempPath());
        QCOMPARE(steps.size(), replayStepNames().size() + 2);
    }

    void commandLineTakesAReplay() {
        const CommandLineResult replay = parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--replay"),
                                                           QStringLiteral("steps.json"), QStringLiteral("--stay")});
        QCOMPARE(int(replay.action), int(CommandLineResult::Action::Run));
        QCOMPARE(replay.options.replay, QStringLiteral("steps.json"));
        QVERIFY(replay.options.stay);
        QCOMPARE(int(parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--stay")}).action),
                 int(CommandLineResult::Action::ExitFailure));
        QCOMPARE(int(parseCommandLine({QStringLiteral("conescope"), QStringLiteral("--replay"), QStringLiteral("a.json"),
                                       QStringLiteral("--screenshot"), QStringLiteral("b.png")})
                         .action),
                 int(CommandLineResult::Action::ExitFailure));
    }

    void stepsPlayInTheWindowWithPathsFromTheReplaysFolder() {
        QDir folder(temporary_.path());
        QVERIFY(folder.mkpath(QStringLiteral("bug/shots")));
        QVERIFY(QFile::copy(datasetPath("icosphere.off"), folder.filePath(QStringLiteral("bug/sphere.off"))));
        const QString file = folder.filePath(QStringLiteral("bug/report.json"));
        writeFile(file, R"([{"open": "sphere.off"}, {"set": {"views": 16, "test": "apex"}}, {"orbit-view": 3}, {"pick": 2},
                            {"caption": "cluster 2 from view 3"}, {"screenshot": "shots/view.png"},
                            {"window-screenshot": "shots/window.png"}, {"export": "orbit.json"}, {"export-eye": "eye.csv"}])");
        ReplayPlayer player(*window_);
        std::vector<size_t> finished;
        connect(&player, &ReplayPlayer::stepFinished, this, [&](size_t step) { finished.push_back(step); });
        const QString error = player.playBlocking(readReplayFile(file));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(finished.size(), size_t(9));
        QCOMPARE(QString::fromStdString(window_->preparedMesh()->path), QDir::cleanPath(folder.filePath(QStringLiteral("bug/sphere.off"))));
        QCOMPARE(window_->session().orbitStep(), 3L);
        QCOMPARE(window_->pickedCluster(), 2);
        QCOMPARE(static_cast<ObserverView*>(window_->observerView())->caption(), QStringLiteral("cluster 2 from view 3"));
        QCOMPARE(QImage(folder.filePath(QStringLiteral("bug/shots/view.png"))).size(), window_->observerView()->size());
        QCOMPARE(QImage(folder.filePath(QStringLiteral("bug/shots/window.png"))).size(), window_->size());
        const nlohmann::json orbit = readJsonFile(folder.filePath(QStringLiteral("bug/orbit.json")));
        QCOMPARE(orbit["view_count"].get<size_t>(), size_t(16));
        QCOMPARE(orbit["settings"]["tests"], nlohmann::json::array({"apex"}));
        QVERIFY(QFile::exists(folder.filePath(QStringLiteral("bug/eye.csv"))));
        // A step that cannot be done stops the replay with its number and text.
        const QString stopped = player.playBlocking(parseReplay(R"([{"caption": ""}, {"pick": 100000}, {"caption": "never"}])", folder.path()));
        QVERIFY2(stopped.startsWith(QStringLiteral("step 2 {\"pick\":100000}: the mesh has ")), qPrintable(stopped));
        QCOMPARE(static_cast<ObserverView*>(window_->observerView())->caption(), QString());
        const QString unshowable = player.playBlocking(parseReplay(R"([{"set": {"distance": 3.14159}}])", folder.path()));
        QVERIFY2(unshowable.contains(QStringLiteral("distance=3.142, not 3.14159")), qPrintable(unshowable));
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
    }

    void replayExitsNonZeroNamingTheStepItCannotDo() {
        QString errors;
        QCOMPARE(replay(QStringLiteral("missing.json"), R"([{"caption": "start"}, {"open": "no-such-mesh.off"}])", &errors), 1);
        QVERIFY2(errors.contains(QStringLiteral("step 2 {\"open\":\"no-such-mesh.off\"}")) && errors.contains(QStringLiteral("no-such-mesh.off")),
                 qPrintable(errors));
        QCOMPARE(replay(QStringLiteral("broken.json"), R"([{"open": "x.off"},])", &errors), 1);
        QVERIFY2(errors.contains(QStringLiteral("not JSON")), qPrintable(errors));
        QCOMPARE(replay(QStringLiteral("swap.json"), R"([{"swap": true}])", &errors), 1);
        QVERIFY2(errors.contains(QStringLiteral("step 1 {\"swap\":true}: nothing is pinned")), qPrintable(errors));
    }

    // Issue 29, done when: meshoptimizer's pipeline pinned as A, the defaults set back, exported.
    void pinnedMeshoptAgainstTheDefaultsExportsWhatTheCliCompares() {
        const QString out = temporary_.filePath(QStringLiteral("meshopt-ab.json"));
        QString errors;
        // As a user sets the boxes: the test last, after the clusters are built (and back first).
        const QByteArray steps = QStringLiteral(R"([{"open": "%1"}, {"set": {"views": 64, "distance": 3}},
            {"set": {"builder": "meshopt", "cone": "meshopt"}}, {"set": {"test": "apex"}}, {"pin": "A"},
            {"set": {"test": "octagon"}}, {"set": {"builder": "optimized", "cone": "chosen"}}, {"export": "%2"}])")
                                     .arg(datasetPath("elephant.off"), out)
                                     .toUtf8();
        QCOMPARE(replay(QStringLiteral("meshopt-ab-replay.json"), steps, &errors), 0);
        const nlohmann::json window = readJsonFile(out);
        const nlohmann::json cli = cliCompare(QStringLiteral("builder=meshopt,cone=meshopt,test=apex"), QString());
        QVERIFY(!cli.is_null());
        for (const char* key : {"efficiency_a", "efficiency_b", "triangles_culled_only_a", "triangles_culled_only_b", "test_a", "test_b"})
            QVERIFY2(window["diff"][key] == cli["diff"][key], key);
        QCOMPARE(window["diff"]["test_a"].get<std::string>(), std::string("apex"));
        QVERIFY(window["diff"]["triangles_culled_only_b"].get<size_t>() > 0);
        // The whole document, each side as `stats` writes it, but for the measured times.
        QVERIFY(withoutTimings(window) == withoutTimings(cli));
    }

    // Issue 29, done when: A pinned after a change of the Test box alone is B itself.
    void pinAfterATestOnlyChangeExportsNoDifference() {
        const QString out = temporary_.filePath(QStringLiteral("test-only.json"));
        const QByteArray steps = QStringLiteral(R"([{"open": "%1"}, {"set": {"views": 64, "distance": 3}}, {"set": {"test": "apex"}},
            {"pin": "A"}, {"export": "%2"}])")
                                     .arg(datasetPath("elephant.off"), out)
                                     .toUtf8();
        QCOMPARE(replay(QStringLiteral("test-only-replay.json"), steps), 0);
        const nlohmann::json window = readJsonFile(out);
        QCOMPARE(window["diff"]["triangles_culled_only_a"].get<size_t>(), size_t(0));
        QCOMPARE(window["diff"]["triangles_culled_only_b"].get<size_t>(), size_t(0));
        const nlohmann::json cli = cliCompare(QStringLiteral("test=apex"), QStringLiteral("test=apex"));
        QVERIFY(!cli.is_null());
        QCOMPARE(window["diff"]["efficiency_a"].get<double>(), cli["diff"]["efficiency_a"].get<double>());
        QVERIFY(withoutTimings(window) == withoutTimings(cli));
    }

    // Issue 33, done when: the elephant's cluster that `conescope-cli clusters --sort test-loss --top 1`
    // names, its six lesson steps as six different pictures, the cross-section and the explanation,
    // whose alpha is the CLI's half_angle_deg.
    void lessonOnTheClusterTheCliRanksFirst() {
        const QString table = temporary_.filePath(QStringLiteral("worst.json"));
        QString errors;
        QCOMPARE(runProgram(QStringLiteral(CONESCOPE_CLI_PATH),
                            {QStringLiteral("clusters"), datasetPath("elephant.off"), QStringLiteral("--sort"), QStringLiteral("test-loss"),
                             QStringLiteral("--top"), QStringLiteral("1"), QStringLiteral("--quiet"), QStringLiteral("-o"), table},
                            &errors),
                 0);
        const nlohmann::json worst = readJsonFile(table)["rows"][0];
        const int cluster = worst["cluster"].get<int>();
        QDir folder(temporary_.path());
        QVERIFY(folder.mkpath(QStringLiteral("lesson")));
        QString steps = QStringLiteral(R"([{"open": "%1"}, {"choose": %2})").arg(datasetPath("elephant.off")).arg(cluster);
        for (int step = 1; step <= kLessonStepCount; ++step)
            steps += QStringLiteral(R"(, {"lesson-step": %1}, {"screenshot": "lesson/step%1.png"})").arg(step);
        steps += QStringLiteral(R"(, {"cross-section": "lesson/cross-section.png"}, {"export-explanation": "lesson/explanation.json"}])");
        QCOMPARE(replay(QStringLiteral("elephant-lesson.json"), steps.toUtf8(), &errors), 0);
        std::vector<QImage> pictures;
        for (int step = 1; step <= kLessonStepCount; ++step) {
            pictures.emplace_back(folder.filePath(QStringLiteral("lesson/step%1.png").arg(step)));
            QVERIFY(!pictures.back().isNull());
        }
        for (size_t a = 0; a < pictures.size(); ++a)
            for (size_t b = a + 1; b < pictures.size(); ++b) QVERIFY2(pictures[a] != pictures[b], qPrintable(QStringLiteral("%1 %2").arg(a + 1).arg(b + 1)));
        QCOMPARE(QImage(folder.filePath(QStringLiteral("lesson/cross-section.png"))).size(), QSize(960, 720));
        const nlohmann::json explanation = readJsonFile(folder.filePath(QStringLiteral("lesson/explanation.json")));
        // Beside the picture, what it drew: the same cluster, cone and verdict as the explanation.
        const nlohmann::json drawn = readJsonFile(folder.filePath(QStringLiteral("lesson/cross-section.json")));
        QCOMPARE(drawn["cluster"].get<int>(), cluster);
        QCOMPARE(drawn["culls"].get<bool>(), explanation["verdict"] == "culled");
        QCOMPARE(drawn["half_angle_deg"].get<double>(), explanation["alpha_degrees"].get<double>());
        QVERIFY(drawn["labels"].size() >= 3 && drawn["labels_left_out"].empty());
        QCOMPARE(explanation["cluster"].get<int>(), cluster);
        QVERIFY2(std::abs(explanation["alpha_degrees"].get<double>() - worst["half_angle_deg"].get<double>()) < 0.05,
                 qPrintable(QString::fromStdString(explanation.dump())));
        QCOMPARE(explanation["test"].get<std::string>(), readJsonFile(table)["test"].get<std::string>());
        QCOMPARE(explanation["steps"].size(), size_t(kLessonStepCount));
        for (const nlohmann::json& step : explanation["steps"])
            QVERIFY(!step["title"].get<std::string>().empty() && step["text"].get<std::string>().size() > 80);
        QVERIFY(explanation["verdict"] == "culled" || explanation["verdict"] == "drawn");
        // The cluster was chosen where the test loses it: the words say so.
        QCOMPARE(explanation["outcome"].get<std::string>(), std::string("lost to the test"));
        QVERIFY(explanation["steps"][5]["text"].get<std::string>().find("lost to the test") != std::string::npos);
    }

    // The lesson's slides are 1920x1080 PNGs and a PDF of 16:9 pages at
    // QT_SCALE_FACTOR 1 and 2 alike (they are laid out and rendered in slide pixels, not the screen's),
    // and the eye's sweep writes a slide at every frame.
    void slidesAreFullHdAtScaleOneAndTwo() {
        QDir folder(temporary_.path());
        for (const char* scale : {"1", "2"}) {
            const QString steps = QStringLiteral(R"([{"open": "%1"}, {"set": {"test": "apex"}}, {"example": "culled"},
                {"slides": "scale%2/lesson"}, {"lesson-step": 5}, {"sweep-eye": {"frames": 4, "slides": "scale%2/sweep"}}])")
                                      .arg(datasetPath("torus.off"), QString::fromLatin1(scale));
            qputenv("QT_SCALE_FACTOR", scale);
            QString errors;
            const int code = replay(QStringLiteral("slides-%1.json").arg(QString::fromLatin1(scale)), steps.toUtf8(), &errors);
            qunsetenv("QT_SCALE_FACTOR");
            QVERIFY2(code == 0, qPrintable(errors));
        }
        for (const auto& [kind, count] : {std::pair<QString, int>{QStringLiteral("lesson"), kLessonStepCount}, {QStringLiteral("sweep"), 4}}) {
            for (int n = 1; n <= count; ++n) {
                const QImage one(folder.filePath(QStringLiteral("scale1/%1/slide-%2.png").arg(kind).arg(n, 2, 10, QLatin1Char('0'))));
                const QImage two(folder.filePath(QStringLiteral("scale2/%1/slide-%2.png").arg(kind).arg(n, 2, 10, QLatin1Char('0'))));
                QCOMPARE(one.size(), QSize(1920, 1080));
                QCOMPARE(two.size(), QSize(1920, 1080));
                // The same slide: at most a sliver of pixels differs (text hinting).
                qint64 differing = 0;
                for (int y = 0; y < one.height(); ++y)
                    for (int x = 0; x < one.width(); ++x) {
                        const QRgb a = one.pixel(x, y), b = two.pixel(x, y);
                        differing += std::abs(qRed(a) - qRed(b)) + std::abs(qGreen(a) - qGreen(b)) + std::abs(qBlue(a) - qBlue(b)) > 48;
                    }
                QVERIFY2(differing < 1920 * 1080 / 100, qPrintable(QStringLiteral("%1 %2: %3 pixels differ").arg(kind).arg(n).arg(differing)));
            }
            for (const char* scale : {"1", "2"}) {
                QFile pdf(folder.filePath(QStringLiteral("scale%1/%2/slides.pdf").arg(QString::fromLatin1(scale), kind)));
                QVERIFY(pdf.open(QIODevice::ReadOnly));
                const QByteArray text = pdf.readAll();
                QVERIFY(text.startsWith("%PDF"));
                QVERIFY(text.contains(QStringLiteral("/Count %1").arg(count).toLatin1()));
                QCOMPARE(text.count("/MediaBox [0 0 960.000000 540.000000]"), count);
            }
        }
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    ReplayTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "ReplayTests.moc"
