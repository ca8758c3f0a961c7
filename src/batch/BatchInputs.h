// The meshes of a batch: found under the paths given, sorted, taken by shard, named in the output
// folder and hashed, so a batch run again knows what it has done. Shared by `conescope-cli batch` and
// the Python module's batch on Dask, whose rows must name and hash alike.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/Settings.h"
#include "io/StatisticsIO.h"

namespace conescope::cli {

struct BatchMesh {
    std::string path;       // as found: the path given, or a folder given joined with the file below it
    std::string canonical;  // absolute with links resolved: one mesh however it was reached
    std::string json;       // its statistics file, relative to the output folder (batchJsonName)
    uintmax_t bytes = 0;    // its size, which weighs it in the ETA
    // Why the path cannot be a mesh (it does not exist, a link to nothing, a folder named like a mesh,
    // a folder that cannot be listed, not a file): its row is this error, no worker reads it.
    std::string problem;
};

// Every file given, and every file below a folder given whose extension a reader takes (the readers'
// one table, io/MeshReader.h), skipping hidden files and folders and not following links to folders;
// sorted by path, each mesh once. A path given that is no mesh or folder, and an entry found with a
// mesh's extension that is no file, come with their `problem`: a batch never stops for one path.
std::vector<BatchMesh> findBatchMeshes(const std::vector<std::string>& paths);

// "I/N" with 1 <= I <= N. Throws std::invalid_argument.
struct Shard {
    size_t index = 1, count = 1;
};
Shard parseShard(const std::string& text);

// Meshes k (0-based, in sorted order) with k % count == index - 1: every count-th, for job arrays.
std::vector<BatchMesh> meshesOfShard(const std::vector<BatchMesh>& meshes, const Shard& shard);

// "meshes/NAME-XXXXXXXX.json": the file's name (two meshes of one name in different folders differ
// in the hash of their canonical paths). `suffix` goes before ".json" (".compare" for a comparison).
std::string batchJsonName(const std::string& canonicalPath, const std::string& suffix = "");

// A hash (XXH3, 128 bits, hex) of the file's bytes, and for a .gltf those of the buffer files it
// names: what decides whether a mesh changed. Empty when the file cannot be read (its reader then says
// why).
std::string contentHash(const std::string& path);

// A hash of everything besides the mesh that decides a row and its files: the settings (and a cluster
// file's bytes), the comparison asked for, the tables the JSON keeps, the columns added on request
// (`extras`: "granularity", "lod", both or none) and the program's version.
std::string settingsHash(const Settings& settings, const std::string& compare, const StatisticsDetail& detail,
                         const std::string& extras = {});

}  // namespace conescope::cli
