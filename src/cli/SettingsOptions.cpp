#include "cli/SettingsOptions.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace conescope::cli {

namespace {

template <typename Enum>
std::string joinNames(const std::vector<Enum>& values) {
    std::string text;
    for (Enum value : values) text += (text.empty() ? "" : ",") + toString(value);
    return text;
}

template <typename Enum>
std::string acceptedNames(const std::vector<Enum>& values, bool withAll) {
    return joinNames(values) + (withAll ? ",all" : "");
}

// A CLI11 validator from one of the core's parse functions: its std::invalid_argument message
// (which lists the accepted names) becomes the parse error.
// `all`, when given, is accepted besides the parsed names and added to the message.
template <typename Parse>
CLI::Validator nameValidator(Parse parse, const std::string& description, bool allowAll = false) {
    return CLI::Validator(
        [parse, allowAll](std::string& text) -> std::string {
            if (allowAll && text == "all") return {};
            try {
                parse(text);
                return {};
            } catch (const std::invalid_argument& error) {
                return error.what() + std::string(allowAll ? " or all" : "");
            }
        },
        description);
}

std::vector<std::string> splitCommas(const std::vector<std::string>& items) {
    std::vector<std::string> names;
    for (const std::string& item : items) {
        size_t start = 0;
        while (start <= item.size()) {
            const size_t comma = std::min(item.find(',', start), item.size());
            names.push_back(item.substr(start, comma - start));
            start = comma + 1;
        }
    }
    return names;
}

template <typename Enum>
std::vector<Enum> parseList(const std::vector<std::string>& items, const std::vector<Enum>& all,
                            const std::function<Enum(const std::string&)>& parse) {
    std::vector<Enum> values;
    auto add = [&](Enum value) {
        if (std::find(values.begin(), values.end(), value) == values.end()) values.push_back(value);
    };
    for (const std::string& name : splitCommas(items)) {
        if (name == "all")
            std::for_each(all.begin(), all.end(), add);
        else
            add(parse(name));
    }
    if (values.empty()) throw std::invalid_argument("empty list");
    return values;
}

double parseNumber(const std::string& text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end || !std::isfinite(value))
        throw std::invalid_argument("'" + text + "' is not a finite number");
    return value;
}

}  // namespace

SettingsOptions::SettingsOptions() {
    builder = toString(settings.builder);
    for (ConeMethod cone : settings.cones) cones.push_back(toString(cone));
    for (CullTest test : settings.tests) tests.push_back(toString(test));
    sphere = toString(settings.sphere);
}

Settings SettingsOptions::toSettings() const {
    Settings result = settings;
    result.builder = parseBuilder(builder);
    result.cones = parseConeList(cones);
    result.tests = parseTestList(tests);
    result.sphere = parseSphereMethod(sphere);
    if (!eye.empty()) result.eye = parseEye(eye);
    return result;
}

glm::dvec3 parseEye(const std::string& text) {
    const std::vector<std::string> parts = splitCommas({text});
    if (parts.size() != 3) throw std::invalid_argument("eye '" + text + "' is not three numbers x,y,z");
    return {parseNumber(parts[0]), parseNumber(parts[1]), parseNumber(parts[2])};
}

std::vector<ConeMethod> parseConeList(const std::vector<std::string>& names) {
    return parseList<ConeMethod>(names, allConeMethods(), parseConeMethod);
}

std::vector<CullTest> parseTestList(const std::vector<std::string>& names) {
    return parseList<CullTest>(names, allCullTests(), parseCullTest);
}

void addBuilderOptions(CLI::App& command, SettingsOptions& options) {
    const Settings defaults;
    command.add_option("--builder", options.builder, "How faces are grouped into clusters: " + acceptedNames(allBuilders(), false))
        ->check(nameValidator(parseBuilder, "BUILDER"))
        ->capture_default_str();
    command.add_option("--max-verts", options.settings.limits.maxVertices, "Most vertices per cluster (optimized, meshlet, meshopt)")
        ->check(CLI::Range(size_t(3), size_t(1) << 20))
        ->capture_default_str();
    command.add_option("--max-tris", options.settings.limits.maxTriangles, "Most triangles per cluster (optimized, meshlet, meshopt; kmeans target when --clusters is 0)")
        ->check(CLI::Range(size_t(1), size_t(1) << 20))
        ->capture_default_str();
    command.add_option("--clusters", options.settings.clusterCount, "Number of clusters for kmeans (0 = triangles / max-tris) and the optimized builder's budget (0 = its default)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command.add_option("--cluster-file", options.settings.clusterFile,
                       "file builder: text file with one cluster id per face (default: the mesh's cluster_id array)");
    command.add_option("--normal-weight", options.settings.normalWeight, "meshlet/kmeans preference for narrow normal cones (0 = locality only)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    command.add_option("--cone-weight", options.settings.meshoptConeWeight, "meshopt builder's cone_weight in [0, 1]")
        ->check(CLI::Range(0.0f, 1.0f))
        ->capture_default_str();
}

void addCullingOptions(CLI::App& command, SettingsOptions& options) {
    command.add_option("--cone", options.cones, "Cone of normals methods, comma separated: " + acceptedNames(allConeMethods(), true))
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(nameValidator(parseConeMethod, "CONES", true))
        ->default_str(joinNames(Settings{}.cones));
    command.add_option("--test", options.tests, "Cull tests, comma separated: " + acceptedNames(allCullTests(), true))
        ->delimiter(',')
        ->allow_extra_args(false)
        ->check(nameValidator(parseCullTest, "TESTS", true))
        ->default_str(joinNames(Settings{}.tests));
    command.add_option("--sphere", options.sphere, "Bounding sphere method: ritter,minimal")
        ->check(nameValidator(parseSphereMethod, "SPHERE"))
        ->capture_default_str();
    CLI::Option* views = command.add_option("--views", options.settings.views, "Number of orbit views around the mesh")
                             ->check(CLI::Range(size_t(1), size_t(1) << 24))
                             ->capture_default_str();
    CLI::Option* distance =
        command.add_option("--distance", options.settings.distance, "Orbit radius in half-diagonals of the mesh's bounding box")
            ->check(CLI::PositiveNumber)
            ->capture_default_str();
    command.add_option("--eye", options.eye, "A single eye point x,y,z instead of the orbit")
        ->check(nameValidator(parseEye, "X,Y,Z"))
        ->excludes(views)
        ->excludes(distance);
    command.add_flag("--ortho", options.settings.orthographic, "Orthographic views (looking from the eye points towards the centre)")
        ->capture_default_str();
    command.add_flag("--fix-winding", options.settings.fixWinding, "Make face winding consistent before culling")
        ->capture_default_str();
}

}  // namespace conescope::cli
