// The settings schema: every field reads back what it writes, refuses what is outside its domain,
// and says which builders use it and what a change of it makes stale.
#include <gtest/gtest.h>

#include <set>

#include "core/SettingsSchema.h"

using namespace conescope;

namespace {

// Settings with every field away from its default.
Settings unusualSettings() {
    Settings settings;
    settings.builder = Builder::KMeans;
    settings.limits = {100, 200};
    settings.clusterCount = 17;
    settings.effort = Effort::Best;
    settings.clusterFile = "ids.txt";
    settings.normalWeight = 2.5;
    settings.meshoptConeWeight = 0.3f;
    settings.cones = {ConeMethod::Average, ConeMethod::Meshopt};
    settings.tests = {CullTest::Sphere, CullTest::Oracle};
    settings.sphere = SphereMethod::Ritter;
    settings.views = 9;
    settings.distance = 4.25;
    settings.orthographic = true;
    settings.eye = glm::dvec3(-1.0, 0.5, 1e-3);
    settings.fixWinding = true;
    return settings;
}

}  // namespace

TEST(SettingsSchema, EveryFieldReadsBackWhatItWrites) {
    for (const Settings& original : {Settings{}, unusualSettings()}) {
        Settings copy;
        for (const SettingField& field : settingFields()) parseSetting(field, settingText(field, original), copy);
        for (const SettingField& field : settingFields())
            EXPECT_TRUE(field.value(copy) == field.value(original)) << field.key << ": " << settingText(field, copy);
    }
    // Every member of Settings has a field: a copy made through the schema is a different run only
    // where the schema says so.
    EXPECT_FALSE(firstStaleStage(unusualSettings(), [] {
        Settings copy;
        for (const SettingField& field : settingFields()) parseSetting(field, settingText(field, unusualSettings()), copy);
        return copy;
    }()));
}

TEST(SettingsSchema, KeysAndFlagsAreUniqueAndFindable) {
    std::set<std::string> keys, flags;
    for (const SettingField& field : settingFields()) {
        EXPECT_TRUE(keys.insert(field.key).second) << field.key;
        EXPECT_TRUE(flags.insert(field.flag).second) << field.flag;
        EXPECT_EQ(&settingField(field.key), &field);
        EXPECT_EQ(&settingField(field.flag), &field);
        EXPECT_FALSE(settingHelp(field).empty());
    }
    EXPECT_EQ(settingFields().size(), 17u);
    EXPECT_THROW(settingField("no-such-setting"), std::out_of_range);
}

TEST(SettingsSchema, ValuesOutsideTheDomainAreRefusedNamingTheFlag) {
    Settings settings;
    auto refused = [&](const std::string& key, const std::string& text) {
        try {
            parseSetting(settingField(key), text, settings);
        } catch (const std::invalid_argument& error) {
            return std::string(error.what()).rfind("--" + settingField(key).flag + ": ", 0) == 0;
        }
        return false;
    };
    EXPECT_TRUE(refused("max_vertices", "2"));   // a cluster needs a triangle
    EXPECT_TRUE(refused("max_vertices", "0"));
    EXPECT_TRUE(refused("max_triangles", "0"));
    EXPECT_TRUE(refused("views", "0"));
    EXPECT_TRUE(refused("views", "-3"));
    EXPECT_TRUE(refused("views", "2.5"));
    EXPECT_TRUE(refused("distance", "0"));
    EXPECT_TRUE(refused("distance", "nan"));
    EXPECT_TRUE(refused("cone_weight", "1.5"));
    EXPECT_TRUE(refused("normal_weight", "-1"));
    EXPECT_TRUE(refused("builder", "fastest"));
    EXPECT_TRUE(refused("cones", "minimal,widest"));
    EXPECT_TRUE(refused("cones", ""));
    EXPECT_TRUE(refused("eye", "1,2"));
    EXPECT_TRUE(refused("eye", "1,2,inf"));
    EXPECT_TRUE(refused("orthographic", "maybe"));
    EXPECT_EQ(settings.limits.maxVertices, Settings{}.limits.maxVertices) << "a refused value changes nothing";

    parseSetting(settingField("cone"), "all", settings);
    EXPECT_EQ(settings.cones, allConeMethods());
    parseSetting(settingField("test"), "sphere,all,sphere", settings);
    EXPECT_EQ(settings.tests.front(), CullTest::Sphere);
    EXPECT_EQ(settings.tests.size(), allCullTests().size()) << "repeats are dropped, the first mention kept";
    parseSetting(settingField("max-verts"), "3", settings);
    EXPECT_EQ(settings.limits.maxVertices, 3u);
}

TEST(SettingsSchema, FieldsMatterToTheBuildersThatUseThem) {
    Settings settings;
    auto matters = [&](const std::string& key, Builder builder) {
        settings.builder = builder;
        return fieldMatters(settingField(key), settings);
    };
    EXPECT_TRUE(matters("max_vertices", Builder::Optimized));
    EXPECT_FALSE(matters("max_vertices", Builder::KMeans));
    EXPECT_FALSE(matters("normal_weight", Builder::Optimized));
    EXPECT_TRUE(matters("normal_weight", Builder::Meshlet));
    EXPECT_TRUE(matters("cone_weight", Builder::Meshopt));
    EXPECT_FALSE(matters("cone_weight", Builder::Meshlet));
    EXPECT_TRUE(matters("cluster_file", Builder::File));
    EXPECT_FALSE(matters("clusters_target", Builder::File));
    EXPECT_TRUE(matters("cones", Builder::File));
    // kmeans takes its count from the triangle limit only when no count is given.
    settings.clusterCount = 0;
    EXPECT_TRUE(matters("max_triangles", Builder::KMeans));
    settings.clusterCount = 12;
    EXPECT_FALSE(matters("max_triangles", Builder::KMeans));
}

TEST(SettingsSchema, AChangeMakesItsStageAndLaterOnesStale) {
    const Settings base;
    auto staleAfter = [&](const std::string& key, const std::string& text, Settings before = Settings{}) {
        Settings after = before;
        parseSetting(settingField(key), text, after);
        return firstStaleStage(before, after);
    };
    EXPECT_EQ(staleAfter("fix_winding", "true"), Stage::PreparedMesh);
    EXPECT_EQ(staleAfter("builder", "meshlet"), Stage::Clusters);
    EXPECT_EQ(staleAfter("max_triangles", "64"), Stage::Clusters);
    EXPECT_EQ(staleAfter("cones", "average"), Stage::Bounds);
    EXPECT_EQ(staleAfter("sphere", "ritter"), Stage::Bounds);
    EXPECT_EQ(staleAfter("tests", "sphere"), Stage::Measurement);
    EXPECT_EQ(staleAfter("views", "7"), Stage::Measurement);
    EXPECT_EQ(staleAfter("tests", "octagon"), std::nullopt) << "the same value is no change";
    EXPECT_EQ(staleAfter("normal_weight", "3"), std::nullopt) << "the optimized builder does not use it";
    Settings kmeans = base;
    kmeans.builder = Builder::KMeans;
    kmeans.clusterCount = 12;
    EXPECT_EQ(staleAfter("max_triangles", "64", kmeans), std::nullopt);
    EXPECT_EQ(staleAfter("clusters_target", "13", kmeans), Stage::Clusters);
    // The best effort keeps whichever of its two searches culls more as the run measures it: the
    // measure's settings choose its partition too.
    Settings best = base;
    best.effort = Effort::Best;
    for (const auto& [key, text] : std::vector<std::pair<std::string, std::string>>{
             {"views", "7"}, {"distance", "5"}, {"tests", "apex"}, {"cones", "minimal"}, {"sphere", "ritter"}, {"orthographic", "true"}})
        EXPECT_EQ(staleAfter(key, text, best), Stage::Clusters) << key;
    EXPECT_EQ(staleAfter("fix_winding", "true", best), Stage::PreparedMesh);
    EXPECT_EQ(staleAfter("eye", "1,2,3", best), Stage::Measurement) << "an eye looks at the orbit's partition";
}
