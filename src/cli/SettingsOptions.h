// The run settings as command-line options. One place names the flags, shows the defaults of
// conescope::Settings{} in --help (no number is restated here) and turns what was parsed into a
// Settings, so `stats` and `partition` accept the same builder flags.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/Settings.h"

namespace conescope::cli {

// CLI11 keeps references into this object: create it before the options and do not move it.
struct SettingsOptions {
    Settings settings;                 // numbers and flags are parsed straight into it
    std::string builder;               // names are parsed as text, then by the core's parse functions
    std::vector<std::string> cones;
    std::vector<std::string> tests;
    std::string sphere;
    std::string eye;                   // "x,y,z", empty = the orbit

    SettingsOptions();

    // The parsed Settings. Throws std::invalid_argument for a bad name or eye (the validators
    // reject those while parsing already).
    Settings toSettings() const;
};

// --builder --max-verts --max-tris --clusters --cluster-file --normal-weight --cone-weight
void addBuilderOptions(CLI::App& command, SettingsOptions& options);

// --cone --test --sphere --views --distance --eye --ortho --fix-winding
void addCullingOptions(CLI::App& command, SettingsOptions& options);

// "x,y,z" as three finite numbers, whatever the C locale. Throws std::invalid_argument.
glm::dvec3 parseEye(const std::string& text);

// Names separated by commas, "all" standing for every entry of `all`; repeats are dropped, the
// order of first mention kept. Throws std::invalid_argument for an unknown name.
std::vector<ConeMethod> parseConeList(const std::vector<std::string>& names);
std::vector<CullTest> parseTestList(const std::vector<std::string>& names);

}  // namespace conescope::cli
