// meshoptimizer 0.18's k-d tree over triangle centres (MIT licence, (c) Arseny Kapoulkine), made
// again for the builder's reproduction (Reproduction.cpp): the library's float arithmetic in the
// library's order (this file is compiled without contracted multiply-adds, as that one is).
// Internal to conescope_core.
#pragma once

#include <cstddef>

#include "CoreAffinity.h"

namespace conescope::meshoptkd {

// Branches split at the mean of the axis of largest variance, leaves hold up to 8 points and list
// them in the nodes that follow.
struct KdNode {
    union {
        float split;
        unsigned int index;
    };
    unsigned int axis : 2;  // 3: leaf
    unsigned int children : 30;
};

// Welford's running mean and variance of some points, as the library computes them.
struct Spread {
    float mean[3] = {};
    float vars[3] = {};
};
Spread spreadOf(const float* points, size_t stride, const unsigned int* indices, size_t count);

// How the library splits a node holding indices[0, count) of spread `spread`: the axis, the mean on
// it, and how many points went below it (the indices are partitioned so); a leaf when the node is
// small or the split too lopsided. The tree (kdBuild) and the search for ties without it
// (Reproduction.cpp) both split so.
struct KdSplit {
    bool leaf = true;
    unsigned int axis = 0;
    float split = 0.f;
    size_t middle = 0;
};
KdSplit kdSplit(const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize, const Spread& spread);

// The whole tree into nodes (2 * count of them at most); returns the nodes used.
size_t kdBuild(KdNode* nodes, const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize);
// The same nodes, the root's second subtree made at once on a thread of its own held on `cores`
// (if any), into an array of its own, then copied after the first: children are counted from
// their node, so a subtree can be made anywhere.
size_t kdBuildInTwo(KdNode* nodes, const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize,
                    const Cores& cores);

// The distance the library's search measures from `position` to a triangle's centre.
float centreDistance(const float* point, const float* position);

// The library's nearest-neighbour search, plus `dead` marks on subtrees holding only placed
// triangles (see there).
void kdNearest(const KdNode* nodes, unsigned int root, const float* points, size_t stride, const unsigned char* emitted,
               const float* position, unsigned int& result, float& limit, unsigned char* dead);

}  // namespace conescope::meshoptkd
