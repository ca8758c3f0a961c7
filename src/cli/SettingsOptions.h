// The run settings as command-line options, made from the settings schema (core/SettingsSchema.h):
// one option per field with its flag, help, default and domain, so `stats` and `partition` accept
// the same builder flags and the application's command line accepts the same text.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "core/Settings.h"

namespace conescope::cli {

// CLI11 keeps references into this object: create it before the options and do not move it.
struct SettingsOptions {
    std::map<std::string, std::vector<std::string>> values;  // per flag, the texts given
    std::map<std::string, bool> flags;                       // per on/off flag, whether given
    std::map<std::string, CLI::Option*> options;             // per flag, its option

    // Settings{} with every option given parsed into it. Throws std::invalid_argument for a bad
    // value (the validators reject those while parsing already).
    Settings toSettings() const;
};

// The schema's builder fields: --builder --max-verts --max-tris --clusters --cluster-file ...
void addBuilderOptions(CLI::App& command, SettingsOptions& options);

// The others: --cone --test --sphere --views --distance --eye --ortho --fix-winding
void addCullingOptions(CLI::App& command, SettingsOptions& options);

}  // namespace conescope::cli
