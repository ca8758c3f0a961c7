// The descriptor tables (Choices.h): every cone method, cull test and builder has a complete row, and
// the settings and the schema list exactly the tables' names, in the tables' order.
#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "core/Choices.h"
#include "core/RecordTests.h"
#include "core/SettingsSchema.h"

using namespace conescope;

namespace {

bool filled(const char* text) { return text != nullptr && *text != '\0'; }

template <typename Rows>
std::vector<std::string> namesOfRows(const Rows& rows) {
    std::vector<std::string> names;
    for (const auto& row : rows) names.push_back(row.name);
    return names;
}

std::set<std::string> distinct(const std::vector<std::string>& names) { return {names.begin(), names.end()}; }

}  // namespace

// Each value 0 .. N-1 has its row, whose name reads back to the value; no two rows share a name.
template <typename Enum, typename Rows, typename Key, typename Parse>
void expectOneNamedRowPerValue(const Rows& rows, Key key, Parse parse) {
    for (size_t value = 0; value < rows.size(); ++value) {
        const Enum choice = Enum(value);
        const auto& row = descriptor(choice);
        EXPECT_EQ(key(row), choice) << "value " << value;
        ASSERT_TRUE(filled(row.name)) << "value " << value << " has no name";
        EXPECT_EQ(toString(choice), row.name);
        EXPECT_EQ(parse(row.name), choice);
    }
    EXPECT_EQ(distinct(namesOfRows(rows)).size(), rows.size());
}

TEST(Choices, EveryConeMethodHasACompleteRowWithItsOwnNameAndColour) {
    expectOneNamedRowPerValue<ConeMethod>(coneDescriptors(), [](const ConeDescriptor& row) { return row.method; }, parseConeMethod);
    std::set<std::array<double, 3>> colours;
    for (const ConeDescriptor& row : coneDescriptors()) {
        EXPECT_TRUE(filled(row.glossary) && filled(row.lessonWording)) << row.name;
        EXPECT_NE(std::string(row.lessonWording).find("\u03b1 = {"), std::string::npos) << row.name << ": wording names no angle";
        for (double component : row.colour) EXPECT_TRUE(component >= 0.0 && component <= 1.0) << row.name;
        EXPECT_TRUE(colours.insert(row.colour).second) << row.name << " shares its colour";
    }
}

TEST(Choices, EveryCullTestHasACompleteRowWithItsOwnName) {
    expectOneNamedRowPerValue<CullTest>(cullTestDescriptors(), [](const CullTestDescriptor& row) { return row.test; }, parseCullTest);
    for (const CullTestDescriptor& row : cullTestDescriptors()) {
        EXPECT_TRUE(filled(row.glossary)) << row.name;
        EXPECT_NE(row.ownRecordRule, nullptr) << row.name;
        EXPECT_EQ(recordBytes(row.test), row.recordBytes) << row.name;
        // Only the oracle reads no record: it reads the faces themselves.
        EXPECT_EQ(row.recordBytes == 0, row.test == CullTest::Oracle) << row.name;
    }
}

TEST(Choices, EveryBuilderHasACompleteRowWithItsOwnName) {
    expectOneNamedRowPerValue<Builder>(builderDescriptors(), [](const BuilderDescriptor& row) { return row.builder; }, parseBuilder);
    for (const BuilderDescriptor& row : builderDescriptors()) EXPECT_TRUE(filled(row.explanation)) << row.name;
}

// The record tests are the four that read records of their own: each has its rule, the others none.
TEST(Choices, OwnRecordRulesBelongToTheRecordTests) {
    const std::set<CullTest> recordTests = {CullTest::MeshoptApexF32, CullTest::MeshoptSphereS8, CullTest::CadsceneBoxS8,
                                            CullTest::OctagonCompact};
    for (const CullTestDescriptor& row : cullTestDescriptors()) {
        EXPECT_EQ(readsOwnRecord(row.test), recordTests.count(row.test) == 1) << row.name;
        EXPECT_EQ(ownRecordRule(row.test).empty(), recordTests.count(row.test) == 0) << row.name;
    }
}

// Settings and schema list the tables' names, in the tables' order (help, "all", the panel).
TEST(Choices, SchemaListsExactlyTheTablesNames) {
    EXPECT_EQ(settingField("cones").names(), namesOfRows(coneDescriptors()));
    EXPECT_EQ(settingField("tests").names(), namesOfRows(cullTestDescriptors()));
    EXPECT_EQ(settingField("builder").names(), namesOfRows(builderDescriptors()));
    EXPECT_EQ(allCullTests().size(), kCullTestCount);
    EXPECT_EQ(allConeMethods().size(), kConeMethodCount);
    EXPECT_EQ(allBuilders().size(), kBuilderCount);
    for (const CullTestDescriptor& row : cullTestDescriptors())
        EXPECT_NE(settingHelp(settingField("test")).find(row.name), std::string::npos) << row.name;
    Settings settings;
    parseSetting(settingField("test"), "all", settings);
    ASSERT_EQ(settings.tests.size(), kCullTestCount);
    for (size_t row = 0; row < kCullTestCount; ++row) EXPECT_EQ(settings.tests[row], cullTestDescriptors()[row].test);
}
