// conescope-cli granularity: what one cone per cluster (each cone and test), 2, 4 and 8 cones per
// cluster and per-triangle culling cull on the same partition and views, and what each record costs.
#include <sstream>

#include "cli/CommandSupport.h"
#include "cli/Commands.h"
#include "core/Granularity.h"
#include "core/GranularityLesson.h"
#include "io/ClusterIdFile.h"
#include "io/GranularityIO.h"

namespace conescope::cli {

namespace {

Settings settingsOf(const GranularityOptions& options) {
    return granularitySettings(withClusterIds(options.run.toSettings()), options.run.options.at("test")->count() > 0);
}

}  // namespace

CLI::App* addGranularityCommand(CLI::App& app, GranularityOptions& options, const std::string& meshFileHelp) {
    CLI::App* command = app.add_subcommand(
        "granularity",
        "What each record culls and costs on one partition: one cone per cluster with every test, 2, 4 and 8 cones per cluster (float and compact), per-triangle culling");
    command->add_option("mesh", options.mesh, meshFileHelp)->required();
    addBuilderOptions(*command, options.run);
    addCullingOptions(*command, options.run);
    command->add_option("--format", options.format, "Output format (default: from the output's extension; on a terminal text, else json)")
        ->check(CLI::IsMember({"json", "csv", "text"}));
    command->add_option("-o,--output", options.output, "Output file, replaced only when the run succeeds (default: stdout)");
    command->add_option("--write-lesson", options.writeLesson,
                        "Write the lesson on why more cones cull more and what they cost, with this mesh's numbers, to this Markdown file");
    command->add_flag("-q,--quiet", options.quiet, "No progress messages on stderr");
    return command;
}

void runGranularity(const GranularityOptions& options) {
    const Settings settings = settingsOf(options);
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settings});
    const GranularityReport report = conescope::runGranularity(mesh, settings, fileName(options.mesh), stderrProgress(options.quiet));
    warnAboutMesh(report.run, options.quiet);
    warnAboutBudget(report.run);
    const std::string format = outputFormat(options.format, options.output, "json");
    std::ostringstream text;
    if (format == "csv")
        writeGranularityCsv(report, text);
    else if (format == "text")
        writeGranularityText(report, text);
    else
        text << granularityToJson(report).dump(2) << "\n";
    if (!options.writeLesson.empty()) {
        writeText(options.writeLesson, granularityLessonMarkdown(makeGranularityLesson(report)));
        note(options.quiet, "wrote " + options.writeLesson);
    }
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

}  // namespace conescope::cli
