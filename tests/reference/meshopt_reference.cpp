// meshoptimizer's own culling loop, written apart from ConeScope: it links only the library. It
// reads an OFF file, builds meshlets with meshopt_buildMeshlets (limits and cone weight from the
// command line; ConeScope's defaults are 64 vertices, 124 triangles, cone weight 1), bounds each
// with meshopt_computeMeshletBounds, optionally writes them as a meshlet JSON (with the bounds) and
// as an OBJ with an `o` object per meshlet, then culls from the standard orbit of docs/user/command-line.md
// ("Standard views") with the two tests engines ship, in float as a shader would:
//   apex-f32:   dot(normalize(cone_apex - eye), cone_axis) >= cone_cutoff          (meshoptimizer.h)
//   sphere-s8:  dot(center - eye, axis) >= cutoff * length(center - eye) + radius,
//               axis = cone_axis_s8 / 127, cutoff = cone_cutoff_s8 / 127            (niagara's coneCull)
// Efficiency: back-facing triangles in culled meshlets over back-facing triangles, summed over the
// views; a triangle is back-facing when n.(e - q) < 0 at each corner q (n its normal in double,
// edge-on and zero-area triangles are not), as ConeScope defines it. Prints one JSON object.
//
// meshopt_reference MESH.off [--views N] [--distance D] [--max-verts V] [--max-tris T]
//                   [--cone-weight W] [--json OUT.json] [--obj OUT.obj]
#include <meshoptimizer.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

struct Mesh {
    std::vector<float> positions;    // x, y, z per vertex, in the file's order
    std::vector<unsigned> triangles;  // fan triangles of the file's faces
};

// OFF as CGAL writes it: "OFF", counts, vertices, then faces "n i0 ... i(n-1) [colour]".
Mesh readOff(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) {
        line = line.substr(0, line.find('#'));
        if (line.find_first_not_of(" \t\r") != std::string::npos) lines.push_back(line);
    }
    size_t at = 0;
    if (lines.empty() || lines[at].rfind("OFF", 0) != 0) throw std::runtime_error(path + ": not an OFF file");
    std::istringstream header(lines[at].size() > 3 ? lines[at].substr(3) : lines[++at]);
    size_t vertices = 0, faces = 0;
    if (!(header >> vertices >> faces)) header.clear(), header.str(lines[++at]), header >> vertices >> faces;
    Mesh mesh;
    for (size_t v = 0; v < vertices; ++v) {
        std::istringstream words(lines.at(++at));
        float x, y, z;
        words >> x >> y >> z;
        mesh.positions.insert(mesh.positions.end(), {x, y, z});
    }
    for (size_t f = 0; f < faces; ++f) {
        std::istringstream words(lines.at(++at));
        size_t n = 0;
        words >> n;
        std::vector<unsigned> corners(n);
        for (unsigned& corner : corners) words >> corner;
        for (size_t k = 1; k + 1 < n; ++k) mesh.triangles.insert(mesh.triangles.end(), {corners[0], corners[k], corners[k + 1]});
    }
    return mesh;
}

struct Meshlets {
    std::vector<meshopt_Meshlet> meshlets;
    std::vector<unsigned> vertices;
    std::vector<unsigned char> triangles;
    std::vector<meshopt_Bounds> bounds;
};

Meshlets buildMeshlets(const Mesh& mesh, size_t maxVertices, size_t maxTriangles, float coneWeight) {
    Meshlets result;
    const size_t bound = meshopt_buildMeshletsBound(mesh.triangles.size(), maxVertices, maxTriangles);
    result.meshlets.resize(bound);
    result.vertices.resize(bound * maxVertices);
    result.triangles.resize(bound * maxTriangles * 3);
    const size_t count = meshopt_buildMeshlets(result.meshlets.data(), result.vertices.data(), result.triangles.data(), mesh.triangles.data(),
                                               mesh.triangles.size(), mesh.positions.data(), mesh.positions.size() / 3, 12, maxVertices,
                                               maxTriangles, coneWeight);
    result.meshlets.resize(count);
    const meshopt_Meshlet& last = result.meshlets.back();
    result.vertices.resize(last.vertex_offset + last.vertex_count);
    result.triangles.resize(last.triangle_offset + ((last.triangle_count * 3 + 3) & ~3u));
    for (const meshopt_Meshlet& m : result.meshlets)
        result.bounds.push_back(meshopt_computeMeshletBounds(&result.vertices[m.vertex_offset], &result.triangles[m.triangle_offset],
                                                             m.triangle_count, mesh.positions.data(), mesh.positions.size() / 3, 12));
    return result;
}

std::string number(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

template <typename T>
std::string list(const T* values, size_t count) {
    std::string text = "[";
    for (size_t i = 0; i < count; ++i) {
        if (i) text += ",";
        if constexpr (std::is_floating_point_v<T>) text += number(values[i]);
        else text += std::to_string(long(values[i]));
    }
    return text + "]";
}

void writeJson(const Meshlets& m, const std::string& path) {
    std::ofstream out(path);
    out << "{\"format\": \"meshoptimizer-meshlets\",\n\"meshlets\": [";
    for (size_t i = 0; i < m.meshlets.size(); ++i) {
        const unsigned fields[4] = {m.meshlets[i].vertex_offset, m.meshlets[i].triangle_offset, m.meshlets[i].vertex_count,
                                    m.meshlets[i].triangle_count};
        out << (i ? "," : "") << list(fields, 4);
    }
    out << "],\n\"meshlet_vertices\": " << list(m.vertices.data(), m.vertices.size());
    out << ",\n\"meshlet_triangles\": " << list(m.triangles.data(), m.triangles.size()) << ",\n\"bounds\": [";
    for (size_t i = 0; i < m.bounds.size(); ++i) {
        const meshopt_Bounds& b = m.bounds[i];
        out << (i ? ",\n" : "") << "{\"center\": " << list(b.center, 3) << ", \"radius\": " << number(b.radius)
            << ", \"cone_apex\": " << list(b.cone_apex, 3) << ", \"cone_axis\": " << list(b.cone_axis, 3)
            << ", \"cone_cutoff\": " << number(b.cone_cutoff) << ", \"cone_axis_s8\": " << list(b.cone_axis_s8, 3)
            << ", \"cone_cutoff_s8\": " << int(b.cone_cutoff_s8) << "}";
    }
    out << "]}\n";
}

// As meshoptimizer's demo dumps meshlets: the vertices, then an object per meshlet.
void writeObj(const Mesh& mesh, const Meshlets& m, const std::string& path) {
    std::ofstream out(path);
    for (size_t v = 0; v < mesh.positions.size(); v += 3)
        out << "v " << number(mesh.positions[v]) << " " << number(mesh.positions[v + 1]) << " " << number(mesh.positions[v + 2]) << "\n";
    for (size_t i = 0; i < m.meshlets.size(); ++i) {
        out << "o meshlet" << i << "\n";
        for (size_t t = 0; t < m.meshlets[i].triangle_count; ++t) {
            out << "f";
            for (int k = 0; k < 3; ++k) out << " " << m.vertices[m.meshlets[i].vertex_offset + m.triangles[m.meshlets[i].triangle_offset + 3 * t + k]] + 1;
            out << "\n";
        }
    }
}

struct Vec {
    double x, y, z;
};
Vec sub(Vec a, Vec b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
double dot(Vec a, Vec b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(Vec a, Vec b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }

// The standard orbit (docs/user/command-line.md): around the box centre at D half-diagonals (the box in float, as read).
std::vector<Vec> orbit(const Mesh& mesh, size_t count, double distance) {
    float low[3] = {mesh.positions[0], mesh.positions[1], mesh.positions[2]}, high[3] = {low[0], low[1], low[2]};
    for (size_t v = 0; v < mesh.positions.size(); ++v) low[v % 3] = std::min(low[v % 3], mesh.positions[v]), high[v % 3] = std::max(high[v % 3], mesh.positions[v]);
    const float center[3] = {0.5f * (low[0] + high[0]), 0.5f * (low[1] + high[1]), 0.5f * (low[2] + high[2])};
    const float extent[3] = {high[0] - low[0], high[1] - low[1], high[2] - low[2]};
    const double radius = 0.5f * std::sqrt(extent[0] * extent[0] + extent[1] * extent[1] + extent[2] * extent[2]);
    std::vector<Vec> eyes;
    for (size_t i = 0; i < count; ++i) {
        const double y = 1.0 - 2.0 * (double(i) + 0.5) / double(count), r = std::sqrt(std::max(0.0, 1.0 - y * y));
        const double phi = double(i) * M_PI * (3.0 - std::sqrt(5.0));
        const double scale = distance * radius;
        eyes.push_back({center[0] + scale * (std::cos(phi) * r), center[1] + scale * y, center[2] + scale * (std::sin(phi) * r)});
    }
    return eyes;
}

bool apexCulls(const meshopt_Bounds& b, const float eye[3]) {
    const float vx = b.cone_apex[0] - eye[0], vy = b.cone_apex[1] - eye[1], vz = b.cone_apex[2] - eye[2];
    const float length = std::sqrt(vx * vx + vy * vy + vz * vz);
    return (vx / length) * b.cone_axis[0] + (vy / length) * b.cone_axis[1] + (vz / length) * b.cone_axis[2] >= b.cone_cutoff;
}

bool sphereS8Culls(const meshopt_Bounds& b, const float eye[3]) {
    const float ax = b.cone_axis_s8[0] / 127.0f, ay = b.cone_axis_s8[1] / 127.0f, az = b.cone_axis_s8[2] / 127.0f;
    const float cutoff = b.cone_cutoff_s8 / 127.0f;
    const float cx = b.center[0] - eye[0], cy = b.center[1] - eye[1], cz = b.center[2] - eye[2];
    return cx * ax + cy * ay + cz * az >= cutoff * std::sqrt(cx * cx + cy * cy + cz * cz) + b.radius;
}

}  // namespace

int main(int argc, char** argv) {
    try {
        if (argc < 2) throw std::runtime_error("usage: meshopt_reference MESH.off [--views N] [--distance D] [--json OUT] [--obj OUT]");
        size_t views = 64, maxVertices = 64, maxTriangles = 124;
        double distance = 3.0;
        float coneWeight = 1.0f;
        std::string json, obj;
        for (int i = 2; i + 1 < argc; i += 2) {
            const std::string flag = argv[i], value = argv[i + 1];
            if (flag == "--views") views = std::stoul(value);
            else if (flag == "--distance") distance = std::stod(value);
            else if (flag == "--max-verts") maxVertices = std::stoul(value);
            else if (flag == "--max-tris") maxTriangles = std::stoul(value);
            else if (flag == "--cone-weight") coneWeight = std::stof(value);
            else if (flag == "--json") json = value;
            else if (flag == "--obj") obj = value;
            else throw std::runtime_error("unknown option " + flag);
        }
        const Mesh mesh = readOff(argv[1]);
        const Meshlets meshlets = buildMeshlets(mesh, maxVertices, maxTriangles, coneWeight);
        if (!json.empty()) writeJson(meshlets, json);
        if (!obj.empty()) writeObj(mesh, meshlets, obj);
        auto corner = [&](unsigned v) { return Vec{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]}; };
        size_t backFacing = 0, culled[2] = {0, 0}, falseCulls[2] = {0, 0};
        for (const Vec& e : orbit(mesh, views, distance)) {
            const float eye[3] = {float(e.x), float(e.y), float(e.z)};
            for (size_t i = 0; i < meshlets.meshlets.size(); ++i) {
                const meshopt_Meshlet& m = meshlets.meshlets[i];
                size_t back = 0, front = 0;
                for (size_t t = 0; t < m.triangle_count; ++t) {
                    Vec q[3];
                    for (int k = 0; k < 3; ++k) q[k] = corner(meshlets.vertices[m.vertex_offset + meshlets.triangles[m.triangle_offset + 3 * t + k]]);
                    const Vec n = cross(sub(q[1], q[0]), sub(q[2], q[0]));
                    if (dot(n, n) == 0.0) continue;  // zero area: neither side
                    bool away = true;
                    for (const Vec& corner : q) away = away && dot(n, sub(e, corner)) < 0.0;
                    ++(away ? back : front);
                }
                backFacing += back;
                const bool culls[2] = {apexCulls(meshlets.bounds[i], eye), sphereS8Culls(meshlets.bounds[i], eye)};
                for (int test = 0; test < 2; ++test)
                    if (culls[test]) culled[test] += back, falseCulls[test] += front > 0;
            }
        }
        auto efficiency = [&](size_t count) { return backFacing ? double(count) / double(backFacing) : 1.0; };
        std::printf("{\"mesh\": \"%s\", \"meshlets\": %zu, \"views\": %zu, \"distance\": %g, \"back_facing_triangles\": %zu,\n"
                    " \"meshopt-apex-f32\": {\"triangles_culled\": %zu, \"efficiency\": %.9f, \"false_culls\": %zu},\n"
                    " \"meshopt-sphere-s8\": {\"triangles_culled\": %zu, \"efficiency\": %.9f, \"false_culls\": %zu}}\n",
                    argv[1], meshlets.meshlets.size(), views, distance, backFacing, culled[0], efficiency(culled[0]), falseCulls[0],
                    culled[1], efficiency(culled[1]), falseCulls[1]);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "meshopt_reference: %s\n", error.what());
        return 1;
    }
    return 0;
}
