// The application's command line (QCommandLineParser): a mesh to open, the run settings, the
// headless `--screenshot OUT.png` mode that renders one frame and exits without a window, and
// `--replay FILE.json`, which plays a replay's steps in the window (ReplaySteps.h).
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include <QSize>
#include <QString>
#include <QStringList>

#include <glm/glm.hpp>

#include "core/Settings.h"
#include "scene/ClusterScene.h"

namespace conescope {

struct AppOptions {
    QString mesh;                     // empty = the bundled mesh
    Settings settings;                // Settings{} changed by the options given
    std::optional<glm::dvec3> eye;    // --eye: the cull eye's position
    QString screenshot;               // --screenshot: render headlessly to this PNG and exit
    QSize size{1280, 800};            // --size WxH of the screenshot
    bool fromEye = false;             // --from-eye: the screenshot shows what the cull eye sees
    FaceColoring coloring = FaceColoring::CullDecision;  // --coloring, as the window starts
    std::optional<std::vector<Layer>> layers;  // --layers: the layers shown, all others hidden
    std::optional<size_t> pick;       // --pick: the cluster highlighted in the screenshot, its test drawn
    QString gaussMap;                 // --gauss-map: also write the picked cluster's Gauss map to this PNG
    std::optional<std::string> compare;  // --compare K=V,...: A for an A/B screenshot (B: the options given)
    QString replay;                   // --replay FILE.json: play its steps in the window, then exit
    bool stay = false;                // --stay: keep the window open after the replay
};

// The scene's names (toString(Layer)). Throws std::invalid_argument.
Layer parseLayer(const QString& text);

// --layers applied to a scene or a window: the layers listed shown, every other one hidden.
template <typename Target>
void showOnly(const std::vector<Layer>& shown, Target& target) {
    for (Layer layer : allLayers()) target.setLayerVisible(layer, std::find(shown.begin(), shown.end(), layer) != shown.end());
}

// The scene's names (toString(FaceColoring)). Throws std::invalid_argument.
FaceColoring parseFaceColoring(const QString& text);

struct CommandLineResult {
    enum class Action { Run, ExitSuccess, ExitFailure } action = Action::Run;
    QString message;                  // help/version text on success, the error on failure
    AppOptions options;
};

// Parses the arguments (args[0] is the program). Never exits the process itself.
CommandLineResult parseCommandLine(const QStringList& arguments);

// "WxH" with both in [16, 16384]. Throws std::invalid_argument.
QSize parseSizeText(const QString& text);

// --screenshot: load, cluster, measure the eye, render through the scene's renderToPng. Returns the
// exit code (0, or 1 with the error on stderr).
int runHeadlessScreenshot(const AppOptions& options);

}  // namespace conescope
