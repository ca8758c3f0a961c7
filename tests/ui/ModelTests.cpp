// The window against a model of it: random sessions (settings changed, A pinned, swapped and
// dropped, builds cancelled, the eye moved, clusters picked) played as replay steps, with fixed
// seeds. After every step the model says which settings the window shows and which are pinned; the
// widgets must show exactly those, and every number the window exports (the orbit and the eye; A
// against B while pinned) must be what the core computes for them on its own: measureRun for the
// settings shown, compareClusterSets with A's and B's settings. A failure prints the seed and the
// steps as a replay file, so `conescope --replay` shows it. CONESCOPE_MODEL_SEQUENCES=N plays more.
#include <map>
#include <optional>
#include <random>
#include <sstream>

#include <QDockWidget>
#include <vtkRenderWindow.h>
#include <QSurfaceFormat>
#include <QtTest>

#include "ReplayPlayer.h"
#include "ReplaySteps.h"
#include "SettingsPanel.h"
#include "UiTestSupport.h"
#include "WindowTestSupport.h"
#include "core/Comparison.h"
#include "core/SettingsSchema.h"
#include "io/ComparisonIO.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

using namespace conescope;
using namespace conescope::testing;
using Json = nlohmann::json;

namespace {

constexpr int defaultSequences = 200;
const char* const meshes[] = {"icosphere.off", "torus.off", "hexagonal-prism.off", "cube-quads.off"};

// What the window should show, by the rules of issue 29: a build that is cancelled changes nothing,
// swapping exchanges the shown and the pinned settings, A takes B's views.
struct Model {
    QString mesh;
    Settings shown;
    std::optional<Settings> pin;
    bool cancelArmed = false;
    glm::dvec3 eye{0.0};
};

// The core's stages for the expected numbers, made once per mesh and per partition and bounds.
class CoreRuns {
public:
    const PreparedMesh& prepared(const QString& mesh) {
        auto found = prepared_.find(mesh);
        if (found == prepared_.end()) {
            PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(readMesh(mesh.toStdString())), mesh.toStdString(), false);
            found = prepared_.emplace(mesh, std::move(prepared)).first;
        }
        return found->second;
    }
    const ClusterSet& clusters(const QString& mesh, const Settings& settings) {
        // Everything that makes the partition or its bounds.
        std::string key = mesh.toStdString();
        for (const SettingField& field : settingFields())
            if (field.invalidates <= Stage::Bounds) key += "|" + field.flag + "=" + settingText(field, settings);
        auto found = clusters_.find(key);
        if (found == clusters_.end()) found = clusters_.emplace(key, buildClusters(prepared(mesh), settings)).first;
        return found->second;
    }
    // The document the window's statistics export must write for these settings (one eye when set).
    Json expected(const Model& model, const Settings& settingsB) {
        const PreparedMesh& prepared = this->prepared(model.mesh);
        const ClusterSet& b = clusters(model.mesh, settingsB);
        const RunStatistics runB = measureRun(prepared, b, settingsB);
        if (!model.pin) return Json::parse(statisticsJsonText(runB));
        const Settings settingsA = withSharedOptions(*model.pin, settingsB);
        const ClusterSet& a = clusters(model.mesh, settingsA);
        const RunStatistics runA = measureRun(prepared, a, settingsA);
        const Comparison comparison = compareClusterSets(prepared, {a, settingsA}, {b, settingsB}, viewsFor(settingsB, prepared.box));
        std::ostringstream text;
        writeComparisonJson(runA, runB, comparison, StatisticsDetail{}, text);
        return Json::parse(text.str());
    }

private:
    std::map<QString, PreparedMesh> prepared_;
    std::map<std::string, ClusterSet> clusters_;
};

template <typename T, size_t N>
const T& pick(std::mt19937& random, const T (&values)[N]) {
    return values[std::uniform_int_distribution<size_t>(0, N - 1)(random)];
}

// One or two settings, with values the panel's widgets show exactly.
Json randomSettings(std::mt19937& random) {
    const struct {
        const char* key;
        std::vector<Json> values;
    } choices[] = {
        {"builder", {"optimized", "meshlet", "meshopt", "kmeans"}},
        {"effort", {"fast", "balanced"}},
        {"max-tris", {32, 64, 124}},
        {"max-verts", {32, 64}},
        {"cone", {"minimal", "average", "meshopt", "seed-sphere"}},
        {"test", {"octagon", "apex", "sphere", "aabb", "aabb-fast", "vertices", "meshopt-sphere", "oracle"}},
        {"sphere", {"minimal", "ritter"}},
        {"views", {8, 12, 16}},
        {"distance", {2, 3, 4.5}},
        {"ortho", {true, false}},
    };
    Json settings = Json::object();
    const int count = std::uniform_int_distribution<int>(1, 2)(random);
    for (int i = 0; i < count; ++i) {
        const auto& choice = choices[std::uniform_int_distribution<size_t>(0, std::size(choices) - 1)(random)];
        settings[choice.key] = choice.values[std::uniform_int_distribution<size_t>(0, choice.values.size() - 1)(random)];
    }
    return settings;
}

Settings applied(Settings settings, const Json& changes) {
    for (const auto& item : changes.items()) {
        const Json& value = item.value();
        const std::string text = value.is_string() ? value.get<std::string>() : value.is_boolean() ? (value.get<bool>() ? "true" : "false")
                                                                                                    : value.dump();
        parseSetting(settingField(item.key()), text, settings);
    }
    return settings;
}

}  // namespace

class ModelTests : public QObject, private WindowFixture {
    Q_OBJECT

    CoreRuns core_;
    Json played_;  // the current sequence's steps, for the failure message

    QString failure(unsigned seed, const QString& what) const {
        QString steps;
        for (const Json& step : played_) steps += (steps.isEmpty() ? QStringLiteral("[") : QStringLiteral(",\n ")) + QString::fromStdString(step.dump());
        return QStringLiteral("seed %1: %2\nthe sequence as a replay file:\n%3]").arg(seed).arg(what, steps);
    }

    // What the window holds when a sequence starts, as steps: a replay of the sequence starts from it.
    void recordStart(const Model& model) {
        Json settings = Json::object();
        for (const char* flag : {"builder", "effort", "max-tris", "max-verts", "cone", "test", "sphere", "views", "distance", "ortho"})
            settings[flag] = settingText(settingField(flag), model.shown);
        played_ = Json::array({Json{{"set", settings}}});
        if (!model.mesh.isEmpty()) played_.push_back(Json{{"open", model.mesh.toStdString()}});
        if (model.cancelArmed) played_.push_back(Json{{"cancel-next-build", true}});
    }

    // Plays one step as a replay step; empty or the player's message.
    QString play(ReplayPlayer& player, const Json& step) {
        played_.push_back(step);
        return player.playBlocking(parseReplay(Json::array({step}).dump(), temporary_.path()));
    }

    // The widgets, the snapshot, the pin and every export against the model.
    void check(ReplayPlayer& player, const Model& model, unsigned seed) {
        const Session& session = window_->session();
        const auto same = [](const Settings& a, const Settings& b) { return sameSettings(a, b); };
        QVERIFY2(same(window_->settingsPanel()->settings(), model.shown), qPrintable(failure(seed, QStringLiteral("the widgets show other settings"))));
        QVERIFY2(same(session.settings(), model.shown), qPrintable(failure(seed, QStringLiteral("the snapshot has other settings"))));
        QVERIFY2(same(session.askedSettings(), model.shown), qPrintable(failure(seed, QStringLiteral("other settings are asked for"))));
        QVERIFY2(session.hasPin() == bool(model.pin), qPrintable(failure(seed, QStringLiteral("pinned or not, unlike the model"))));
        if (model.pin)
            QVERIFY2(same(*session.pinnedSettings(), withSharedOptions(*model.pin, model.shown)),
                     qPrintable(failure(seed, QStringLiteral("A has other settings"))));
        QVERIFY2(session.eyePosition() == model.eye, qPrintable(failure(seed, QStringLiteral("the eye is elsewhere"))));

        const QString orbitPath = temporary_.filePath(QStringLiteral("model-orbit.json"));
        const QString eyePath = temporary_.filePath(QStringLiteral("model-eye.json"));
        QString error = play(player, Json{{"export", orbitPath.toStdString()}});
        QVERIFY2(error.isEmpty(), qPrintable(failure(seed, error)));
        error = play(player, Json{{"export-eye", eyePath.toStdString()}});
        QVERIFY2(error.isEmpty(), qPrintable(failure(seed, error)));
        const Json orbit = core_.expected(model, model.shown);
        const Json eye = core_.expected(model, exportSettings(model.shown, model.eye));
        QVERIFY2(withoutTimings(readJsonFile(orbitPath)) == withoutTimings(orbit),
                 qPrintable(failure(seed, QStringLiteral("the orbit export is not the core's"))));
        QVERIFY2(withoutTimings(readJsonFile(eyePath)) == withoutTimings(eye),
                 qPrintable(failure(seed, QStringLiteral("the eye export is not the core's"))));
        // What the window shows: the eye's numbers, and A against B for the eye and the orbit.
        const Json& eyeB = model.pin ? eye["b"] : eye;
        QVERIFY2(session.measurement() && session.measurement()->view().trianglesCulled == eyeB["results"][0]["triangles_culled"].get<size_t>(),
                 qPrintable(failure(seed, QStringLiteral("the eye's statistics are not the core's"))));
        if (!model.pin) return;
        const Comparison* shownEye = session.eyeComparison();
        const Comparison* shownOrbit = session.orbitComparison();
        QVERIFY2(shownEye && shownEye->trianglesCulledOnlyA == eye["diff"]["triangles_culled_only_a"].get<size_t>() &&
                     shownEye->trianglesCulledOnlyB == eye["diff"]["triangles_culled_only_b"].get<size_t>(),
                 qPrintable(failure(seed, QStringLiteral("the eye's A/B is not the core's"))));
        QVERIFY2(shownOrbit && shownOrbit->trianglesCulledOnlyA == orbit["diff"]["triangles_culled_only_a"].get<size_t>() &&
                     shownOrbit->trianglesCulledOnlyB == orbit["diff"]["triangles_culled_only_b"].get<size_t>(),
                 qPrintable(failure(seed, QStringLiteral("the orbit's A/B is not the core's"))));
    }

    // A random action, played, and the model moved as the window should move.
    void step(std::mt19937& random, ReplayPlayer& player, Model& model, unsigned seed) {
        const int kind = std::uniform_int_distribution<int>(0, 99)(random);
        const PreparedMesh& prepared = core_.prepared(model.mesh);
        Json step;
        if (kind < 36) {
            step = {{"set", randomSettings(random)}};
            const Settings next = applied(model.shown, step["set"]);
            const bool builds = boundsChanged(model.shown, next) || next.fixWinding != model.shown.fixWinding;
            if (builds && model.cancelArmed)
                model.cancelArmed = false;  // cancelled: nothing changes
            else
                model.shown = next;
        } else if (kind < 48) {
            step = {{"pin", "A"}};
            model.pin = model.shown;
        } else if (kind < 56 && model.pin) {
            step = {{"swap", true}};
            const Settings previous = model.shown;
            model.shown = withSharedOptions(*model.pin, model.shown);
            model.pin = previous;
        } else if (kind < 62) {
            step = {{"drop-pin", true}};
            model.pin.reset();
        } else if (kind < 72) {
            step = {{"cancel-next-build", true}};
            model.cancelArmed = true;
        } else if (kind < 82) {
            // Anywhere from 1.5 to 4 half-diagonals out, in any direction.
            std::normal_distribution<double> normal;
            glm::dvec3 direction(normal(random), normal(random), normal(random));
            direction = glm::length(direction) > 1e-9 ? glm::normalize(direction) : glm::dvec3(0.0, 0.0, 1.0);
            const double distance = std::uniform_real_distribution<double>(1.5, 4.0)(random) * prepared.box.halfDiagonal();
            model.eye = glm::dvec3(prepared.box.center()) + distance * direction;
            step = {{"eye", {model.eye.x, model.eye.y, model.eye.z}}};
        } else if (kind < 90) {
            const long view = std::uniform_int_distribution<long>(0, long(model.shown.views) - 1)(random);
            step = {{"orbit-view", view}};
            model.eye = orbitOf(model.shown, prepared.box)[size_t(view)].position;
        } else {
            const int count = int(window_->clusters()->partition.clusterCount);
            step = {{"pick", std::uniform_int_distribution<int>(-1, count - 1)(random)}};
        }
        const QString error = play(player, step);
        QVERIFY2(error.isEmpty(), qPrintable(failure(seed, error)));
        check(player, model, seed);
    }

    void open(ReplayPlayer& player, Model& model, const QString& mesh, unsigned seed) {
        const QString error = play(player, Json{{"open", mesh.toStdString()}});
        QVERIFY2(error.isEmpty(), qPrintable(failure(seed, error)));
        if (model.cancelArmed && !model.mesh.isEmpty()) {
            model.cancelArmed = false;  // the load was cancelled: the mesh shown stays
        } else {
            model.cancelArmed = false;
            model.mesh = mesh;
            model.pin.reset();
            model.eye = startingEyePosition(core_.prepared(mesh).box, model.shown);
        }
        check(player, model, seed);
    }

private slots:
    void initTestCase() {
        openWindow();
        // Numbers are checked here, not pictures: a small window with its docks closed, drawing the
        // faces alone without multisampling, lets the software renderer keep the run near a minute
        // (the panels' widgets still hold what they show).
        for (QVTKOpenGLNativeWidget* view : window_->findChildren<QVTKOpenGLNativeWidget*>()) view->renderWindow()->SetMultiSamples(0);
        for (QDockWidget* dock : window_->findChildren<QDockWidget*>()) dock->hide();
        window_->resize(400, 300);
        for (Layer layer : allLayers()) window_->setLayerVisible(layer, layer == Layer::Faces);
    }
    void cleanupTestCase() { window_.reset(); }

    void randomSessionsShowAndExportWhatTheCoreComputes() {
        const int sequences = qEnvironmentVariableIsSet("CONESCOPE_MODEL_SEQUENCES") ? qEnvironmentVariableIntValue("CONESCOPE_MODEL_SEQUENCES")
                                                                                     : defaultSequences;
        ReplayPlayer player(*window_);
        Model model;
        // Small views and the defaults otherwise; each sequence opens a mesh and takes a few steps.
        window_->setSettings(applied(Settings{}, Json{{"views", 12}}));
        window_->waitUntilIdle();
        model.shown = window_->settings();
        for (int sequence = 0; sequence < sequences; ++sequence) {
            const unsigned seed = 29000u + unsigned(sequence);
            std::mt19937 random(seed);
            recordStart(model);
            open(player, model, datasetPath(pick(random, meshes)), seed);
            if (QTest::currentTestFailed()) return;
            const int steps = std::uniform_int_distribution<int>(3, 6)(random);
            for (int s = 0; s < steps; ++s) {
                step(random, player, model, seed);
                if (QTest::currentTestFailed()) return;
            }
        }
    }
};

int main(int argc, char** argv) {
    // The GL format VTK needs, before the application object exists.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    ModelTests tests;
    return QTest::qExec(&tests, argc, argv);
}

#include "ModelTests.moc"
