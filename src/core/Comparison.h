// Two configurations (A and B) of the same prepared mesh compared over the same eyes: which
// back-facing triangles each culls that the other does not. A and B may differ in anything that
// makes clusters or decides a cull (builder, cluster file, limits, cluster count, cone, sphere, test,
// cone weight); the mesh, its winding repair and the views are shared. Each side culls with the
// displayed (first) test of its own settings, as the product does (measureEye).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "Pipeline.h"

namespace conescope {

// "K=V,K=V" on top of `base`: K a run option's flag without the dashes (builder=meshopt, max-tris=64,
// cone=average, test=sphere, cluster-file=ids.txt, ...), V its text as the option takes it; an on/off
// option takes K alone or K=on/off (true/false, 1/0). A piece without "=" whose text is not an option
// continues the value before it, so lists and paths keep their commas (cone=minimal,average); a
// piece with "=" always starts an option of its own (a mistyped key is named, and a value cannot
// hold ",x="). The shared options (views, distance, eye, ortho, fix-winding) are refused: both
// sides use the same.
// Throws std::invalid_argument naming the key and what it accepts.
Settings parseConfiguration(const std::string& text, const Settings& base);

// The run options a configuration text may set (every schema flag but the shared ones).
std::vector<std::string> configurationKeys();

// `side` with the options both sides share (views, distance, eye, projection, winding repair) taken
// from `shared`: a configuration pinned earlier is compared over the views of the current one.
Settings withSharedOptions(Settings side, const Settings& shared);

// One side of a comparison: its clusters and the settings it is shown with. The settings decide the
// test; the clusters' own builtWith does not (the test changes without new clusters).
struct ClusterConfiguration {
    const ClusterSet& clusters;
    const Settings& settings;
};

struct ViewComparison {
    size_t view = 0;
    Eye eye;
    size_t trianglesCulledOnlyA = 0, trianglesCulledOnlyB = 0, trianglesCulledBoth = 0;
    size_t backFacingTriangles = 0;
    double efficiencyA = 0.0, efficiencyB = 0.0;
};

// What a face's clusters did from one eye.
enum class FaceDiff : uint8_t { Neither = 0, OnlyA = 1, OnlyB = 2, Both = 3 };

struct Comparison {
    CullTest testA = kDefaultTest, testB = kDefaultTest;
    ConeMethod coneA = kDefaultCone, coneB = kDefaultCone;
    std::vector<ViewComparison> views;
    // Summed over the views. Back-facing triangles only, as triangles_culled counts them: only A +
    // both is A's triangles_culled and only B + both is B's, view by view and in total.
    size_t trianglesCulledOnlyA = 0, trianglesCulledOnlyB = 0, trianglesCulledBoth = 0, backFacingTriangles = 0;
    double efficiencyA = 0.0, efficiencyB = 0.0;
    // Per face of the mesh: the views in which it faced away and only A (only B) culled it.
    std::vector<uint32_t> viewsCulledOnlyA, viewsCulledOnlyB;
    size_t clustersA = 0, clustersB = 0;
    // More than 5 % apart, relative to the smaller count: smaller clusters cull more for free.
    bool clusterCountsDiffer() const;
};

// A sentence for people when the cluster counts differ by more than 5 %, else "".
std::string clusterCountWarning(const Comparison& comparison);

// Per face, from each side's per-cluster decisions for one eye (EyeMeasurement::culled): whether
// its cluster in A, in B was culled. By decision alone: a degenerate face in a culled cluster
// counts as culled here, where the statistics count back-facing triangles only.
std::vector<FaceDiff> faceDiff(const ClusterSet& a, const std::vector<uint8_t>& culledA, const ClusterSet& b,
                               const std::vector<uint8_t>& culledB);

// A (`a`) against B (`b`), both of `prepared`, from every eye of `views`; each side with the
// displayed test of its settings through the product's path (cullClusters), so each side's numbers
// are its measureCulling's. The views of a run are viewsFor(settings, prepared.box). `progress`
// hears of every 16th view and may cancel (OperationCancelled).
Comparison compareClusterSets(const PreparedMesh& prepared, const ClusterConfiguration& a, const ClusterConfiguration& b,
                              const std::vector<Eye>& views, const ProgressCallback& progress = {});

// One eye from decisions already made (each side's cullClusters, EyeMeasurement::culled): that view's
// comparison, and each face's FaceDiff in `diff`. What the window does at every eye move and the
// headless screenshot once, without culling either side again.
Comparison compareAtEye(const PreparedMesh& prepared, const ClusterConfiguration& a, const std::vector<uint8_t>& culledA,
                        const ClusterConfiguration& b, const std::vector<uint8_t>& culledB, const Eye& eye,
                        std::vector<FaceDiff>& diff);

// A whole comparison from a prepared mesh: each side's clusters and statistics exactly as `stats` with
// its settings makes them (measureRun), and what only each culls over the views of `shared` (the
// options both sides share). What `conescope-cli compare`, its batch columns and the Python module give.
struct ComparedRuns {
    RunStatistics a, b;
    Comparison comparison;
};
// `building` hears 'A' or 'B' before that side's clusters are built (for the user: the slow part).
ComparedRuns runComparison(const PreparedMesh& prepared, const Settings& a, const Settings& b, const Settings& shared,
                           const ProgressCallback& progress = {}, const std::function<void(char side)>& building = {});

}  // namespace conescope
