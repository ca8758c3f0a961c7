#include "ReplaySteps.h"

#include <fstream>
#include <iterator>

#include <QDir>
#include <QFileInfo>

#include <nlohmann/json.hpp>

#include "MainWindow.h"
#include "SettingsPanel.h"
#include "core/ClusterRanking.h"
#include "core/Lesson.h"
#include "core/LessonExamples.h"
#include "core/SettingsSchema.h"

namespace conescope {

namespace {

using Json = nlohmann::json;
using Action = std::function<void(MainWindow&)>;

// A path from the replay file, relative ones taken from its folder.
QString pathIn(const QDir& folder, const Json& value) {
    if (!value.is_string() || value.get<std::string>().empty()) throw std::invalid_argument("takes a file path (a string)");
    return QDir::cleanPath(folder.absoluteFilePath(QString::fromStdString(value.get<std::string>())));
}

// Steps that are one action without an argument take `true`.
void requireTrue(const Json& value) {
    if (!value.is_boolean() || !value.get<bool>()) throw std::invalid_argument("takes true");
}

long wholeNumber(const Json& value, long minimum, const char* what) {
    if (!value.is_number_integer() || value.get<long>() < minimum)
        throw std::invalid_argument(std::string("takes ") + what + " (a whole number from " + std::to_string(minimum) + ")");
    return value.get<long>();
}

// A setting's value as the command line's text: strings as they are, numbers as JSON writes them
// (shortest form that reads back the same), true/false, and lists joined by commas.
std::string settingValueText(const Json& value) {
    if (value.is_string()) return value.get<std::string>();
    if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
    if (value.is_number()) return value.dump();
    if (value.is_array()) {
        std::string text;
        for (const Json& item : value) text += (text.empty() ? "" : ",") + settingValueText(item);
        return text;
    }
    throw std::invalid_argument("is not a string, a number, true/false or a list");
}

// The keys "set" takes: every schema flag but the eye, which has a step of its own.
std::vector<const SettingField*> settableFields() {
    std::vector<const SettingField*> fields;
    for (const SettingField& field : settingFields())
        if (field.flag != "eye") fields.push_back(&field);
    return fields;
}

const SettingField& settableField(const std::string& key) {
    std::string known;
    for (const SettingField* field : settableFields()) {
        if (field->flag == key) return *field;
        known += (known.empty() ? "" : ", ") + field->flag;
    }
    throw std::invalid_argument("unknown key '" + key + "' (expected one of: " + known + ")");
}

// The settings shown after a step must be the ones the step set: a value the widgets cannot hold
// (more decimals, outside their range) is named instead of quietly differing.
void checkShown(MainWindow& window) {
    const Settings asked = window.session().askedSettings();
    const Settings shown = window.settingsPanel()->settings();
    for (const SettingField& field : settingFields())
        if (settingText(field, shown) != settingText(field, asked))
            throw std::runtime_error("the window's settings show " + field.flag + "=" + settingText(field, shown) + ", not " +
                                     settingText(field, asked));
}

Action parseSet(const Json& value, const QDir& folder) {
    if (!value.is_object() || value.empty()) throw std::invalid_argument("takes an object of settings, {\"test\": \"apex\", ...}");
    std::vector<std::pair<const SettingField*, std::string>> changes;
    Settings check;
    for (const auto& [key, item] : value.items()) {
        const SettingField& field = settableField(key);
        std::string text;
        try {
            text = settingValueText(item);
        } catch (const std::invalid_argument& error) {
            throw std::invalid_argument("'" + key + "' " + error.what());
        }
        if (field.kind == SettingKind::Path && !text.empty()) text = pathIn(folder, item).toStdString();
        parseSetting(field, text, check);  // a bad value fails when the file is read
        changes.emplace_back(&field, text);
    }
    return [changes](MainWindow& window) {
        Settings settings = window.session().askedSettings();
        for (const auto& [field, text] : changes) parseSetting(*field, text, settings);
        window.session().applySettings(settings);
        checkShown(window);
    };
}

Action parseEye(const Json& value, const QDir&) {
    if (!value.is_array() || value.size() != 3 || !value[0].is_number() || !value[1].is_number() || !value[2].is_number())
        throw std::invalid_argument("takes a point [x, y, z]");
    const glm::dvec3 position(value[0].get<double>(), value[1].get<double>(), value[2].get<double>());
    return [position](MainWindow& window) { window.session().moveEye(position, -1); };
}

// Whatever acts on the clusters needs a mesh shown.
const ClusterSet& shownClusters(MainWindow& window) {
    if (!window.session().clusters()) throw std::runtime_error("no mesh is shown (open one first)");
    return *window.session().clusters();
}

// What Export statistics writes, for the orbit or the current eye (while A is pinned: A against B).
std::function<Action(const Json&, const QDir&)> exportStep(bool orbit) {
    return [orbit](const Json& value, const QDir& folder) -> Action {
        const QString path = pathIn(folder, value);
        return [path, orbit](MainWindow& window) {
            shownClusters(window);
            window.session().startStatisticsExport(path, statisticsFormatOf(path.toStdString()), orbit, [](bool) {});
        };
    };
}

// A lesson step, 0 (the end of the lesson) to kLessonStepCount.
Action parseLessonStep(const Json& value, const QDir&) {
    const std::string takes = "a lesson step, 1 to " + std::to_string(kLessonStepCount) + ", or 0 to end the lesson";
    const long step = wholeNumber(value, 0, takes.c_str());
    if (step > kLessonStepCount) throw std::invalid_argument("takes " + takes);
    return [step](MainWindow& window) {
        shownClusters(window);
        window.showLessonStep(int(step));
        if (step > 0 && !window.session().lesson()) throw std::runtime_error("no cluster is picked (pick or choose one first)");
    };
}

// A cluster id, or the key of the orbit's ranking whose first cluster to take (as `conescope-cli
// clusters --sort KEY --top 1`).
Action parseChoose(const Json& value, const QDir&) {
    if (value.is_string()) {
        const ClusterSortKey key = parseClusterSortKey(value.get<std::string>());
        return [key](MainWindow& window) {
            shownClusters(window);
            if (window.chooseWorstCluster(key) < 0) throw std::runtime_error("the orbit has not been measured");
        };
    }
    const long cluster = wholeNumber(value, 0, "a cluster id or a ranking such as \"test-loss\"");
    return [cluster](MainWindow& window) {
        const size_t count = shownClusters(window).partition.clusterCount;
        if (cluster >= long(count))
            throw std::runtime_error("the mesh has " + std::to_string(count) + " clusters (0 to " + std::to_string(count - 1) + ")");
        window.chooseCluster(int(cluster));
    };
}

// An example of an outcome: the cluster and orbit view the lesson dock's buttons choose.
Action parseExample(const Json& value, const QDir&) {
    if (!value.is_string()) throw std::invalid_argument("takes one of: culled, drawn, test-loss, partition-loss");
    const LessonOutcome outcome = conescope::parseExample(value.get<std::string>());
    return [outcome](MainWindow& window) {
        shownClusters(window);
        if (!window.session().orbitStatistics()) throw std::runtime_error("the orbit has not been measured");
        if (window.chooseExample(outcome) < 0)
            throw std::runtime_error("no cluster is " + toString(outcome) + " from any orbit view with these settings");
    };
}

// The eye swept across the picked cluster's cull boundary: N frames, or {"frames": N, "slides": FOLDER}
// with a slide of the lesson step at every frame.
Action parseSweep(const Json& value, const QDir& folder) {
    const char* takes = "takes a number of frames (2 or more) or {\"frames\": N, \"slides\": FOLDER}";
    long frames = 0;
    QString slides;
    if (value.is_object()) {
        for (const auto& [key, item] : value.items())
            if (key != "frames" && key != "slides") throw std::invalid_argument("unknown key '" + key + "' (expected frames, slides)");
        if (!value.contains("frames")) throw std::invalid_argument(takes);
        frames = wholeNumber(value["frames"], 2, "a number of frames");
        if (value.contains("slides")) slides = pathIn(folder, value["slides"]);
    } else {
        frames = wholeNumber(value, 2, "a number of frames");
    }
    return [frames, slides](MainWindow& window) {
        shownClusters(window);
        std::vector<Slide> made;
        const auto frame = [&](size_t) {
            if (!slides.isEmpty()) made.push_back(window.lessonSlide(window.session().lessonStep()));
        };
        if (!window.sweepEye(size_t(frames), frame)) throw std::runtime_error(window.lastError().toStdString());
        if (!slides.isEmpty() && !window.writeSlides(made, slides, QStringLiteral("Cannot write the sweep's slides")))
            throw std::runtime_error(window.lastError().toStdString());
    };
}

// A file the window writes through `write` (false: it said why in its last error).
std::function<Action(const Json&, const QDir&)> writeStep(bool (MainWindow::*write)(const QString&)) {
    return [write](const Json& value, const QDir& folder) -> Action {
        const QString path = pathIn(folder, value);
        return [path, write](MainWindow& window) {
            if (!(window.*write)(path)) throw std::runtime_error(window.lastError().toStdString());
        };
    };
}

Action parseOrbitView(const Json& value, const QDir&) {
    const long view = wholeNumber(value, 0, "an orbit view, counted from 0");
    return [view](MainWindow& window) {
        shownClusters(window);
        if (!window.session().moveEyeToOrbitView(view))
            throw std::runtime_error("the orbit has " + std::to_string(window.session().settings().views) +
                                     " views (0 to " + std::to_string(window.session().settings().views - 1) + ")");
    };
}

Action parsePick(const Json& value, const QDir&) {
    const long cluster = wholeNumber(value, -1, "a cluster id, or -1 for none");
    return [cluster](MainWindow& window) {
        const size_t count = shownClusters(window).partition.clusterCount;
        if (cluster >= long(count))
            throw std::runtime_error("the mesh has " + std::to_string(count) + " clusters (0 to " + std::to_string(count - 1) + ")");
        window.session().pickCluster(int(cluster));
    };
}

struct StepKind {
    const char* name;
    // Checks the step's value (throws std::invalid_argument saying what it takes) and returns the
    // action that plays it.
    std::function<Action(const Json& value, const QDir& folder)> parse;
};

// Every step kind: a new kind is one row here (and a line in docs/user/window.md's table).
const std::vector<StepKind>& stepKinds() {
    static const std::vector<StepKind> kinds = {
        {"open",
         [](const Json& value, const QDir& folder) -> Action {
             const QString path = pathIn(folder, value);
             return [path](MainWindow& window) { window.session().openMesh(path); };
         }},
        {"set", parseSet},
        {"eye", parseEye},
        {"orbit-view", parseOrbitView},
        {"pick", parsePick},
        {"pin",
         [](const Json& value, const QDir&) -> Action {
             if (value != Json("A")) throw std::invalid_argument("takes \"A\"");
             return [](MainWindow& window) {
                 shownClusters(window);
                 window.session().pinAsA();
             };
         }},
        {"swap",
         [](const Json& value, const QDir&) -> Action {
             requireTrue(value);
             return [](MainWindow& window) {
                 if (!window.session().hasPin()) throw std::runtime_error("nothing is pinned as A to swap with");
                 window.session().swapAB();
             };
         }},
        {"drop-pin",
         [](const Json& value, const QDir&) -> Action {
             requireTrue(value);
             return [](MainWindow& window) { window.session().clearPin(); };
         }},
        {"cancel-next-build",
         [](const Json& value, const QDir&) -> Action {
             requireTrue(value);
             return [](MainWindow& window) { window.session().cancelNextBuild(); };
         }},
        {"cancel-at-stage",
         [](const Json& value, const QDir&) -> Action {
             if (!value.is_string() || value.get<std::string>().empty())
                 throw std::invalid_argument("takes the name of a stage the progress shows (\"scene\", \"orbit statistics\", ...)");
             const QString stage = QString::fromStdString(value.get<std::string>());
             return [stage](MainWindow& window) { window.session().cancelAtStage(stage); };
         }},
        {"choose", parseChoose},
        {"lesson-step", parseLessonStep},
        {"example", parseExample},
        {"sweep-eye", parseSweep},
        {"screenshot", writeStep(&MainWindow::saveScreenshot)},
        {"window-screenshot", writeStep(&MainWindow::saveWindowScreenshot)},
        {"cross-section", writeStep(&MainWindow::saveCrossSection)},
        {"export-explanation", writeStep(&MainWindow::exportExplanation)},
        {"slides", writeStep(&MainWindow::exportLessonSlides)},
        {"orbit-slides", writeStep(&MainWindow::exportOrbitSlides)},
        {"export", exportStep(true)},
        {"export-eye", exportStep(false)},
        {"caption",
         [](const Json& value, const QDir&) -> Action {
             if (!value.is_string()) throw std::invalid_argument("takes a text (a string)");
             const QString text = QString::fromStdString(value.get<std::string>());
             return [text](MainWindow& window) { window.showCaption(text); };
         }},
    };
    return kinds;
}

ReplayStep parseStep(const Json& step, size_t number, const QDir& folder) {
    ReplayStep parsed;
    parsed.number = number;
    parsed.text = step.dump();
    auto fail = [&parsed](const std::string& what) { return ReplayError(describeStep(parsed, what)); };
    if (!step.is_object() || step.size() != 1) throw fail("a step is an object with one member, {\"KIND\": VALUE}");
    const std::string& name = step.begin().key();
    for (const StepKind& kind : stepKinds()) {
        if (name != kind.name) continue;
        try {
            parsed.play = kind.parse(step.begin().value(), folder);
        } catch (const std::exception& error) {
            throw fail("'" + name + "' " + error.what());
        }
        return parsed;
    }
    std::string known;
    for (const std::string& kind : replayStepNames()) known += (known.empty() ? "" : ", ") + kind;
    throw fail("unknown step '" + name + "' (expected one of: " + known + ")");
}

}  // namespace

std::string describeStep(const ReplayStep& step, const std::string& what) {
    return "step " + std::to_string(step.number) + " " + step.text + ": " + what;
}

std::vector<std::string> replayStepNames() {
    std::vector<std::string> names;
    for (const StepKind& kind : stepKinds()) names.emplace_back(kind.name);
    return names;
}

std::vector<ReplayStep> parseReplay(const std::string& json, const QString& folder) {
    Json document;
    try {
        document = Json::parse(json);
    } catch (const Json::parse_error& error) {
        throw ReplayError(std::string("not JSON: ") + error.what());
    }
    if (document.is_object() && document.size() == 1 && document.contains("steps")) document = document["steps"];
    if (!document.is_array()) throw ReplayError("a replay is a list of steps, [{\"open\": \"mesh.off\"}, ...], or {\"steps\": [...]}");
    const QDir directory(folder);
    std::vector<ReplayStep> steps;
    for (size_t i = 0; i < document.size(); ++i) steps.push_back(parseStep(document[i], i + 1, directory));
    return steps;
}

std::vector<ReplayStep> readReplayFile(const QString& path) {
    std::ifstream in(path.toStdString(), std::ios::binary);
    if (!in) throw ReplayError(path.toStdString() + ": cannot read the replay file");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ReplayError(path.toStdString() + ": cannot read the replay file");
    try {
        return parseReplay(text, QFileInfo(path).absolutePath());
    } catch (const ReplayError& error) {
        throw ReplayError(path.toStdString() + ": " + error.what());
    }
}

}  // namespace conescope
