// conescope-cli compare: two configurations of one mesh over the same views.
#include <sstream>

#include "cli/CommandSupport.h"
#include "cli/Commands.h"
#include "batch/MeshRuns.h"
#include "core/Comparison.h"
#include "io/ClusterIdFile.h"
#include "io/ComparisonIO.h"

namespace conescope::cli {

void runCompare(const CompareOptions& options) {
    const Settings base = options.run.toSettings();
    // Both texts are checked before the mesh is read: a typo fails at once.
    const Settings settingsA = withClusterIds(parseConfiguration(options.a, base));
    const Settings settingsB = withClusterIds(parseConfiguration(options.b, base));
    const std::string format = outputFormat(options.format, options.output, "json");
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settingsA, settingsB});
    const ProgressCallback progress = stderrProgress(options.quiet);
    const ComparedRuns runs = compareMesh(mesh, options.mesh, settingsA, settingsB, base, progress, [&](char side) {
        const Settings& settings = side == 'A' ? settingsA : settingsB;
        note(options.quiet, std::string("building ") + side + "'s clusters (" + toString(settings.builder) + ")");
    });
    warnAboutMesh(runs.a, options.quiet);
    warnAboutBudget(runs.a, "A: ");
    warnAboutBudget(runs.b, "B: ");
    // Unequal counts make the comparison unfair: said even with --quiet.
    const std::string warning = clusterCountWarning(runs.comparison);
    if (!warning.empty()) warn(warning);

    std::ostringstream text;
    if (format == "csv")
        writeComparisonCsv(runs.comparison, text);
    else if (format == "text")
        writeComparisonText(runs.a, runs.b, runs.comparison, base, text);
    else
        writeComparisonJson(runs.a, runs.b, runs.comparison, options.detail, text);
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

}  // namespace conescope::cli
