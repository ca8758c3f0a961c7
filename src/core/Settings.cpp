#include "Settings.h"

#include <stdexcept>
#include <utility>

#include "Choices.h"

namespace conescope {

namespace {
template <typename Enum>
using NameTable = std::vector<std::pair<Enum, const char*>>;

// The cone, test and builder names come from their descriptor tables (Choices.h), in their order.
template <typename Enum, typename Row, size_t N>
NameTable<Enum> namesFrom(const std::array<Row, N>& rows, Enum Row::*value) {
    NameTable<Enum> names;
    for (const Row& row : rows) names.emplace_back(row.*value, row.name);
    return names;
}

const NameTable<Builder>& builderNames() {
    static const NameTable<Builder> names = namesFrom(builderDescriptors(), &BuilderDescriptor::builder);
    return names;
}
const NameTable<ConeMethod>& coneNames() {
    static const NameTable<ConeMethod> names = namesFrom(coneDescriptors(), &ConeDescriptor::method);
    return names;
}
const NameTable<CullTest>& testNames() {
    static const NameTable<CullTest> names = namesFrom(cullTestDescriptors(), &CullTestDescriptor::test);
    return names;
}
const NameTable<SphereMethod>& sphereNames() {
    static const NameTable<SphereMethod> names = {{SphereMethod::Ritter, "ritter"}, {SphereMethod::Minimal, "minimal"}};
    return names;
}
const NameTable<Effort>& effortNames() {
    static const NameTable<Effort> names = {{Effort::Fast, "fast"}, {Effort::Balanced, "balanced"}, {Effort::Best, "best"}};
    return names;
}

template <typename Enum>
std::string nameOf(const NameTable<Enum>& table, Enum value) {
    for (const auto& [entry, name] : table)
        if (entry == value) return name;
    return "unknown";
}

template <typename Enum>
Enum parseName(const NameTable<Enum>& table, const std::string& text, const char* what) {
    std::string accepted;
    for (const auto& [entry, name] : table) {
        if (text == name) return entry;
        accepted += accepted.empty() ? name : std::string(", ") + name;
    }
    throw std::invalid_argument("unknown " + std::string(what) + " '" + text + "' (expected one of: " + accepted + ")");
}

template <typename Enum>
std::vector<Enum> entriesOf(const NameTable<Enum>& table) {
    std::vector<Enum> entries;
    for (const auto& entry : table) entries.push_back(entry.first);
    return entries;
}
}  // namespace

std::string toString(Builder value) { return nameOf(builderNames(), value); }
std::string toString(ConeMethod value) { return nameOf(coneNames(), value); }
std::string toString(CullTest value) { return nameOf(testNames(), value); }
std::string toString(SphereMethod value) { return nameOf(sphereNames(), value); }
std::string toString(Effort value) { return nameOf(effortNames(), value); }
Builder parseBuilder(const std::string& text) { return parseName(builderNames(), text, "builder"); }
ConeMethod parseConeMethod(const std::string& text) { return parseName(coneNames(), text, "cone method"); }
CullTest parseCullTest(const std::string& text) { return parseName(testNames(), text, "cull test"); }
SphereMethod parseSphereMethod(const std::string& text) { return parseName(sphereNames(), text, "sphere method"); }
Effort parseEffort(const std::string& text) { return parseName(effortNames(), text, "effort"); }

namespace {
// Every entry of an enum's table, made once per enum type.
template <typename Enum>
const std::vector<Enum>& allOf(const NameTable<Enum>& table) {
    static const std::vector<Enum> all = entriesOf(table);
    return all;
}
}  // namespace

const std::vector<ConeMethod>& allConeMethods() { return allOf(coneNames()); }
const std::vector<CullTest>& allCullTests() { return allOf(testNames()); }
const std::vector<Builder>& allBuilders() { return allOf(builderNames()); }
const std::vector<SphereMethod>& allSphereMethods() { return allOf(sphereNames()); }
const std::vector<Effort>& allEfforts() { return allOf(effortNames()); }

ConeMethod displayedCone(const Settings& settings) {
    return settings.cones.empty() ? ConeMethod::Minimal : settings.cones.front();
}

CullTest displayedTest(const Settings& settings) {
    return settings.tests.empty() ? CullTest::Vertices : settings.tests.front();
}

std::vector<Eye> viewsFor(const Settings& settings, const Aabb& worldBox) {
    if (settings.eye) {
        if (!settings.orthographic) return {Eye::perspective(*settings.eye)};
        // An orthographic eye given as a point looks from there towards the mesh centre.
        const glm::dvec3 direction = glm::dvec3(worldBox.center()) - *settings.eye;
        if (!(glm::length(direction) > 0.0)) throw std::invalid_argument("orthographic eye is at the mesh centre: no direction");
        Eye eye = Eye::orthographicAlong(direction);
        eye.position = *settings.eye;  // reported with the view, as orbit views report theirs
        return {eye};
    }
    return orbitViews(worldBox, settings.views, settings.distance, settings.orthographic);
}

std::vector<Eye> orbitOf(const Settings& settings, const Aabb& worldBox) {
    Settings orbit = settings;
    orbit.eye.reset();
    return viewsFor(orbit, worldBox);
}

}  // namespace conescope
