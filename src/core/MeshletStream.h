// meshoptimizer's meshlets of a mesh (buildMeshoptMeshlets), made on a thread of their own and
// handed over in parts as they are made, so that the optimized builder refines the first parts on
// one core while the builder places the last triangles on the other (ClusterOptimizer.h). The
// builder sweeps the surface meshlet by meshlet, so consecutive meshlets make a part of the mesh:
// part i holds the meshlets closed once placedThroughPart(i - 1) triangles were placed and before
// placedThroughPart(i) were; a face goes with the meshlet of its first placed fan triangle (the
// lowest, as buildMeshoptMeshlets does). Where the linked meshoptimizer is not the one reproduced
// (MeshoptMeshlets.h), the library builds them and they come as one part.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "CoreAffinity.h"
#include "Mesh.h"
#include "MeshoptMeshlets.h"
#include "Partition.h"

namespace conescope {

// One part: its faces in ascending order, and each one's meshlet numbered from 0 within the part.
struct MeshletPart {
    std::vector<uint32_t> faces;
    Partition meshlets;  // clusterOfFace[k] is the meshlet of faces[k]
};

// How many parts the meshlets of a mesh of this many faces come in: one below 2,048 faces, then
// shares of about 640 faces each (at least two, at most 64) with the last share in two halves.
// Fixed by the face count alone, so the partitions do not depend on the machine.
size_t meshletPartsFor(size_t faceCount);

// How many of `triangles` placed triangles close part `part` of `partCount` (2 or more): equal
// shares, the last share in two halves, so that the last part, which only begins once the builder
// is done, is short. The last part ends at `triangles`.
size_t placedThroughPart(size_t part, size_t partCount, size_t triangles);

// The partition of faces buildMeshoptMeshlets gives for meshlets made from fanTriangles(mesh).
Partition facesOfMeshlets(const Mesh& mesh, const MeshoptMeshlets& meshlets);

class MeshletStream {
public:
    // Starts meshoptimizer's builder at cone weight 1 on a thread of its own, in `partCount` parts
    // (meshletPartsFor). The limits must be ones meshoptimizer takes.
    MeshletStream(std::shared_ptr<const Mesh> mesh, const MeshletLimits& limits, size_t partCount);
    // Stops the builder at its next meshlet if it still runs, and waits for its thread.
    ~MeshletStream();
    MeshletStream(const MeshletStream&) = delete;
    MeshletStream& operator=(const MeshletStream&) = delete;

    const Mesh& mesh() const { return *mesh_; }
    const MeshletLimits& limits() const { return limits_; }
    size_t partCount() const { return parts_.size(); }

    // Part i, once it is made (waits for it; rethrows what the builder threw).
    const MeshletPart& part(size_t i);
    // Every part made: the number of meshlets, and buildMeshoptMeshlets' partition.
    size_t meshletCount();
    Partition whole();

    // Runs `work` on the stream's thread once every meshlet is made (at once if they are), so that
    // the core it ran on goes on with what the meshlets are for; finishWork waits for it and
    // rethrows what it threw. At most one piece of work.
    void runAfterwards(std::function<void()> work);
    void finishWork();

    // While the builder runs it is kept off the core its creator ran on; a thread that refines the
    // parts holds that core meanwhile (CoreAffinity.h), until every part is made.
    CoreHold holdConsumerCore() const;
    bool allPartsMade();

private:
    void build();
    void waitFor(size_t partsMade);
    // The fan triangles meshoptimizer is given: the mesh's own corners when every face is a triangle.
    const uint32_t* triangleIndices() const;
    size_t triangleIndexCount() const;

    std::shared_ptr<const Mesh> mesh_;
    MeshletLimits limits_;
    bool allTriangles_ = false;
    std::vector<uint32_t> indices_, faceOfTriangle_;  // fan triangles and their faces, unless allTriangles_
    MeshoptMeshlets meshlets_;
    // Per part, as the builder's thread hands it over: (face, meshlet from the part's first) in the
    // order placed; sorted into parts_[i] by the first to ask for it, off the builder's thread.
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> handedOver_;
    std::vector<MeshletPart> parts_;
    std::unique_ptr<std::once_flag[]> sorted_;
    std::vector<uint8_t> claimed_;  // per face: its part is known

    std::mutex mutex_;
    std::condition_variable changed_;
    size_t partsMade_ = 0;
    bool stopping_ = false, working_ = false, workDone_ = false;
    std::atomic<bool> workFinished_{false};  // workDone_, readable without the lock (finishWork watches it)
    std::function<void()> work_;
    std::exception_ptr buildError_, workError_;
    CoreSplit cores_;
    CoreHold builderHold_;
    std::thread thread_;
};

}  // namespace conescope
