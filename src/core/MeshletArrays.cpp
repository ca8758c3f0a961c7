#include "MeshletArrays.h"

#include <algorithm>
#include <limits>
#include <map>
#include <unordered_map>

#include "Adjacency.h"

namespace conescope {

namespace {

constexpr uint32_t kNone = std::numeric_limits<uint32_t>::max();

std::string meshletName(size_t m) { return "meshlet " + std::to_string(m); }

std::string triangleName(size_t m, size_t t) { return meshletName(m) + ", triangle " + std::to_string(t); }

// What a meshlet of these counts breaks of meshoptimizer's limits.
std::string beyondLimits(size_t vertexCount, size_t triangleCount) {
    const std::string limits = " (meshoptimizer's meshlets hold at most " + std::to_string(kMeshletMaxVertices) + " vertices and " +
                               std::to_string(kMeshletMaxTriangles) + " triangles)";
    if (vertexCount > kMeshletMaxVertices) return "vertex_count " + std::to_string(vertexCount) + " is above " + std::to_string(kMeshletMaxVertices) + limits;
    return "triangle_count " + std::to_string(triangleCount) + " is above " + std::to_string(kMeshletMaxTriangles) + limits;
}

// Offsets, counts, vertex indices and local indices in range, before anything is looked up.
void checkRanges(const MeshletArrays& arrays, size_t fileVertexCount) {
    if (!arrays.bounds.empty() && arrays.bounds.size() != arrays.meshlets.size())
        throw MeshletError("bounds has " + std::to_string(arrays.bounds.size()) + " entries for " + std::to_string(arrays.meshlets.size()) +
                           " meshlets");
    if (arrays.meshlets.empty()) throw MeshletError("no meshlets");
    for (size_t m = 0; m < arrays.meshlets.size(); ++m) {
        const auto [vertexOffset, triangleOffset, vertexCount, triangleCount] = arrays.meshlets[m];
        if (triangleCount == 0) throw MeshletError(meshletName(m) + " has no triangles");
        if (vertexCount > kMeshletMaxVertices || triangleCount > kMeshletMaxTriangles)
            throw MeshletError(meshletName(m) + ": " + beyondLimits(vertexCount, triangleCount));
        if (uint64_t(vertexOffset) + vertexCount > arrays.vertices.size())
            throw MeshletError(meshletName(m) + ": vertex_offset " + std::to_string(vertexOffset) + " + vertex_count " +
                               std::to_string(vertexCount) + " runs past meshlet_vertices (" + std::to_string(arrays.vertices.size()) +
                               " entries)");
        if (uint64_t(triangleOffset) + 3 * uint64_t(triangleCount) > arrays.triangles.size())
            throw MeshletError(meshletName(m) + ": triangle_offset " + std::to_string(triangleOffset) + " + 3 x triangle_count " +
                               std::to_string(triangleCount) + " runs past meshlet_triangles (" + std::to_string(arrays.triangles.size()) +
                               " bytes)");
        for (uint32_t i = vertexOffset; i < vertexOffset + vertexCount; ++i)
            if (arrays.vertices[i] >= fileVertexCount)
                throw MeshletError(meshletName(m) + ": meshlet_vertices[" + std::to_string(i) + "] = " + std::to_string(arrays.vertices[i]) +
                                   " is past the mesh file's " + std::to_string(fileVertexCount) + " vertices");
        for (uint32_t t = 0; t < triangleCount; ++t)
            for (int k = 0; k < 3; ++k) {
                const uint8_t local = arrays.triangles[triangleOffset + 3 * t + k];
                if (local >= vertexCount)
                    throw MeshletError(triangleName(m, t) + ": local vertex " + std::to_string(local) + " is past the meshlet's " +
                                       std::to_string(vertexCount) + " vertices");
            }
    }
}

// One triangle of a meshlet that lies in a polygon: its corners and where it came from.
struct Piece {
    std::array<uint32_t, 3> corners;  // sorted mesh vertices
    uint32_t meshlet;
    std::array<uint32_t, 3> oriented{};  // the corners in the polygon's winding, once it is known to tile
    size_t order = 0;                    // its place among the polygon's pieces: the fan's order for a fan
};

// Where a corner sits on a face (its first occurrence), or the face size when it is not one.
size_t cornerPosition(const Mesh& mesh, uint32_t face, uint32_t vertex) {
    const uint32_t* corners = mesh.faceBegin(face);
    return size_t(std::find(corners, corners + mesh.faceSize(face), vertex) - corners);
}

// Whether the pieces cut the polygon into triangles: n - 2 of them, each side of the polygon in
// exactly one, each other pair of corners they use in exactly two (a fan, a strip, any triangulation).
bool piecesTile(const Mesh& mesh, uint32_t face, const std::vector<Piece>& pieces) {
    const size_t n = mesh.faceSize(face);
    if (pieces.size() != n - 2) return false;
    std::map<std::pair<size_t, size_t>, int> uses;
    for (const Piece& piece : pieces) {
        std::array<size_t, 3> at{};
        for (int k = 0; k < 3; ++k) at[k] = cornerPosition(mesh, face, piece.corners[k]);
        std::sort(at.begin(), at.end());
        if (at[0] == at[1] || at[1] == at[2]) return false;
        for (auto [i, j] : {std::pair(at[0], at[1]), std::pair(at[1], at[2]), std::pair(at[0], at[2])}) ++uses[{i, j}];
    }
    for (const auto& [edge, count] : uses) {
        const bool side = edge.second == edge.first + 1 || (edge.first == 0 && edge.second == n - 1);
        if (count != (side ? 1 : 2)) return false;
    }
    return uses.size() == 2 * n - 3;  // n sides and n - 3 diagonals
}

// The polygon's fan triangles as sorted corners, each with its corners in the polygon's winding and
// its place in the fan; sorted by corners.
struct FanTriangle {
    std::array<uint32_t, 3> key, corners;
    size_t order;
    bool operator<(const FanTriangle& other) const { return key < other.key || (key == other.key && order < other.order); }
};
std::vector<FanTriangle> fanOf(const Mesh& mesh, uint32_t face) {
    const uint32_t* c = mesh.faceBegin(face);
    std::vector<FanTriangle> fan;
    for (size_t k = 1; k + 1 < mesh.faceSize(face); ++k) fan.push_back({sortedCorners(c[0], c[k], c[k + 1]), {c[0], c[k], c[k + 1]}, k});
    std::sort(fan.begin(), fan.end());
    return fan;
}

// Whether the pieces cut the polygon into triangles, and if so their corners in its winding: its own
// fan triangles (a polygon that repeats a vertex has the same triangle more than once), or another
// triangulation of its corners (piecesTile). Pieces come sorted by corners.
bool orientPieces(const Mesh& mesh, uint32_t face, std::vector<Piece>& pieces) {
    const auto fan = fanOf(mesh, face);
    bool isFan = fan.size() == pieces.size();
    for (size_t i = 0; isFan && i < fan.size(); ++i) isFan = fan[i].key == pieces[i].corners;
    if (isFan) {
        for (size_t i = 0; i < fan.size(); ++i) pieces[i].oriented = fan[i].corners, pieces[i].order = fan[i].order;
        std::sort(pieces.begin(), pieces.end(), [](const Piece& a, const Piece& b) { return a.order < b.order; });
        return true;
    }
    if (!piecesTile(mesh, face, pieces)) return false;
    for (Piece& piece : pieces) {
        std::array<uint32_t, 3> at{};
        for (int k = 0; k < 3; ++k) at[k] = uint32_t(cornerPosition(mesh, face, piece.corners[k]));
        std::sort(at.begin(), at.end());  // corners in the polygon's order keep its winding
        const uint32_t* corners = mesh.faceBegin(face);
        piece.oriented = {corners[at[0]], corners[at[1]], corners[at[2]]};
    }
    return true;
}

// A triangle a polygon holds more often than its fan does (in two meshlets, or twice in one): the
// first copy too many, with the first copy before it; null when there is none. Pieces come sorted
// by corners, then meshlet.
std::pair<const Piece*, const Piece*> repeatedPiece(const Mesh& mesh, uint32_t face, const std::vector<Piece>& pieces) {
    const auto fan = fanOf(mesh, face);
    for (size_t run = 0, end = 0; run < pieces.size(); run = end) {
        while (end < pieces.size() && pieces[end].corners == pieces[run].corners) ++end;
        const auto key = pieces[run].corners;
        const size_t inFan = size_t(std::count_if(fan.begin(), fan.end(), [&](const FanTriangle& t) { return t.key == key; }));
        if (end - run > std::max<size_t>(inFan, 1)) return {&pieces[run + std::max<size_t>(inFan, 1)], &pieces[run]};
    }
    return {nullptr, nullptr};
}

std::string firstFew(const std::vector<uint32_t>& faces) {
    std::string text;
    for (size_t i = 0; i < std::min<size_t>(faces.size(), 5); ++i) text += (i ? ", " : "") + std::to_string(faces[i]);
    if (faces.size() > 5) text += " and " + std::to_string(faces.size() - 5) + " more";
    return text;
}

// How many of the polygon's fan triangles have these sorted corners.
size_t timesInFan(const Mesh& mesh, uint32_t face, const std::array<uint32_t, 3>& key) {
    const uint32_t* c = mesh.faceBegin(face);
    size_t times = 0;
    for (size_t k = 1; k + 1 < mesh.faceSize(face); ++k) times += sortedCorners(c[0], c[k], c[k + 1]) == key;
    return times;
}

using PolygonPieces = std::unordered_map<uint32_t, std::vector<Piece>>;

// Whether the triangle's corners run around the face in the face's own winding.
bool sameWinding(const Mesh& mesh, uint32_t face, const std::array<uint32_t, 3>& corners) {
    std::array<size_t, 3> at{};
    for (int k = 0; k < 3; ++k) at[k] = cornerPosition(mesh, face, corners[k]);
    return (at[0] < at[1]) + (at[1] < at[2]) + (at[2] < at[0]) == 2;
}

// How well a polygon holding all three corners suits another triangle with them, higher better:
// room first (its fan has the triangle more often than it holds it yet; else it holds fewer pieces
// than it needs, another triangulation; else full), then the same winding. Copies of one triangle
// (a polygon and its back-to-back twin, polygons sharing corners) so go one to each polygon, each
// to the polygon facing its way.
int polygonRoom(const Mesh& mesh, uint32_t face, const std::array<uint32_t, 3>& corners, const std::array<uint32_t, 3>& key,
                const PolygonPieces& pieces) {
    const auto found = pieces.find(face);
    const size_t held = found == pieces.end() ? 0 : found->second.size();
    const size_t heldKey = found == pieces.end() ? 0 : size_t(std::count_if(found->second.begin(), found->second.end(),
                                                                             [&](const Piece& p) { return p.corners == key; }));
    const int room = timesInFan(mesh, face, key) > heldKey ? 3 : held + 2 < mesh.faceSize(face) ? 2 : 1;
    return 2 * room + sameWinding(mesh, face, corners);
}

// The face a triangle of mesh vertices (corners, as the meshlet winds them) lands on: an unmatched
// triangle face with these corners (one wound the same way first), else the polygon holding all
// three that suits it best (polygonRoom; a triangle whose corners merged into one vertex lies on
// any polygon around it). kNone with `taken` set when only a matched triangle face has them.
uint32_t faceOfTriangle(const Mesh& mesh, const Rows& around, const std::vector<uint32_t>& meshletOfFace, const PolygonPieces& pieces,
                        const std::array<uint32_t, 3>& corners, uint32_t& taken) {
    const std::array<uint32_t, 3> key = sortedCorners(corners[0], corners[1], corners[2]);
    uint32_t triangle = kNone, polygon = kNone;
    int best = 0;
    taken = kNone;
    for (const uint32_t* f = around.begin(key[0]); f != around.end(key[0]); ++f) {
        const uint32_t* c = mesh.faceBegin(*f);
        if (mesh.faceSize(*f) == 3) {
            if (sortedCorners(c[0], c[1], c[2]) != key) continue;
            if (meshletOfFace[*f] != kNone) {
                if (taken == kNone) taken = *f;
            } else if (sameWinding(mesh, *f, corners)) {
                taken = kNone;  // a duplicate face takes the copy its twin's meshlet did not
                return *f;
            } else if (triangle == kNone) {
                triangle = *f;
            }
        } else if (triangle == kNone && cornerPosition(mesh, *f, key[1]) < mesh.faceSize(*f) &&
                   cornerPosition(mesh, *f, key[2]) < mesh.faceSize(*f)) {
            const int its = polygonRoom(mesh, *f, corners, key, pieces);
            if (its > best) polygon = *f, best = its;
        }
    }
    if (triangle != kNone || polygon != kNone) taken = kNone;
    return triangle != kNone ? triangle : polygon;
}

// The mesh with the listed polygons replaced by their pieces (in the polygon's winding), each
// piece carrying its polygon's face-array values and file-partition ids; returns each new face's
// meshlet.
std::vector<uint32_t> cutPolygons(Mesh& mesh, const std::vector<uint32_t>& meshletOfFace,
                                  const std::unordered_map<uint32_t, std::vector<Piece>>& cuts) {
    Mesh cut;
    cut.positions = std::move(mesh.positions);
    cut.model = mesh.model;
    cut.fileVertices = std::move(mesh.fileVertices);
    std::vector<uint32_t> meshletOfNewFace, sourceFace;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        const auto pieces = cuts.find(f);
        if (pieces == cuts.end()) {
            cut.addFace(mesh.faceBegin(f), mesh.faceSize(f));
            meshletOfNewFace.push_back(meshletOfFace[f]);
            sourceFace.push_back(f);
            continue;
        }
        for (const Piece& piece : pieces->second) {
            cut.addFace(piece.oriented.data(), 3);
            meshletOfNewFace.push_back(piece.meshlet);
            sourceFace.push_back(f);
        }
    }
    for (const auto& [name, values] : mesh.faceArrays) {
        std::vector<double>& copied = cut.faceArrays[name];
        for (uint32_t f : sourceFace) copied.push_back(values[f]);
    }
    for (const auto& [path, clusters] : mesh.fileClusters) {
        FileClusters& copied = cut.fileClusters[path] = clusters;
        copied.clusterOfFace.clear();
        for (uint32_t f : sourceFace) copied.clusterOfFace.push_back(clusters.clusterOfFace[f]);
    }
    mesh = std::move(cut);
    return meshletOfNewFace;
}

}  // namespace

AppliedMeshlets applyMeshlets(Mesh& mesh, const MeshletArrays& arrays) {
    const size_t fileVertexCount = mesh.fileVertices.empty() ? mesh.positions.size() : mesh.fileVertices.size();
    checkRanges(arrays, fileVertexCount);
    auto meshVertex = [&](uint32_t fileVertex) { return mesh.fileVertices.empty() ? fileVertex : mesh.fileVertices[fileVertex]; };
    const Rows around = facesAroundVertices(mesh);
    std::vector<uint32_t> meshletOfFace(mesh.faceCount(), kNone);
    PolygonPieces pieces;  // polygons' triangles
    for (uint32_t m = 0; m < arrays.meshlets.size(); ++m) {
        const auto [vertexOffset, triangleOffset, vertexCount, triangleCount] = arrays.meshlets[m];
        for (uint32_t t = 0; t < triangleCount; ++t) {
            const uint8_t* local = &arrays.triangles[triangleOffset + 3 * t];
            std::array<uint32_t, 3> corners{};
            for (int k = 0; k < 3; ++k) corners[k] = meshVertex(arrays.vertices[vertexOffset + local[k]]);
            const std::array<uint32_t, 3> key = sortedCorners(corners[0], corners[1], corners[2]);
            uint32_t taken = kNone;
            const uint32_t f = faceOfTriangle(mesh, around, meshletOfFace, pieces, corners, taken);
            const std::string where = triangleName(m, t) + " (vertices " + std::to_string(key[0]) + ", " + std::to_string(key[1]) + ", " +
                                      std::to_string(key[2]) + " of the mesh)";
            if (taken != kNone)
                throw MeshletError(where + ": its face " + std::to_string(taken) + " is already in " + meshletName(meshletOfFace[taken]));
            if (f == kNone) throw MeshletError(where + ": no face of the mesh has these three corners");
            if (mesh.faceSize(f) == 3) {
                meshletOfFace[f] = m;
                continue;
            }
            pieces[f].push_back({key, m});
        }
    }
    // Polygons: whole in one meshlet, or cut where meshlets split them.
    std::unordered_map<uint32_t, std::vector<Piece>> cuts;
    for (auto& entry : pieces) {
        const uint32_t f = entry.first;
        std::vector<Piece>& held = entry.second;
        // By corners, then meshlet: a repeated triangle's copies side by side, first its first meshlet's.
        std::sort(held.begin(), held.end(), [](const Piece& a, const Piece& b) {
            return a.corners < b.corners || (a.corners == b.corners && a.meshlet < b.meshlet);
        });
        if (const auto [repeated, firstCopy] = repeatedPiece(mesh, f, held); repeated) {
            const Piece& first = *firstCopy;
            throw MeshletError(meshletName(repeated->meshlet) + ": its triangle (vertices " + std::to_string(first.corners[0]) + ", " +
                               std::to_string(first.corners[1]) + ", " + std::to_string(first.corners[2]) + " of the mesh) of face " +
                               std::to_string(f) + " is already in " + meshletName(first.meshlet));
        }
        if (!orientPieces(mesh, f, held)) {
            std::string meshlets;
            for (const Piece& piece : held) meshlets += (meshlets.empty() ? "" : ", ") + std::to_string(piece.meshlet);
            throw MeshletError("face " + std::to_string(f) + " (a polygon of " + std::to_string(mesh.faceSize(f)) + " corners): the " +
                               std::to_string(held.size()) + " triangles of meshlets " + meshlets +
                               " do not cut it into triangles (it needs " + std::to_string(mesh.faceSize(f) - 2) +
                               " that tile it; the rest of it is in no meshlet)");
        }
        const bool split = std::any_of(held.begin(), held.end(), [&](const Piece& piece) { return piece.meshlet != held[0].meshlet; });
        if (!split) {
            meshletOfFace[f] = held[0].meshlet;
            continue;
        }
        cuts.emplace(f, held);
    }
    std::vector<uint32_t> missing;
    for (uint32_t f = 0; f < mesh.faceCount(); ++f)
        if (meshletOfFace[f] == kNone && !cuts.count(f)) missing.push_back(f);
    if (!missing.empty())
        throw MeshletError(std::to_string(missing.size()) + (missing.size() == 1 ? " face is" : " faces are") + " in no meshlet: face" +
                           (missing.size() == 1 ? " " : "s ") + firstFew(missing));
    AppliedMeshlets applied;
    applied.cutPolygons = cuts.size();
    applied.clusters.clusterCount = uint32_t(arrays.meshlets.size());
    applied.clusters.bounds = arrays.bounds;
    applied.clusters.clusterOfFace = cuts.empty() ? std::move(meshletOfFace) : cutPolygons(mesh, meshletOfFace, cuts);
    return applied;
}

MeshletArrays meshletsOfPartition(const Mesh& mesh, const Partition& partition) {
    const ClusterFaces rows = facesByCluster(partition);
    MeshletArrays arrays;
    std::vector<uint32_t> localOf(mesh.positions.size(), kNone);
    for (uint32_t c = 0; c < partition.clusterCount; ++c) {
        const uint32_t vertexOffset = uint32_t(arrays.vertices.size()), triangleOffset = uint32_t(arrays.triangles.size());
        auto local = [&](uint32_t v) {
            if (localOf[v] == kNone) localOf[v] = uint32_t(arrays.vertices.size()) - vertexOffset, arrays.vertices.push_back(v);
            return localOf[v];
        };
        uint32_t triangleCount = 0;
        for (uint32_t i = rows.starts[c]; i < rows.starts[c + 1]; ++i) {
            const uint32_t* corners = mesh.faceBegin(rows.faces[i]);
            for (size_t k = 0; k < mesh.faceSize(rows.faces[i]); ++k) local(corners[k]);
            for (size_t k = 1; k + 1 < mesh.faceSize(rows.faces[i]); ++k, ++triangleCount)
                for (uint32_t v : {corners[0], corners[k], corners[k + 1]}) arrays.triangles.push_back(uint8_t(localOf[v]));
        }
        const uint32_t vertexCount = uint32_t(arrays.vertices.size()) - vertexOffset;
        if (vertexCount > kMeshletMaxVertices || triangleCount > kMeshletMaxTriangles)
            throw std::invalid_argument("cluster " + std::to_string(c) + ": " + beyondLimits(vertexCount, triangleCount) +
                                        "; write .obj, .gltf or .txt, or build with --max-verts 255 --max-tris 512");
        for (uint32_t i = vertexOffset; i < arrays.vertices.size(); ++i) localOf[arrays.vertices[i]] = kNone;
        // Each meshlet's triangles start on a multiple of 4 bytes, as meshopt_buildMeshlets lays them out.
        arrays.triangles.resize((arrays.triangles.size() + 3) & ~size_t(3), 0);
        arrays.meshlets.push_back({vertexOffset, triangleOffset, vertexCount, triangleCount});
    }
    return arrays;
}

}  // namespace conescope
