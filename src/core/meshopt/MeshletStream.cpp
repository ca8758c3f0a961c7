// meshoptimizer's meshlets made on a thread of their own and handed over in parts (Meshopt.h).
#include "Meshopt.h"
#include "Reproduction.h"

#include <algorithm>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>

namespace conescope {

namespace {

// Below this many faces the meshlets come whole; above, in two parts at least, of about
// kFacesPerPart faces. Smaller parts let the second core start sooner and leave less to do once
// the builder is done, but refine within more borders; the last share comes in two halves, so the
// part that only begins once the builder is done is short. The sizes tried are in
// docs/benchmarks.md ("Why the constants are what they are").
constexpr size_t kPartsFromFaces = size_t(1) << 11;
constexpr size_t kFacesPerPart = 640;
constexpr size_t kMostShares = 64;

// (face, meshlet) pairs by face, each face once: a radix sort on the face's bytes, as many as the
// face count needs (two below 65,536 faces), linear where a comparison sort was a tenth of a
// small mesh's preparation.
void sortByFace(std::vector<std::pair<uint32_t, uint32_t>>& pairs, uint32_t faceCount) {
    std::vector<std::pair<uint32_t, uint32_t>> other(pairs.size());
    for (uint32_t shift = 0; shift < 32 && (faceCount - 1) >> shift != 0; shift += 8) {
        uint32_t starts[257] = {};
        for (const auto& pair : pairs) ++starts[((pair.first >> shift) & 0xff) + 1];
        for (int d = 0; d < 256; ++d) starts[d + 1] += starts[d];
        for (const auto& pair : pairs) other[starts[(pair.first >> shift) & 0xff]++] = pair;
        pairs.swap(other);
    }
}

}  // namespace

size_t meshletPartsFor(size_t faceCount) {
    if (faceCount < kPartsFromFaces) return 1;
    return std::clamp<size_t>((faceCount + kFacesPerPart - 1) / kFacesPerPart, 2, kMostShares) + 1;
}

size_t placedThroughPart(size_t part, size_t partCount, size_t triangles) {
    const size_t shares = partCount - 1;
    if (part + 1 >= partCount) return triangles;
    if (part + 1 < shares) return (part + 1) * triangles / shares;
    return (2 * shares - 1) * triangles / (2 * shares);
}

// The stream's thread and what it shares with the threads that take the parts.
struct MeshletStream::State {
    State(std::shared_ptr<const Mesh> mesh, const MeshletLimits& limits, size_t partCount);
    ~State();

    void build();
    void waitFor(size_t partsMade);
    // The fan triangles meshoptimizer is given: the mesh's own corners when every face is a triangle.
    const uint32_t* triangleIndices() const;
    size_t triangleIndexCount() const;

    std::shared_ptr<const Mesh> mesh_;
    MeshletLimits limits_;
    bool reproduced_;  // else the library builds them, as one part
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
    bool stopping_ = false, workDone_ = false;
    bool workAsked_ = false;  // a piece of work was handed over and not yet finished (finishWork)
    std::function<void()> work_;
    std::exception_ptr buildError_, workError_;
    CoreSplit cores_;
    CoreHold builderHold_;
    std::thread thread_;
};

MeshletStream::State::State(std::shared_ptr<const Mesh> mesh, const MeshletLimits& limits, size_t partCount)
    : mesh_(std::move(mesh)),
      limits_(limits),
      reproduced_(reproducesLinkedMeshopt()),
      handedOver_(reproduced_ ? std::max<size_t>(partCount, 1) : 1),
      parts_(handedOver_.size()),
      sorted_(new std::once_flag[handedOver_.size()]),
      cores_(splitCores()) {
    // The builder is started off this thread's core: a new thread would wait for this core while
    // another idles. The lock keeps it from releasing its hold before the hold is made.
    std::unique_lock<std::mutex> starting(mutex_);
    thread_ = std::thread([this] {
        { std::lock_guard<std::mutex> started(mutex_); }
        try {
            build();
        } catch (...) {
            std::lock_guard<std::mutex> lock(mutex_);
            buildError_ = std::current_exception();
            changed_.notify_all();
        }
        builderHold_.release();
        // Then each piece of work handed over, until the stream is dropped with none waiting.
        std::unique_lock<std::mutex> lock(mutex_);
        for (;;) {
            changed_.wait(lock, [this] { return stopping_ || work_; });
            if (!work_) return;
            const std::function<void()> work = std::move(work_);
            work_ = nullptr;
            lock.unlock();
            std::exception_ptr error;
            try {
                work();
            } catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            workError_ = error;
            workDone_ = true;
            changed_.notify_all();
        }
    });
    builderHold_ = CoreHold(thread_.native_handle(), cores_.others);
}

const uint32_t* MeshletStream::State::triangleIndices() const { return allTriangles_ ? mesh_->faceVertices.data() : indices_.data(); }

size_t MeshletStream::State::triangleIndexCount() const { return allTriangles_ ? mesh_->faceVertices.size() : indices_.size(); }

MeshletStream::State::~State() {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
        changed_.notify_all();
    }
    thread_.join();
}

void MeshletStream::State::build() {
    const Mesh& mesh = *mesh_;
    if (!reproduced_) {  // the library: everything at once, one part
        MeshletPart all;
        all.meshlets = meshoptLibraryMeshlets(mesh, limits_, 1.0f);
        for (uint32_t f = 0; f < mesh.faceCount(); ++f) all.faces.push_back(f);
        meshlets_.count = all.meshlets.clusterCount;
        std::lock_guard<std::mutex> lock(mutex_);
        parts_[0] = std::move(all);
        partsMade_ = 1;
        changed_.notify_all();
        return;
    }
    requireMeshoptLimits(limits_);
    // A mesh of triangles is its own fan triangulation: no copy.
    allTriangles_ = true;
    for (size_t f = 0; f < mesh.faceCount() && allTriangles_; ++f) allTriangles_ = mesh.faceSize(f) == 3;
    if (!allTriangles_) indices_ = fanTriangles(mesh);
    const size_t triangles = triangleIndexCount() / 3;
    if (!allTriangles_) {
        faceOfTriangle_.reserve(triangles);
        for (uint32_t f = 0; f < mesh.faceCount(); ++f) faceOfTriangle_.insert(faceOfTriangle_.end(), mesh.faceSize(f) - 2, f);
    }
    auto faceOf = [&](uint32_t t) { return allTriangles_ ? t : faceOfTriangle_[t]; };
    claimed_.assign(mesh.faceCount(), 0);

    const size_t partCount = parts_.size();
    size_t nextPart = 0, partBegin = 0, meshletBegin = 0;
    // Part nextPart takes the triangles placed since the last part, in the meshlets closed since;
    // the last one also the faces the library left unplaced (coordinates near the float range),
    // together in a cluster of their own.
    auto handOver = [&](size_t placedEnd, size_t meshletEnd, bool last) {
        std::vector<std::pair<uint32_t, uint32_t>> faceMeshlets;
        for (size_t k = partBegin; k < placedEnd; ++k) {
            const uint32_t t = meshlets_.placementOrder[k], f = faceOf(t);
            if (claimed_[f]) continue;
            claimed_[f] = 1;
            faceMeshlets.emplace_back(f, meshlets_.meshletOfTriangle[t] - uint32_t(meshletBegin));
        }
        for (uint32_t f = 0; last && f < mesh.faceCount(); ++f)
            if (!claimed_[f]) claimed_[f] = 1, faceMeshlets.emplace_back(f, uint32_t(meshletEnd - meshletBegin));
        partBegin = placedEnd, meshletBegin = meshletEnd;
        std::lock_guard<std::mutex> lock(mutex_);
        handedOver_[nextPart++] = std::move(faceMeshlets);
        if (last) nextPart = parts_.size();  // parts no meshlet reached stay empty
        partsMade_ = nextPart;
        changed_.notify_all();
    };
    const MeshletClosed closed = [&](size_t closedMeshlets, size_t placed) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (stopping_) return false;
        }
        while (nextPart + 1 < partCount && placed >= placedThroughPart(nextPart, partCount, triangles))
            handOver(placed, closedMeshlets, false);
        return true;
    };
    reproduceMeshoptMeshlets(meshlets_, triangleIndices(), triangleIndexCount(), &mesh.positions[0].x, mesh.positions.size(),
                             sizeof(glm::vec3), limits_.maxVertices, limits_.maxTriangles, 1.0f, closed, cores_.current);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopping_) return;
    }
    handOver(meshlets_.placementOrder.size(), meshlets_.count, true);
}

void MeshletStream::State::waitFor(size_t partsMade) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return partsMade_ >= partsMade || buildError_; });
    if (partsMade_ < partsMade) std::rethrow_exception(buildError_);
}

MeshletStream::MeshletStream(std::shared_ptr<const Mesh> mesh, const MeshletLimits& limits, size_t partCount)
    : state_(std::make_unique<State>(std::move(mesh), limits, partCount)) {}

MeshletStream::~MeshletStream() = default;

const Mesh& MeshletStream::mesh() const { return *state_->mesh_; }

const MeshletLimits& MeshletStream::limits() const { return state_->limits_; }

size_t MeshletStream::partCount() const { return state_->parts_.size(); }

const MeshletPart& MeshletStream::part(size_t i) {
    State& s = *state_;
    s.waitFor(i + 1);
    std::call_once(s.sorted_[i], [&] {
        if (!s.reproduced_) return;  // the library's one part is made whole
        std::vector<std::pair<uint32_t, uint32_t>>& faceMeshlets = s.handedOver_[i];
        sortByFace(faceMeshlets, uint32_t(s.mesh_->faceCount()));
        std::vector<uint32_t> ids;
        ids.reserve(faceMeshlets.size());
        for (const auto& [f, meshlet] : faceMeshlets) s.parts_[i].faces.push_back(f), ids.push_back(meshlet);
        s.parts_[i].meshlets = renumberClusters(std::move(ids));
        faceMeshlets = {};
    });
    return s.parts_[i];
}

size_t MeshletStream::meshletCount() {
    size_t count = 0;
    for (size_t i = 0; i < partCount(); ++i) count += part(i).meshlets.clusterCount;
    return count;
}

Partition MeshletStream::whole() {
    state_->waitFor(partCount());
    if (!state_->reproduced_) return state_->parts_[0].meshlets;
    return facesOfMeshlets(*state_->mesh_, state_->meshlets_);
}

CoreHold MeshletStream::holdConsumerCore() const { return CoreHold(thisThread(), state_->cores_.current); }

bool MeshletStream::allPartsMade() {
    std::lock_guard<std::mutex> lock(state_->mutex_);
    return state_->partsMade_ >= partCount() || state_->buildError_;
}

void MeshletStream::runAfterwards(std::function<void()> work) {
    std::lock_guard<std::mutex> lock(state_->mutex_);
    State& s = *state_;
    // One piece at a time: a second before finishWork would wait behind the first, or never run.
    if (s.workAsked_) throw std::logic_error("MeshletStream::runAfterwards: the last piece of work was not finished (finishWork)");
    s.work_ = std::move(work);
    s.workAsked_ = true;
    s.workDone_ = false;
    s.changed_.notify_all();
}

void MeshletStream::finishWork() {
    State& s = *state_;
    std::unique_lock<std::mutex> lock(s.mutex_);
    if (!s.workAsked_) return;
    s.changed_.wait(lock, [&s] { return s.workDone_; });
    s.workAsked_ = false;
    if (s.workError_) std::rethrow_exception(std::exchange(s.workError_, nullptr));
}

}  // namespace conescope
