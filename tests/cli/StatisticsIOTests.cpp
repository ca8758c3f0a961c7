// The statistics writers on a small hand-made RunStatistics: every key, every column, exact text.
#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "io/StatisticsIO.h"

namespace conescope {
namespace {

ViewStatistics makeView(size_t index, const Eye& eye, std::array<size_t, 7> counts, double efficiency, double ns) {
    ViewStatistics view;
    view.view = index;
    view.eye = eye;
    view.clustersCulled = counts[0];
    view.trianglesCulled = counts[1];
    view.backFacingTriangles = counts[2];
    view.frontFacingTriangles = counts[3];
    view.backFacingClusters = counts[4];
    view.missedClusters = counts[5];
    view.falseCulls = counts[6];
    view.efficiency = efficiency;
    view.nanosecondsPerCluster = ns;
    return view;
}

ClusterStatistics makeCluster(uint32_t index, size_t faces, size_t triangles, size_t vertices, double halfAngle,
                              bool cullable, size_t culled, size_t back) {
    ClusterStatistics cluster;
    cluster.cluster = index;
    cluster.faces = faces;
    cluster.triangles = triangles;
    cluster.vertices = vertices;
    cluster.halfAngleDegrees = halfAngle;
    cluster.cullable = cullable;
    cluster.timesCulled = culled;
    cluster.timesBackFacing = back;
    return cluster;
}

// Two views (one perspective, one orthographic) and two clusters of one (cone, test).
RunStatistics smallRun() {
    RunStatistics run;
    run.settings.builder = Builder::KMeans;
    run.settings.clusterCount = 2;
    run.settings.cones = {ConeMethod::Average};
    run.settings.tests = {CullTest::Sphere, CullTest::Apex};
    run.settings.meshoptConeWeight = 0.3f;
    run.settings.eye = glm::dvec3(1.0, -2.0, 0.5);
    run.meshName = "tiny.off";
    run.vertices = 4;
    run.faces = 2;
    run.triangles = 3;
    run.meshReport.openEdges = 5;
    run.meshReport.inconsistentEdges = 4;
    run.meshReport.components = 1;
    run.windingFixedFaces = 3;
    run.clusters = 2;
    run.viewCount = 2;

    CullTestStatistics result;
    result.cone = ConeMethod::Average;
    result.test = CullTest::Sphere;
    result.clustersCulled = 1;
    result.trianglesCulled = 2;
    result.backFacingTriangles = 6;
    result.missedClusters = 1;
    result.falseCulls = 0;
    result.efficiency = 1.0 / 3.0;
    result.expectedEfficiency = 0.25;
    result.uncullableClusters = 1;
    result.nanosecondsPerCluster = 12.5;
    result.bytesPerCluster = 36;
    result.testLossTriangles = 3;
    result.partitionLossTriangles = 1;
    result.meanViewEfficiency = 0.5;
    result.meanClusterTriangles = 1.5;
    result.meanClusterVertices = 3.5;
    result.meanSphereRadius = 0.75;
    result.maxSphereRadius = 1.0;
    result.cullFraction = 0.25;
    result.oracleFraction = 0.375;
    result.views.push_back(makeView(0, Eye::perspective({0.0, 0.0, 3.0}), {1, 2, 2, 1, 1, 0, 0}, 1.0, 10.0));
    result.views.push_back(makeView(1, Eye{{0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, true}, {0, 0, 4, 1, 1, 1, 0}, 0.0, 15.0));
    result.views[1].testLossTriangles = 3;
    result.views[1].partitionLossTriangles = 1;
    result.clusters.push_back(makeCluster(0, 1, 2, 4, 12.75, true, 1, 2));
    result.clusters.push_back(makeCluster(1, 1, 1, 3, 90.0, false, 0, 0));
    result.clusters[0].timesMissed = 1;
    result.clusters[0].testLossTriangles = 3;
    result.clusters[0].sphereRadius = 0.5;
    result.clusters[0].cullFraction = 0.375;
    result.clusters[0].oracleFraction = 0.5;
    result.clusters[1].partitionLossTriangles = 1;
    result.clusters[1].sphereRadius = 1.0;
    run.results.push_back(result);
    return run;
}

std::set<std::string> keysOf(const nlohmann::json& object) {
    std::set<std::string> keys;
    for (const auto& [key, value] : object.items()) keys.insert(key);
    return keys;
}

TEST(StatisticsJson, HasEveryKeyWithItsValue) {
    const nlohmann::json json = statisticsToJson(smallRun());
    EXPECT_EQ(keysOf(json), (std::set<std::string>{"conescope_version", "mesh", "settings", "clusters", "view_count", "results"}));
    EXPECT_EQ(json["conescope_version"], CONESCOPE_EXPECTED_VERSION);
    EXPECT_EQ(json["clusters"], 2);
    EXPECT_EQ(json["view_count"], 2);

    const nlohmann::json& mesh = json["mesh"];
    EXPECT_EQ(keysOf(mesh), (std::set<std::string>{"name", "vertices", "faces", "triangles", "degenerate_faces", "report",
                                                   "winding_fixed_faces"}));
    EXPECT_EQ(mesh["name"], "tiny.off");
    EXPECT_EQ(mesh["triangles"], 3);
    EXPECT_EQ(mesh["report"]["open_edges"], 5);
    EXPECT_EQ(mesh["report"]["orientable"], true);
    EXPECT_EQ(keysOf(mesh["report"]), (std::set<std::string>{"open_edges", "non_manifold_edges", "inconsistent_edges",
                                                             "duplicate_faces", "double_sided_faces", "degenerate_faces", "components", "orientable",
                                                             "inside_out_components"}));

    const nlohmann::json& settings = json["settings"];
    EXPECT_EQ(keysOf(settings),
              (std::set<std::string>{"builder", "max_vertices", "max_triangles", "clusters_target", "effort", "cluster_file",
                                     "normal_weight", "cone_weight", "cones", "tests", "sphere", "views", "distance",
                                     "orthographic", "eye", "fix_winding"}));
    EXPECT_EQ(settings["builder"], "kmeans");
    EXPECT_EQ(settings["clusters_target"], 2);
    EXPECT_EQ(settings["effort"], "balanced");  // recorded whatever the builder
    EXPECT_TRUE(settings["cluster_file"].is_null());
    EXPECT_EQ(settings["cone_weight"].get<double>(), 0.3);  // the float's shortest text, not 0.30000001...
    EXPECT_EQ(settings["cones"], nlohmann::json::array({"average"}));
    EXPECT_EQ(settings["tests"], nlohmann::json::array({"sphere", "apex"}));
    EXPECT_EQ(settings["eye"], nlohmann::json::array({1.0, -2.0, 0.5}));
    EXPECT_EQ(settings["max_vertices"], Settings{}.limits.maxVertices);

    ASSERT_EQ(json["results"].size(), 1u);
    const nlohmann::json& result = json["results"][0];
    EXPECT_EQ(keysOf(result), (std::set<std::string>{"cone", "test", "clusters_culled", "triangles_culled",
                                                     "back_facing_triangles", "missed_clusters", "false_culls",
                                                     "efficiency", "expected_efficiency", "uncullable_clusters",
                                                     "ns_per_cluster", "views", "clusters", "test_loss_triangles",
                                                     "partition_loss_triangles", "mean_view_efficiency",
                                                     "mean_cluster_triangles", "mean_cluster_vertices", "mean_sphere_radius",
                                                     "max_sphere_radius", "cull_fraction", "oracle_fraction", "bytes_per_cluster",
                                                     "engine_record", "quantisation_loss_triangles", "uncullable_share"}));
    EXPECT_EQ(result["test_loss_triangles"], 3);
    EXPECT_EQ(result["bytes_per_cluster"], 36);
    EXPECT_EQ(result["engine_record"], false);
    EXPECT_EQ(result["oracle_fraction"].get<double>(), 0.375);
    EXPECT_EQ(result["cone"], "average");
    EXPECT_EQ(result["test"], "sphere");
    EXPECT_EQ(result["efficiency"].get<double>(), 1.0 / 3.0);
    EXPECT_EQ(result["back_facing_triangles"], 6);

    ASSERT_EQ(result["views"].size(), 2u);
    const nlohmann::json& ortho = result["views"][1];
    EXPECT_EQ(keysOf(ortho), (std::set<std::string>{"view", "eye", "direction", "orthographic", "clusters_culled",
                                                    "triangles_culled", "back_facing_triangles", "front_facing_triangles",
                                                    "back_facing_clusters", "missed_clusters", "false_culls", "efficiency",
                                                    "ns_per_cluster", "test_loss_triangles", "partition_loss_triangles",
                                                    "quantisation_loss_triangles"}));
    EXPECT_EQ(ortho["partition_loss_triangles"], 1);
    EXPECT_EQ(ortho["view"], 1);
    EXPECT_EQ(ortho["orthographic"], true);
    EXPECT_EQ(ortho["direction"], nlohmann::json::array({0.0, 1.0, 0.0}));
    EXPECT_EQ(ortho["missed_clusters"], 1);
    EXPECT_EQ(result["views"][0]["eye"], nlohmann::json::array({0.0, 0.0, 3.0}));

    ASSERT_EQ(result["clusters"].size(), 2u);
    const nlohmann::json& cluster = result["clusters"][1];
    EXPECT_EQ(keysOf(cluster), (std::set<std::string>{"cluster", "faces", "triangles", "vertices", "half_angle_deg",
                                                      "cullable", "times_culled", "times_back_facing", "false_culls",
                                                      "times_missed", "test_loss_triangles", "partition_loss_triangles",
                                                      "sphere_radius", "cull_fraction", "oracle_fraction", "quantisation_loss_triangles"}));
    EXPECT_EQ(result["clusters"][0]["times_missed"], 1);
    EXPECT_EQ(result["clusters"][0]["cull_fraction"].get<double>(), 0.375);
    EXPECT_EQ(cluster["cluster"], 1);
    EXPECT_EQ(cluster["cullable"], false);
    EXPECT_EQ(cluster["half_angle_deg"].get<double>(), 90.0);
    EXPECT_EQ(result["clusters"][0]["half_angle_deg"].get<double>(), 12.75);
}

TEST(StatisticsJson, UnsetEyeAndDefaultSettings) {
    RunStatistics run;
    const nlohmann::json settings = statisticsToJson(run)["settings"];
    EXPECT_TRUE(settings["eye"].is_null());
    EXPECT_EQ(settings["views"], Settings{}.views);
    EXPECT_EQ(settings["distance"].get<double>(), Settings{}.distance);
    EXPECT_EQ(settings["builder"], toString(Settings{}.builder));
    EXPECT_EQ(settings["sphere"], toString(Settings{}.sphere));
    EXPECT_TRUE(statisticsToJson(run)["results"].empty());
}

// The file is written as it is made, without a tree: its text must still be nlohmann's layout of
// the same document, keys in order, with every level of detail.
TEST(StatisticsJson, WrittenTextIsNlohmannsLayoutOfTheSameDocument) {
    for (const StatisticsDetail detail : {StatisticsDetail{}, StatisticsDetail{false, true}, StatisticsDetail{true, false},
                                          StatisticsDetail{false, false}}) {
        const RunStatistics run = smallRun();
        std::ostringstream text;
        writeStatisticsJson(run, text, detail);
        EXPECT_EQ(text.str(), statisticsToJson(run, detail).dump(2) + "\n");
    }
    std::ostringstream empty;
    writeStatisticsJson(RunStatistics{}, empty);
    EXPECT_EQ(empty.str(), statisticsToJson(RunStatistics{}).dump(2) + "\n");
}

TEST(StatisticsJson, DetailLeavesTablesOut) {
    const nlohmann::json noViews = statisticsToJson(smallRun(), StatisticsDetail{false, true});
    EXPECT_FALSE(noViews["results"][0].contains("views"));
    EXPECT_EQ(noViews["results"][0]["clusters"].size(), 2u);
    const nlohmann::json noClusters = statisticsToJson(smallRun(), StatisticsDetail{true, false});
    EXPECT_FALSE(noClusters["results"][0].contains("clusters"));
    EXPECT_EQ(noClusters["results"][0]["views"].size(), 2u);
}

std::string csvText(const RunStatistics& run, CsvTable table) {
    std::ostringstream text;
    writeStatisticsCsv(run, text, table);
    return text.str();
}

TEST(StatisticsCsv, ExactText) {
    EXPECT_EQ(csvText(smallRun(), CsvTable::Totals),
              "cone,test,clusters,views,clusters_culled,triangles_culled,back_facing_triangles,missed_clusters,false_culls,"
              "efficiency,expected_efficiency,uncullable_clusters,ns_per_cluster,open_edges,non_manifold_edges,inconsistent_edges,"
              "duplicate_faces,double_sided_faces,degenerate_faces,components,orientable,winding_fixed_faces,inside_out_components,"
              "test_loss_triangles,partition_loss_triangles,mean_view_efficiency,mean_cluster_triangles,mean_cluster_vertices,"
              "mean_sphere_radius,max_sphere_radius,cull_fraction,oracle_fraction,bytes_per_cluster,engine_record,"
              "quantisation_loss_triangles,uncullable_share\n"
              "average,sphere,2,2,1,2,6,1,0,0.3333333333333333,0.25,1,12.5,5,0,4,0,0,0,1,1,3,0,3,1,0.5,1.5,3.5,0.75,1,0.25,0.375,36,0,0,0.5\n");
    EXPECT_EQ(csvText(smallRun(), CsvTable::Views),
              "cone,test,view,eye_x,eye_y,eye_z,direction_x,direction_y,direction_z,orthographic,clusters_culled,"
              "triangles_culled,back_facing_triangles,front_facing_triangles,back_facing_clusters,missed_clusters,false_culls,"
              "efficiency,ns_per_cluster,test_loss_triangles,partition_loss_triangles,quantisation_loss_triangles\n"
              "average,sphere,0,0,0,3,0,0,-1,0,1,2,2,1,1,0,0,1,10,0,0,0\n"
              "average,sphere,1,0,0,0,0,1,0,1,0,0,4,1,1,1,0,0,15,3,1,0\n");
    EXPECT_EQ(csvText(smallRun(), CsvTable::Clusters),
              "cone,test,cluster,faces,triangles,vertices,half_angle_deg,cullable,times_culled,times_back_facing,false_culls,"
              "times_missed,test_loss_triangles,partition_loss_triangles,sphere_radius,cull_fraction,oracle_fraction,"
              "quantisation_loss_triangles\n"
              "average,sphere,0,1,2,4,12.75,1,1,2,0,1,3,0,0.5,0.375,0.5,0\n"
              "average,sphere,1,1,1,3,90,0,0,0,0,0,0,1,1,0,0,0\n");
}

TEST(StatisticsCsv, TablesGoBesideTheTotalsFile) {
    using Files = std::vector<std::pair<CsvTable, std::string>>;
    EXPECT_EQ(csvTableFiles("out/run.csv"),
              (Files{{CsvTable::Totals, "out/run.csv"}, {CsvTable::Views, "out/run.views.csv"}, {CsvTable::Clusters, "out/run.clusters.csv"}}));
    EXPECT_EQ(csvTableFiles("RUN.CSV", StatisticsDetail{false, true}),
              (Files{{CsvTable::Totals, "RUN.CSV"}, {CsvTable::Clusters, "RUN.clusters.csv"}}));
    EXPECT_EQ(csvTableFiles("table", StatisticsDetail{false, false}), (Files{{CsvTable::Totals, "table"}}));
    EXPECT_EQ(parseCsvTable("views"), CsvTable::Views);
    EXPECT_THROW(parseCsvTable("sections"), std::invalid_argument);
}

// The CSV headers are the JSON keys: a column cannot exist in one format only.
TEST(StatisticsCsv, ColumnsAreTheJsonKeys) {
    const RunStatistics run = smallRun();
    const nlohmann::json result = statisticsToJson(run)["results"][0];
    std::vector<std::set<std::string>> headers;
    for (CsvTable table : {CsvTable::Totals, CsvTable::Views, CsvTable::Clusters}) {
        const std::string text = csvText(run, table);
        std::set<std::string> columns;
        std::istringstream cells(text.substr(0, text.find('\n')));
        for (std::string cell; std::getline(cells, cell, ',');) columns.insert(cell);
        headers.push_back(columns);
    }

    std::set<std::string> totals = keysOf(result);
    totals.erase("views");
    totals.erase("clusters");
    totals.insert({"clusters", "views"});  // the run's counts, repeated on every row
    std::set<std::string> report = keysOf(statisticsToJson(run)["mesh"]["report"]);
    totals.insert(report.begin(), report.end());  // the run's mesh check, repeated on every row
    totals.insert("winding_fixed_faces");
    EXPECT_EQ(headers[0], totals);

    std::set<std::string> views = keysOf(result["views"][0]);
    views.erase("eye");
    views.erase("direction");
    views.insert({"cone", "test", "eye_x", "eye_y", "eye_z", "direction_x", "direction_y", "direction_z"});
    EXPECT_EQ(headers[1], views);

    std::set<std::string> clusters = keysOf(result["clusters"][0]);
    clusters.insert({"cone", "test"});
    EXPECT_EQ(headers[2], clusters);
}

}  // namespace
}  // namespace conescope
