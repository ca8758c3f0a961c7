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

#include "BuildPlan.h"
#include "ForCones.h"
#include "Parts.h"
#include "Runs.h"
#include "State.h"
#include "Steps.h"
#include "core/ClusterBounds.h"
#include "core/Parallel.h"
#include "core/Settings.h"
#include "core/Statistics.h"
#include "core/Views.h"
#include "core/meshopt/Meshopt.h"

namespace conescope {

namespace {

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

bool startsFromMeshoptMeshlets(const MeshletLimits& limits, Effort effort) { return startsFromMeshlets(effort, meshoptTakesLimits(limits)); }

namespace {

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
    const SearchPlan fast = searchPlanFor(Effort::Fast, meshoptTakesLimits(limits));
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

// Whether partition `a` is the one to keep over `b` at a budget (nearerTheBudget, then the higher
// expected cull rate).
bool betterAtBudget(const Mesh& mesh, const FaceGeometry& faces, const Partition& a, const Partition& b, size_t target) {
    if (const std::optional<bool> nearer = nearerTheBudget(a.clusterCount, b.clusterCount, target)) return *nearer;
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

// One build's inputs, shared by the steps of its plan.
struct BuildInputs {
    const Mesh& mesh;
    const FaceGeometry& faces;
    const MeshletLimits& limits;
    MeshletStream* meshlets;  // meshoptimizer's meshlets of this mesh where the plan starts there
    BuildFacts facts;
};

// A callback that maps a build's progress into [from, to] of the caller's.
ProgressCallback progressShare(const ProgressCallback& progress, double from, double to) {
    if (!progress) return {};
    return [&progress, from, to](double fraction, const std::string& stage) { return progress(from + (to - from) * fraction, stage); };
}

// BuildStart::Meshlets: meshoptimizer's meshlets searched at the budget, and grown clusters as the
// plan asks (the better at the budget kept; heard as one part when growth was run alongside).
Partition fromMeshlets(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone) {
    const size_t sweeps = annealingSweepsFor(plan.effort, in.facts.faces, in.meshlets->partCount());
    const bool always = plan.alsoGrown == AlsoGrown::Always;
    // Where growth always follows, the two share the progress, so it never runs back.
    const Partition searched = optimizeMeshletParts(in.mesh, in.faces, in.limits, plan.budget, plan.search, sweeps, *in.meshlets,
                                                    always ? progressShare(progress, 0.0, 0.5) : progress, always ? PartClusters() : partDone);
    if (plan.alsoGrown == AlsoGrown::Never || (!always && searched.clusterCount <= plan.budget)) return searched;
    // At the default budget growth aims at the meshlets' own count, so never makes more clusters.
    const size_t budget = plan.budget != 0 ? plan.budget : searched.clusterCount;
    const Partition grown = optimizeGrownParts(in.mesh, in.faces, in.limits, budget, plan.search,
                                               annealingSweeps(plan.search, in.facts.faces),
                                               always ? progressShare(progress, 0.5, 1.0) : progress, {});
    const bool grownKept = betterAtBudget(in.mesh, in.faces, grown, searched, budget);
    const Partition& kept = grownKept ? grown : searched;
    if (always || grownKept) heardAsOnePart(partDone, in.facts.faces, kept);  // else its parts were heard
    return kept;
}

// BuildStart::SplitMeshlets: the searched meshlets at their count split to the budget and searched
// again, against clusters grown to it. Growth keeps ties: its clusters are of near faces, where a
// split's halves can span pieces a meshlet joined across gaps.
Partition fromSplitMeshlets(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone) {
    const size_t sweeps = annealingSweeps(plan.search, in.facts.faces);
    const Partition searched = optimizeMeshletParts(in.mesh, in.faces, in.limits, 0, plan.search,
                                                    annealingSweepsFor(plan.effort, in.facts.faces, in.meshlets->partCount()),
                                                    *in.meshlets, progress, {});
    const Partition halves = splitToBudget(in.mesh, in.faces, in.limits, searched, plan.budget);
    Partition split = optimizeClusters(in.mesh, in.faces, in.limits, plan.budget, plan.search, sweeps, &halves);
    Partition best = optimizeGrownParts(in.mesh, in.faces, in.limits, plan.budget, plan.search, sweeps, progress, {});
    if (betterAtBudget(in.mesh, in.faces, split, best, plan.budget)) best = std::move(split);
    heardAsOnePart(partDone, in.facts.faces, best);
    return best;
}

// The plan's start, searched to the budget (before its finish).
Partition started(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone) {
    switch (plan.start) {
        case BuildStart::Meshlets: return fromMeshlets(in, plan, progress, partDone);
        case BuildStart::SplitMeshlets: return fromSplitMeshlets(in, plan, progress, partDone);
        case BuildStart::Grown: break;
    }
    const size_t target = plan.budget != 0 ? plan.budget : defaultBudget(in.mesh, in.limits, in.facts.meshoptLimits);
    return optimizeGrownParts(in.mesh, in.faces, in.limits, target, plan.search, annealingSweeps(plan.search, in.facts.faces),
                              progress, partDone);
}

// The plan's finish of a started partition: a reached budget annealed further, kept where it culls
// more in expectation; a missed one packed to, kept only where packing reaches it (compact clusters
// cull less than clusters shaped by their normals: a trade worth making for the budget only).
Partition finished(const BuildInputs& in, const BuildPlan& plan, Partition made, const ProgressCallback& progress,
                   const PartClusters& partDone) {
    Partition kept;
    if (made.clusterCount <= plan.budget || plan.budget == 0) {
        if (!plan.annealFurther) return made;
        // It may take a second or two on a large mesh: a cancel is heard before it.
        if (progress && !progress(1.0, "annealing clusters")) throw OperationCancelled();
        optimizer::State state(in.mesh, in.faces, in.limits);
        kept = optimizer::annealedFurther(state, made, plan.finishSweeps);
        if (expectedCullRate(in.mesh, in.faces, kept) <= expectedCullRate(in.mesh, in.faces, made)) return made;
    } else {
        if (!plan.packWhenMissed) return made;
        kept = optimizer::packToBudget(in.mesh, in.faces, in.limits, plan.budget, plan.finishSweeps, made, progress);
        if (kept.clusterCount > plan.budget) return made;
    }
    heardAsOnePart(partDone, in.facts.faces, kept);
    return kept;
}

// The plan of one budget without its climb or balanced rival.
Partition atBudget(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone) {
    return finished(in, plan, started(in, plan, progress, partDone), progress, partDone);
}

// The climb: from the fewest clusters the limits allow (asked for; the count reached is where it
// starts) one cluster at a time, each step the better of the step below with one cluster split
// (never culling less) and, every stride budgets and at the count and the budget asked for, the
// budget's own search; a step not searched is the split alone. Progress runs once over the whole
// climb: the base a share as if every budget were searched, the budgets from its count the rest.
Partition climbed(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone) {
    auto planAt = [&](size_t budget) { return planBuild(plan.effort, budget, in.facts); };
    const size_t target = plan.budget, fewest = in.facts.fewest, count = in.facts.meshletCount;
    const double baseShare = 1.0 / double(target - fewest + 2);
    Partition best = atBudget(in, planAt(fewest), progressShare(progress, 0.0, baseShare), {});
    const size_t start = best.clusterCount, stride = climbStride(in.facts.faces, start, highestClimb(count));
    if (start > target || stride == 0) return atBudget(in, plan, progressShare(progress, baseShare, 1.0), partDone);
    auto searchedAt = [&](size_t k) { return (k - start) % stride == 0 || k == count || k == target; };
    size_t searches = 0, searched = 0;
    for (size_t k = start; k <= target; ++k) searches += searchedAt(k);
    for (size_t k = start; k <= target; ++k) {
        Partition stepped = splitToBudget(in.mesh, in.faces, in.limits, std::move(best), k);
        if (!searchedAt(k)) {
            best = std::move(stepped);
            continue;
        }
        const double from = baseShare + (1.0 - baseShare) * double(searched++) / double(searches);
        Partition own = atBudget(in, planAt(k), progressShare(progress, from, from + (1.0 - baseShare) / double(searches)), {});
        best = betterAtBudget(in.mesh, in.faces, stepped, own, k) ? std::move(stepped) : std::move(own);
    }
    if (progress && !progress(1.0, "clusters")) throw OperationCancelled();
    heardAsOnePart(partDone, in.facts.faces, best);
    return best;
}

// The best level's search, then the balanced one's, and the better kept: nearer the budget; at one
// count its own only where it culls at least as much both in expectation over far views and as the
// run measures it, `measure` (the best level's larger clusters of like normals can cull less from up
// close, and its longer search from grown clusters can end in a worse basin: on foliage,
// docs/benchmarks.md). So best never culls less than the default there nor makes more clusters;
// `choice` hears which was kept and why. The balanced run takes the last tenth of the progress;
// where it is kept it is heard as one part.
Partition bestOfBoth(const BuildInputs& in, const BuildPlan& plan, const ProgressCallback& progress, const PartClusters& partDone,
                     const PartitionMeasure& measure, BestEffortChoice& choice) {
    Partition best = atBudget(in, plan, progressShare(progress, 0.0, 0.9), partDone);
    // The default count asked for is the default: its balanced run is the default's (no climb).
    const size_t defaultCount = defaultClusterBudget(in.mesh, in.limits);
    const size_t target = plan.budget != 0 ? plan.budget : defaultCount;
    Partition balanced = buildOptimizedClusters(in.mesh, in.faces, in.limits, target == defaultCount ? 0 : target,
                                                progressShare(progress, 0.9, 1.0), Effort::Balanced, in.meshlets, {});
    auto measured = [&](const Partition& partition) {
        return measure ? measure(partition) : shownEfficiency(in.mesh, in.faces, partition, Settings{});
    };
    choice = {true,
              false,
              best.clusterCount,
              balanced.clusterCount,
              measured(best),
              measured(balanced),
              expectedCullRate(in.mesh, in.faces, best),
              expectedCullRate(in.mesh, in.faces, balanced)};
    const std::optional<bool> balancedNearer = nearerTheBudget(balanced.clusterCount, best.clusterCount, target);
    if (balancedNearer ? !*balancedNearer
                       : choice.ownExpected >= choice.balancedExpected && choice.ownEfficiency >= choice.balancedEfficiency)
        return best;
    choice.keptBalanced = true;
    heardAsOnePart(partDone, in.facts.faces, balanced);
    return balanced;
}

}  // namespace

Partition buildOptimizedClusters(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits,
                                 size_t targetClusters, const ProgressCallback& progress, Effort effort,
                                 MeshletStream* meshlets, const PartClusters& partDone, uint32_t conesPerCluster,
                                 BestEffortChoice* choice, const PartitionMeasure& measure) {
    BestEffortChoice made;
    if (choice) *choice = made;
    if (mesh.faceCount() == 0) return {};
    const double viewDistance = kStandardOrbitDistance * double(computeAabb(mesh.positions).halfDiagonal());
    BuildInputs in{mesh, faces, limits, meshlets, {mesh.faceCount(), meshoptTakesLimits(limits), 0, fewestClustersWithin(mesh, limits), viewDistance, conesPerCluster}};
    // One stream of meshoptimizer's meshlets for every step; its count (which waits for every
    // meshlet) is asked for only where an explicit budget is set against it.
    std::unique_ptr<MeshletStream> ownStream;
    if (startsFromMeshlets(effort, in.facts.meshoptLimits)) {
        in.meshlets = &meshletsFor(mesh, limits, meshlets, ownStream);
        if (targetClusters != 0) in.facts.meshletCount = in.meshlets->meshletCount();
    }
    const BuildPlan plan = planBuild(effort, targetClusters, in.facts);
    // Aimed at K cones, faces move across the parts afterwards: no part is heard.
    const PartClusters none;
    const PartClusters& heard = plan.forCones > 1 ? none : partDone;
    const double built = plan.forCones > 1 ? 0.8 : 1.0;  // the moves for K cones take the rest
    const ProgressCallback building = built < 1.0 ? progressShare(progress, 0.0, built) : progress;
    Partition partition = plan.alsoBalanced ? bestOfBoth(in, plan, building, heard, measure, choice ? *choice : made)
                          : plan.climb      ? climbed(in, plan, building, heard)
                                            : atBudget(in, plan, building, heard);
    if (plan.forCones > 1)
        refineForCones(mesh, faces, limits, plan.forCones, partition, kForConesPasses, plan.forConesTryBelow,
                       progressShare(progress, built, 1.0));
    return partition;
}

}  // namespace conescope
