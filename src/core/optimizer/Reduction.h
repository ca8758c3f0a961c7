// The reduction's shared pieces (Reduction.cpp: dissolving, three into two, the order of steps;
// Merges.cpp: whole-cluster merges and dissolving across gaps, where separate pieces meet).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <limits>
#include <vector>

#include "Steps.h"

namespace conescope::optimizer {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Which clusters each step changed, so that a step that failed on a cluster is tried again only
// once a cluster it reads has changed: until then it fails the same way, since a failed step
// leaves every cluster as it was, down to the order of its faces and its cap (the passes below
// retry every cluster, and failures cost as much as successes).
struct Changes {
    std::vector<uint32_t> at;                          // per cluster: the commit that last changed it
    std::vector<uint32_t> dissolveFailed, splitFailed;  // per cluster: commits at its last failure, or kNone
    uint32_t commits = 0;
    std::vector<uint32_t> ring, nextRing;  // scratch for unchangedSince

    explicit Changes(size_t clusters) : at(clusters, 0), dissolveFailed(clusters, kNone), splitFailed(clusters, kNone) {}
    template <typename Clusters>
    void commit(const Clusters& clusters) {
        ++commits;
        for (uint32_t c : clusters) at[c] = commits;
    }
    void commit(std::initializer_list<uint32_t> clusters) { commit<std::initializer_list<uint32_t>>(clusters); }
};

// Live clusters, smallest first (ties by id): the order in which dissolving is tried.
std::vector<uint32_t> clustersBySize(const State& state);
// The face moves on (recorded in state.undo) and the cluster it joins gets a cap that holds it
// (grown, not exact: cheap, and recomputed once the step is done).
void moveGrowingCap(State& state, uint32_t face, uint32_t to);
// Exact caps for every cluster the moves in state.undo touched, listed in state.members.
void recomputeTouchedCaps(State& state);

// How many of the nearest clusters (by centre) a cluster may merge with across a gap: near enough
// that the merged cluster stays compact for frustum and occlusion culling. Where the limits stop
// every such merge, farther ones are tried.
constexpr size_t kNearestAcrossGaps[] = {6, 24, 96};

// Whole-cluster merges, cheapest objective loss first, at most `count`: between clusters that
// share an edge (acrossGaps 0), or between each cluster and its acrossGaps nearest by centre.
void mergeCheapest(State& state, size_t count, size_t acrossGaps, Changes& changes);
// Dissolving across gaps (into the `nearest` clusters nearest by centre), smallest clusters first,
// while above the target; a dissolve `accept` refuses is put back.
void dissolveSmallestAcrossGaps(State& state, size_t target, size_t nearest, const std::function<bool()>& accept);

}  // namespace conescope::optimizer
