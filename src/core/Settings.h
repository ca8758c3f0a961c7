// One value that says how a run is made: what the CLI parses, what the GUI's panel edits and what
// the statistics record, so a GUI export and a CLI run with the same settings give the same file.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "Choices.h"
#include "ClusterBounds.h"
#include "Culling.h"
#include "Effort.h"
#include "Partition.h"

namespace conescope {

struct Settings {
    // Defaults are the best measured combination (docs/benchmarks.md): optimized clusters, exact
    // minimal cones, the octagon test.
    Builder builder = Builder::Optimized;
    MeshletLimits limits;
    Effort effort = Effort::Balanced; // how long the optimized builder searches
    size_t clusterCount = 0;          // kmeans target (0 = triangles / maxTriangles); optimized budget (0 = defaultClusterBudget)
    std::string clusterFile;          // file builder: text file of ids; empty = the mesh's cluster_id array
    std::shared_ptr<const ClusterIdFile> clusterIds;  // clusterFile as io read it (io/ClusterIdFile.h)
    double normalWeight = 1.0;        // meshlet / kmeans preference for narrow cones
    float meshoptConeWeight = 1.0f;   // meshopt builder's cone_weight
    std::vector<ConeMethod> cones{kDefaultCone};
    std::vector<CullTest> tests{kDefaultTest};
    SphereMethod sphere = kDefaultSphere;
    uint32_t conesPerCluster = 1;     // K cones per cluster measured beside the one cone (1: none); 1, 2, 4 or 8
    size_t views = kStandardOrbitViews;
    double distance = kStandardOrbitDistance;
    bool orthographic = false;
    std::optional<glm::dvec3> eye;    // a single eye instead of the orbit
    bool fixWinding = false;          // make face winding consistent before culling (orientable parts)
};

std::string toString(Builder);
std::string toString(ConeMethod);
std::string toString(SphereMethod);
std::string toString(Effort);
// Throw std::invalid_argument listing the accepted names.
Builder parseBuilder(const std::string&);
ConeMethod parseConeMethod(const std::string&);
CullTest parseCullTest(const std::string&);
SphereMethod parseSphereMethod(const std::string&);
Effort parseEffort(const std::string&);
const std::vector<ConeMethod>& allConeMethods();
const std::vector<CullTest>& allCullTests();
const std::vector<Builder>& allBuilders();
const std::vector<SphereMethod>& allSphereMethods();
const std::vector<Effort>& allEfforts();

// The first cone method and cull test of the settings: the ones the window shows and a run's
// summary heads with.
ConeMethod displayedCone(const Settings& settings);
CullTest displayedTest(const Settings& settings);

// The views a run uses: the single eye if set, else the standard orbit around the world AABB.
std::vector<Eye> viewsFor(const Settings& settings, const Aabb& worldBox);
// The standard orbit of the settings (views, distance, projection), ignoring settings.eye.
std::vector<Eye> orbitOf(const Settings& settings, const Aabb& worldBox);

}  // namespace conescope
