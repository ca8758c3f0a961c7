#include "Parts.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

#include "State.h"
#include "core/Parallel.h"

namespace conescope::optimizer {

namespace {

// A part keeps at least kMinPartClusters of the budget.
constexpr size_t kMinPartClusters = 16;

// Splits faces [begin, end) in place at their median centroid along their box's longest axis; ties
// go by face index, so the halves are the same sets whatever order the faces came in.
uint32_t* splitAtMedian(const FaceGeometry& faces, uint32_t* begin, uint32_t* end) {
    glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
    for (const uint32_t* f = begin; f != end; ++f) low = glm::min(low, faces.centroids[*f]), high = glm::max(high, faces.centroids[*f]);
    const glm::dvec3 extent = high - low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    uint32_t* middle = begin + (end - begin) / 2;
    std::nth_element(begin, middle, end, [&](uint32_t a, uint32_t b) {
        const double ca = faces.centroids[a][axis], cb = faces.centroids[b][axis];
        return ca != cb ? ca < cb : a < b;
    });
    return middle;
}

}  // namespace

// The halving runs in place, the parts of one level at once; parts 2i and 2i + 1 of a level are
// the halves of part i of the level before. The number of levels is fixed by the sizes alone.
Parts splitIntoParts(const FaceGeometry& faces, size_t target, size_t maxPartFaces) {
    Parts parts;
    parts.faces.resize(faces.centroids.size());
    for (uint32_t f = 0; f < parts.faces.size(); ++f) parts.faces[f] = f;
    parts.starts = {0, uint32_t(parts.faces.size())};
    size_t levels = 0;
    while ((parts.faces.size() >> levels) > std::max<size_t>(maxPartFaces, 1)) ++levels;
    for (size_t level = 0; level < levels && target >= 2 * parts.count() * kMinPartClusters; ++level) {
        std::vector<uint32_t> middles(parts.count());
        forEachInParallel(parts.count(), [&](size_t i, size_t) {
            uint32_t* begin = parts.faces.data() + parts.starts[i];
            middles[i] = uint32_t(splitAtMedian(faces, begin, begin + parts.size(i)) - parts.faces.data());
        });
        std::vector<uint32_t> finer(1, 0);
        for (size_t i = 0; i < parts.count(); ++i) finer.push_back(middles[i]), finer.push_back(parts.starts[i + 1]);
        parts.starts.swap(finer);
    }
    // Only the final parts need the mesh's own order back: one counting pass over part labels,
    // cheaper than sorting each part.
    std::vector<uint32_t> partOf(parts.faces.size());
    for (uint32_t i = 0; i < parts.count(); ++i)
        for (size_t k = 0; k < parts.size(i); ++k) partOf[parts.begin(i)[k]] = i;
    std::vector<uint32_t> next(parts.starts.begin(), parts.starts.end() - 1);
    for (uint32_t f = 0; f < partOf.size(); ++f) parts.faces[next[partOf[f]]++] = f;
    return parts;
}

namespace {

// Shares of `target` in proportion to each part's weight, rounded cumulatively so that they add up.
std::vector<size_t> shares(const std::vector<double>& weights, size_t target) {
    double total = 0.0;
    for (double w : weights) total += w;
    std::vector<size_t> result(weights.size());
    double before = 0.0;
    const auto share = [&](double w) { return size_t(std::llround(double(target) * w / total)); };
    for (size_t i = 0; i < weights.size(); ++i) {
        result[i] = std::max<size_t>(1, share(before + weights[i]) - share(before));
        before += weights[i];
    }
    return result;
}

}  // namespace

std::vector<size_t> partTargets(const Mesh& mesh, const Parts& parts, size_t target) {
    std::vector<double> triangles(parts.count(), 0.0);
    for (size_t i = 0; i < parts.count(); ++i)
        for (size_t k = 0; k < parts.size(i); ++k) triangles[i] += double(mesh.faceSize(parts.begin(i)[k]) - 2);
    return shares(triangles, target);
}

std::vector<size_t> partTargets(const std::vector<size_t>& clustersHeld, size_t target) {
    return shares(std::vector<double>(clustersHeld.begin(), clustersHeld.end()), target);
}

MeshPart extractPart(const Mesh& mesh, const FaceGeometry& faces, const uint32_t* faceIds, size_t faceCount,
                     std::vector<uint32_t>& newIndex) {
    MeshPart part;
    part.mesh.faceStarts.reserve(faceCount + 1);
    part.mesh.faceVertices.reserve(3 * faceCount);
    part.mesh.positions.reserve(faceCount / 2 + 16);
    for (const uint32_t* face = faceIds; face != faceIds + faceCount; ++face) {
        const uint32_t* vertices = mesh.faceBegin(*face);
        for (size_t k = 0; k < mesh.faceSize(*face); ++k) {
            uint32_t& index = newIndex[vertices[k]];
            if (index == kNone) index = uint32_t(part.mesh.positions.size()), part.mesh.positions.push_back(mesh.positions[vertices[k]]);
            part.mesh.faceVertices.push_back(index);
        }
        part.mesh.faceStarts.push_back(uint32_t(part.mesh.faceVertices.size()));
    }
    for (const uint32_t* face = faceIds; face != faceIds + faceCount; ++face)
        for (size_t k = 0; k < mesh.faceSize(*face); ++k) newIndex[mesh.faceBegin(*face)[k]] = kNone;
    auto pick = [&](const auto& values) {
        std::remove_const_t<std::remove_reference_t<decltype(values)>> picked(faceCount);
        for (size_t i = 0; i < faceCount; ++i) picked[i] = values[faceIds[i]];
        return picked;
    };
    part.faces.normals = pick(faces.normals);
    part.faces.centroids = pick(faces.centroids);
    part.faces.areas = pick(faces.areas);
    part.faces.degenerate = pick(faces.degenerate);
    for (uint8_t d : part.faces.degenerate) part.faces.degenerateCount += d;
    return part;
}

Partition joinParts(const Parts& parts, const std::vector<Partition>& results) {
    Partition partition;
    partition.clusterOfFace.resize(parts.faces.size());
    for (size_t i = 0; i < parts.count(); ++i) {
        for (size_t k = 0; k < parts.size(i); ++k) partition.clusterOfFace[parts.begin(i)[k]] = partition.clusterCount + results[i].clusterOfFace[k];
        partition.clusterCount += results[i].clusterCount;
    }
    return partition;
}

}  // namespace conescope::optimizer
