// The optimized builder's entry points (declared in core/ClusterOptimizer.h): the budget, one run
// of the steps (Steps.h) on a mesh, and the large-mesh path that runs them on parts at once.
#include "core/ClusterOptimizer.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <utility>
#include <vector>

#include "Parts.h"
#include "Runs.h"
#include "State.h"
#include "Steps.h"
#include "core/Parallel.h"

namespace conescope {

namespace {

// The default budget fills clusters to this fraction of what a round patch holds: at 64/124 that
// is 84 triangles, about what meshoptimizer's builder reaches at cone weight 1 (84-87 on the CGAL
// meshes) and a budget the reduction reaches on all of them.
constexpr double kDefaultFill = 0.68;
SearchPlan planFor(Effort effort) {
    switch (effort) {
        case Effort::Fast: return {false, 0, 0, 0.0, 0};
        case Effort::Balanced: return {false, 2, 2, std::numeric_limits<double>::infinity(), 1, kGrowWhereUncullable, true, kOnePartSweepVisits};
        case Effort::Best: break;
    }
    return {true, 100, 8, 5.0e6, 100};
}

SearchPlan planAt(Effort effort, const MeshletLimits& limits) {
    SearchPlan plan = planFor(effort);
    plan.meshoptLimits = meshoptTakesLimits(limits);
    return plan;
}

// The fast levels start from meshoptimizer's meshlets where it takes the limits.
bool startsFromMeshlets(const SearchPlan& plan) { return !plan.growthStart && plan.meshoptLimits; }


// defaultClusterBudget, with whether meshoptimizer takes the limits known.
size_t defaultBudget(const Mesh& mesh, const MeshletLimits& limits, bool meshoptLimits) {
    // meshoptimizer's own count at cone weight 1: the fair comparison at defaults.
    if (meshoptLimits && mesh.faceCount() > 0) return meshoptMeshletCount(mesh, limits, 1.0f);
    const double roundPatch = double(std::min(limits.maxTriangles, 2 * limits.maxVertices));
    const double perCluster = std::max(1.0, kDefaultFill * roundPatch);
    return std::max<size_t>(1, size_t(std::ceil(double(triangleCount(mesh)) / perCluster)));
}

}  // namespace

size_t defaultClusterBudget(const Mesh& mesh, const MeshletLimits& limits) {
    return defaultBudget(mesh, limits, meshoptTakesLimits(limits));
}

size_t fewestClustersWithin(const Mesh& mesh, const MeshletLimits& limits) {
    std::vector<bool> used(mesh.positions.size(), false);
    size_t usedVertices = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 0; k < mesh.faceSize(f); ++k) {
            const uint32_t v = mesh.faceBegin(f)[k];
            if (!used[v]) used[v] = true, ++usedVertices;
        }
    auto atLeast = [](size_t count, size_t perCluster) { return (count + perCluster - 1) / std::max<size_t>(perCluster, 1); };
    return std::max(atLeast(triangleCount(mesh), limits.maxTriangles), atLeast(usedVertices, limits.maxVertices));
}

size_t annealingSweepsFor(Effort effort, size_t faceCount, size_t meshletParts) {
    const SearchPlan plan = planFor(effort);
    if (meshletParts == 1 && plan.onePartSweepVisits > 0.0)
        return std::clamp<size_t>(size_t(plan.onePartSweepVisits / double(std::max<size_t>(faceCount, 1))), plan.minSweeps, kOnePartSweepsAtMost);
    const size_t sweeps = annealingSweeps(plan, faceCount);
    return meshletParts > 1 ? std::min(sweeps, plan.sweepsPerPart) : sweeps;
}

bool startsFromMeshoptMeshlets(const MeshletLimits& limits, Effort effort) { return startsFromMeshlets(planAt(effort, limits)); }

namespace {

// The default orbit's distance in half-diagonals of the mesh's box (Settings::distance).
constexpr double kOrbitDistance = 3.0;

// The optimisation from meshoptimizer's meshlets, part by part as the stream makes them: this
// thread takes parts in order as they come, and the stream's thread takes them too once its
// meshlets are made. Each part keeps its own meshlet count at the default budget (`target` 0);
// a smaller budget is shared by the meshlets each part holds.
Partition optimizeMeshletParts(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target,
                               const SearchPlan& plan, size_t sweeps, MeshletStream& stream, const ProgressCallback& progress,
                               const PartClusters& partDone) {
    const size_t partCount = stream.partCount();
    // A mesh of one part grows its own clusters too: milliseconds there.
    SearchPlan partPlan = plan;
    if (partCount == 1 && plan.growOnOnePart) partPlan.growWhereUncullable = 0.0;
    std::vector<size_t> targets(partCount, 0);
    if (target != 0) {
        std::vector<size_t> held(partCount);
        for (size_t i = 0; i < partCount; ++i) held[i] = stream.part(i).meshlets.clusterCount;
        targets = optimizer::partTargets(held, target);
    }
    std::vector<Partition> results(partCount);
    std::atomic<size_t> next{0}, partsDone{0};
    std::atomic<bool> cancelled{false};
    auto work = [&](size_t worker) {
        // The calling thread keeps its core while the builder runs on the other (MeshletStream.h).
        CoreHold core = worker == 0 ? stream.holdConsumerCore() : CoreHold();
        std::vector<uint32_t> newIndex(mesh.positions.size(), optimizer::kNone);
        for (size_t i; !cancelled && (i = next++) < partCount;) {
            if (core.held() && stream.allPartsMade()) core.release();
            const MeshletPart& part = stream.part(i);
            if (!part.faces.empty()) {
                const optimizer::MeshPart piece = optimizer::extractPart(mesh, faces, part.faces.data(), part.faces.size(), newIndex);
                const size_t partTarget = target != 0 ? targets[i] : part.meshlets.clusterCount;
                results[i] = optimizeClusters(piece.mesh, piece.faces, limits, partTarget, partPlan, sweeps, &part.meshlets);
            }
            if (partDone) partDone(i, partCount, part.faces, results[i]);
            const size_t done = ++partsDone;
            // Progress is reported by the calling thread only, so the callback needs no lock.
            if (worker == 0 && progress && !progress(double(done) / double(partCount), "clusters")) cancelled = true;
        }
    };
    stream.runAfterwards([&] { work(1); });
    try {
        work(0);
    } catch (...) {
        cancelled = true;
        try {
            stream.finishWork();
        } catch (...) {
        }
        throw;
    }
    stream.finishWork();
    if (cancelled || (progress && !progress(1.0, "clusters"))) throw OperationCancelled();
    if (partCount == 1) return results[0];
    optimizer::Parts parts;
    parts.starts.assign(1, 0);
    for (size_t i = 0; i < partCount; ++i) {
        const MeshletPart& part = stream.part(i);
        parts.faces.insert(parts.faces.end(), part.faces.begin(), part.faces.end());
        parts.starts.push_back(uint32_t(parts.faces.size()));
    }
    return optimizer::joinParts(parts, results);
}

// The optimisation from grown clusters, in parts of at most 2^17 faces that share the budget,
// optimised at once on all cores.
Partition optimizeGrownParts(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t target,
                             const SearchPlan& plan, size_t sweeps, const ProgressCallback& progress, const PartClusters& partDone) {
    const optimizer::Parts parts = optimizer::splitIntoParts(faces, target);
    if (parts.count() == 1) {
        Partition whole = optimizeClusters(mesh, faces, limits, target, plan, sweeps, nullptr);
        if (partDone) partDone(0, 1, parts.faces, whole);
        if (progress && !progress(1.0, "clusters")) throw OperationCancelled();
        return whole;
    }

    // Parts are optimised independently, as many at once as the machine has cores; the result does
    // not depend on that number.
    const std::vector<size_t> targets = optimizer::partTargets(mesh, parts, target);
    std::vector<Partition> results(parts.count());
    std::vector<std::vector<uint32_t>> newIndex(threadsFor(parts.count()));  // per thread: kNone per mesh vertex
    // Progress is reported by the calling thread (worker 0) only, so the callback needs no lock; a
    // cancel stops the parts not yet started.
    std::atomic<size_t> partsDone{0};
    std::atomic<bool> cancelled{false};
    forEachInParallel(parts.count(), [&](size_t i, size_t worker) {
        if (cancelled) return;
        if (newIndex[worker].empty()) newIndex[worker].assign(mesh.positions.size(), optimizer::kNone);
        const optimizer::MeshPart part = optimizer::extractPart(mesh, faces, parts.begin(i), parts.size(i), newIndex[worker]);
        results[i] = optimizeClusters(part.mesh, part.faces, limits, targets[i], plan, sweeps, nullptr);
        if (partDone) partDone(i, parts.count(), std::vector<uint32_t>(parts.begin(i), parts.begin(i) + parts.size(i)), results[i]);
        const size_t done = ++partsDone;
        if (worker == 0 && progress && !progress(double(done) / double(parts.count()), "clusters")) cancelled = true;
    });
    if (cancelled || (progress && !progress(1.0, "clusters"))) throw OperationCancelled();
    return optimizer::joinParts(parts, results);
}

// Whether a mesh is one piece through shared vertices.
bool onePiece(const Mesh& mesh) {
    std::vector<uint32_t> parent(mesh.positions.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    size_t pieces = mesh.positions.size();
    for (size_t f = 0; f < mesh.faceCount(); ++f)
        for (size_t k = 1; k < mesh.faceSize(f); ++k) {
            const uint32_t a = root(mesh.faceBegin(f)[0]), b = root(mesh.faceBegin(f)[k]);
            if (a != b) parent[b] = a, --pieces;
        }
    return pieces == 1;
}

// `start` split to `target` clusters, the clusters whose halves gain most in expectation first
// (halves grown and reduced as on any mesh): a cone's halves are never wider, so the split never
// culls less in expectation than `start`. Clusters of one face, of separate pieces (a meshlet
// joined across a gap: its halves could span it), or whose halves miss 2 stay whole.
Partition splitToBudget(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, Partition start,
                        size_t target) {
    const SearchPlan fast = planAt(Effort::Fast, limits);
    std::vector<uint32_t> newIndex(mesh.positions.size(), optimizer::kNone);
    while (start.clusterCount < target) {
        const ClusterFaces rows = facesByCluster(start);
        std::vector<std::pair<double, uint32_t>> gains;  // (culled triangles gained, cluster)
        std::vector<Partition> halves(start.clusterCount);
        for (uint32_t c = 0; c < start.clusterCount; ++c) {
            const size_t count = rows.starts[c + 1] - rows.starts[c];
            if (count < 2) continue;
            const optimizer::MeshPart piece = optimizer::extractPart(mesh, faces, rows.faces.data() + rows.starts[c], count, newIndex);
            if (!onePiece(piece.mesh)) continue;
            halves[c] = optimizeClusters(piece.mesh, piece.faces, limits, 2, fast, 0, nullptr);
            if (halves[c].clusterCount != 2) continue;
            Partition whole;
            whole.clusterOfFace.assign(count, 0);
            whole.clusterCount = 1;
            const double triangles = double(triangleCount(piece.mesh));
            gains.emplace_back(triangles * (expectedCullRate(piece.mesh, piece.faces, halves[c]) -
                                            expectedCullRate(piece.mesh, piece.faces, whole)), c);
        }
        if (gains.empty()) break;
        std::sort(gains.begin(), gains.end(), [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
        gains.resize(std::min(gains.size(), target - start.clusterCount));
        for (const auto& [gain, c] : gains) {
            const uint32_t second = start.clusterCount++;
            for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i)
                if (halves[c].clusterOfFace[i - rows.starts[c]] == 1) start.clusterOfFace[rows.faces[i]] = second;
        }
    }
    return start;
}

// Whether partition `a` is the one to keep over `b` at a budget: within it first, then the nearer
// count, then the higher expected cull rate.
bool betterAtBudget(const Mesh& mesh, const FaceGeometry& faces, const Partition& a, const Partition& b, size_t target) {
    const bool aAbove = a.clusterCount > target, bAbove = b.clusterCount > target;
    if (aAbove != bAbove) return !aAbove;
    if (a.clusterCount != b.clusterCount) return aAbove ? a.clusterCount < b.clusterCount : a.clusterCount > b.clusterCount;
    return expectedCullRate(mesh, faces, a) > expectedCullRate(mesh, faces, b);
}

// A partition of the whole mesh told to `partDone` as its one part.
void heardAsOnePart(const PartClusters& partDone, size_t faceCount, const Partition& partition) {
    if (!partDone) return;
    std::vector<uint32_t> every(faceCount);
    std::iota(every.begin(), every.end(), 0u);
    partDone(0, 1, every, partition);
}

bool sameLimits(const MeshletLimits& a, const MeshletLimits& b) { return a.maxVertices == b.maxVertices && a.maxTriangles == b.maxTriangles; }

// The caller's meshlet stream when it is of this mesh at these limits, else one made here (held by `own`).
MeshletStream& meshletsFor(const Mesh& mesh, const MeshletLimits& limits, MeshletStream* given, std::unique_ptr<MeshletStream>& own) {
    if (given && &given->mesh() == &mesh && sameLimits(given->limits(), limits)) return *given;
    own = std::make_unique<MeshletStream>(std::shared_ptr<const Mesh>(&mesh, [](const Mesh*) {}), limits, meshletPartsFor(mesh.faceCount()));
    return *own;
}

}  // namespace

namespace {

// The builder's steps to the budget, before packing (buildOptimizedClusters).
Partition buildNearBudget(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t targetClusters,
                          const ProgressCallback& progress, Effort effort, MeshletStream* meshlets, const PartClusters& partDone) {
    const size_t faceCount = mesh.faceCount();
    if (faceCount == 0) return {};
    SearchPlan plan = planAt(effort, limits);
    plan.viewDistance = kOrbitDistance * double(computeAabb(mesh.positions).halfDiagonal());
    const size_t sweeps = annealingSweeps(plan, faceCount);
    // The fast levels start from meshoptimizer's meshlets, whose count is the default budget; a
    // budget above it is grown instead.
    std::unique_ptr<MeshletStream> ownStream;
    if (startsFromMeshlets(plan)) {
        meshlets = &meshletsFor(mesh, limits, meshlets, ownStream);
        if (targetClusters == 0 || targetClusters <= meshlets->meshletCount()) {
            // The default budget keeps the refined meshlets: as fast as meshoptimizer's own build.
            // At the balanced level an explicit budget also grows its own clusters and keeps what
            // culls more in expectation: growth beat the refined meshlets a few clusters below
            // their count (a cliff at the count: docs/benchmarks.md, "Budget sweep").
            const bool alsoGrow = targetClusters != 0 && effort == Effort::Balanced;
            const Partition fromMeshlets = optimizeMeshletParts(mesh, faces, limits, targetClusters, plan,
                                                                annealingSweepsFor(effort, faceCount, meshlets->partCount()),
                                                                *meshlets, progress, alsoGrow ? PartClusters() : partDone);
            if (targetClusters == 0 || (!alsoGrow && fromMeshlets.clusterCount <= targetClusters)) return fromMeshlets;
            // Elsewhere growth is tried where a part's share of the budget is below what its own
            // faces allow while the whole mesh allows the budget.
            const Partition grown = optimizeGrownParts(mesh, faces, limits, targetClusters, plan, sweeps, progress, {});
            const Partition& kept = betterAtBudget(mesh, faces, grown, fromMeshlets, targetClusters) ? grown : fromMeshlets;
            if (alsoGrow || &kept == &grown) heardAsOnePart(partDone, faceCount, kept);  // else its parts were heard
            return kept;
        }
        // A budget above meshoptimizer's count: its optimised meshlets split to the budget and
        // searched again, or clusters grown and reduced to it, whichever culls more in expectation.
        // Growth alone culled less than meshoptimizer's count on a third of CGAL's meshes (a cliff
        // at 1.05x its count: docs/benchmarks.md, "Budget sweep").
        const Partition fromMeshlets = optimizeMeshletParts(mesh, faces, limits, 0, plan,
                                                            annealingSweepsFor(effort, faceCount, meshlets->partCount()),
                                                            *meshlets, progress, {});
        const Partition halves = splitToBudget(mesh, faces, limits, fromMeshlets, targetClusters);
        // Growth keeps ties: its clusters are of near faces, where a split's halves can span pieces
        // a meshlet joined across gaps.
        Partition split = optimizeClusters(mesh, faces, limits, targetClusters, plan, sweeps, &halves);
        Partition best = optimizeGrownParts(mesh, faces, limits, targetClusters, plan, sweeps, progress, {});
        if (betterAtBudget(mesh, faces, split, best, targetClusters)) best = std::move(split);
        heardAsOnePart(partDone, faceCount, best);
        return best;
    }
    const size_t target = targetClusters != 0 ? targetClusters : defaultBudget(mesh, limits, plan.meshoptLimits);
    return optimizeGrownParts(mesh, faces, limits, target, plan, sweeps, progress, partDone);
}

// Packing is tried on meshes up to this many faces (one part's size): its seeds and reduction
// run over the whole mesh at once.
constexpr size_t kPackingFacesAtMost = size_t(1) << 17;

}  // namespace

namespace {

// The whole build at one budget (buildOptimizedClusters without the climb).
Partition buildAtBudget(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t targetClusters,
                        const ProgressCallback& progress, Effort effort, MeshletStream* meshlets, const PartClusters& partDone) {
    Partition made = buildNearBudget(mesh, faces, limits, targetClusters, progress, effort, meshlets, partDone);
    // At the balanced level an explicit budget is annealed as long as a packing is (the best level's
    // sweeps, one run, on at most 2^17 faces): a budget is asked for when the clusters are built
    // once, and every budget then meets the same search (a shorter one left the count culling less
    // than a packed budget below it: docs/benchmarks.md, "Budget sweep"). The best level has
    // annealed that long already; the fast level does not anneal.
    if (targetClusters == 0 || mesh.faceCount() > kPackingFacesAtMost) return made;
    const size_t sweeps = effort == Effort::Fast ? 0 : annealingSweepsFor(Effort::Best, mesh.faceCount(), 1);
    Partition kept;
    if (made.clusterCount <= targetClusters) {
        if (effort != Effort::Balanced || sweeps == 0) return made;
        // It may take a second or two on a large mesh: a cancel is heard before it.
        if (progress && !progress(1.0, "annealing clusters")) throw OperationCancelled();
        optimizer::State state(mesh, faces, limits);
        kept = optimizer::annealedFurther(state, made, sweeps);
        if (expectedCullRate(mesh, faces, kept) <= expectedCullRate(mesh, faces, made)) return made;
    } else {
        // Missed: compact clusters packed to it, kept only when they reach it (they cull less than
        // clusters shaped by their normals: a trade worth making for the budget only).
        if (targetClusters < fewestClustersWithin(mesh, limits)) return made;
        kept = optimizer::packToBudget(mesh, faces, limits, targetClusters, sweeps, made, progress);
        if (kept.clusterCount > targetClusters) return made;
    }
    heardAsOnePart(partDone, mesh.faceCount(), kept);
    return kept;
}

// The climb's own searches cost a whole build each (about 0.1 s on 4,096 faces): faces times the
// own searches stay within kClimbWork, one every stride budgets (at most kClimbStrideAtMost), up to
// kClimbAboveCount times the count; the steps between are splits only (milliseconds each).
constexpr size_t kClimbWork = size_t(1) << 17;
constexpr size_t kClimbStrideAtMost = 8;
constexpr double kClimbAboveCount = 1.25;

// Every how many budgets the climb from `from` to `highest` searches on its own: 0 when even every
// kClimbStrideAtMost-th budget costs too much.
size_t climbStride(size_t faceCount, size_t from, size_t highest) {
    const size_t steps = highest - std::min(from, highest) + 1;
    for (size_t stride = 1; stride <= kClimbStrideAtMost; ++stride)
        if (faceCount * ((steps + stride - 1) / stride + 1) <= kClimbWork) return stride;
    return 0;
}

// The best level's search, then the balanced one's, and the better kept: nearer the budget (within
// it first), then more culled in expectation, over far views and from the default orbit's distance
// (the best level's larger clusters of like normals can cull less from up close). The best level's longer search from grown clusters
// can end in a worse basin than the balanced one's from meshoptimizer's meshlets (a coconut tree
// 0.068 against 0.362; a tree of 154k triangles 3 clusters above meshoptimizer's count); so it
// never culls less in expectation nor makes more clusters than the default. The balanced run takes
// the last tenth of the progress; where it is kept it is heard as one part.
Partition buildBest(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, size_t targetClusters,
                    const ProgressCallback& progress, MeshletStream* meshlets, const PartClusters& partDone) {
    auto share = [&progress](double from, double to) -> ProgressCallback {
        if (!progress) return {};
        return [&progress, from, to](double fraction, const std::string& stage) { return progress(from + (to - from) * fraction, stage); };
    };
    Partition best = buildAtBudget(mesh, faces, limits, targetClusters, share(0.0, 0.9), Effort::Best, meshlets, partDone);
    // The default count asked for is the default: its balanced run is the default's (no climb), so
    // asking for it or leaving it out gives the same partition.
    const size_t defaultCount = defaultClusterBudget(mesh, limits);
    const size_t target = targetClusters != 0 ? targetClusters : defaultCount;
    Partition balanced = buildOptimizedClusters(mesh, faces, limits, target == defaultCount ? 0 : target, share(0.9, 1.0),
                                                Effort::Balanced, meshlets, {});
    const double distance = kOrbitDistance * double(computeAabb(mesh.positions).halfDiagonal());
    if (!betterAtBudget(mesh, faces, balanced, best, target) &&
        (best.clusterCount != balanced.clusterCount || cullsAsMuchFrom(mesh, faces, limits, best, balanced, distance)))
        return best;
    heardAsOnePart(partDone, mesh.faceCount(), balanced);
    return balanced;
}

}  // namespace

Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters, const ProgressCallback& progress, Effort effort,
                                 MeshletStream* meshlets, const PartClusters& partDone) {
    // On small meshes, at the balanced level, an explicit budget climbs from the fewest clusters
    // the builder reaches one cluster at a time: each step keeps the better in expectation of the
    // step below with one cluster split (which never culls less) and its own search. Where every
    // step is searched (stride 1) one more cluster never culls less in expectation; on larger
    // meshes a search every stride steps keeps a budget at least at the chain below it. Searched
    // alone, one more cluster could land in a worse basin: CGAL's pinion 0.413 at 18 clusters,
    // 0.346 at 19; bones 0.0331 at 41, 0.0332 at 44 where 41 split to 44 gives 0.0509
    // (docs/benchmarks.md).
    const size_t faceCount = mesh.faceCount();
    if (effort == Effort::Best) return buildBest(mesh, faces, limits, targetClusters, progress, meshlets, partDone);
    if (targetClusters == 0 || effort != Effort::Balanced || !meshoptTakesLimits(limits))
        return buildAtBudget(mesh, faces, limits, targetClusters, progress, effort, meshlets, partDone);
    // One stream of meshoptimizer's meshlets for every step: its count is the default budget.
    std::unique_ptr<MeshletStream> ownStream;
    meshlets = &meshletsFor(mesh, limits, meshlets, ownStream);
    // Which budgets a mesh climbs to, and its stride, depend on the mesh and limits only, so a
    // climbed budget never meets a budget above it searched alone or on another stride. The base
    // reaches the count or fewer: a mesh too large for a climb from there is not tried.
    const size_t count = meshlets->meshletCount(), fewest = fewestClustersWithin(mesh, limits);
    const size_t highest = size_t(kClimbAboveCount * double(count));
    if (targetClusters <= fewest || targetClusters > highest || climbStride(faceCount, count, highest) == 0)
        return buildAtBudget(mesh, faces, limits, targetClusters, progress, effort, meshlets, partDone);
    // Progress runs once over the whole climb: the base a share as if every budget were searched,
    // the budgets from the count it reached the rest.
    const double baseShare = 1.0 / double(targetClusters - fewest + 2);
    auto share = [&progress](double from, double to) -> ProgressCallback {
        if (!progress) return {};
        return [&progress, from, to](double fraction, const std::string& stage) { return progress(from + (to - from) * fraction, stage); };
    };
    // The base: the fewest clusters the limits allow, asked for; the count reached is where the climb starts.
    Partition best = buildAtBudget(mesh, faces, limits, fewest, share(0.0, baseShare), effort, meshlets, {});
    const size_t start = best.clusterCount, stride = climbStride(faceCount, start, highest);
    if (start > targetClusters || stride == 0)
        return buildAtBudget(mesh, faces, limits, targetClusters, share(baseShare, 1.0), effort, meshlets, partDone);
    // Searched on its own: every stride-th budget, the count and the budget asked for (so a climb
    // never culls less in expectation than the budget's own search).
    auto searchedAt = [&](size_t k) { return (k - start) % stride == 0 || k == count || k == targetClusters; };
    size_t searches = 0, searched = 0;
    for (size_t k = start; k <= targetClusters; ++k) searches += searchedAt(k);
    for (size_t k = start; k <= targetClusters; ++k) {
        Partition stepped = splitToBudget(mesh, faces, limits, std::move(best), k);
        if (!searchedAt(k)) {
            best = std::move(stepped);
            continue;
        }
        const double from = baseShare + (1.0 - baseShare) * double(searched++) / double(searches);
        Partition own = buildAtBudget(mesh, faces, limits, k, share(from, from + (1.0 - baseShare) / double(searches)), effort, meshlets, {});
        best = betterAtBudget(mesh, faces, stepped, own, k) ? std::move(stepped) : std::move(own);
    }
    if (progress && !progress(1.0, "clusters")) throw OperationCancelled();
    heardAsOnePart(partDone, faceCount, best);
    return best;
}

}  // namespace conescope
