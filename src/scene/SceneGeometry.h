// The geometry of the scene's layers as plain arrays, then turned into vtkPolyData in one go (no
// per-cell vtkCell objects), so a mesh of a million triangles builds in about a second.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>
#include <vtkSmartPointer.h>

#include "core/ClusterBounds.h"
#include "core/Mesh.h"
#include "core/Partition.h"

class vtkPoints;
class vtkPolyData;

namespace conescope {

// Cells of one kind (all lines or all polygons) with one cluster id per cell.
struct GlyphGeometry {
    std::vector<glm::vec3> points;
    std::vector<int64_t> offsets{0};  // cell i uses connectivity[offsets[i] .. offsets[i + 1])
    std::vector<int64_t> connectivity;
    std::vector<int> clusterIds;      // one per cell

    void addCell(std::initializer_list<int64_t> pointIds, int cluster);
    void reserve(size_t pointCount, size_t cellCount, size_t connectivityCount);
};
enum class CellKind { Lines, Polygons };

// Float points from glm vectors (one copy, no per-point calls).
vtkSmartPointer<vtkPoints> pointsFrom(const std::vector<glm::vec3>& positions);

// A polydata holding the cells as lines or polygons, the cluster ids as int cell array "cluster_id".
// points may be given to share one vtkPoints between polydatas (then geometry.points is ignored).
vtkSmartPointer<vtkPolyData> polyDataFrom(const GlyphGeometry& geometry, CellKind kind, vtkPoints* points = nullptr);

// The mesh: shared world points, one polygon per face (cell id = face index), cluster ids per face.
vtkSmartPointer<vtkPolyData> meshPolyData(const Mesh& mesh, vtkPoints* points, const Partition& partition);

// Edges whose faces lie in different clusters, and open edges (one face only), as point-id pairs into
// the mesh's points; the cluster id of each line is that of the first face found on it. An edge is
// undirected: (a, b) and (b, a) are the same edge.
GlyphGeometry borderEdges(const Mesh& mesh, const Partition& partition);

// Edges of the faces of one cluster that no other face of that cluster shares: its outline.
GlyphGeometry clusterOutline(const Mesh& mesh, const uint32_t* clusterFaces, size_t faceCount, int cluster);

// Cone of normals of a cluster: apex at the bounding-sphere centre, opening along the cone axis with
// exactly the cone's half-angle. The slant length is the sphere radius (so wide cones become flat
// disks instead of growing without bound): height = r cos(alpha), base radius = r sin(alpha).
// `segments` triangles (apex, ring i, ring i + 1); no base cap, so every point but the apex lies on the
// rim. Clusters that are not cullable get no cone. A zero radius takes fallbackLength.
void appendCone(GlyphGeometry& geometry, const ConeOfNormals& cone, const Sphere& sphere, int cluster,
                int segments, double fallbackLength);
GlyphGeometry coneGlyphs(const ClusterBounds& bounds, int segments, double fallbackLength);

// 8 corners and 12 edge lines per box.
void appendBox(GlyphGeometry& geometry, const Aabb& box, int cluster);
GlyphGeometry boxGlyphs(const ClusterBounds& bounds);

// Three orthogonal great circles (in the xy, yz and zx planes) of `segments` lines each.
void appendSphere(GlyphGeometry& geometry, const Sphere& sphere, int cluster, int segments);
GlyphGeometry sphereGlyphs(const ClusterBounds& bounds, int segments);

// Mean length of the faces' edges (each face's edges counted once per face).
double meanEdgeLength(const Mesh& mesh, const std::vector<glm::vec3>& world);

// Two unit vectors that make an orthonormal frame with the unit vector axis.
void orthonormalFrame(const glm::dvec3& axis, glm::dvec3& first, glm::dvec3& second);

}  // namespace conescope
