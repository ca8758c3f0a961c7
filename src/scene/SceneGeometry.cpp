#include "scene/SceneGeometry.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include "scene/SceneTypes.h"

namespace conescope {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "glm::vec3 must be three packed floats");

void GlyphGeometry::addCell(std::initializer_list<int64_t> pointIds, int cluster) {
    connectivity.insert(connectivity.end(), pointIds.begin(), pointIds.end());
    offsets.push_back(int64_t(connectivity.size()));
    clusterIds.push_back(cluster);
}

void GlyphGeometry::reserve(size_t pointCount, size_t cellCount, size_t connectivityCount) {
    points.reserve(points.size() + pointCount);
    offsets.reserve(offsets.size() + cellCount);
    clusterIds.reserve(clusterIds.size() + cellCount);
    connectivity.reserve(connectivity.size() + connectivityCount);
}

namespace {

// cos and sin of 2 pi i / segments, computed once per glyph set instead of once per cluster.
struct UnitCircle {
    std::vector<double> cosines, sines;
    explicit UnitCircle(int segments) {
        for (int i = 0; i < segments; ++i) {
            cosines.push_back(std::cos(2.0 * M_PI * i / segments));
            sines.push_back(std::sin(2.0 * M_PI * i / segments));
        }
    }
};

const UnitCircle& unitCircle(int segments) {
    thread_local std::vector<std::unique_ptr<UnitCircle>> circles;
    if (size_t(segments) >= circles.size()) circles.resize(segments + 1);
    if (!circles[segments]) circles[segments] = std::make_unique<UnitCircle>(segments);
    return *circles[segments];
}

}  // namespace

vtkSmartPointer<vtkPoints> pointsFrom(const std::vector<glm::vec3>& positions) {
    auto coordinates = vtkSmartPointer<vtkFloatArray>::New();
    coordinates->SetNumberOfComponents(3);
    coordinates->SetNumberOfTuples(vtkIdType(positions.size()));
    if (!positions.empty()) std::memcpy(coordinates->GetPointer(0), positions.data(), positions.size() * sizeof(glm::vec3));
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetData(coordinates);
    return points;
}

namespace {

vtkSmartPointer<vtkIdTypeArray> idArrayFrom(const int64_t* values, size_t count) {
    auto array = vtkSmartPointer<vtkIdTypeArray>::New();
    array->SetNumberOfTuples(vtkIdType(count));
    std::copy(values, values + count, array->GetPointer(0));
    return array;
}

vtkSmartPointer<vtkIntArray> clusterIdArray(const int* values, size_t count) {
    auto array = vtkSmartPointer<vtkIntArray>::New();
    array->SetName(clusterIdArrayName);
    array->SetNumberOfTuples(vtkIdType(count));
    if (count) std::memcpy(array->GetPointer(0), values, count * sizeof(int));
    return array;
}

}  // namespace

vtkSmartPointer<vtkPolyData> polyDataFrom(const GlyphGeometry& geometry, CellKind kind, vtkPoints* points) {
    auto cells = vtkSmartPointer<vtkCellArray>::New();
    cells->SetData(idArrayFrom(geometry.offsets.data(), geometry.offsets.size()),
                   idArrayFrom(geometry.connectivity.data(), geometry.connectivity.size()));
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points ? points : pointsFrom(geometry.points).Get());
    if (kind == CellKind::Lines)
        polyData->SetLines(cells);
    else
        polyData->SetPolys(cells);
    polyData->GetCellData()->AddArray(clusterIdArray(geometry.clusterIds.data(), geometry.clusterIds.size()));
    return polyData;
}

vtkSmartPointer<vtkPolyData> meshPolyData(const Mesh& mesh, vtkPoints* points, const Partition& partition) {
    auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
    offsets->SetNumberOfTuples(vtkIdType(mesh.faceStarts.size()));
    std::copy(mesh.faceStarts.begin(), mesh.faceStarts.end(), offsets->GetPointer(0));
    auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
    connectivity->SetNumberOfTuples(vtkIdType(mesh.faceVertices.size()));
    std::copy(mesh.faceVertices.begin(), mesh.faceVertices.end(), connectivity->GetPointer(0));
    auto polygons = vtkSmartPointer<vtkCellArray>::New();
    polygons->SetData(offsets, connectivity);

    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->SetPoints(points);
    polyData->SetPolys(polygons);
    std::vector<int> ids(partition.clusterOfFace.begin(), partition.clusterOfFace.end());
    polyData->GetCellData()->AddArray(clusterIdArray(ids.data(), ids.size()));
    return polyData;
}

GlyphGeometry borderEdges(const Mesh& mesh, const Partition& partition) {
    // Every face edge as (smaller vertex, larger vertex, face); sorting groups the faces of each edge.
    struct FaceEdge {
        uint64_t key;
        uint32_t face;
        bool operator<(const FaceEdge& other) const { return key < other.key || (key == other.key && face < other.face); }
    };
    std::vector<FaceEdge> edges;
    edges.reserve(mesh.faceVertices.size());
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        const size_t size = mesh.faceSize(f);
        for (size_t k = 0; k < size; ++k) {
            const uint32_t a = face[k], b = face[(k + 1) % size];
            if (a == b) continue;
            edges.push_back({uint64_t(std::min(a, b)) << 32 | std::max(a, b), f});
        }
    }
    std::sort(edges.begin(), edges.end());

    GlyphGeometry lines;
    for (size_t begin = 0; begin < edges.size();) {
        size_t end = begin + 1;
        bool mixed = false;
        const uint32_t firstCluster = partition.clusterOfFace[edges[begin].face];
        for (; end < edges.size() && edges[end].key == edges[begin].key; ++end)
            mixed |= partition.clusterOfFace[edges[end].face] != firstCluster;
        if (end - begin == 1 || mixed)
            lines.addCell({int64_t(edges[begin].key >> 32), int64_t(edges[begin].key & 0xffffffffu)}, int(firstCluster));
        begin = end;
    }
    return lines;
}

GlyphGeometry clusterOutline(const Mesh& mesh, const uint32_t* clusterFaces, size_t faceCount, int cluster) {
    std::vector<uint64_t> edges;
    for (size_t i = 0; i < faceCount; ++i) {
        const uint32_t* face = mesh.faceBegin(clusterFaces[i]);
        const size_t size = mesh.faceSize(clusterFaces[i]);
        for (size_t k = 0; k < size; ++k) {
            const uint32_t a = face[k], b = face[(k + 1) % size];
            if (a != b) edges.push_back(uint64_t(std::min(a, b)) << 32 | std::max(a, b));
        }
    }
    std::sort(edges.begin(), edges.end());
    GlyphGeometry lines;
    for (size_t begin = 0; begin < edges.size();) {
        size_t end = begin + 1;
        while (end < edges.size() && edges[end] == edges[begin]) ++end;
        if (end - begin == 1) lines.addCell({int64_t(edges[begin] >> 32), int64_t(edges[begin] & 0xffffffffu)}, cluster);
        begin = end;
    }
    return lines;
}

void orthonormalFrame(const glm::dvec3& axis, glm::dvec3& first, glm::dvec3& second) {
    // Cross with the coordinate axis least aligned with `axis`, so the result is never tiny.
    const glm::dvec3 magnitude = glm::abs(axis);
    const glm::dvec3 helper = magnitude.x <= magnitude.y && magnitude.x <= magnitude.z ? glm::dvec3(1, 0, 0)
                              : magnitude.y <= magnitude.z                             ? glm::dvec3(0, 1, 0)
                                                                                       : glm::dvec3(0, 0, 1);
    first = glm::normalize(glm::cross(axis, helper));
    second = glm::cross(axis, first);
}

void appendCone(GlyphGeometry& geometry, const ConeOfNormals& cone, const Sphere& sphere, int cluster, int segments,
                double fallbackLength) {
    if (!cone.cullable) return;
    const double slant = sphere.radius > 0.0 ? sphere.radius : fallbackLength;
    const double alpha = cone.halfAngle();
    const glm::dvec3 axis = glm::normalize(cone.axis);
    glm::dvec3 first, second;
    orthonormalFrame(axis, first, second);

    const UnitCircle& circle = unitCircle(segments);
    const int64_t apex = int64_t(geometry.points.size());
    geometry.points.push_back(glm::vec3(sphere.center));
    for (int i = 0; i < segments; ++i) {
        const glm::dvec3 side = circle.cosines[i] * first + circle.sines[i] * second;
        geometry.points.push_back(glm::vec3(sphere.center + slant * (std::cos(alpha) * axis + std::sin(alpha) * side)));
    }
    for (int i = 0; i < segments; ++i)
        geometry.addCell({apex, apex + 1 + i, apex + 1 + (i + 1) % segments}, cluster);
}

GlyphGeometry coneGlyphs(const ClusterBounds& bounds, int segments, double fallbackLength) {
    GlyphGeometry geometry;
    geometry.reserve(bounds.count() * (segments + 1), bounds.count() * segments, bounds.count() * segments * 3);
    for (size_t c = 0; c < bounds.count(); ++c)
        appendCone(geometry, bounds.cones[c], bounds.spheres[c], int(c), segments, fallbackLength);
    return geometry;
}

void appendBox(GlyphGeometry& geometry, const Aabb& box, int cluster) {
    const int64_t first = int64_t(geometry.points.size());
    // Corner k takes max on axis i when bit i of k is set.
    for (int k = 0; k < 8; ++k)
        geometry.points.push_back({k & 1 ? box.max.x : box.min.x, k & 2 ? box.max.y : box.min.y, k & 4 ? box.max.z : box.min.z});
    // The 12 edges join corners that differ in one bit.
    for (int k = 0; k < 8; ++k)
        for (int bit = 1; bit < 8; bit <<= 1)
            if (!(k & bit)) geometry.addCell({first + k, first + (k | bit)}, cluster);
}

GlyphGeometry boxGlyphs(const ClusterBounds& bounds) {
    GlyphGeometry geometry;
    geometry.reserve(bounds.count() * 8, bounds.count() * 12, bounds.count() * 24);
    for (size_t c = 0; c < bounds.count(); ++c) appendBox(geometry, bounds.boxes[c], int(c));
    return geometry;
}

void appendSphere(GlyphGeometry& geometry, const Sphere& sphere, int cluster, int segments) {
    const glm::dvec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const UnitCircle& circle = unitCircle(segments);
    for (int plane = 0; plane < 3; ++plane) {
        const glm::dvec3& u = axes[plane];
        const glm::dvec3& v = axes[(plane + 1) % 3];
        const int64_t first = int64_t(geometry.points.size());
        for (int i = 0; i < segments; ++i)
            geometry.points.push_back(glm::vec3(sphere.center + sphere.radius * (circle.cosines[i] * u + circle.sines[i] * v)));
        for (int i = 0; i < segments; ++i) geometry.addCell({first + i, first + (i + 1) % segments}, cluster);
    }
}

GlyphGeometry sphereGlyphs(const ClusterBounds& bounds, int segments) {
    GlyphGeometry geometry;
    geometry.reserve(bounds.count() * 3 * segments, bounds.count() * 3 * segments, bounds.count() * 6 * segments);
    for (size_t c = 0; c < bounds.count(); ++c) appendSphere(geometry, bounds.spheres[c], int(c), segments);
    return geometry;
}

double meanEdgeLength(const Mesh& mesh, const std::vector<glm::vec3>& world) {
    double sum = 0.0;
    size_t count = 0;
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
        const uint32_t* face = mesh.faceBegin(f);
        const size_t size = mesh.faceSize(f);
        for (size_t k = 0; k < size; ++k) sum += glm::distance(glm::dvec3(world[face[k]]), glm::dvec3(world[face[(k + 1) % size]]));
        count += size;
    }
    return count ? sum / double(count) : 0.0;
}

}  // namespace conescope
