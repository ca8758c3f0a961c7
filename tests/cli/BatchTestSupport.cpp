#include "BatchTestSupport.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "CliTestSupport.h"
#include "io/BatchTable.h"

namespace conescope::clitest {

namespace fs = std::filesystem;

namespace {

void writeText(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

void copyInto(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

std::string vertexLine(double x, double y, double z) {
    std::ostringstream line;
    line.precision(9);
    line << "v " << x << ' ' << y << ' ' << z << '\n';
    return line.str();
}

}  // namespace

std::string quadSphereObj() {
    const int rings = 10, segments = 12;
    std::string text = "# a UV sphere: quads between the rings, a 12-gon at each pole\n";
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
            text += vertexLine(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
        }
    const auto index = [&](int r, int s) { return std::to_string((r - 1) * segments + (s % segments) + 1); };
    std::string top = "f", bottom = "f";
    for (int s = segments - 1; s >= 0; --s) top += " " + index(1, s);
    for (int s = 0; s < segments; ++s) bottom += " " + index(rings - 1, s);
    text += top + "\n" + bottom + "\n";
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s)
            text += "f " + index(r, s) + " " + index(r, s + 1) + " " + index(r + 1, s + 1) + " " + index(r + 1, s) + "\n";
    return text;
}

std::string dodecahedronObj() {
    const double p = (1 + std::sqrt(5.0)) / 2, q = 1 / p;
    const double v[20][3] = {{1, 1, 1},   {1, 1, -1},  {1, -1, 1},  {1, -1, -1}, {-1, 1, 1},  {-1, 1, -1}, {-1, -1, 1},
                             {-1, -1, -1}, {0, q, p},   {0, q, -p},  {0, -q, p},  {0, -q, -p}, {q, p, 0},   {q, -p, 0},
                             {-q, p, 0},  {-q, -p, 0}, {p, 0, q},   {p, 0, -q},  {-p, 0, q},  {-p, 0, -q}};
    const int faces[12][5] = {{0, 8, 10, 2, 16},  {0, 16, 17, 1, 12}, {0, 12, 14, 4, 8},  {1, 17, 3, 11, 9},
                              {1, 9, 5, 14, 12},  {2, 10, 6, 15, 13}, {2, 13, 3, 17, 16}, {3, 13, 15, 7, 11},
                              {4, 14, 5, 19, 18}, {4, 18, 6, 10, 8},  {5, 9, 11, 7, 19},  {6, 18, 19, 7, 15}};
    std::string text = "# a dodecahedron: twelve pentagons\n";
    for (const auto& vertex : v) text += vertexLine(vertex[0], vertex[1], vertex[2]);
    for (const auto& face : faces) {
        text += "f";
        for (int corner : face) text += " " + std::to_string(corner + 1);
        text += "\n";
    }
    return text;
}

std::string hexagonTubeObj() {
    const int sides = 6, levels = 8;
    std::string text = "# a hexagonal tube: quads around, a hexagon at each end\n";
    for (int l = 0; l < levels; ++l)
        for (int s = 0; s < sides; ++s)
            text += vertexLine(std::cos(2 * M_PI * s / sides), 0.4 * l, std::sin(2 * M_PI * s / sides));
    const auto index = [&](int l, int s) { return std::to_string(l * sides + (s % sides) + 1); };
    std::string bottom = "f", top = "f";
    for (int s = 0; s < sides; ++s) bottom += " " + index(0, s);
    for (int s = sides - 1; s >= 0; --s) top += " " + index(levels - 1, s);
    text += bottom + "\n" + top + "\n";
    for (int l = 0; l + 1 < levels; ++l)
        for (int s = 0; s < sides; ++s)
            text += "f " + index(l, s) + " " + index(l + 1, s) + " " + index(l + 1, s + 1) + " " + index(l, s + 1) + "\n";
    return text;
}

void copyBundledDatasets(const fs::path& folder) {
    for (const char* name : {"cube-quads.off", "cube.off", "elephant.off", "fandisk.off", "hexagonal-prism.off",
                             "icosphere-clusters.vtp", "icosphere.off", "torus.off"})
        copyInto(datasetsDir() / name, folder / name);
}

std::vector<std::string> makeMeshLibrary(const fs::path& folder) {
    copyBundledDatasets(folder);
    const fs::path data = CONESCOPE_TESTDATA_DIR;
    copyInto(data / "formats/cube-binary.ply", folder / "formats/cube-binary.ply");
    copyInto(data / "gltf/cube.glb", folder / "formats/cube.glb");
    copyInto(data / "gltf/cube.gltf", folder / "formats/cube.gltf");  // and its buffer, which is no mesh
    copyInto(data / "gltf/cube.bin", folder / "formats/cube.bin");
    copyInto(datasetsDir() / "torus.off", folder / "formats/torus.off");  // the name of another mesh
    writeText(folder / "polygons/quad-sphere.obj", quadSphereObj());
    writeText(folder / "polygons/dodecahedron.obj", dodecahedronObj());
    writeText(folder / "polygons/hexagon-tube.obj", hexagonTubeObj());
    writeText(folder / "broken.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
    std::vector<std::string> files;
    for (const auto& entry : fs::recursive_directory_iterator(folder))
        if (entry.is_regular_file() && entry.path().extension() != ".bin") files.push_back(entry.path().string());
    return files;
}

std::vector<std::map<std::string, std::string>> readResults(const std::string& path, std::vector<std::string>* lines) {
    const std::vector<std::string> all = splitLines(readTextFile(path));
    if (lines) *lines = all;
    std::vector<std::map<std::string, std::string>> rows;
    if (all.empty()) return rows;
    const std::vector<std::string> header = splitCsvLine(all[0]);
    for (size_t k = 1; k < all.size(); ++k) {
        const std::vector<std::string> cells = splitCsvLine(all[k]);
        if (cells.size() != header.size()) throw std::runtime_error("a row of " + path + " has another number of cells");
        std::map<std::string, std::string> row;
        for (size_t c = 0; c < cells.size(); ++c) row[header[c]] = cells[c];
        rows.push_back(row);
    }
    return rows;
}

}  // namespace conescope::clitest
