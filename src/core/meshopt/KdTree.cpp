// meshoptimizer 0.18's k-d tree (KdTree.h), made again.
#include "KdTree.h"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace conescope::meshoptkd {

namespace {

size_t kdPartition(unsigned int* indices, size_t count, const float* points, size_t stride, unsigned int axis, float pivot) {
    size_t m = 0;
    for (size_t i = 0; i < count; ++i) {
        float v = points[indices[i] * stride + axis];
        unsigned int t = indices[m];
        indices[m] = indices[i];
        indices[i] = t;
        m += v < pivot;
    }
    return m;
}

size_t kdBuildLeaf(size_t offset, KdNode* nodes, unsigned int* indices, size_t count) {
    KdNode& result = nodes[offset];
    result.index = indices[0];
    result.axis = 3;
    result.children = unsigned(count - 1);
    for (size_t i = 1; i < count; ++i) {
        KdNode& tail = nodes[offset + i];
        tail.index = indices[i];
        tail.axis = 3;
        tail.children = ~0u >> 2;
    }
    return offset + count;
}

}  // namespace

// One running sum after another, in index order.
Spread spreadOf(const float* points, size_t stride, const unsigned int* indices, size_t count) {
    Spread s;
    float runc = 1, runs = 1;
    for (size_t i = 0; i < count; ++i, runc += 1.f, runs = 1.f / runc) {
        const float* point = points + indices[i] * stride;
        for (int k = 0; k < 3; ++k) {
            float delta = point[k] - s.mean[k];
            s.mean[k] += delta * runs;
            s.vars[k] += delta * (point[k] - s.mean[k]);
        }
    }
    return s;
}

namespace {

// The same for two sets of points at once: each step waits for the step before of its own set
// only, so the two interleave on the processor; the arithmetic of each is spreadOf's.
void spreadsOf(const float* points, size_t stride, const unsigned int* a, size_t countA, const unsigned int* b, size_t countB,
               Spread& sa, Spread& sb) {
    const size_t both = std::min(countA, countB);
    float runc = 1, runs = 1;
    for (size_t i = 0; i < both; ++i, runc += 1.f, runs = 1.f / runc) {
        const float* pa = points + a[i] * stride;
        const float* pb = points + b[i] * stride;
        for (int k = 0; k < 3; ++k) {
            float deltaA = pa[k] - sa.mean[k], deltaB = pb[k] - sb.mean[k];
            sa.mean[k] += deltaA * runs, sb.mean[k] += deltaB * runs;
            sa.vars[k] += deltaA * (pa[k] - sa.mean[k]), sb.vars[k] += deltaB * (pb[k] - sb.mean[k]);
        }
    }
    // The longer set goes on alone, its running count where it was.
    Spread& s = countA > both ? sa : sb;
    const unsigned int* rest = countA > both ? a : b;
    const size_t count = std::max(countA, countB);
    for (size_t i = both; i < count; ++i, runc += 1.f, runs = 1.f / runc) {
        const float* point = points + rest[i] * stride;
        for (int k = 0; k < 3; ++k) {
            float delta = point[k] - s.mean[k];
            s.mean[k] += delta * runs;
            s.vars[k] += delta * (point[k] - s.mean[k]);
        }
    }
}

}  // namespace

KdSplit kdSplit(const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize, const Spread& spread) {
    KdSplit node;
    if (count <= leafSize) return node;
    const float* vars = spread.vars;
    node.axis = vars[0] >= vars[1] && vars[0] >= vars[2] ? 0 : vars[1] >= vars[2] ? 1 : 2;
    node.split = spread.mean[node.axis];
    node.middle = kdPartition(indices, count, points, stride, node.axis, node.split);
    node.leaf = node.middle <= leafSize / 2 || node.middle >= count - leafSize / 2;
    return node;
}

namespace {

// The library's recursion, with each node's spread computed by its parent together with its
// sibling's (the spreads of two disjoint sets do not depend on which is built first).
size_t kdBuild(size_t offset, KdNode* nodes, const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize,
               const Spread& spread) {
    const KdSplit node = kdSplit(points, stride, indices, count, leafSize, spread);
    if (node.leaf) return kdBuildLeaf(offset, nodes, indices, count);
    const size_t middle = node.middle;
    KdNode& result = nodes[offset];
    result.split = node.split;
    result.axis = node.axis;
    Spread left, right;  // only nodes above the leaf size use theirs
    spreadsOf(points, stride, indices, middle > leafSize ? middle : 0, indices + middle, count - middle > leafSize ? count - middle : 0,
              left, right);
    size_t nextOffset = kdBuild(offset + 1, nodes, points, stride, indices, middle, leafSize, left);
    result.children = unsigned(nextOffset - offset - 1);
    return kdBuild(nextOffset, nodes, points, stride, indices + middle, count - middle, leafSize, right);
}

}  // namespace

size_t kdBuild(KdNode* nodes, const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize) {
    return kdBuild(0, nodes, points, stride, indices, count, leafSize,
                   count > leafSize ? spreadOf(points, stride, indices, count) : Spread{});
}

size_t kdBuildInTwo(KdNode* nodes, const float* points, size_t stride, unsigned int* indices, size_t count, size_t leafSize,
                    const Cores& cores) {
    const Spread spread = count > leafSize ? spreadOf(points, stride, indices, count) : Spread{};
    const KdSplit node = kdSplit(points, stride, indices, count, leafSize, spread);
    if (node.leaf) return kdBuildLeaf(0, nodes, indices, count);
    const size_t middle = node.middle;
    nodes[0].split = node.split;
    nodes[0].axis = node.axis;
    Spread left, right;
    spreadsOf(points, stride, indices, middle > leafSize ? middle : 0, indices + middle, count - middle > leafSize ? count - middle : 0,
              left, right);
    std::vector<KdNode> second(2 * (count - middle));
    size_t secondCount = 0;
    auto makeSecond = [&] { secondCount = kdBuild(0, second.data(), points, stride, indices + middle, count - middle, leafSize, right); };
    std::thread maker = threadOnCores(cores, makeSecond);
    const size_t nextOffset = kdBuild(1, nodes, points, stride, indices, middle, leafSize, left);
    if (maker.joinable()) maker.join();
    else makeSecond();
    nodes[0].children = unsigned(nextOffset - 1);
    std::copy(second.begin(), second.begin() + long(secondCount), nodes + nextOffset);
    return nextOffset + secondCount;
}

// The distance the library's search measures from `position` to a triangle's centre.
float centreDistance(const float* point, const float* position) {
    float distance2 = (point[0] - position[0]) * (point[0] - position[0]) + (point[1] - position[1]) * (point[1] - position[1]) +
                      (point[2] - position[2]) * (point[2] - position[2]);
    return sqrtf(distance2);
}

// The library's nearest-neighbour search, plus `dead` marks on subtrees found to hold only placed
// triangles: placed triangles never come back, so skipping such a subtree changes no answer, and
// late in the build, when most of the tree is placed, the search stops visiting it all.
void kdNearest(const KdNode* nodes, unsigned int root, const float* points, size_t stride, const unsigned char* emitted,
               const float* position, unsigned int& result, float& limit, unsigned char* dead) {
    if (dead[root]) return;
    const KdNode& node = nodes[root];
    if (node.axis == 3) {
        bool live = false;
        for (unsigned int i = 0; i <= node.children; ++i) {
            unsigned int index = nodes[root + i].index;
            if (emitted[index]) continue;
            live = true;
            float distance = centreDistance(points + index * stride, position);
            if (distance < limit) {
                result = index;
                limit = distance;
            }
        }
        dead[root] = !live;
    } else {
        float delta = position[node.axis] - node.split;
        unsigned int first = (delta <= 0) ? 0 : node.children;
        unsigned int second = first ^ node.children;
        kdNearest(nodes, root + 1 + first, points, stride, emitted, position, result, limit, dead);
        if (fabsf(delta) <= limit) kdNearest(nodes, root + 1 + second, points, stride, emitted, position, result, limit, dead);
        dead[root] = dead[root + 1] && dead[root + 1 + node.children];
    }
}

}  // namespace conescope::meshoptkd
