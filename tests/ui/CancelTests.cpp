// Cancel at every stage the progress shows ({"cancel-at-stage": NAME}) of every kind of background
// work: a load, new clusters, another test, a pin, new clusters with A pinned, a swap and an export.
// Whatever the stage, the window shows what it showed before (the settings in its widgets, the same
// clusters, their orbit on the plot, A and its comparison) and its export is conescope-cli's for the
// settings shown. The stages are those a run of the same action shows, so a new stage is tested too.
#include <iterator>
#include <map>

#include <QFile>
#include <QStatusBar>
#include <QSurfaceFormat>
#include <QtTest>

#include "ReplayPlayer.h"
#include "ReplaySteps.h"
#include "SettingsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/SettingsSchema.h"

using namespace conescope;
using namespace conescope::testing;

namespace {

// What the window shows: each piece as the object it is, so "the same" means not made again.
struct Shown {
    const PreparedMesh* prepared = nullptr;
    const ClusterSet* clusters = nullptr;
    const CullTestStatistics* orbit = nullptr;
    Settings settings;
    const ClusterSet* pinned = nullptr;
    const Comparison* comparison = nullptr;
};

Shown shownBy(MainWindow& window) {
    Session& session = window.session();
    return {session.preparedMesh(), session.clusters(), session.orbitStatistics(), session.settings(), session.pinnedClusters(),
            session.orbitComparison()};
}

// One action and the state it starts from.
struct Case {
    const char* name;
    const char* setup;   // steps after opening the elephant at 16 views
    const char* action;  // the steps whose stages are cancelled, %1 the temporary folder
};

const Case cases[] = {
    {"load", "[]", R"([{"open": "%2"}])"},
    {"clusters", "[]", R"([{"set": {"max-tris": 48}}])"},
    {"test", "[]", R"([{"set": {"test": "apex"}}])"},
    {"views", "[]", R"([{"set": {"views": 24}}])"},
    {"pin", "[]", R"([{"pin": "A"}])"},
    {"clusters with A", R"([{"set": {"builder": "meshopt", "cone": "meshopt", "test": "apex"}}, {"pin": "A"}, {"set": {"builder": "optimized", "cone": "minimal", "test": "octagon"}}])",
     R"([{"set": {"max-tris": 48}}])"},
    {"swap", R"([{"set": {"builder": "meshopt"}}, {"pin": "A"}, {"set": {"builder": "optimized", "views": 20}}])", R"([{"swap": true}])"},
    {"export", "[]", R"([{"export": "%1/cancelled-export.json"}])"},
};

}  // namespace

class CancelTests : public QObject, private WindowFixture {
    Q_OBJECT

    std::map<QString, nlohmann::json> cliDocuments_;  // conescope-cli stats's documents, by their arguments

    QString play(const QString& steps) {
        ReplayPlayer player(*window_);
        try {
            return player.playBlocking(parseReplay(steps.toStdString(), temporary_.path()));
        } catch (const ReplayError& error) {
            return QString::fromStdString(error.what());
        }
    }

    QString actionOf(const Case& test) const {
        return QString::fromUtf8(test.action).replace(QStringLiteral("%1"), temporary_.path()).replace(QStringLiteral("%2"), datasetPath("torus.off"));
    }

    // The elephant at 16 views with the case's setup, nothing else asked.
    void setUp(const Case& test) {
        window_->session().clearPin();
        window_->setSettings(Settings{});
        window_->waitUntilIdle();
        const QString error = play(QStringLiteral(R"([{"open": "%1"}, {"set": {"views": 16}}])").arg(datasetPath("elephant.off")));
        QVERIFY2(error.isEmpty(), qPrintable(error));
        const QString setup = play(QString::fromUtf8(test.setup));
        QVERIFY2(setup.isEmpty(), qPrintable(setup));
    }

    // The stages the progress shows while the action runs to its end, each once.
    QStringList stagesOf(const Case& test) {
        setUp(test);
        QStringList stages;
        Session& session = window_->session();
        const auto add = [&stages](const QString& stage) {
            if (!stages.contains(stage)) stages << stage;
        };
        const auto started = connect(&session, &Session::taskStarted, this, add);
        const auto progress = connect(&session, &Session::progressChanged, this, [add](double, const QString& stage) { add(stage); });
        const QString error = play(actionOf(test));
        disconnect(started);
        disconnect(progress);
        if (!error.isEmpty()) qWarning("%s", qPrintable(error));
        return stages;
    }

    // The window's export now, against conescope-cli's for the settings shown (each side for A and B).
    void checkExportIsTheCli(const QString& where) {
        const QString path = temporary_.filePath(QStringLiteral("after-cancel.json"));
        QFile::remove(path);
        const QString error = play(QStringLiteral(R"([{"export": "%1"}])").arg(path));
        QVERIFY2(error.isEmpty(), qPrintable(where + error));
        const nlohmann::json exported = readJsonFile(path);
        const Session& session = window_->session();
        std::vector<std::pair<nlohmann::json, Settings>> sides = {{exported, session.settings()}};
        if (session.hasPin())
            sides = {{exported["a"], withSharedOptions(*session.pinnedSettings(), session.settings())}, {exported["b"], session.settings()}};
        for (const auto& [side, settings] : sides) {
            QStringList arguments = {QStringLiteral("stats"), datasetPath("elephant.off"), QStringLiteral("--quiet"), QStringLiteral("--format"),
                                     QStringLiteral("json"), QStringLiteral("-o"), temporary_.filePath(QStringLiteral("cli.json"))};
            for (const std::string& argument : settingArguments(settings)) arguments << QString::fromStdString(argument);
            // Run once for each setting's arguments: the same arguments give the same document.
            nlohmann::json& cli = cliDocuments_[arguments.join(QLatin1Char(' '))];
            if (cli.is_null()) {
                QString errors;
                QCOMPARE(runProgram(QStringLiteral(CONESCOPE_CLI_PATH), arguments, &errors), 0);
                cli = readJsonFile(temporary_.filePath(QStringLiteral("cli.json")));
            }
            QVERIFY2(withoutTimings(side) == withoutTimings(cli), qPrintable(where + QString::fromStdString(nlohmann::json::diff(withoutTimings(cli), withoutTimings(side)).dump()).left(600)));
        }
        // The plot draws the orbit the export measured.
        const std::vector<ViewStatistics>& rows = session.orbitRows();
        const nlohmann::json& views = (session.hasPin() ? exported["b"] : exported)["results"][0]["views"];
        QCOMPARE(rows.size(), views.size());
        for (size_t v = 0; v < rows.size(); ++v) QCOMPARE(rows[v].efficiency, views[v]["efficiency"].get<double>());
    }

private slots:
    void initTestCase() { openWindow(); }
    void cleanupTestCase() { window_.reset(); }

    void cancelAtEveryStageLeavesWhatWasShown_data() {
        QTest::addColumn<int>("index");
        for (size_t index = 0; index < std::size(cases); ++index) QTest::newRow(cases[index].name) << int(index);
    }

    void cancelAtEveryStageLeavesWhatWasShown() {
        QFETCH(int, index);
        const Case& test = cases[index];
        const QStringList stages = stagesOf(test);
        QVERIFY2(stages.size() >= 2, test.name);
        qInfo("%s: %s", test.name, qPrintable(stages.join(QStringLiteral(" | "))));
        // A Cancel leaves the window as it was: each stage starts from the same state.
        setUp(test);
        const Shown before = shownBy(*window_);
        checkExportIsTheCli(QStringLiteral("before: "));
        {
            for (const QString& stage : stages) {
                const QString where = QStringLiteral("%1, cancelled at '%2': ").arg(QString::fromUtf8(test.name), stage);
                QVERIFY(before.orbit);
                QFile::remove(temporary_.filePath(QStringLiteral("cancelled-export.json")));
                const QString error = play(QStringLiteral(R"([{"cancel-at-stage": "%1"}, )").arg(stage) + actionOf(test).mid(1));
                QVERIFY2(error.isEmpty(), qPrintable(where + error));
                const Shown after = shownBy(*window_);
                QVERIFY2(after.prepared == before.prepared && after.clusters == before.clusters, qPrintable(where + "other clusters"));
                QVERIFY2(after.orbit == before.orbit, qPrintable(where + "another orbit"));
                QVERIFY2(sameSettings(after.settings, before.settings), qPrintable(where + "other settings"));
                QVERIFY2(sameSettings(window_->settingsPanel()->settings(), after.settings), qPrintable(where + "the widgets show other settings"));
                QVERIFY2(after.pinned == before.pinned && after.comparison == before.comparison, qPrintable(where + "another A or comparison"));
                QVERIFY2(window_->statusBar()->currentMessage().startsWith(QStringLiteral("Cancelled:")), qPrintable(where + window_->statusBar()->currentMessage()));
                QVERIFY2(!QFile::exists(temporary_.filePath(QStringLiteral("cancelled-export.json"))), qPrintable(where + "the export was written"));
                checkExportIsTheCli(where);
            }
        }
    }

    // The stages of the bug: new clusters were shown but their orbit was still to come when Cancel
    // was pressed while the progress read "scene". The orbit now comes with them.
    void newClustersShowTheirSceneAndOrbitStages() {
        const QStringList stages = stagesOf(cases[1]);
        for (const char* stage : {"Building clusters", "scene", "orbit statistics"})
            QVERIFY2(stages.contains(QString::fromUtf8(stage)), qPrintable(stages.join(QStringLiteral(" | "))));
        QVERIFY(stages.indexOf(QStringLiteral("scene")) < stages.indexOf(QStringLiteral("orbit statistics")));
    }

    // Cancel pressed as the last task delivers (the click comes in while the new clusters are put on
    // screen): nothing is left to cancel, the new clusters stay whole with their orbit, and the
    // status line says so rather than that the old ones stay.
    void cancelAsTheBuildEndsKeepsTheNewClustersWhole() {
        setUp(cases[1]);
        const ClusterSet* before = window_->clusters();
        Session& session = window_->session();
        const auto late = connect(&session, &Session::sceneReplaced, this, [&session]() { session.cancel(); });
        const QString error = play(actionOf(cases[1]));
        disconnect(late);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QVERIFY(window_->clusters() != before);
        QCOMPARE(window_->settings().limits.maxTriangles, size_t(48));
        QCOMPARE(size_t(window_->settingsPanel()->settings().limits.maxTriangles), size_t(48));
        QVERIFY(session.orbitStatistics());
        QVERIFY2(window_->statusBar()->currentMessage().startsWith(QStringLiteral("Nothing to cancel")),
                 qPrintable(window_->statusBar()->currentMessage()));
        checkExportIsTheCli(QStringLiteral("cancelled as it ended: "));
    }

    // A stage that never comes stops the replay, naming the stages that did.
    void aStageThatNeverComesStopsTheReplay() {
        setUp(cases[2]);
        const QString error = play(QStringLiteral(R"([{"cancel-at-stage": "no such stage"}, {"set": {"test": "apex"}}])"));
        QVERIFY2(error.startsWith(QStringLiteral("step 2 ")) && error.contains(QStringLiteral("never showed the stage")) &&
                     error.contains(QStringLiteral("orbit statistics")),
                 qPrintable(error));
        QVERIFY(!window_->session().cancelStageArmed());
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    CancelTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "CancelTests.moc"
