// conescope-cli lod: a cluster LOD hierarchy built from the mesh, cone culling at each level and of
// the cut an eye draws.
#include <filesystem>
#include <sstream>

#include "cli/CommandSupport.h"
#include "cli/Commands.h"
#include "core/lod/LodCut.h"
#include "core/lod/LodLesson.h"
#include "io/ClusterFiles.h"
#include "io/ClusterIdFile.h"
#include "io/MeshWriter.h"
#include "io/MeshletFiles.h"
#include "io/LodIO.h"

namespace conescope::cli {

namespace {

// Each level, and the cut from the first view (the orbit's or --eye), as VTP meshes with their
// clusters: for ParaView, or the window with --builder file.
void writeLevelMeshes(const ClusterHierarchy& hierarchy, const Settings& settings, const LodCommandOptions& options) {
    std::error_code error;
    std::filesystem::create_directories(options.writeLevels, error);
    if (error) throw std::runtime_error(options.writeLevels + ": cannot make the folder (" + error.message() + ")");
    for (size_t l = 0; l < hierarchy.levels.size(); ++l) {
        const LodLevel& level = hierarchy.levels[l];
        std::vector<double> groups;
        for (uint32_t c : level.clusters.partition.clusterOfFace)
            groups.push_back(level.place[c].group == kNoGroup ? -1.0 : double(level.place[c].group));
        const std::string name = std::string("level-") + (l < 10 ? "0" : "") + std::to_string(l) + ".vtp";
        writePolyData(level.prepared.mesh(), (std::filesystem::path(options.writeLevels) / name).string(), {{"group_id", groups}});
    }
    const Eye eye = viewsFor(settings, hierarchy.levels.front().prepared.box).front();
    writePolyData(meshOfCut(hierarchy, cutFrom(hierarchy, eye.position, options.threshold)),
                  (std::filesystem::path(options.writeLevels) / "cut.vtp").string());
    note(options.quiet, "wrote " + std::to_string(hierarchy.levels.size()) + " levels and the cut to " + options.writeLevels);
}

// The lesson on why coarse clusters cull less, from this run's levels, as Markdown.
void writeLesson(const LodStatistics& statistics, const std::string& meshName, const LodCommandOptions& options) {
    const LodLesson lesson = options.lessonLevel < 0 ? makeLodLesson(statistics, meshName)
                                                     : makeLodLesson(statistics, meshName, size_t(options.lessonLevel));
    std::string text = "# Why coarse clusters cull less: " + meshName + ", level 0 and level " + std::to_string(lesson.coarse.level) + "\n";
    for (const LessonStep& step : lesson.steps) text += "\n## " + step.title + "\n\n" + step.text + "\n";
    writeText(options.writeLesson, text);
    note(options.quiet, "wrote " + options.writeLesson);
}

}  // namespace

void runLod(const LodCommandOptions& options) {
    const Settings settings = withClusterIds(options.run.toSettings());
    if (!(options.threshold.value >= 0.0)) throw std::invalid_argument("--threshold must be 0 or more");
    if (!(options.threshold.screenHeight > 0.0)) throw std::invalid_argument("--screen-height must be above 0");
    if (!(options.threshold.fovDegrees > 0.0 && options.threshold.fovDegrees < 180.0))
        throw std::invalid_argument("--fov must be between 0 and 180 degrees");
    if (options.groupSize < 2) throw std::invalid_argument("--group-size must be 2 or more");
    const std::string format = outputFormat(options.format, options.output, "json");
    const Mesh mesh = readMeshNoting(options.mesh, options.quiet, {settings});
    const ProgressCallback progress = stderrProgress(options.quiet);
    PreparedMesh prepared = prepareMesh(std::make_shared<const Mesh>(mesh), options.mesh, settings.fixWinding, progressWithin(progress, 0.0, 0.1));
    prepared.name = fileName(options.mesh);
    ClusterHierarchy hierarchy;
    if (options.hierarchy.empty()) {
        LodBuildOptions build;
        build.groupSize = options.groupSize;
        hierarchy = buildClusterHierarchy(prepared, settings, build, progressWithin(progress, 0.1, 0.6));
    } else {
        note(options.quiet, "reading " + options.hierarchy);
        try {
            hierarchy = hierarchyFromRecords(prepared, readHierarchyFile(options.hierarchy), settings);
        } catch (const HierarchyError& error) {
            throw std::runtime_error(options.hierarchy + ": " + error.what());
        }
    }
    if (!options.writeHierarchy.empty()) {
        const HierarchyRecords records = hierarchyRecordsOf(hierarchy, firstFileVertices(mesh));
        writeText(options.writeHierarchy, isHierarchyBinaryPath(options.writeHierarchy) ? hierarchyBinary(records) : hierarchyJson(records));
        note(options.quiet, "wrote " + options.writeHierarchy);
    }
    if (!options.writeLevels.empty()) writeLevelMeshes(hierarchy, settings, options);
    const LodStatistics statistics = measureHierarchy(hierarchy, settings, options.threshold, progressWithin(progress, 0.6, 1.0),
                                                       options.cones > 0 ? options.cones : settings.conesPerCluster > 1 ? settings.conesPerCluster : 0);
    if (!options.writeLesson.empty()) writeLesson(statistics, prepared.name, options);
    std::ostringstream text;
    if (format == "csv")
        writeLodCsv(statistics, text);
    else if (format == "text")
        writeLodText(statistics, settings, text);
    else
        text << lodStatisticsToJson(statistics, settings, options.perView).dump(2) << "\n";
    writeText(options.output, text.str());
    if (!options.output.empty()) note(options.quiet, "wrote " + options.output);
}

}  // namespace conescope::cli
