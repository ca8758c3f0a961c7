#include "SettingsSchema.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace conescope {

namespace {

template <typename Enum>
std::vector<std::string> namesOf(const std::vector<Enum>& values) {
    std::vector<std::string> names;
    for (Enum value : values) names.push_back(toString(value));
    return names;
}

template <typename Enum, typename Parse>
std::vector<Enum> enumsOf(const std::vector<std::string>& names, Parse parse) {
    std::vector<Enum> values;
    for (const std::string& name : names) values.push_back(parse(name));
    return values;
}

std::string joined(const std::vector<std::string>& names, const char* separator) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : separator) + name;
    return text;
}

std::vector<std::string> splitCommas(const std::string& text) {
    std::vector<std::string> parts;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t comma = std::min(text.find(',', start), text.size());
        parts.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return parts;
}

// Shortest text first, so "1e3" and "0.3" are read the same in every locale.
double parseFiniteNumber(const std::string& text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value))
        throw std::invalid_argument("'" + text + "' is not a finite number");
    return value;
}

// A float setting as the double with the same shortest text, so 0.3f is recorded as 0.3 and not
// as 0.30000001192092896; it still reads back to the same float.
double floatAsShortestDouble(float value) {
    std::array<char, 32> buffer{};
    const auto end = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr;
    double result = 0.0;
    std::from_chars(buffer.data(), end, result);
    return result;
}

std::string numberText(double value) {
    std::array<char, 32> buffer{};
    return std::string(buffer.data(), std::to_chars(buffer.data(), buffer.data() + buffer.size(), value).ptr);
}

// Names given (with "all" for every accepted one), each once, in the order of first mention.
std::vector<std::string> nameList(const SettingField& field, const std::string& text) {
    const std::vector<std::string> accepted = field.names();
    std::vector<std::string> names;
    auto add = [&](const std::string& name) {
        if (std::find(accepted.begin(), accepted.end(), name) == accepted.end())
            throw std::invalid_argument("unknown name '" + name + "' (expected one of: " + joined(accepted, ", ") + ", all)");
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    };
    for (const std::string& name : splitCommas(text)) {
        if (name == "all")
            std::for_each(accepted.begin(), accepted.end(), add);
        else
            add(name);
    }
    return names;
}

SettingValue parsedValue(const SettingField& field, const std::string& text) {
    switch (field.kind) {
        case SettingKind::Count: {
            size_t value = 0;
            const auto [stop, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error != std::errc() || stop != text.data() + text.size() || double(value) < field.minimum ||
                double(value) > field.maximum)
                throw std::invalid_argument("'" + text + "' is not a whole number in [" + numberText(field.minimum) + ", " +
                                            numberText(field.maximum) + "]");
            return value;
        }
        case SettingKind::Number: {
            const double value = parseFiniteNumber(text);
            const bool low = field.minimumExcluded ? !(value > field.minimum) : value < field.minimum;
            if (low || value > field.maximum)
                throw std::invalid_argument("'" + text + "' is not in " + (field.minimumExcluded ? "(" : "[") +
                                            numberText(field.minimum) + ", " + numberText(field.maximum) + "]");
            return value;
        }
        case SettingKind::Name: {
            const std::vector<std::string> accepted = field.names();
            if (std::find(accepted.begin(), accepted.end(), text) == accepted.end())
                throw std::invalid_argument("unknown name '" + text + "' (expected one of: " + joined(accepted, ", ") + ")");
            return text;
        }
        case SettingKind::NameList: return nameList(field, text);
        case SettingKind::Point: return text.empty() ? std::optional<glm::dvec3>() : std::optional<glm::dvec3>(parseEye(text));
        case SettingKind::Path: return text;
        case SettingKind::Flag:
            if (text.empty() || text == "true" || text == "1" || text == "on") return true;
            if (text == "false" || text == "0" || text == "off") return false;
            throw std::invalid_argument("'" + text + "' is not true or false");
    }
    throw std::invalid_argument("unknown setting kind");
}

const std::vector<Builder> clusterLimitBuilders = {Builder::Optimized, Builder::Meshlet, Builder::Meshopt};
constexpr double largestCount = double(size_t(1) << 20);

// A field's description; the caller adds its domain, names, value and assign.
SettingField describe(std::string key, std::string flag, std::string valueName, std::string help, SettingKind kind,
                      bool builderOption, Stage invalidates, std::vector<Builder> usedBy = {}) {
    SettingField field;
    field.key = std::move(key), field.flag = std::move(flag), field.valueName = std::move(valueName);
    field.help = std::move(help), field.kind = kind, field.builderOption = builderOption;
    field.invalidates = invalidates, field.usedBy = std::move(usedBy);
    return field;
}

// How the clusters are made: the builder and its limits (Stage::Clusters).
void addClusterFields(std::vector<SettingField>& fields) {
    auto row = [&](SettingField field) { fields.push_back(std::move(field)); };
    SettingField f;

    f = describe("builder", "builder", "BUILDER", "How faces are grouped into clusters", SettingKind::Name, true, Stage::Clusters);
    f.names = [] { return namesOf(allBuilders()); };
    f.value = [](const Settings& s) -> SettingValue { return toString(s.builder); };
    f.assign = [](Settings& s, const SettingValue& v) { s.builder = parseBuilder(std::get<std::string>(v)); };
    row(f);

    f = describe("max_vertices", "max-verts", "N", "Most vertices per cluster (optimized, meshlet, meshopt)", SettingKind::Count, true,
         Stage::Clusters, clusterLimitBuilders);
    f.minimum = 3, f.maximum = largestCount;
    f.value = [](const Settings& s) -> SettingValue { return s.limits.maxVertices; };
    f.assign = [](Settings& s, const SettingValue& v) { s.limits.maxVertices = std::get<size_t>(v); };
    row(f);

    // kmeans derives its default cluster count from the triangle limit.
    f = describe("max_triangles", "max-tris", "N",
         "Most triangles per cluster (optimized, meshlet, meshopt; kmeans target when --clusters is 0)", SettingKind::Count,
         true, Stage::Clusters, {Builder::Optimized, Builder::Meshlet, Builder::Meshopt, Builder::KMeans});
    f.minimum = 1, f.maximum = largestCount;
    f.onlyWhen = [](const Settings& s) { return s.builder != Builder::KMeans || s.clusterCount == 0; };
    f.value = [](const Settings& s) -> SettingValue { return s.limits.maxTriangles; };
    f.assign = [](Settings& s, const SettingValue& v) { s.limits.maxTriangles = std::get<size_t>(v); };
    row(f);

    f = describe("clusters_target", "clusters", "K",
         "Number of clusters for kmeans (0 = triangles / max-tris) and the optimized builder's budget (0 = its "
         "default, meshoptimizer's count; a budget given, even that count, is searched longer at the balanced effort)",
         SettingKind::Count, true, Stage::Clusters, {Builder::KMeans, Builder::Optimized});
    f.minimum = 0, f.maximum = double(std::numeric_limits<uint32_t>::max());
    f.value = [](const Settings& s) -> SettingValue { return s.clusterCount; };
    f.assign = [](Settings& s, const SettingValue& v) { s.clusterCount = std::get<size_t>(v); };
    row(f);

    f = describe("effort", "effort", "LEVEL", "How long the optimized builder searches (docs/benchmarks.md has the trade)",
                 SettingKind::Name, true, Stage::Clusters, {Builder::Optimized});
    f.names = [] { return namesOf(allEfforts()); };
    f.value = [](const Settings& s) -> SettingValue { return toString(s.effort); };
    f.assign = [](Settings& s, const SettingValue& v) { s.effort = parseEffort(std::get<std::string>(v)); };
    row(f);

    f = describe("cluster_file", "cluster-file", "PATH",
         "file builder: meshoptimizer's meshlets (JSON or binary) or a text file of one cluster id per face (default: the mesh's cluster_id array, else its OBJ groups or glTF primitives)", SettingKind::Path,
         true, Stage::Clusters, {Builder::File});
    f.value = [](const Settings& s) -> SettingValue { return s.clusterFile; };
    f.assign = [](Settings& s, const SettingValue& v) { s.clusterFile = std::get<std::string>(v); };
    row(f);

    f = describe("normal_weight", "normal-weight", "W", "meshlet/kmeans preference for narrow normal cones (0 = locality only)",
         SettingKind::Number, true, Stage::Clusters, {Builder::Meshlet, Builder::KMeans});
    f.minimum = 0.0, f.maximum = 1e6;
    f.value = [](const Settings& s) -> SettingValue { return s.normalWeight; };
    f.assign = [](Settings& s, const SettingValue& v) { s.normalWeight = std::get<double>(v); };
    row(f);

    f = describe("cone_weight", "cone-weight", "W", "meshopt builder's cone_weight in [0, 1]", SettingKind::Number, true,
         Stage::Clusters, {Builder::Meshopt});
    f.minimum = 0.0, f.maximum = 1.0;
    f.value = [](const Settings& s) -> SettingValue { return floatAsShortestDouble(s.meshoptConeWeight); };
    f.assign = [](Settings& s, const SettingValue& v) { s.meshoptConeWeight = float(std::get<double>(v)); };
    row(f);
}

// The bounds, the tests and the views they are measured from.
void addMeasurementFields(std::vector<SettingField>& fields) {
    auto row = [&](SettingField field) { fields.push_back(std::move(field)); };
    SettingField f;

    f = describe("cones", "cone", "CONES", "Cone of normals methods, comma separated; the first is the one shown",
         SettingKind::NameList, false, Stage::Bounds);
    f.names = [] { return namesOf(allConeMethods()); };
    f.value = [](const Settings& s) -> SettingValue { return namesOf(s.cones); };
    f.assign = [](Settings& s, const SettingValue& v) {
        s.cones = enumsOf<ConeMethod>(std::get<std::vector<std::string>>(v), parseConeMethod);
    };
    row(f);

    f = describe("tests", "test", "TESTS", "Cull tests, comma separated; the first is the one shown", SettingKind::NameList, false,
         Stage::Measurement);
    f.names = [] { return namesOf(allCullTests()); };
    f.value = [](const Settings& s) -> SettingValue { return namesOf(s.tests); };
    f.assign = [](Settings& s, const SettingValue& v) {
        s.tests = enumsOf<CullTest>(std::get<std::vector<std::string>>(v), parseCullTest);
    };
    row(f);

    f = describe("sphere", "sphere", "SPHERE", "Bounding sphere method", SettingKind::Name, false, Stage::Bounds);
    f.names = [] { return namesOf(allSphereMethods()); };
    f.value = [](const Settings& s) -> SettingValue { return toString(s.sphere); };
    f.assign = [](Settings& s, const SettingValue& v) { s.sphere = parseSphereMethod(std::get<std::string>(v)); };
    row(f);

    // Beside the tests, not one of them: the K-cone record splits each cluster's cone. The optimized
    // builder builds its partition for it (at balanced and best), so a change makes new clusters.
    f = describe("cones_per_cluster", "cones-per-cluster", "K",
                 "Also cull with K cones per cluster, each its sub-group's cone and apex (1, 2, 4 or 8; 1: one cone only; granularity's "
                 "cones-K record); the optimized builder then builds its clusters for K cones (balanced and best efforts)",
                 SettingKind::Count, true, Stage::Clusters);  // a builder option too: `partition` writes the clusters for K
    f.minimum = 1, f.maximum = 8, f.omittedAtDefault = true;
    f.value = [](const Settings& s) -> SettingValue { return size_t(s.conesPerCluster); };
    f.assign = [](Settings& s, const SettingValue& v) {
        const size_t k = std::get<size_t>(v);
        if (k != 1 && k != 2 && k != 4 && k != 8) throw std::invalid_argument("'" + std::to_string(k) + "' is not 1, 2, 4 or 8");
        s.conesPerCluster = uint32_t(k);
    };
    row(f);

    f = describe("views", "views", "N", "Number of orbit views around the mesh", SettingKind::Count, false, Stage::Measurement);
    f.minimum = 1, f.maximum = double(size_t(1) << 24);
    f.value = [](const Settings& s) -> SettingValue { return s.views; };
    f.assign = [](Settings& s, const SettingValue& v) { s.views = std::get<size_t>(v); };
    row(f);

    f = describe("distance", "distance", "D", "Orbit radius in half-diagonals of the mesh's bounding box", SettingKind::Number, false,
         Stage::Measurement);
    f.minimum = 0.0, f.maximum = 1e12, f.minimumExcluded = true;
    f.value = [](const Settings& s) -> SettingValue { return s.distance; };
    f.assign = [](Settings& s, const SettingValue& v) { s.distance = std::get<double>(v); };
    row(f);

    f = describe("eye", "eye", "X,Y,Z", "A single eye point x,y,z instead of the orbit", SettingKind::Point, false,
         Stage::Measurement);
    f.excludes = {"views", "distance"};
    f.value = [](const Settings& s) -> SettingValue { return s.eye; };
    f.assign = [](Settings& s, const SettingValue& v) { s.eye = std::get<std::optional<glm::dvec3>>(v); };
    row(f);

    f = describe("orthographic", "ortho", "", "Orthographic views (looking from the eye points towards the centre)",
         SettingKind::Flag, false, Stage::Measurement);
    f.value = [](const Settings& s) -> SettingValue { return s.orthographic; };
    f.assign = [](Settings& s, const SettingValue& v) { s.orthographic = std::get<bool>(v); };
    row(f);

    f = describe("fix_winding", "fix-winding", "",
         "Make face winding consistent, and closed parts that are inside out face outward, before culling",
         SettingKind::Flag, false, Stage::PreparedMesh);
    f.value = [](const Settings& s) -> SettingValue { return s.fixWinding; };
    f.assign = [](Settings& s, const SettingValue& v) { s.fixWinding = std::get<bool>(v); };
    row(f);
}

std::vector<SettingField> makeFields() {
    std::vector<SettingField> fields;
    addClusterFields(fields);
    addMeasurementFields(fields);
    return fields;
}

}  // namespace

const std::vector<SettingField>& settingFields() {
    static const std::vector<SettingField> fields = makeFields();
    return fields;
}

const SettingField& settingField(const std::string& keyOrFlag) {
    for (const SettingField& field : settingFields())
        if (field.key == keyOrFlag || field.flag == keyOrFlag) return field;
    throw std::out_of_range("no setting named '" + keyOrFlag + "'");
}

bool fieldMatters(const SettingField& field, const Settings& settings) {
    const bool used = field.usedBy.empty() || std::find(field.usedBy.begin(), field.usedBy.end(), settings.builder) != field.usedBy.end();
    return used && (!field.onlyWhen || field.onlyWhen(settings));
}

std::string settingText(const SettingField& field, const Settings& settings) {
    const SettingValue value = field.value(settings);
    if (const bool* flag = std::get_if<bool>(&value)) return *flag ? "true" : "false";
    if (const size_t* count = std::get_if<size_t>(&value)) return std::to_string(*count);
    if (const double* number = std::get_if<double>(&value)) return numberText(*number);
    if (const std::string* text = std::get_if<std::string>(&value)) return *text;
    if (const auto* names = std::get_if<std::vector<std::string>>(&value)) return joined(*names, ",");
    const auto& point = std::get<std::optional<glm::dvec3>>(value);
    return point ? numberText(point->x) + "," + numberText(point->y) + "," + numberText(point->z) : std::string();
}

void parseSetting(const SettingField& field, const std::string& text, Settings& settings) {
    try {
        field.assign(settings, parsedValue(field, text));
    } catch (const std::invalid_argument& error) {
        throw std::invalid_argument("--" + field.flag + ": " + error.what());
    }
}

std::vector<std::string> settingArguments(const Settings& settings) {
    std::vector<std::string> arguments;
    for (const SettingField& field : settingFields()) {
        const std::string text = settingText(field, settings);
        if (text == settingText(field, Settings{})) continue;
        arguments.push_back("--" + field.flag);
        if (field.kind != SettingKind::Flag) arguments.push_back(text);
    }
    return arguments;
}

std::string settingHelp(const SettingField& field) {
    std::string help = field.help;
    if (field.kind == SettingKind::Name) help += ": " + joined(field.names(), ", ");
    if (field.kind == SettingKind::NameList) help += ": " + joined(field.names(), ", ") + " or all";
    return help;
}

bool sameSettings(const Settings& a, const Settings& b) {
    for (const SettingField& field : settingFields())
        if (field.value(a) != field.value(b)) return false;
    return true;
}

std::optional<Stage> firstStaleStage(const Settings& before, const Settings& after) {
    // The best effort keeps whichever of its two searches culls more as the run measures it from its
    // orbit (shownEfficiency): its cone, sphere, test and orbit choose the partition too; an eye does not.
    const bool judgedByTheRun = after.builder == Builder::Optimized && after.effort == Effort::Best;
    std::optional<Stage> stale;
    for (const SettingField& field : settingFields()) {
        if (!fieldMatters(field, after) || field.value(before) == field.value(after)) continue;
        const bool choosesClusters = judgedByTheRun && field.key != "eye";
        const Stage invalidates = choosesClusters ? std::min(field.invalidates, Stage::Clusters) : field.invalidates;
        if (!stale || invalidates < *stale) stale = invalidates;
    }
    return stale;
}

glm::dvec3 parseEye(const std::string& text) {
    const std::vector<std::string> parts = splitCommas(text);
    if (parts.size() != 3) throw std::invalid_argument("eye '" + text + "' is not three numbers x,y,z");
    return {parseFiniteNumber(parts[0]), parseFiniteNumber(parts[1]), parseFiniteNumber(parts[2])};
}

}  // namespace conescope
