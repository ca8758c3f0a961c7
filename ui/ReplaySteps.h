// The steps of a replay file (`conescope --replay FILE.json`, docs/user/window.md, "Replay files"): a JSON
// list of objects of one member each, {"open": "mesh.off"}, {"set": {"test": "apex"}}, ... Each step
// kind is one row of the table in ReplaySteps.cpp: its name, how its value is checked when the file is
// read, and the Session or window action that plays it (the same one a click makes).
#pragma once

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <QString>

namespace conescope {

class MainWindow;

// A replay that cannot be read or a step that cannot be done; the message names the step (its
// number, counted from 1, and its text) where there is one.
class ReplayError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct ReplayStep {
    size_t number = 0;  // from 1, in file order
    std::string text;   // the step as written (compact JSON), for messages
    // Does the step's action; throws std::exception when it cannot be done now (no such cluster, no
    // mesh to pin, ...). What it starts in the background is waited for by the player.
    std::function<void(MainWindow&)> play;
};

// "step N {TEXT}: what": how every message about a step starts.
std::string describeStep(const ReplayStep& step, const std::string& what);

// The steps of a replay document: a JSON list of steps, or an object {"steps": [...]}. Relative paths
// in it (open, screenshot, window-screenshot, export, cluster-file) are taken from `folder`. Throws
// ReplayError for JSON that does not parse (with its line) and for a step of unknown kind, with an
// unknown key or a value its kind does not take (naming the step).
std::vector<ReplayStep> parseReplay(const std::string& json, const QString& folder);

// parseReplay of a file, relative paths from the file's folder. Throws ReplayError also when the
// file cannot be read.
std::vector<ReplayStep> readReplayFile(const QString& path);

// The step kinds, in the table's order ("open", "set", ...).
std::vector<std::string> replayStepNames();

}  // namespace conescope
