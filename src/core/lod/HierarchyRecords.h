// A cluster LOD hierarchy as an engine ships it: every level's clusters as meshoptimizer's meshlet
// arrays (level after level in one set), and per cluster and per group the fields meshoptimizer's
// clusterlod keeps (level, group, the group it refines, bounds and error). io's MeshletFiles.h reads
// and writes them as JSON; docs/user/engine-meshlets.md, "Cluster LOD hierarchies", has the layout.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "core/MeshletArrays.h"
#include "core/lod/ClusterHierarchy.h"

namespace conescope {

struct HierarchyClusterRecord {
    uint32_t level = 0;
    int64_t group = -1;    // index into HierarchyRecords::groups: the group it is simplified in (-1 at the top)
    int64_t refined = -1;  // the group of the level below it was made from (-1 at level 0)
    Sphere sphere;         // its own error is measured from here
    double error = 0.0;
};

struct HierarchyGroupRecord {
    uint32_t level = 0;    // the level of its members
    Sphere sphere;         // holds its members' spheres
    double error = 0.0;    // at least its members' errors
};

struct HierarchyRecords {
    MeshletArrays arrays;  // meshlet m is clusters[m]; vertex ids index the mesh file's vertices
    std::vector<HierarchyClusterRecord> clusters;
    std::vector<HierarchyGroupRecord> groups;
};

// Thrown for records that do not make a hierarchy of the mesh; what() names the cluster or group.
class HierarchyError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The hierarchy's records; `fileVertexOf` maps the mesh's vertices to the file's (empty: the same).
HierarchyRecords hierarchyRecordsOf(const ClusterHierarchy& hierarchy, const std::vector<uint32_t>& fileVertexOf);

// The hierarchy the records describe on `prepared` (vertex ids through its mesh's fileVertices), its
// clusters bounded with the cone and sphere of `settings`. Checks what the cut needs: levels from 0
// without a gap, groups of one level with members and clusters made from them, every cluster below
// the top in a group, errors and spheres that hold their members'. Level 0 is the mesh itself, its
// polygons whole, when its triangles are the faces' fans (as written from a built hierarchy), else a
// mesh of its triangles like the levels above. Throws HierarchyError.
ClusterHierarchy hierarchyFromRecords(const PreparedMesh& prepared, const HierarchyRecords& records, const Settings& settings);

}  // namespace conescope
