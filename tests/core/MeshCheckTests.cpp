#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "TestMeshes.h"
#include "core/MeshChecks.h"

using namespace conescope;

TEST(MeshChecks, ClosedSphereIsClean) {
    const Mesh mesh = testmesh::icosphere(2);
    const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.openEdges, 0u);
    EXPECT_EQ(report.nonManifoldEdges, 0u);
    EXPECT_EQ(report.inconsistentEdges, 0u);
    EXPECT_EQ(report.duplicateFaces, 0u);
    EXPECT_EQ(report.components, 1u);
    EXPECT_TRUE(report.orientable);
}

// A band of `segments` quads around a circle, given a half twist (a Moebius strip) or not.
Mesh band(int segments, bool twisted) {
    Mesh mesh;
    for (int i = 0; i < segments; ++i) {
        const double t = 2.0 * 3.14159265358979 * i / segments, half = twisted ? t / 2.0 : 0.0;
        for (double w : {-0.3, 0.3}) {
            const double r = 1.0 + w * std::cos(half);
            mesh.positions.push_back(glm::vec3(float(r * std::cos(t)), float(r * std::sin(t)), float(w * std::sin(half))));
        }
    }
    for (int i = 0; i < segments; ++i) {
        const uint32_t a = uint32_t(2 * i), b = a + 1;
        const bool last = i + 1 == segments;
        // The last quad joins the first rung, its two ends swapped by the twist.
        const uint32_t c = last ? (twisted ? 1u : 0u) : a + 2, d = last ? (twisted ? 0u : 1u) : a + 3;
        mesh.addFace({a, c, d});
        mesh.addFace({a, d, b});
    }
    return mesh;
}

// A Moebius strip has one side: no winding agrees across all its edges, whichever faces flip. A
// plain band, and the strip's halves, can be wound one way.
TEST(MeshChecks, MoebiusStripIsNotOrientable) {
    const Mesh strip = band(24, true), ring = band(24, false);
    const MeshReport twisted = checkMesh(strip, computeFaceGeometry(strip));
    EXPECT_FALSE(twisted.orientable);
    EXPECT_EQ(twisted.components, 1u);
    EXPECT_EQ(twisted.nonManifoldEdges, 0u);
    EXPECT_GT(twisted.inconsistentEdges, 0u);
    const MeshReport plain = checkMesh(ring, computeFaceGeometry(ring));
    EXPECT_TRUE(plain.orientable);
    EXPECT_EQ(plain.inconsistentEdges, 0u);
    // Both in one mesh: two components, and the one that cannot be wound makes the mesh so.
    Mesh both = ring;
    const uint32_t offset = uint32_t(both.positions.size());
    for (const glm::vec3& p : strip.positions) both.positions.push_back(p + glm::vec3(5.0f, 0.0f, 0.0f));
    for (size_t f = 0; f < strip.faceCount(); ++f)
        both.addFace({strip.faceBegin(f)[0] + offset, strip.faceBegin(f)[1] + offset, strip.faceBegin(f)[2] + offset});
    const MeshReport two = checkMesh(both, computeFaceGeometry(both));
    EXPECT_FALSE(two.orientable);
    EXPECT_EQ(two.components, 2u);
    // Flipping faces changes which edges disagree, never whether the strip can be wound.
    Mesh flipped = strip;
    for (size_t f = 0; f < flipped.faceCount(); f += 3)
        std::reverse(flipped.faceVertices.begin() + flipped.faceStarts[f], flipped.faceVertices.begin() + flipped.faceStarts[f + 1]);
    EXPECT_FALSE(checkMesh(flipped, computeFaceGeometry(flipped)).orientable);
}

TEST(MeshChecks, FlippedFacesAreFoundAndFixed) {
    Mesh mesh = testmesh::icosphere(2);
    const Mesh original = mesh;
    for (size_t f : {3u, 17u, 100u}) std::reverse(mesh.faceVertices.begin() + mesh.faceStarts[f], mesh.faceVertices.begin() + mesh.faceStarts[f + 1]);
    const MeshReport broken = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(broken.inconsistentEdges, 9u);
    EXPECT_EQ(fixWinding(mesh), 3u);
    EXPECT_EQ(checkMesh(mesh, computeFaceGeometry(mesh)).inconsistentEdges, 0u);
    const FaceGeometry fixed = computeFaceGeometry(mesh), expected = computeFaceGeometry(original);
    for (size_t f = 0; f < mesh.faceCount(); ++f) EXPECT_NEAR(glm::dot(fixed.normals[f], expected.normals[f]), 1.0, 1e-9);
}

TEST(MeshChecks, OpenNonManifoldAndDuplicateFaces) {
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
    mesh.addFace({0, 1, 2});
    mesh.addFace({1, 0, 3});
    mesh.addFace({0, 1, 4});  // third face on edge 0-1
    mesh.addFace({2, 1, 0});  // duplicate of the first, reversed
    const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.nonManifoldEdges, 1u);
    EXPECT_GT(report.openEdges, 0u);
    EXPECT_EQ(report.duplicateFaces, 1u);
}

TEST(MeshChecks, DuplicateFacesCountedAsABruteForceSetWould) {
    // Thousands of faces of 3-5 vertices over few vertices, some triangles repeating a corner, many
    // faces repeating an earlier face's vertex set in another rotation or winding: the count is
    // faces minus distinct vertex lists.
    std::mt19937_64 random(7);
    for (int round = 0; round < 5; ++round) {
        Mesh mesh;
        for (int v = 0; v < 40; ++v) mesh.positions.emplace_back(float(v), float(v * v % 7), float(v % 5));
        std::vector<std::vector<uint32_t>> faces;
        for (int f = 0; f < 6000; ++f) {
            std::vector<uint32_t> face;
            if (!faces.empty() && random() % 3 == 0) {
                face = faces[random() % faces.size()];
                std::rotate(face.begin(), face.begin() + long(random() % face.size()), face.end());
                if (random() % 2) std::reverse(face.begin(), face.end());
            } else if (random() % 8 == 0) {  // a triangle repeating a corner: counted by its vertex list too
                const uint32_t a = uint32_t(random() % 40), b = uint32_t(random() % 40);
                face = random() % 2 ? std::vector<uint32_t>{a, a, b} : std::vector<uint32_t>{a, b, b};
            } else {
                const size_t size = 3 + random() % 3;
                while (face.size() < size) {
                    const uint32_t v = uint32_t(random() % 40);
                    if (std::find(face.begin(), face.end(), v) == face.end()) face.push_back(v);
                }
            }
            faces.push_back(face);
            mesh.addFace(face.data(), face.size());
        }
        std::set<std::vector<uint32_t>> distinct;
        for (std::vector<uint32_t> face : faces) {
            std::sort(face.begin(), face.end());
            distinct.insert(face);
        }
        const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
        EXPECT_EQ(report.duplicateFaces, faces.size() - distinct.size());
        EXPECT_GT(report.duplicateFaces, 1000u);
    }
}

// Double-sided geometry as exporters write it: faces each followed by the same face wound the
// other way (any rotation), beside copies wound the same way, triangles and polygons alike. Only the
// reversed copies are double-sided; every copy is a duplicate; the warning gives the count.
TEST(MeshChecks, DoubleSidedFacesAreTheDuplicatesWoundTheOtherWay) {
    std::mt19937_64 random(19256);
    for (const Mesh& single : {testmesh::icosphere(2), testmesh::quadCube()}) {
        Mesh mesh;
        mesh.positions = single.positions;
        size_t reversed = 0, copies = 0;
        for (size_t f = 0; f < single.faceCount(); ++f) {
            std::vector<uint32_t> face(single.faceBegin(f), single.faceBegin(f) + single.faceSize(f));
            mesh.addFace(face.data(), face.size());
            const unsigned kind = unsigned(random() % 3);  // 0: alone, 1: a reversed copy, 2: a same-wound copy
            if (kind == 0) continue;
            std::rotate(face.begin(), face.begin() + long(random() % face.size()), face.end());
            if (kind == 1) std::reverse(face.begin(), face.end());
            mesh.addFace(face.data(), face.size());
            ++copies, reversed += kind == 1;
        }
        ASSERT_GT(reversed, 0u);
        ASSERT_GT(copies, reversed);
        const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
        EXPECT_EQ(report.duplicateFaces, copies);
        EXPECT_EQ(report.doubleSidedFaces, reversed);
        EXPECT_NE(doubleSidedWarning(report).find(std::to_string(reversed) + " faces lie back to back"), std::string::npos)
            << doubleSidedWarning(report);
        EXPECT_EQ(doubleSidedWarning(checkMesh(single, computeFaceGeometry(single))), "");
    }
}

namespace {

void turnOver(Mesh& mesh, size_t firstFace, size_t endFace) {
    for (size_t f = firstFace; f < endFace; ++f)
        std::reverse(mesh.faceVertices.begin() + mesh.faceStarts[f], mesh.faceVertices.begin() + mesh.faceStarts[f + 1]);
}

// `b` appended to `a` as a second component, moved by `offset`.
Mesh withSecondComponent(Mesh a, const Mesh& b, glm::vec3 offset) {
    const uint32_t base = uint32_t(a.positions.size());
    for (const glm::vec3& p : b.positions) a.positions.push_back(p + offset);
    for (size_t f = 0; f < b.faceCount(); ++f) {
        std::vector<uint32_t> face(b.faceBegin(f), b.faceBegin(f) + b.faceSize(f));
        for (uint32_t& v : face) v += base;
        a.addFace(face.data(), face.size());
    }
    return a;
}

// The share of faces whose normal points away from `centre`, the centre of a convex component.
double outwardShare(const Mesh& mesh, glm::dvec3 centre, size_t firstFace, size_t endFace) {
    const FaceGeometry faces = computeFaceGeometry(mesh);
    size_t outward = 0;
    for (size_t f = firstFace; f < endFace; ++f) outward += glm::dot(faces.normals[f], faces.centroids[f] - centre) > 0.0;
    return double(outward) / double(endFace - firstFace);
}

}  // namespace

TEST(MeshChecks, InsideOutClosedComponentsAreCountedAndTurnedOver) {
    const Mesh cube = testmesh::quadCube();
    // Two cubes, the second turned inside out: consistent winding, but its normals all point in.
    Mesh mesh = withSecondComponent(cube, cube, {3.0f, 0.0f, 0.0f});
    const size_t cubeFaces = cube.faceCount();
    turnOver(mesh, cubeFaces, 2 * cubeFaces);
    MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.components, 2u);
    EXPECT_EQ(report.inconsistentEdges, 0u);
    EXPECT_EQ(report.insideOutComponents, 1u);
    EXPECT_TRUE(windingNeedsFixing(report));
    EXPECT_NE(windingWarning(report).find("1 closed component turned inside out"), std::string::npos) << windingWarning(report);

    EXPECT_EQ(fixWinding(mesh), cubeFaces);
    report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_EQ(report.insideOutComponents, 0u);
    EXPECT_FALSE(windingNeedsFixing(report));
    EXPECT_TRUE(windingWarning(report).empty());
    const glm::dvec3 cubeCentre(computeAabb(cube.positions).center());
    EXPECT_EQ(outwardShare(mesh, cubeCentre, 0, cubeFaces), 1.0);
    EXPECT_EQ(outwardShare(mesh, cubeCentre + glm::dvec3(3, 0, 0), cubeFaces, 2 * cubeFaces), 1.0);
}

TEST(MeshChecks, MostlyInwardWindingIsMadeConsistentThenOutward) {
    // 75 of 80 faces inside out: agreeing with the majority alone would turn the 5 good ones over too.
    Mesh mesh = testmesh::icosphere(1);
    turnOver(mesh, 5, mesh.faceCount());
    const MeshReport report = checkMesh(mesh, computeFaceGeometry(mesh));
    EXPECT_GT(report.inconsistentEdges, 0u);
    EXPECT_EQ(report.insideOutComponents, 0u) << "inconsistent components have no inside";
    EXPECT_EQ(fixWinding(mesh), mesh.faceCount() - 5);
    EXPECT_EQ(outwardShare(mesh, glm::dvec3(0.0), 0, mesh.faceCount()), 1.0);
}

TEST(MeshChecks, InsideOutIsJudgedInWorldSpaceAndOnlyForClosedComponents) {
    Mesh mirrored = testmesh::icosphere(1);
    mirrored.model = glm::scale(glm::dmat4(1.0), glm::dvec3(-1.0, 1.0, 1.0));
    // An outward sphere seen through a mirror winds clockwise: its world normals point in.
    EXPECT_EQ(checkMesh(mirrored, computeFaceGeometry(mirrored)).insideOutComponents, 1u);
    turnOver(mirrored, 0, mirrored.faceCount());
    EXPECT_EQ(checkMesh(mirrored, computeFaceGeometry(mirrored)).insideOutComponents, 0u);

    // An open cap has no inside: never counted, never turned over.
    Mesh cap = testmesh::icosphere(1);
    cap.faceStarts.resize(cap.faceStarts.size() - 10);
    cap.faceVertices.resize(cap.faceStarts.back());
    turnOver(cap, 0, cap.faceCount());
    EXPECT_EQ(checkMesh(cap, computeFaceGeometry(cap)).insideOutComponents, 0u);
    EXPECT_EQ(fixWinding(cap), 0u);
}
