// What the batch tests share: a library of meshes made in a scratch folder and results.csv read back.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace conescope::clitest {

// The 8 meshes bundled in datasets/ (not datasets/cgal), into `folder`.
void copyBundledDatasets(const std::filesystem::path& folder);

// The bundled datasets (8), four meshes of tests/data (one named like a dataset, in another folder;
// a .gltf with its .bin), three polygon OBJ files written here into polygons/ (quads and an n-gon cap, pentagons, hexagons),
// and broken.off (a truncated header): 16 files, 15 of them readable.
std::vector<std::string> makeMeshLibrary(const std::filesystem::path& folder);

// The OBJ files of makeMeshLibrary: a UV sphere of quads with 12-gon caps, a dodecahedron, a
// hexagonal prism tube.
std::string quadSphereObj();
std::string dodecahedronObj();
std::string hexagonTubeObj();

// results.csv as rows of column -> cell; `lines` gets every line of the file, the header included.
std::vector<std::map<std::string, std::string>> readResults(const std::string& path, std::vector<std::string>* lines = nullptr);

}  // namespace conescope::clitest
