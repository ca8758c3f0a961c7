#include "CommandLine.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <iostream>
#include <stdexcept>

#include <QCommandLineParser>
#include <QCoreApplication>

#include <vtkImageData.h>

#include "Datasets.h"
#include "core/Comparison.h"
#include "core/Pipeline.h"
#include "MeshLoading.h"
#include "SceneBinding.h"
#include "core/SettingsSchema.h"
#include "io/MeshReader.h"
#include "scene/GaussMapScene.h"
#include "scene/SceneRendering.h"

namespace conescope {

QSize parseSizeText(const QString& text) {
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool widthValid = false, heightValid = false;
    const int width = parts.size() == 2 ? parts[0].toInt(&widthValid) : 0;
    const int height = parts.size() == 2 ? parts[1].toInt(&heightValid) : 0;
    if (!widthValid || !heightValid || width < 16 || height < 16 || width > 16384 || height > 16384)
        throw std::invalid_argument("size '" + text.toStdString() + "' is not WxH with both in 16..16384");
    return {width, height};
}

namespace {

// One of `values` by its scene name (toString), or an error that lists them all.
template <typename Enum, typename Values>
Enum parseSceneName(const QString& text, const Values& values, const char* what) {
    QStringList names;
    for (Enum value : values) {
        const QString name = QString::fromStdString(toString(value));
        if (text == name) return value;
        names << name;
    }
    throw std::invalid_argument(std::string("unknown ") + what + " '" + text.toStdString() + "' (expected one of: " +
                                names.join(QStringLiteral(", ")).toStdString() + ")");
}

}  // namespace

// The colourings' names for the help, separated by commas.
QString colouringNames() {
    QStringList names;
    for (FaceColoring coloring : allFaceColorings()) names << QString::fromStdString(toString(coloring));
    return names.join(QStringLiteral(", "));
}

FaceColoring parseFaceColoring(const QString& text) {
    return parseSceneName<FaceColoring>(text, allFaceColorings(), "colouring");
}

Layer parseLayer(const QString& text) { return parseSceneName<Layer>(text, allLayers(), "layer"); }

namespace {

// Names separated by commas, through the core's parse function; the first is the one displayed.
template <typename Enum, typename Parse>
std::vector<Enum> parseNameList(const QString& text, Parse parse) {
    std::vector<Enum> values;
    for (const QString& name : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const Enum value = parse(name.trimmed().toStdString());
        if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
    }
    if (values.empty()) throw std::invalid_argument("empty list '" + text.toStdString() + "'");
    return values;
}

}  // namespace

namespace {

// The window's options besides the run settings, and one option per field of the settings schema.
struct AppOptionSet {
    QCommandLineOption help, version, screenshot, size, fromEye, coloring, layers, pick, gaussMap, compare, replay, stay;
    std::vector<std::pair<const SettingField*, QCommandLineOption>> settings;
};

// The run settings, one option per field of the schema (core/SettingsSchema.h), as the CLI has them.
std::vector<std::pair<const SettingField*, QCommandLineOption>> settingOptions() {
    const Settings defaults;
    std::vector<std::pair<const SettingField*, QCommandLineOption>> settingOptions;
    for (const SettingField& field : settingFields()) {
        // Here --eye places the window's cull eye; the orbit is measured as well.
        QString help = field.key == "eye" ? QStringLiteral("Cull eye position x,y,z") : QString::fromStdString(settingHelp(field));
        const std::string defaultText = settingText(field, defaults);
        if (field.kind != SettingKind::Flag && !defaultText.empty()) help += QStringLiteral(" (default %1)").arg(QString::fromStdString(defaultText));
        QCommandLineOption option(QString::fromStdString(field.flag), help + QLatin1Char('.'));
        if (field.kind != SettingKind::Flag) option.setValueName(QString::fromStdString(field.valueName));
        settingOptions.emplace_back(&field, option);
    }
    return settingOptions;
}

// Declares every option and the MESH argument on the parser, in the order the help lists them.
AppOptionSet addAppOptions(QCommandLineParser& parser) {
    parser.setApplicationDescription(QStringLiteral(
        "ConeScope: cluster back-face culling with normal cones. Opens MESH (or a bundled mesh) in the "
        "viewer, or with --screenshot renders one frame to a PNG and exits."));
    const QCommandLineOption help = parser.addHelpOption();
    const QCommandLineOption version = parser.addVersionOption();
    const QCommandLineOption screenshot(QStringLiteral("screenshot"), QStringLiteral("Render one frame to this PNG and exit."),
                                        QStringLiteral("OUT.png"));
    const QCommandLineOption size(QStringLiteral("size"), QStringLiteral("Screenshot size (default 1280x800)."),
                                  QStringLiteral("WxH"));
    const QCommandLineOption fromEye(QStringLiteral("from-eye"),
                                     QStringLiteral("Screenshot what the cull eye sees (culled clusters removed)."));
    const QCommandLineOption coloring(
        QStringLiteral("coloring"),
        QStringLiteral("Face colours: %1 (default: %2).").arg(colouringNames(), QString::fromStdString(toString(FaceColoring::CullDecision))),
        QStringLiteral("name"));
    std::vector<std::pair<const SettingField*, QCommandLineOption>> settings = settingOptions();
    QStringList layerNames;
    for (Layer layer : allLayers()) layerNames << QString::fromStdString(toString(layer));
    const QCommandLineOption layers(
        QStringLiteral("layers"),
        QStringLiteral("Layers shown, comma separated; all others are hidden (%1). In the window, keys 1-9 and 0 "
                       "still switch them.").arg(layerNames.join(QStringLiteral(", "))),
        QStringLiteral("names"));
    const QCommandLineOption pick(QStringLiteral("pick"),
                                  QStringLiteral("Screenshot with this cluster picked: highlighted, its test drawn and "
                                                 "framed; without --eye the cull eye is at the first orbit view that "
                                                 "loses the cluster's back faces."),
                                  QStringLiteral("ID"));
    const QCommandLineOption gaussMap(QStringLiteral("gauss-map"),
                                      QStringLiteral("With --pick: also write the picked cluster's Gauss map (normals, "
                                                     "every cone method's cap, the view vector) to this PNG."),
                                      QStringLiteral("file"));
    const QCommandLineOption compare(QStringLiteral("compare"),
                                     QStringLiteral("Screenshot of an A/B comparison: A is the options given changed by "
                                                    "K=V[,K=V...] (as conescope-cli compare --a), B the options given; faces "
                                                    "coloured by what only A, only B or both cull."),
                                     QStringLiteral("K=V"));
    const QCommandLineOption replay(QStringLiteral("replay"),
                                    QStringLiteral("Play the steps of a replay file in the window (open, set, eye, pin, "
                                                   "export, screenshot, ...; see the README), each once the window is "
                                                   "idle, and exit: 0 after the last, 1 with the step at fault. Without "
                                                   "MESH the window starts empty."),
                                    QStringLiteral("FILE.json"));
    const QCommandLineOption stay(QStringLiteral("stay"), QStringLiteral("With --replay: keep the window open afterwards."));
    parser.addOptions({screenshot, size, fromEye, coloring, layers, pick, gaussMap, compare, replay, stay});
    for (const auto& [field, option] : settings) parser.addOption(option);
    QStringList extensions;
    for (const std::string& extension : supportedMeshExtensions()) extensions << QString::fromStdString(extension);
    parser.addPositionalArgument(QStringLiteral("MESH"), QStringLiteral("Mesh file (%1).").arg(extensions.join(QLatin1Char(' '))),
                                 QStringLiteral("[MESH]"));
    return {help, version, screenshot, size, fromEye, coloring, layers, pick, gaussMap, compare, replay, stay, std::move(settings)};
}

// The help text, or nothing when neither --help nor --help-all was given.
std::optional<QString> helpText(const QCommandLineParser& parser, const AppOptionSet& o) {
    if (!parser.isSet(o.help) && !parser.isSet(QStringLiteral("help-all"))) return std::nullopt;
    if (QCoreApplication::instance()) return parser.helpText();
    // QCommandLineParser writes its usage line from the application object: make a
    // short-lived one, so asking for help needs neither a display nor a window.
    static int argumentCount = 1;
    static char programName[] = "conescope";
    static char* argumentValues[] = {programName, nullptr};
    QCoreApplication application(argumentCount, argumentValues);
    return parser.helpText();
}

// The options given, checked against each other; throws std::invalid_argument saying what is wrong.
void readAppOptions(const QCommandLineParser& parser, const AppOptionSet& o, AppOptions& options) {
    const QStringList positional = parser.positionalArguments();
    if (positional.size() > 1) throw std::invalid_argument("more than one mesh given");
    if (!positional.isEmpty()) options.mesh = positional.front();
    Settings& settings = options.settings;
    for (const auto& [field, option] : o.settings) {
        if (!parser.isSet(option)) continue;
        // A list option given twice adds to the list, as in the CLI.
        const QStringList values = field->kind == SettingKind::Flag ? QStringList{QStringLiteral("true")} : parser.values(option);
        parseSetting(*field, values.join(QLatin1Char(',')).toStdString(), settings);
    }
    options.eye = settings.eye;
    settings.eye.reset();
    if (parser.isSet(o.size)) options.size = parseSizeText(parser.value(o.size));
    if (parser.isSet(o.screenshot)) {
        options.screenshot = parser.value(o.screenshot);
        if (options.screenshot.isEmpty()) throw std::invalid_argument("--screenshot needs a file name");
    }
    options.fromEye = parser.isSet(o.fromEye);
    if (parser.isSet(o.coloring)) options.coloring = parseFaceColoring(parser.value(o.coloring));
    if (parser.isSet(o.layers))
        options.layers = parseNameList<Layer>(parser.value(o.layers), [](const std::string& name) { return parseLayer(QString::fromStdString(name)); });
    if (parser.isSet(o.pick)) {
        bool valid = false;
        options.pick = parser.value(o.pick).toULongLong(&valid);
        if (!valid) throw std::invalid_argument("--pick '" + parser.value(o.pick).toStdString() + "' is not a cluster id");
    }
    if (options.screenshot.isEmpty() && (parser.isSet(o.size) || options.fromEye || options.pick))
        throw std::invalid_argument("--size, --from-eye and --pick only apply to --screenshot");
    options.gaussMap = parser.value(o.gaussMap);
    if (parser.isSet(o.compare)) {
        if (options.screenshot.isEmpty()) throw std::invalid_argument("--compare only applies to --screenshot");
        options.compare = parser.value(o.compare).toStdString();
        parseConfiguration(*options.compare, settings);  // a typo fails before anything is read
        if (!parser.isSet(o.coloring)) options.coloring = FaceColoring::Comparison;
    }
    if (parser.isSet(o.gaussMap) && (!options.pick || options.gaussMap.isEmpty()))
        throw std::invalid_argument("--gauss-map needs a file name and --pick");
    options.replay = parser.value(o.replay);
    options.stay = parser.isSet(o.stay);
    if (parser.isSet(o.replay) && options.replay.isEmpty()) throw std::invalid_argument("--replay needs a file name");
    if (!options.replay.isEmpty() && !options.screenshot.isEmpty())
        throw std::invalid_argument("--replay plays in the window: use its screenshot steps instead of --screenshot");
    if (options.stay && options.replay.isEmpty()) throw std::invalid_argument("--stay only applies to --replay");
}

}  // namespace

CommandLineResult parseCommandLine(const QStringList& arguments) {
    QCommandLineParser parser;
    const AppOptionSet o = addAppOptions(parser);
    CommandLineResult result;
    if (!parser.parse(arguments)) {
        result.action = CommandLineResult::Action::ExitFailure;
        result.message = parser.errorText();
        return result;
    }
    if (const std::optional<QString> help = helpText(parser, o)) {
        result.action = CommandLineResult::Action::ExitSuccess;
        result.message = *help;
        return result;
    }
    if (parser.isSet(o.version)) {
        result.action = CommandLineResult::Action::ExitSuccess;
        result.message = QStringLiteral("conescope %1").arg(QStringLiteral(CONESCOPE_VERSION));
        return result;
    }
    try {
        readAppOptions(parser, o, result.options);
    } catch (const std::exception& error) {
        result.action = CommandLineResult::Action::ExitFailure;
        result.message = QString::fromStdString(error.what());
    }
    return result;
}

int runHeadlessScreenshot(const AppOptions& options) {
    try {
        const QString meshPath = options.mesh.isEmpty() ? defaultMeshPath() : options.mesh;
        if (meshPath.isEmpty()) throw std::runtime_error("no mesh given and no bundled mesh found");
        const Settings settings = withClusterIds(options.settings);
        PreparedMesh prepared = loadMesh(meshPath.toStdString(), settings);
        // A cluster file that could not be used is an error here, not a reason to show other clusters.
        if (needsClusterFile(prepared, settings)) prepared = reprepareMesh(prepared, settings);
        const ClusterSet clusters = buildClusters(prepared, settings);
        ClusterScene scene(prepared.mesh(), prepared.world, prepared.faces, clusters.partition, clusters.bounds);
        if (options.pick && *options.pick >= clusters.partition.clusterCount)
            throw std::invalid_argument("--pick " + std::to_string(*options.pick) + ": the mesh has " +
                                        std::to_string(clusters.partition.clusterCount) + " clusters (0 to " +
                                        std::to_string(clusters.partition.clusterCount - 1) + ")");
        glm::dvec3 eyePosition = options.eye ? *options.eye : startingEyePosition(prepared.box, settings);
        // A picked cluster is shown where it costs, as the worst-cluster table shows it: from the first
        // orbit view that loses its back faces (unless --eye says where to look from).
        if (options.pick && !options.eye) {
            const long lost = viewMissingCluster(prepared, clusters, settings, uint32_t(*options.pick));
            if (lost >= 0) eyePosition = orbitOf(settings, prepared.box)[size_t(lost)].position;
        }
        const EyeMeasurement measurement =
            measureEye(prepared, clusters, eyeAt(settings, eyePosition, prepared.box), displayedTest(settings));
        showMeasurement(scene, prepared, clusters, measurement);
        scene.setFaceColoring(options.coloring);
        showEyeColouring(scene, prepared, clusters, measurement, options.coloring);
        showSubGroupsFromEye(scene, prepared, clusters, settings.conesPerCluster, measurement.eye);
        if (options.compare) {
            // A: the options changed by --compare; B: the clusters shown. The diff of this eye per face.
            const Settings settingsA = withClusterIds(parseConfiguration(*options.compare, settings));
            const ClusterSet a = buildClusters(prepared, settingsA);
            const std::string warning =
                clusterCountWarning(showComparison(scene, prepared, {a, settingsA}, {clusters, settings}, measurement));
            if (!warning.empty()) std::cerr << "conescope: warning: " << warning << '\n';
        }
        for (const auto& [layer, visible] : firstLookLayers()) scene.setLayerVisible(layer, visible);
        if (options.layers) showOnly(*options.layers, scene);
        if (options.pick) {
            scene.setHighlightedCluster(int(*options.pick));
            showTestDrawing(scene, prepared, clusters, int(*options.pick), measurement);
        }
        RenderOptions render;
        render.frameEye = true;
        render.width = options.size.width();
        render.height = options.size.height();
        render.fromEye = options.fromEye;
        if (options.pick) frameTestDrawing(scene, render);
        // A comparison is about back faces: seen from behind, the mesh filling the picture.
        if (options.compare) render.frameEye = false, render.fromBehind = true;
        renderToPng(scene, render, options.screenshot.toStdString());
        if (!options.gaussMap.isEmpty()) {
            GaussMapScene gauss;
            gauss.show(gaussMapOf(prepared, clusters, uint32_t(*options.pick), scene.testDrawing().why), clusters.bounds.coneMethod,
                       int(*options.pick));
            writePng(renderGaussMapToImage(gauss, options.size.height() * 4 / 3, options.size.height()), options.gaussMap.toStdString());
        }
        return 0;
    } catch (const std::exception& error) {
        std::cerr << "conescope: " << error.what() << '\n';
        return 1;
    }
}

}  // namespace conescope
