// Where the bundled meshes are: the source tree's datasets/ (a compile definition, for a build
// run in place) or a datasets/ folder found relative to the executable (an installed or copied build).
#pragma once

#include <QString>
#include <QStringList>

namespace conescope {

// Folders that may hold the bundled meshes, most specific first.
QStringList datasetFolderCandidates();

// The mesh the window starts on when none is given: torus.off, else icosphere.off, from the first
// folder that has one. Empty when none is found.
QString defaultMeshPath();

}  // namespace conescope
