#include "BuildPartition.h"

#include <stdexcept>

#include "FileBuilder.h"
#include "Statistics.h"
#include "meshopt/Meshopt.h"

namespace conescope {

namespace {

Partition fromClusterFile(const Mesh& mesh, const Settings& settings) {
    const ClusterIdFile* file = settings.clusterIds.get();
    if (!file || file->path != settings.clusterFile)
        throw std::logic_error(settings.clusterFile + ": cluster file not read (io: withClusterIds for ids, readClusterFileOf for meshlets)");
    if (!file->error.empty()) throw std::runtime_error(file->error);
    return partitionFromIds(file->ids, mesh.faceCount(), settings.clusterFile);
}

}  // namespace

bool startsFromMeshoptMeshlets(const Settings& settings) {
    return settings.builder == Builder::Optimized && startsFromMeshoptMeshlets(settings.limits, settings.effort);
}

Partition buildPartition(const Mesh& mesh, const FaceGeometry& faces, const Settings& settings,
                         const ProgressCallback& progress, MeshletStream* meshlets, const PartClusters& partDone,
                         BestEffortChoice* choice) {
    if (choice) *choice = {};
    switch (settings.builder) {
        case Builder::Meshlet: return buildMeshlets(mesh, faces, settings.limits, settings.normalWeight);
        case Builder::KMeans: {
            const size_t target = settings.clusterCount > 0
                                      ? settings.clusterCount
                                      : (triangleCount(mesh) + settings.limits.maxTriangles - 1) / settings.limits.maxTriangles;
            return buildKMeans(mesh, faces, target, settings.normalWeight);
        }
        case Builder::Meshopt: return buildMeshoptMeshlets(mesh, settings.limits, settings.meshoptConeWeight);
        case Builder::Optimized: {
            // The best effort keeps whichever of its two searches culls more as this run measures it.
            const PartitionMeasure shown = [&](const Partition& partition) { return shownEfficiency(mesh, faces, partition, settings); };
            return buildOptimizedClusters(mesh, faces, settings.limits, settings.clusterCount, progress, settings.effort, meshlets,
                                          partDone, settings.conesPerCluster, choice, shown);
        }
        case Builder::File: {
            // A meshlet file read with the mesh, an id file read into the settings, or the mesh's own.
            if (const FileClusters* meshlets = meshletClusters(mesh, settings.clusterFile)) return {meshlets->clusterOfFace, meshlets->clusterCount};
            if (!settings.clusterFile.empty()) return fromClusterFile(mesh, settings);
            return ownClusters(mesh);
        }
    }
    throw std::invalid_argument("unknown builder");
}

}  // namespace conescope
