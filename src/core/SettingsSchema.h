// The one description of every run setting: its name in the statistics JSON, its command-line flag
// and help, the text it accepts, its default (Settings{}), the builders that use it and the stage a
// change of it makes stale. The CLI's options, the application's command line, the settings panel's
// enabled states, the window's recompute rules and the JSON `settings` object all come from this
// table, so a new setting is one row (docs/dev/architecture.md).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "Settings.h"

namespace conescope {

// What a change makes stale, in pipeline order (core/Pipeline.h): everything from that stage on.
enum class Stage {
    PreparedMesh,  // face geometry and winding repair
    Clusters,      // the partition (and so its bounds)
    Bounds,        // the cones and bounds of the partition
    Measurement,   // the decisions and statistics for the views
};

enum class SettingKind {
    Count,     // a whole number in [minimum, maximum]
    Number,    // a finite number in [minimum, maximum] (strictly above minimum when minimumExcluded)
    Name,      // one of names()
    NameList,  // names separated by commas, or "all"; repeats dropped, first mention kept
    Point,     // "x,y,z", or nothing
    Path,      // any text
    Flag,      // on when given
};

// A setting's value as the statistics record it: the JSON type follows the alternative.
using SettingValue = std::variant<bool, size_t, double, std::string, std::vector<std::string>, std::optional<glm::dvec3>>;

struct SettingField {
    std::string key;                  // statistics JSON key: "max_vertices"
    std::string flag;                 // command-line flag without dashes: "max-verts"
    std::string valueName;            // placeholder in help: "N"
    std::string help;                 // one line, without the default
    SettingKind kind = SettingKind::Flag;
    bool builderOption = false;       // true: given to every command that builds clusters (stats, partition)
    Stage invalidates = Stage::Measurement;
    std::vector<Builder> usedBy;      // empty: every builder
    std::function<bool(const Settings&)> onlyWhen;  // when set, the field matters only if this holds
    std::vector<std::string> excludes;  // flags that cannot be given together with this one
    bool omittedAtDefault = false;    // the statistics' settings object leaves it out at its default (added later)
    double minimum = 0.0, maximum = 0.0;
    bool minimumExcluded = false;
    std::function<std::vector<std::string>()> names;  // Name / NameList: the accepted names
    std::function<SettingValue(const Settings&)> value;
    std::function<void(Settings&, const SettingValue&)> assign;
};

// Every field, in the order help lists them.
const std::vector<SettingField>& settingFields();
// The field with this JSON key or flag. Throws std::out_of_range.
const SettingField& settingField(const std::string& keyOrFlag);

// Whether the field changes anything for these settings: their builder uses it (and onlyWhen holds).
bool fieldMatters(const SettingField& field, const Settings& settings);

// The field's value in the text form parseSetting reads ("" for an unset point).
std::string settingText(const SettingField& field, const Settings& settings);
// Parses `text` as the field's kind and domain and stores it in `settings`. Throws
// std::invalid_argument with a message naming the flag and what is accepted.
void parseSetting(const SettingField& field, const std::string& text, Settings& settings);
// The command-line arguments that give these settings: "--flag" "text" for every field whose text
// differs from the default's (a flag alone when on), in the schema's order. parseSetting reads each
// text back to the same value, so a program started with them (a batch's workers) runs the same.
std::vector<std::string> settingArguments(const Settings& settings);
// The help line with the accepted names (for name fields); the default is settingText(field, Settings{}).
std::string settingHelp(const SettingField& field);

// Whether every field of the schema has the same value in both.
bool sameSettings(const Settings& a, const Settings& b);

// The earliest stage that differs between `before` and `after`: a change of builder, or of a field
// that matters to `after` (at the optimized builder's best effort every field but the eye is the
// partition's: it chooses by the run's own orbit). Empty when nothing that matters changed.
std::optional<Stage> firstStaleStage(const Settings& before, const Settings& after);

// "x,y,z" as three finite numbers, whatever the C locale. Throws std::invalid_argument.
glm::dvec3 parseEye(const std::string& text);

}  // namespace conescope
