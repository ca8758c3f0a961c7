// conescope-cli compare: two configurations of one mesh over the same views.
#include <sstream>

#include "cli/CommandSupport.h"
#include "cli/Commands.h"
#include "core/Comparison.h"
#include "io/ComparisonIO.h"

namespace conescope::cli {

void runCompare(const CompareOptions& options) {
    const Settings base = options.run.toSettings();
    // Both texts are checked before the mesh is read: a typo fails at once.
    const Settings settingsA = parseConfiguration(options.a, base);
    const Settings settingsB = parseConfiguration(options.b, base);
    const std::string format = outputFormat(options.format, options.output, "json");
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settingsA, settingsB});
    const ProgressCallback progress = stderrProgress(options.quiet);
    const PreparedMesh prepared = prepareMesh(std::make_shared<Mesh>(mesh), options.mesh, base.fixWinding, progress);
    note(options.quiet, "building A's clusters (" + toString(settingsA.builder) + ")");
    const ClusterSet a = buildClusters(prepared, settingsA, nullptr, progress);
    note(options.quiet, "building B's clusters (" + toString(settingsB.builder) + ")");
    const ClusterSet b = buildClusters(prepared, settingsB, nullptr, progress);
    // Each side exactly as `stats` with its options would write it.
    RunStatistics runA = measureRun(prepared, a, settingsA, progress);
    RunStatistics runB = measureRun(prepared, b, settingsB, progress);
    runA.meshName = runB.meshName = fileName(options.mesh);
    warnAboutWinding(runA, options.quiet);
    warnAboutBudget(runA, "A: ");
    warnAboutBudget(runB, "B: ");
    note(options.quiet, "comparing A and B");
    const Comparison comparison = compareClusterSets(prepared, a, b, viewsFor(base, prepared.box), progress);
    // Unequal counts make the comparison unfair: said even with --quiet.
    const std::string warning = clusterCountWarning(comparison);
    if (!warning.empty()) warn(warning);

    std::ostringstream text;
    if (format == "csv")
        writeComparisonCsv(comparison, text);
    else if (format == "text")
        writeComparisonText(runA, runB, comparison, base, text);
    else
        writeComparisonJson(runA, runB, comparison, options.detail, text);
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

}  // namespace conescope::cli
