#include "ClusterIdFile.h"

#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "io/ClassicLocale.h"
#include "io/FileChecks.h"
#include "io/MeshletFiles.h"

namespace conescope {

std::vector<double> readClusterIdFile(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open cluster id file");
    const ScopedClassicNumericLocale classic;  // "2.5" is a number under any locale the window runs in
    std::vector<double> ids;
    std::string line;
    size_t lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        const size_t hash = line.find('#');
        if (hash != std::string::npos) line.resize(hash);
        std::istringstream words(line);
        std::string word;
        while (words >> word) {
            char* end = nullptr;
            const double value = std::strtod(word.c_str(), &end);
            if (end == word.c_str() || *end != '\0')
                throw std::runtime_error(path + ":" + std::to_string(lineNumber) + ": " + quotedForMessage(word) + " is not a number");
            ids.push_back(value);
        }
    }
    return ids;
}

Settings withClusterIds(Settings settings) {
    // A meshlet file is read onto the mesh instead (ClusterFiles.h: it may cut the mesh's polygons).
    if (settings.builder != Builder::File || settings.clusterFile.empty() || isMeshletFile(settings.clusterFile)) return settings;
    auto file = std::make_shared<ClusterIdFile>();
    file->path = settings.clusterFile;
    try {
        file->ids = readClusterIdFile(settings.clusterFile);
    } catch (const std::exception& error) {
        file->error = error.what();
    }
    settings.clusterIds = std::move(file);
    return settings;
}

}  // namespace conescope
