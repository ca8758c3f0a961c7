// Helpers shared by the ui tests: where the datasets are, the statistics the core computes
// in-process for comparison, and small JSON/CSV readers for the exported files.
#pragma once

#include <string>

#include <QString>
#include <QStringList>

#include <nlohmann/json.hpp>

#include "core/Pipeline.h"

namespace conescope::testing {

QString datasetPath(const char* name);

// runStatistics on the file as read, with these settings (what an export must match).
RunStatistics statisticsInProcess(const QString& meshPath, const Settings& settings);

nlohmann::json readJsonFile(const QString& path);

// The rows of one "# section: NAME" of a statistics CSV, as header -> value maps.
std::vector<std::map<std::string, std::string>> readCsvTable(const QString& path);

// The document without its measured times (ns_per_cluster, at any depth): what two runs of the same
// settings must write alike.
nlohmann::json withoutTimings(nlohmann::json document);

// Runs a program to its end (two minutes at most): its exit code (-1 when it did not end normally),
// its stderr in `errors`.
int runProgram(const QString& program, const QStringList& arguments, QString* errors = nullptr);

// "x,y,z" with enough digits to read back the same doubles.
QString eyeArgument(const glm::dvec3& eye);

// The CLI flags that give `settings` (builder, limits, cones, tests, sphere, views, distance, eye, ortho).
QStringList cliSettingsArguments(const Settings& settings);

}  // namespace conescope::testing
