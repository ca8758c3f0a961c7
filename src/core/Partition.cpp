#include "Partition.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <future>
#include <limits>
#include <random>
#include <sstream>
#include <stdexcept>
#include <unordered_map>

#include "Adjacency.h"

namespace conescope {

namespace {
constexpr uint32_t kUnassigned = std::numeric_limits<uint32_t>::max();
}  // namespace

Partition renumberClusters(std::vector<uint32_t> clusterOfFace) {
    // Ids from builders are small: a table; ids from files can be anything: a map.
    const uint32_t largest = clusterOfFace.empty() ? 0 : *std::max_element(clusterOfFace.begin(), clusterOfFace.end());
    if (size_t(largest) < 4 * clusterOfFace.size() + 1024) {
        std::vector<uint32_t> table(size_t(largest) + 1, kUnassigned);
        uint32_t next = 0;
        for (uint32_t& id : clusterOfFace) id = table[id] == kUnassigned ? (table[id] = next++) : table[id];
        return {std::move(clusterOfFace), next};
    }
    std::unordered_map<uint32_t, uint32_t> renumber;
    for (uint32_t& id : clusterOfFace) {
        auto [it, inserted] = renumber.try_emplace(id, uint32_t(renumber.size()));
        id = it->second;
    }
    return {std::move(clusterOfFace), uint32_t(renumber.size())};
}

// Seed next to the previous cluster when possible, so clusters tile the surface without gaps; else
// the first face not yet in a cluster (kUnassigned when none is left).
static uint32_t nextSeed(const std::vector<uint32_t>& leftovers, const std::vector<uint32_t>& clusterOfFace, size_t& nextUnassigned) {
    for (uint32_t f : leftovers)
        if (clusterOfFace[f] == kUnassigned) return f;
    while (nextUnassigned < clusterOfFace.size() && clusterOfFace[nextUnassigned] != kUnassigned) ++nextUnassigned;
    return nextUnassigned == clusterOfFace.size() ? kUnassigned : uint32_t(nextUnassigned);
}

Partition buildMeshlets(const Mesh& mesh, const FaceGeometry& faces, const MeshletLimits& limits, double normalWeight) {
    const size_t faceCount = mesh.faceCount();
    const Rows facesAround = facesAroundVertices(mesh);
    std::vector<uint32_t> clusterOfFace(faceCount, kUnassigned);
    std::vector<uint32_t> vertexCluster(mesh.positions.size(), kUnassigned);
    std::vector<uint32_t> candidateCluster(faceCount, kUnassigned);
    std::vector<uint32_t> candidates, leftovers;
    size_t nextUnassigned = 0;
    uint32_t cluster = 0;

    auto newVertices = [&](uint32_t f) {
        size_t added = 0;
        for (size_t k = 0; k < mesh.faceSize(f); ++k) added += vertexCluster[mesh.faceBegin(f)[k]] != cluster;
        return added;
    };

    while (true) {
        const uint32_t seed = nextSeed(leftovers, clusterOfFace, nextUnassigned);
        if (seed == kUnassigned) break;
        candidates.clear();
        size_t vertexCount = 0, triangleTotal = 0;
        glm::dvec3 normalSum(0.0);
        glm::dvec3 positionSum(0.0);
        size_t faceTotal = 0;

        auto addFace = [&](uint32_t f) {
            clusterOfFace[f] = cluster;
            triangleTotal += mesh.faceSize(f) - 2;
            normalSum += faces.normals[f];
            positionSum += faces.centroids[f];
            ++faceTotal;
            for (size_t k = 0; k < mesh.faceSize(f); ++k) {
                const uint32_t v = mesh.faceBegin(f)[k];
                if (vertexCluster[v] != cluster) vertexCluster[v] = cluster, ++vertexCount;
                for (const uint32_t* g = facesAround.begin(v); g != facesAround.end(v); ++g)
                    if (clusterOfFace[*g] == kUnassigned && candidateCluster[*g] != cluster)
                        candidateCluster[*g] = cluster, candidates.push_back(*g);
            }
        };
        addFace(seed);
        double radiusSquared = 0.0;  // running extent of the cluster, to keep it round

        while (true) {
            const glm::dvec3 axis = glm::length(normalSum) > 0.0 ? glm::normalize(normalSum) : glm::dvec3(0.0);
            const glm::dvec3 center = positionSum / double(faceTotal);
            double bestScore = std::numeric_limits<double>::infinity();
            uint32_t chosen = kUnassigned;  // a face id: the list below is compacted while scanned
            for (size_t i = 0; i < candidates.size();) {
                const uint32_t f = candidates[i];
                if (clusterOfFace[f] != kUnassigned) {  // taken since it was listed
                    candidates[i] = candidates.back();
                    candidates.pop_back();
                    continue;
                }
                const size_t added = newVertices(f);
                if (vertexCount + added > limits.maxVertices || triangleTotal + mesh.faceSize(f) - 2 > limits.maxTriangles) {
                    ++i;
                    continue;
                }
                // Few new vertices keeps the meshlet dense; a normal close to the axis keeps the cone
                // narrow; distance from the centre keeps the cluster round so its bounds stay tight.
                const glm::dvec3 offset = faces.centroids[f] - center;
                const double spread = radiusSquared > 0.0 ? glm::dot(offset, offset) / radiusSquared : 0.0;
                const double score = double(added) / double(mesh.faceSize(f)) + 0.25 * spread +
                                     normalWeight * 4.0 * (1.0 - glm::dot(faces.normals[f], axis));
                if (score < bestScore) bestScore = score, chosen = f;
                ++i;
            }
            if (chosen == kUnassigned) break;
            const glm::dvec3 offset = faces.centroids[chosen] - center;
            radiusSquared = std::max(radiusSquared, glm::dot(offset, offset));
            addFace(chosen);
        }
        leftovers.swap(candidates);
        ++cluster;
    }
    return {std::move(clusterOfFace), cluster};
}

// k-means' update step: each centre moves to the area-weighted mean of its faces (positions divided
// by scale, normals times normalWeight); an emptied cluster keeps its old centre.
static void moveCentersToMeans(const FaceGeometry& faces, const std::vector<uint32_t>& assignment, double scale, double normalWeight,
                               std::vector<glm::dvec3>& centerPositions, std::vector<glm::dvec3>& centerNormals) {
    const size_t clusterCount = centerPositions.size();
    std::vector<glm::dvec3> positionSums(clusterCount, glm::dvec3(0.0)), normalSums(clusterCount, glm::dvec3(0.0));
    std::vector<double> weights(clusterCount, 0.0);
    for (size_t f = 0; f < assignment.size(); ++f) {
        const double w = std::max(faces.areas[f], 1e-300);
        positionSums[assignment[f]] += w * faces.centroids[f] / scale;
        normalSums[assignment[f]] += w * faces.normals[f];
        weights[assignment[f]] += w;
    }
    for (size_t k = 0; k < clusterCount; ++k) {
        if (weights[k] <= 0.0) continue;
        centerPositions[k] = positionSums[k] / weights[k];
        const double length = glm::length(normalSums[k]);
        centerNormals[k] = length > 0.0 ? normalSums[k] / length * normalWeight : glm::dvec3(0.0);
    }
}

Partition buildKMeans(const Mesh& mesh, const FaceGeometry& faces, size_t clusterCount, double normalWeight,
                      size_t iterations, uint64_t seed) {
    const size_t faceCount = mesh.faceCount();
    if (faceCount == 0) return {};
    clusterCount = std::clamp<size_t>(clusterCount, 1, faceCount);
    double totalArea = 0.0;
    for (double a : faces.areas) totalArea += a;
    // Positions are divided by the expected cluster diameter so that position and normal weigh alike.
    const double scale = std::max(std::sqrt(std::max(totalArea, 1e-300) / double(clusterCount)), 1e-300);
    std::vector<glm::dvec3> centerPositions(clusterCount), centerNormals(clusterCount);
    std::mt19937_64 random(seed);
    std::vector<uint32_t> order(faceCount);
    for (size_t f = 0; f < faceCount; ++f) order[f] = uint32_t(f);
    std::shuffle(order.begin(), order.end(), random);
    for (size_t k = 0; k < clusterCount; ++k) {
        centerPositions[k] = faces.centroids[order[k]] / scale;
        centerNormals[k] = faces.normals[order[k]] * normalWeight;
    }
    std::vector<uint32_t> assignment(faceCount, 0);
    for (size_t iteration = 0; iteration < iterations; ++iteration) {
        // Grid over centre positions (cell = 1 in scaled units): the nearest centre is found by
        // searching rings of cells until the ring is farther than the best distance so far.
        glm::dvec3 low = centerPositions[0], high = centerPositions[0];
        for (const glm::dvec3& c : centerPositions) low = glm::min(low, c), high = glm::max(high, c);
        const double cell = 1.0;
        // Clamped in double before converting: a double beyond int's range converts to nothing defined.
        const glm::ivec3 dims(glm::clamp(glm::floor((high - low) / cell) + 1.0, 1.0, 256.0));
        const glm::dvec3 cellSize = glm::max((high - low) / glm::dvec3(dims), glm::dvec3(1e-300));
        auto cellOf = [&](const glm::dvec3& p) {
            // On a flat axis cellSize is 1e-300 and the quotient is huge: clamp before converting.
            return glm::ivec3(glm::clamp(glm::floor((p - low) / cellSize), glm::dvec3(0.0), glm::dvec3(dims - 1)));
        };
        const size_t cellCount = size_t(dims.x) * dims.y * dims.z;
        std::vector<uint32_t> cellStarts(cellCount + 1, 0), cellCenters(clusterCount);
        for (const glm::dvec3& c : centerPositions) {
            const glm::ivec3 g = cellOf(c);
            ++cellStarts[size_t(g.x) + size_t(dims.x) * (size_t(g.y) + size_t(dims.y) * g.z) + 1];
        }
        for (size_t i = 0; i < cellCount; ++i) cellStarts[i + 1] += cellStarts[i];
        std::vector<uint32_t> cursor(cellStarts.begin(), cellStarts.end() - 1);
        for (size_t k = 0; k < clusterCount; ++k) {
            const glm::ivec3 g = cellOf(centerPositions[k]);
            cellCenters[cursor[size_t(g.x) + size_t(dims.x) * (size_t(g.y) + size_t(dims.y) * g.z)]++] = uint32_t(k);
        }
        const double minCell = std::min({cellSize.x, cellSize.y, cellSize.z});
        const int maxRing = std::max({dims.x, dims.y, dims.z});
        for (size_t f = 0; f < faceCount; ++f) {
            const glm::dvec3 p = faces.centroids[f] / scale, n = faces.normals[f] * normalWeight;
            const glm::ivec3 home = cellOf(p);
            double best = std::numeric_limits<double>::infinity();
            uint32_t bestCluster = assignment[f];
            for (int ring = 0; ring <= maxRing; ++ring) {
                const double reach = std::max(0.0, (ring - 1) * minCell);
                if (reach * reach > best) break;
                for (int z = home.z - ring; z <= home.z + ring; ++z)
                    for (int y = home.y - ring; y <= home.y + ring; ++y)
                        for (int x = home.x - ring; x <= home.x + ring; ++x) {
                            if (std::max({std::abs(x - home.x), std::abs(y - home.y), std::abs(z - home.z)}) != ring) continue;
                            if (x < 0 || y < 0 || z < 0 || x >= dims.x || y >= dims.y || z >= dims.z) continue;
                            const size_t c = size_t(x) + size_t(dims.x) * (size_t(y) + size_t(dims.y) * z);
                            for (uint32_t i = cellStarts[c]; i < cellStarts[c + 1]; ++i) {
                                const uint32_t k = cellCenters[i];
                                const glm::dvec3 dp = p - centerPositions[k], dn = n - centerNormals[k];
                                const double d = glm::dot(dp, dp) + glm::dot(dn, dn);
                                if (d < best) best = d, bestCluster = k;
                            }
                        }
            }
            assignment[f] = bestCluster;
        }
        moveCentersToMeans(faces, assignment, scale, normalWeight, centerPositions, centerNormals);
    }
    return renumberClusters(std::move(assignment));
}

Partition partitionFromIds(const std::vector<double>& ids, size_t faceCount, const std::string& source) {
    if (ids.size() != faceCount)
        throw std::runtime_error(source + ": " + std::to_string(ids.size()) + " cluster ids for " +
                                 std::to_string(faceCount) + " faces");
    std::vector<uint32_t> clusterOfFace(faceCount);
    for (size_t f = 0; f < faceCount; ++f) {
        const double id = ids[f];
        if (!(id >= 0.0) || id != std::floor(id) || id > 4294967294.0) {
            std::ostringstream message;
            message << source << ": face " << f << " has cluster id " << id << " (must be a non-negative integer)";
            throw std::runtime_error(message.str());
        }
        clusterOfFace[f] = uint32_t(id);
    }
    return renumberClusters(std::move(clusterOfFace));
}

ClusterFaces facesByCluster(const Partition& partition) {
    ClusterFaces rows;
    rows.starts.assign(size_t(partition.clusterCount) + 1, 0);
    for (uint32_t c : partition.clusterOfFace) ++rows.starts[c + 1];
    for (size_t c = 0; c < partition.clusterCount; ++c) rows.starts[c + 1] += rows.starts[c];
    rows.faces.resize(partition.clusterOfFace.size());
    std::vector<uint32_t> cursor(rows.starts.begin(), rows.starts.end() - 1);
    for (size_t f = 0; f < partition.clusterOfFace.size(); ++f) rows.faces[cursor[partition.clusterOfFace[f]]++] = uint32_t(f);
    return rows;
}

}  // namespace conescope
