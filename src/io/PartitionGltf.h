// A partition as a glTF 2.0 document (internal to conescope_io; ClusterFiles.h writes it): one mesh
// with a triangle primitive per cluster, all reading one POSITION accessor of the mesh's world
// positions, its buffer embedded as a base64 data URI. Polygons are written as fan triangles.
#pragma once

#include <string>

#include "core/Mesh.h"
#include "core/Partition.h"

namespace conescope {

std::string partitionGltf(const Mesh& mesh, const Partition& partition);

}  // namespace conescope
