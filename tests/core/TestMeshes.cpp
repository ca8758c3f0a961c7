#include "TestMeshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>
#include <string>
#include <stdexcept>
#include <sstream>
#include <fstream>
#include <filesystem>

namespace conescope::testmesh {

Mesh icosphere(int subdivisions) {
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    std::vector<glm::dvec3> points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& p : points) p = glm::normalize(p);
    std::vector<glm::uvec3> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                                     {11, 10, 2}, {10, 7, 6}, {7, 1, 8},   {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                                     {3, 8, 9},  {4, 9, 5},  {2, 4, 11},  {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
    for (int s = 0; s < subdivisions; ++s) {
        std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
        auto midpoint = [&](uint32_t a, uint32_t b) {
            auto key = std::minmax(a, b);
            auto it = midpoints.find(key);
            if (it != midpoints.end()) return it->second;
            points.push_back(glm::normalize(points[a] + points[b]));
            return midpoints[key] = uint32_t(points.size() - 1);
        };
        std::vector<glm::uvec3> finer;
        for (const auto& f : faces) {
            const uint32_t ab = midpoint(f.x, f.y), bc = midpoint(f.y, f.z), ca = midpoint(f.z, f.x);
            for (const glm::uvec3& child : {glm::uvec3(f.x, ab, ca), glm::uvec3(f.y, bc, ab), glm::uvec3(f.z, ca, bc), glm::uvec3(ab, bc, ca)})
                finer.push_back(child);
        }
        faces.swap(finer);
    }
    Mesh mesh;
    for (const auto& p : points) mesh.positions.emplace_back(p);
    for (const auto& f : faces) mesh.addFace({f.x, f.y, f.z});
    return mesh;
}

Mesh torus(double majorRadius, double minorRadius, int majorSegments, int minorSegments) {
    Mesh mesh;
    for (int i = 0; i < majorSegments; ++i)
        for (int j = 0; j < minorSegments; ++j) {
            const double u = 2 * M_PI * i / majorSegments, v = 2 * M_PI * j / minorSegments;
            const double r = majorRadius + minorRadius * std::cos(v);
            mesh.positions.emplace_back(r * std::cos(u), minorRadius * std::sin(v), r * std::sin(u));
        }
    auto index = [&](int i, int j) { return uint32_t((i % majorSegments) * minorSegments + (j % minorSegments)); };
    for (int i = 0; i < majorSegments; ++i)
        for (int j = 0; j < minorSegments; ++j) {
            const uint32_t a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            mesh.addFace({a, d, c});
            mesh.addFace({a, c, b});
        }
    return mesh;
}

Mesh quadCube() {
    Mesh mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.emplace_back((i & 1) ? 1.f : -1.f, (i & 2) ? 1.f : -1.f, (i & 4) ? 1.f : -1.f);
    mesh.addFace({0, 4, 6, 2});  // -x
    mesh.addFace({1, 3, 7, 5});  // +x
    mesh.addFace({0, 1, 5, 4});  // -y
    mesh.addFace({2, 6, 7, 3});  // +y
    mesh.addFace({0, 2, 3, 1});  // -z
    mesh.addFace({4, 5, 7, 6});  // +z
    return mesh;
}

Mesh roof(int sides, double height) {
    Mesh mesh;
    mesh.positions.emplace_back(0.f, 0.f, float(height));
    for (int i = 0; i < sides; ++i) {
        const double angle = 2.0 * M_PI * i / sides;
        mesh.positions.emplace_back(float(std::cos(angle)), float(std::sin(angle)), 0.f);
    }
    for (int i = 0; i < sides; ++i) mesh.addFace({0, uint32_t(1 + i), uint32_t(1 + (i + 1) % sides)});
    return mesh;
}

Mesh flatPatch(int cells) {
    Mesh mesh;
    for (int i = 0; i <= cells; ++i)
        for (int j = 0; j <= cells; ++j) mesh.positions.emplace_back(float(i) / float(cells), float(j) / float(cells), 0.f);
    for (int i = 0; i < cells; ++i)
        for (int j = 0; j < cells; ++j) {
            const uint32_t a = uint32_t(i * (cells + 1) + j);
            mesh.addFace({a, a + uint32_t(cells + 1), a + uint32_t(cells + 2), a + 1});
        }
    return mesh;
}

void addBox(Mesh& mesh, const glm::dvec3& low, const glm::dvec3& extent, int cells, bool triangles) {
    // Each side: a (cells + 1)^2 grid of corners over two axes, wound outwards.
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const uint32_t first = uint32_t(mesh.positions.size());
            for (int i = 0; i <= cells; ++i)
                for (int j = 0; j <= cells; ++j) {
                    glm::dvec3 p = low;
                    p[axis] += side * extent[axis];
                    p[u] += extent[u] * i / cells;
                    p[v] += extent[v] * j / cells;
                    mesh.positions.emplace_back(p);
                }
            for (int i = 0; i < cells; ++i)
                for (int j = 0; j < cells; ++j) {
                    const uint32_t a = first + uint32_t(i * (cells + 1) + j), c = a + uint32_t(cells + 2);
                    uint32_t quad[4] = {a, a + 1, c, a + uint32_t(cells + 1)};
                    if (side == 1) std::swap(quad[1], quad[3]);
                    if (!triangles) mesh.addFace({quad[0], quad[1], quad[2], quad[3]});
                    else mesh.addFace({quad[0], quad[1], quad[2]}), mesh.addFace({quad[0], quad[2], quad[3]});
                }
        }
}

Mesh boxProp(std::mt19937_64& random, int boxes, int cells) {
    std::uniform_real_distribution<double> size(0.05, 1.5), place(-1.0, 1.0);
    Mesh mesh;
    for (int b = 0; b < boxes; ++b) {
        const glm::dvec3 low(place(random), place(random), place(random)), extent(size(random), size(random), size(random));
        addBox(mesh, low, extent, cells, false);
    }
    return mesh;
}

Mesh furnitureProp(std::mt19937_64& random, int kind, int cells, bool triangles) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto between = [&](double low, double high) { return low + (high - low) * unit(random); };
    Mesh mesh;
    const double width = between(0.8, 2.0), depth = between(0.3, 0.9), height = between(0.7, 2.2), board = between(0.02, 0.06);
    if (kind == 0) {  // a desk: a top on four legs, a drawer box under one side
        addBox(mesh, {0, height - board, 0}, {width, board, depth}, cells, triangles);
        for (int leg = 0; leg < 4; ++leg)
            addBox(mesh, {(leg & 1) * (width - 0.05), 0, (leg >> 1) * (depth - 0.05)}, {0.05, height - board, 0.05}, 1, triangles);
        addBox(mesh, {0.05, height * 0.6, 0.05}, {width * 0.4, height * 0.3, depth - 0.1}, std::max(1, cells / 2), triangles);
    } else if (kind == 1) {  // shelves: two sides, a back and boards between them
        addBox(mesh, {0, 0, 0}, {board, height, depth}, cells, triangles);
        addBox(mesh, {width - board, 0, 0}, {board, height, depth}, cells, triangles);
        addBox(mesh, {board, 0, 0}, {width - 2 * board, height, board}, cells, triangles);
        const int boards = 2 + int(unit(random) * 4);
        for (int k = 0; k < boards; ++k)
            addBox(mesh, {board, height * k / (boards - 1) * 0.97, board}, {width - 2 * board, board, depth - board}, cells, triangles);
    } else {  // a door: one panel, a handle on each side
        addBox(mesh, {0, 0, 0}, {width * 0.5, height, board}, cells, triangles);
        addBox(mesh, {width * 0.4, height * 0.5, board}, {0.02, 0.1, 0.04}, 1, triangles);
        addBox(mesh, {width * 0.4, height * 0.5, -0.04}, {0.02, 0.1, 0.04}, 1, triangles);
    }
    return mesh;
}

glm::dvec3 randomUnit(std::mt19937_64& random) {
    std::normal_distribution<double> gauss;
    glm::dvec3 v;
    do v = {gauss(random), gauss(random), gauss(random)};
    while (glm::length(v) < 1e-9);
    return glm::normalize(v);
}

Mesh randomPatch(std::mt19937_64& random, int cells, double maxTiltDegrees) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Mesh mesh;
    const double amplitude = std::tan(glm::radians(maxTiltDegrees)) * 0.5 / cells;
    for (int y = 0; y <= cells; ++y)
        for (int x = 0; x <= cells; ++x)
            mesh.positions.emplace_back(double(x) / cells, double(y) / cells, amplitude * unit(random));
    for (int y = 0; y < cells; ++y)
        for (int x = 0; x < cells; ++x) {
            const uint32_t a = uint32_t(y * (cells + 1) + x), b = a + 1, c = a + uint32_t(cells) + 2, d = a + uint32_t(cells) + 1;
            mesh.addFace({a, b, c});
            mesh.addFace({a, c, d});
        }
    return mesh;
}

// Just enough of OFF for the bundled meshes (the core tests do not link the io layer).
Mesh randomSoup(std::mt19937_64& random, size_t triangles, double spreadDegrees) {
    Mesh mesh;
    const glm::dvec3 axis = randomUnit(random);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 normal = glm::normalize(axis + std::tan(glm::radians(std::min(spreadDegrees, 89.0))) *
                                                            unit(random) * randomUnit(random));
        const glm::dvec3 n = spreadDegrees > 90.0 && t % 3 == 0 ? -normal : normal;
        const glm::dvec3 u = glm::normalize(glm::cross(n, randomUnit(random))), v = glm::cross(n, u);
        const glm::dvec3 center(unit(random), unit(random), unit(random));
        const uint32_t base = uint32_t(mesh.positions.size());
        for (int k = 0; k < 3; ++k) {
            const double angle = 2 * M_PI * k / 3 + 0.3 * unit(random);
            mesh.positions.emplace_back(center + 0.3 * (std::cos(angle) * u + std::sin(angle) * v));
        }
        mesh.addFace({base, base + 1, base + 2});
    }
    return mesh;
}

Mesh foliage(std::mt19937_64& random, int leaves) {
    Mesh mesh;
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int leaf = 0; leaf < leaves; ++leaf) {
        glm::dvec3 centre;
        do centre = glm::dvec3(unit(random), unit(random), unit(random));
        while (glm::dot(centre, centre) > 1.0);
        const glm::dvec3 n = randomUnit(random);
        const glm::dvec3 u = glm::normalize(glm::cross(n, randomUnit(random))), v = glm::cross(n, u);
        // The fold runs along v through the centre: the pentagon on the +u side lies flat, the quad
        // on the -u side is turned 30 degrees about the fold.
        const double size = 0.03, fold = glm::radians(30.0);
        const glm::dvec3 back = -std::cos(fold) * u + std::sin(fold) * n;
        const uint32_t base = uint32_t(mesh.positions.size());
        const glm::dvec3 corners[] = {centre - size * v, centre + size * v,                                  // the fold
                                      centre + size * (0.8 * u + v), centre + size * 1.2 * u, centre + size * (0.8 * u - v),
                                      centre + size * (back - v), centre + size * (back + v)};
        for (const glm::dvec3& p : corners) mesh.positions.emplace_back(p);
        mesh.addFace({base, base + 4, base + 3, base + 2, base + 1});  // the pentagon, wound about n
        mesh.addFace({base, base + 1, base + 6, base + 5});            // the quad
    }
    return mesh;
}

glm::dmat4 randomModel(std::mt19937_64& random, double scale) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0), stretch(0.3, 3.0);
    glm::dmat4 model = glm::translate(glm::dmat4(1.0), scale * glm::dvec3(unit(random), unit(random), unit(random)));
    model = glm::rotate(model, M_PI * unit(random), randomUnit(random));
    glm::dvec3 s = scale * glm::dvec3(stretch(random), stretch(random), stretch(random));
    if (unit(random) < 0.0) s.x = -s.x;  // mirrored
    return glm::scale(model, s);
}

Mesh scatteredSpheres(std::mt19937_64& random, int pieces) {
    Mesh mesh;
    std::uniform_real_distribution<float> place(-20.f, 20.f), size(0.05f, 2.f);
    for (int p = 0; p < pieces; ++p) {
        const Mesh piece = icosphere(p % 3);
        const glm::vec3 centre(place(random), place(random), place(random));
        const float scale = size(random);
        const uint32_t first = uint32_t(mesh.positions.size());
        for (const glm::vec3& q : piece.positions) mesh.positions.push_back(centre + scale * q);
        for (size_t f = 0; f < piece.faceCount(); ++f)
            mesh.addFace({first + piece.faceBegin(f)[0], first + piece.faceBegin(f)[1], first + piece.faceBegin(f)[2]});
    }
    return mesh;
}

namespace {

Mesh readOffAt(const std::filesystem::path& path);

}  // namespace

Mesh readBundledOff(const std::string& name) {
    return readOffAt(std::filesystem::path(__FILE__).parent_path().parent_path().parent_path() / "datasets" / name);
}

Mesh readTestDataOff(const std::string& name) {
    return readOffAt(std::filesystem::path(__FILE__).parent_path().parent_path() / "data" / name);
}

namespace {

Mesh readOffAt(const std::filesystem::path& path) {
    std::ifstream file(path);
    if (!file) throw std::runtime_error("cannot open " + path.string());
    std::vector<double> numbers;
    std::string line;
    bool header = false;
    while (std::getline(file, line)) {
        line = line.substr(0, line.find('#'));
        std::istringstream words(line);
        std::string word;
        while (words >> word) {
            if (!header && word == "OFF") { header = true; continue; }
            numbers.push_back(std::stod(word));
        }
    }
    Mesh mesh;
    const size_t vertices = size_t(numbers.at(0)), faceCount = size_t(numbers.at(1));
    size_t at = 3;
    for (size_t v = 0; v < vertices; ++v, at += 3) mesh.positions.emplace_back(numbers.at(at), numbers.at(at + 1), numbers.at(at + 2));
    for (size_t f = 0; f < faceCount; ++f) {
        const size_t size = size_t(numbers.at(at++));
        std::vector<uint32_t> face;
        for (size_t k = 0; k < size; ++k) face.push_back(uint32_t(numbers.at(at++)));
        mesh.addFace(face.data(), face.size());
    }
    validateMesh(mesh);
    return mesh;
}

}  // namespace

}  // namespace conescope::testmesh
