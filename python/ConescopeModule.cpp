// conescope._conescope: the C++ side of the Python module. Every function here calls what the CLI's
// commands call (batch/MeshRuns.h, batch/BatchJob.h) and returns the CLI's own text (its JSON, read by
// json.loads in conescope/__init__.py) or its own cells, so a notebook gets the CLI's numbers. Settings
// arrive as (name, text) pairs and are read by the settings schema, as the command line's are.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>

#include "batch/BatchInputs.h"
#include "batch/BatchJob.h"
#include "batch/MeshRuns.h"
#include "batch/OutputFiles.h"
#include "core/Granularity.h"
#include "core/SettingsSchema.h"
#include "core/lod/LodCut.h"
#include "io/BatchReport.h"
#include "io/BatchTable.h"
#include "io/ClusterIdFile.h"
#include "io/ComparisonIO.h"
#include "io/GranularityIO.h"
#include "io/LodIO.h"
#include "io/ClusterFiles.h"
#include "io/MeshReader.h"
#include "io/StatisticsIO.h"

namespace py = pybind11;
using namespace conescope;

namespace {

using SettingPairs = std::vector<std::pair<std::string, std::string>>;

// A keyword as the schema names it: the JSON key or the flag, with underscores for dashes.
const SettingField& fieldNamed(const std::string& name) {
    std::string dashed = name;
    std::replace(dashed.begin(), dashed.end(), '_', '-');
    for (const SettingField& field : settingFields())
        if (field.key == name || field.flag == name || field.flag == dashed) return field;
    std::string names;
    for (const SettingField& field : settingFields()) {
        std::string flag = field.flag;
        std::replace(flag.begin(), flag.end(), '-', '_');
        names += (names.empty() ? "" : ", ") + flag;
    }
    throw std::invalid_argument("unknown setting '" + name + "' (expected one of: " + names + ")");
}

// The settings of keyword arguments, checked as the command line checks its options: the schema's
// domain and message, each setting once, and the options that exclude each other.
Settings settingsFrom(const SettingPairs& pairs) {
    Settings settings;
    std::set<std::string> given;
    for (const auto& [name, text] : pairs) {
        const SettingField& field = fieldNamed(name);
        if (!given.insert(field.flag).second) throw std::invalid_argument("--" + field.flag + " is given twice");
        parseSetting(field, text, settings);
    }
    for (const std::string& flag : given)
        for (const std::string& excluded : settingField(flag).excludes)
            if (given.count(excluded)) throw std::invalid_argument("--" + flag + " excludes --" + excluded);
    return settings;
}

// Ctrl-C in Python stops a long run at its next progress report (on the main thread).
bool keepGoing(double, const std::string&) {
    py::gil_scoped_acquire gil;
    return PyErr_CheckSignals() == 0;
}

// Runs `work` without the GIL, so other Python threads (a Dask worker's) go on meanwhile; a Ctrl-C
// that cancelled it is raised as KeyboardInterrupt.
template <typename Work>
auto withoutGil(Work&& work) {
    try {
        py::gil_scoped_release release;
        return work();
    } catch (const OperationCancelled&) {
        if (PyErr_Occurred()) throw py::error_already_set();
        throw std::runtime_error("cancelled");
    }
}

// A mesh from arrays: n x 3 positions, faces as an m x k integer array or a sequence of sequences,
// optional per-face cluster ids; then the checks and merging every file's mesh gets. Positions come
// as float64, so positions that only rounding to float32 merges are told (`notes`).
Mesh meshFromPython(py::array_t<double, py::array::c_style | py::array::forcecast> vertices, py::object faces,
                    const py::object& clusterIds, const std::string& name, std::vector<std::string>& notes) {
    if (vertices.ndim() != 2 || vertices.shape(1) != 3) throw std::invalid_argument("vertices must be an n x 3 array");
    Mesh mesh;
    std::vector<glm::dvec3> exact;
    const double* xyz = vertices.data();
    const size_t count = size_t(vertices.shape(0));
    withoutGil([&] {
        exact.reserve(count);
        mesh.positions.reserve(count);
        for (size_t k = 0; k < count; ++k) {
            exact.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
            mesh.positions.emplace_back(exact.back());
        }
        return 0;
    });
    // An (m, k) uint32 C array (what conescope._arrays makes of any integer face array): read from
    // its buffer without a Python object per index, and without the GIL.
    if (py::isinstance<py::array>(faces)) {
        const py::array table = py::reinterpret_borrow<py::array>(faces);
        if (table.ndim() == 2 && table.dtype().is(py::dtype::of<uint32_t>()) && (table.flags() & py::array::c_style)) {
            const uint32_t* indices = static_cast<const uint32_t*>(table.data());
            const size_t rows = size_t(table.shape(0)), k = size_t(table.shape(1));
            withoutGil([&] {
                mesh.faceStarts.reserve(rows + 1);
                mesh.faceVertices.reserve(rows * k);
                for (size_t row = 0; row < rows; ++row) mesh.addFace(indices + row * k, k);
                return 0;
            });
            faces = py::none();  // read: the loop below has nothing to do
        }
    }
    std::vector<uint32_t> corners;
    size_t index = 0;
    for (const py::handle face : faces.is_none() ? py::list() : faces) {
        corners.clear();
        for (const py::handle corner : face) {
            const long long value = corner.cast<long long>();
            if (value < 0 || value > static_cast<long long>(UINT32_MAX))
                throw std::invalid_argument("faces[" + std::to_string(index) + "] has the vertex index " + std::to_string(value) +
                                            ", outside [0, " + std::to_string(mesh.positions.size()) + ")");
            corners.push_back(uint32_t(value));
        }
        mesh.addFace(corners.data(), corners.size());
        ++index;
    }
    if (!clusterIds.is_none()) {
        const auto ids = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(clusterIds);
        if (!ids || ids.ndim() != 1 || size_t(ids.shape(0)) != mesh.faceCount())
            throw std::invalid_argument("cluster_ids must hold one id per face (" + std::to_string(mesh.faceCount()) + ")");
        mesh.faceArrays["cluster_id"].assign(ids.data(), ids.data() + ids.shape(0));
    }
    MeshFile file = withoutGil([&] { return meshFromArrays(std::move(mesh), name, exact); });
    notes.insert(notes.end(), file.notes.begin(), file.notes.end());
    return std::move(file.mesh);
}

// A mesh read as the CLI reads it, with the file builder's cluster files of `settings`; the reader's
// notes go to `notes`.
Mesh readMeshForPython(const std::string& path, std::vector<std::string>& notes, const std::vector<Settings>& settings) {
    MeshFile file = withoutGil([&] {
        MeshFile read = readMeshFile(path, keepGoing);
        for (const Settings& each : settings) readClusterFileOf(read.mesh, each, read.notes);
        return read;
    });
    notes.insert(notes.end(), file.notes.begin(), file.notes.end());
    return std::move(file.mesh);
}

// The CLI's text and what it would have said on stderr.
using Document = std::pair<std::string, std::vector<std::string>>;

Document statsDocument(const Mesh& mesh, const std::string& name, const SettingPairs& pairs, bool perView, bool perCluster,
                       std::vector<std::string> notes) {
    const Settings settings = withClusterIds(settingsFrom(pairs));
    const RunStatistics run = withoutGil([&] { return runStatistics(mesh, settings, name, keepGoing); });
    for (const std::string& warning : cli::runWarnings(run)) notes.push_back(warning);
    return {statisticsJsonText(run, {perView, perCluster}), notes};
}

Document clustersDocument(const Mesh& mesh, const std::string& name, const SettingPairs& pairs, const std::string& sort,
                          size_t top, std::vector<std::string> notes) {
    const Settings settings = cli::clusterTableSettings(withClusterIds(settingsFrom(pairs)));
    const ClusterSortKey key = parseClusterSortKey(sort);
    const RunStatistics run = withoutGil([&] { return runStatistics(mesh, settings, name, keepGoing); });
    for (const std::string& warning : cli::runWarnings(run)) notes.push_back(warning);
    return {cli::clusterTableJson(run, key, top).dump(2) + "\n", notes};
}

// The partition the settings make of the mesh, as one cluster id per face of the mesh as given (what
// `conescope-cli partition -o ids.txt` writes), with what the run would warn of.
std::pair<py::array_t<uint32_t>, std::vector<std::string>> partitionIds(const Mesh& mesh, const std::string& name, const SettingPairs& pairs,
                                                                        std::vector<std::string> notes) {
    const Settings settings = withClusterIds(settingsFrom(pairs));
    const Partition partition = withoutGil([&] {
        const PreparedMesh prepared = prepareBorrowed(mesh, name, settings.fixWinding, keepGoing);
        return buildClusters(prepared, settings, nullptr, keepGoing).partition;
    });
    py::array_t<uint32_t> ids(py::ssize_t(partition.clusterOfFace.size()));
    std::copy(partition.clusterOfFace.begin(), partition.clusterOfFace.end(), ids.mutable_data());
    return {ids, notes};
}

// `conescope-cli granularity`'s document: without a test among the settings, every test a row.
Document granularityDocument(const Mesh& mesh, const std::string& name, const SettingPairs& pairs, std::vector<std::string> notes) {
    const bool testsGiven = std::any_of(pairs.begin(), pairs.end(), [](const auto& pair) { return pair.first == "test"; });
    const Settings settings = granularitySettings(withClusterIds(settingsFrom(pairs)), testsGiven);
    const GranularityReport report = withoutGil([&] { return runGranularity(mesh, settings, name, keepGoing); });
    for (const std::string& warning : cli::runWarnings(report.run)) notes.push_back(warning);
    return {granularityToJson(report).dump(2) + "\n", notes};
}

// `conescope-cli lod`'s document for a hierarchy built from the mesh.
Document lodDocument(const Mesh& mesh, const std::string& name, const SettingPairs& pairs, const LodThreshold& threshold,
                     size_t groupSize, bool perView, std::vector<std::string> notes) {
    const Settings settings = withClusterIds(settingsFrom(pairs));
    LodBuildOptions options;
    options.groupSize = groupSize;
    const LodStatistics statistics = withoutGil([&] { return lodOfMesh(mesh, name, settings, threshold, options, keepGoing); });
    return {lodStatisticsToJson(statistics, settings, perView).dump(2) + "\n", notes};
}

Document compareDocument(const Mesh& mesh, const std::string& name, const std::string& a, const std::string& b,
                         const SettingPairs& pairs, bool perView, bool perCluster, std::vector<std::string> notes) {
    const Settings base = settingsFrom(pairs);
    const Settings settingsA = withClusterIds(parseConfiguration(a, base)), settingsB = withClusterIds(parseConfiguration(b, base));
    const ComparedRuns runs =
        withoutGil([&] { return cli::compareMesh(mesh, name, settingsA, settingsB, base, keepGoing); });
    for (const std::string& warning : cli::runWarnings(runs.a, "A: ")) notes.push_back(warning);
    for (const std::string& warning : cli::runWarnings(runs.b, "B: ")) notes.push_back(warning);
    const std::string countWarning = clusterCountWarning(runs.comparison);
    if (!countWarning.empty()) notes.push_back(countWarning);
    std::ostringstream text;
    writeComparisonJson(runs.a, runs.b, runs.comparison, {perView, perCluster}, text);
    return {text.str(), notes};
}

cli::BatchConfig batchConfigFrom(const SettingPairs& pairs, const std::string& compare, bool perView, bool perCluster) {
    return cli::batchConfig(settingsFrom(pairs), compare, {perView, perCluster});
}

// One row of results.csv for a mesh, computed here (a Dask worker): the cells `conescope-cli batch`
// gives it, its JSON files written into `folder` when one is given.
BatchRow batchRow(const std::string& path, const std::string& folder, const SettingPairs& pairs, const std::string& compare,
                       bool perView, bool perCluster) {
    const cli::BatchConfig config = batchConfigFrom(pairs, compare, perView, perCluster);
    const cli::BatchMesh mesh = cli::findBatchMeshes({path}).front();
    BatchRow row = cli::batchRowStart(mesh, config);
    cli::BatchJob job{path, "", ""};
    if (!folder.empty()) {
        job.json = (std::filesystem::path(folder) / row["json"]).string();
        if (!compare.empty()) job.compareJson = (std::filesystem::path(folder) / row["compare_json"]).string();
    }
    const BatchRow cells = withoutGil([&] { return cli::runBatchJob(config, job, cli::testFaultFor(path)); });
    for (const auto& [key, value] : cells) row[key] = value;
    return row;
}

// Per mesh (absolute paths, as the Dask batch sends them), the row of folder/results.csv a new run
// keeps (the command line's batch's rule, cli::reusableRow), or None.
std::vector<std::optional<BatchRow>> keptRows(const std::vector<std::string>& paths, const std::string& folder, const SettingPairs& pairs,
                                              const std::string& compare, bool perView, bool perCluster) {
    const cli::BatchConfig config = batchConfigFrom(pairs, compare, perView, perCluster);
    const BatchTable previous = readBatchCsv((std::filesystem::path(folder) / "results.csv").string());
    std::map<std::string, const BatchRow*> byJson;
    for (const BatchRow& row : previous.rows)
        if (row.count("json")) byJson[row.at("json")] = &row;
    std::vector<std::optional<BatchRow>> kept;
    for (const std::string& path : paths) {
        const cli::BatchMesh mesh = cli::findBatchMeshes({path}).front();  // one each, in the order given
        const auto found = byJson.find(mesh.json);
        const bool keep = mesh.problem.empty() && found != byJson.end() && cli::reusableRow(*found->second, cli::batchRowStart(mesh, config), folder);
        kept.push_back(keep ? std::optional<BatchRow>(*found->second) : std::nullopt);
    }
    return kept;
}

BatchRow errorRow(const std::string& path, const std::string& kind, const std::string& message, const SettingPairs& pairs,
                  const std::string& compare, bool perView, bool perCluster) {
    const cli::BatchConfig config = batchConfigFrom(pairs, compare, perView, perCluster);
    BatchRow row = cli::batchRowStart(cli::findBatchMeshes({path}).front(), config);
    for (const auto& [key, value] : cli::errorCells(kind, message)) row[key] = value;
    return row;
}

// results.csv and report.html of rows made elsewhere (on Dask), written whole as the batch writes them.
void writeResults(const std::string& folder, const std::vector<BatchRow>& rows, const std::string& compare) {
    const std::filesystem::path path(folder);
    cli::writeTextFileAtomically((path / "results.csv").string(), batchCsvText(rows));
    const BatchReportInfo info{std::filesystem::absolute(path).lexically_normal().filename().string(), rows.size(), compare};
    cli::writeTextFileAtomically((path / "report.html").string(), batchReportHtml(rows, info));
}

std::vector<std::string> findMeshes(const std::vector<std::string>& paths, const std::string& shard) {
    std::vector<cli::BatchMesh> meshes = cli::findBatchMeshes(paths);
    if (!shard.empty()) meshes = cli::meshesOfShard(meshes, cli::parseShard(shard));
    std::vector<std::string> found;
    for (const cli::BatchMesh& mesh : meshes) found.push_back(mesh.path);
    return found;
}

}  // namespace

PYBIND11_MODULE(_conescope, m) {
    m.doc() = "ConeScope's core for Python: see the conescope package";
    py::register_exception<MeshReadError>(m, "MeshReadError", PyExc_OSError);
    m.attr("__version__") = conescopeVersion();
    m.attr("cli_path") = CONESCOPE_CLI_BUILT;
    m.def("extensions", &supportedMeshExtensions);
    m.def("check_settings", [](const SettingPairs& pairs) { settingsFrom(pairs); });
    m.def("setting_arguments", [](const SettingPairs& pairs) { return settingArguments(settingsFrom(pairs)); });
    m.def("check_compare", [](const std::string& text, const SettingPairs& pairs) { parseConfiguration(text, settingsFrom(pairs)); });
    m.def("stats", [](const std::string& path, const SettingPairs& pairs, bool perView, bool perCluster) {
        std::vector<std::string> notes;
        const Mesh mesh = readMeshForPython(path, notes, {settingsFrom(pairs)});
        return statsDocument(mesh, std::filesystem::path(path).filename().string(), pairs, perView, perCluster, notes);
    });
    m.def("stats_arrays", [](py::array_t<double, py::array::c_style | py::array::forcecast> vertices, const py::object& faces,
                             const py::object& clusterIds, const std::string& name, const SettingPairs& pairs, bool perView,
                             bool perCluster) {
        std::vector<std::string> notes;
        const Mesh mesh = meshFromPython(vertices, faces, clusterIds, name, notes);
        return statsDocument(mesh, name, pairs, perView, perCluster, notes);
    });
    m.def("clusters", [](const std::string& path, const SettingPairs& pairs, const std::string& sort, size_t top) {
        std::vector<std::string> notes;
        const Mesh mesh = readMeshForPython(path, notes, {settingsFrom(pairs)});
        return clustersDocument(mesh, std::filesystem::path(path).filename().string(), pairs, sort, top, notes);
    });
    m.def("clusters_arrays", [](py::array_t<double, py::array::c_style | py::array::forcecast> vertices, const py::object& faces,
                                const py::object& clusterIds, const std::string& name, const SettingPairs& pairs,
                                const std::string& sort, size_t top) {
        std::vector<std::string> notes;
        const Mesh mesh = meshFromPython(vertices, faces, clusterIds, name, notes);
        return clustersDocument(mesh, name, pairs, sort, top, notes);
    });
    m.def("compare", [](const std::string& path, const std::string& a, const std::string& b, const SettingPairs& pairs,
                        bool perView, bool perCluster) {
        std::vector<std::string> notes;
        const Settings base = settingsFrom(pairs);
        const Mesh mesh = readMeshForPython(path, notes, {parseConfiguration(a, base), parseConfiguration(b, base)});
        return compareDocument(mesh, path, a, b, pairs, perView, perCluster, notes);
    });
    m.def("compare_arrays", [](py::array_t<double, py::array::c_style | py::array::forcecast> vertices, const py::object& faces,
                               const py::object& clusterIds, const std::string& name, const std::string& a, const std::string& b,
                               const SettingPairs& pairs, bool perView, bool perCluster) {
        std::vector<std::string> notes;
        const Mesh mesh = meshFromPython(vertices, faces, clusterIds, name, notes);
        return compareDocument(mesh, name, a, b, pairs, perView, perCluster, notes);
    });
    m.def("partition", [](const std::string& path, const SettingPairs& pairs) {
        std::vector<std::string> notes;
        const Mesh mesh = readMeshForPython(path, notes, {settingsFrom(pairs)});
        return partitionIds(mesh, std::filesystem::path(path).filename().string(), pairs, notes);
    });
    m.def("partition_arrays", [](py::array_t<double, py::array::c_style | py::array::forcecast> vertices, const py::object& faces,
                                 const py::object& clusterIds, const std::string& name, const SettingPairs& pairs) {
        std::vector<std::string> notes;
        const Mesh mesh = meshFromPython(vertices, faces, clusterIds, name, notes);
        return partitionIds(mesh, name, pairs, notes);
    });
    m.def("granularity", [](const std::string& path, const SettingPairs& pairs) {
        std::vector<std::string> notes;
        const Mesh mesh = readMeshForPython(path, notes, {settingsFrom(pairs)});
        return granularityDocument(mesh, std::filesystem::path(path).filename().string(), pairs, notes);
    });
    m.def("lod", [](const std::string& path, const SettingPairs& pairs, double threshold, bool world, double screenHeight,
                    double fovDegrees, size_t groupSize, bool perView) {
        std::vector<std::string> notes;
        const Mesh mesh = readMeshForPython(path, notes, {settingsFrom(pairs)});
        return lodDocument(mesh, std::filesystem::path(path).filename().string(), pairs,
                           LodThreshold{threshold, world, screenHeight, fovDegrees}, groupSize, perView, notes);
    });
    m.def("find_meshes", &findMeshes);
    m.def("batch_columns", &batchColumns);
    m.def("batch_row", &batchRow);
    m.def("error_row", &errorRow);
    m.def("kept_rows", &keptRows);
    m.def("results_csv", &batchCsvText);
    m.def("write_results", &writeResults);
}
