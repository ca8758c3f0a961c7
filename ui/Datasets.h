// Where the bundled meshes are: the source tree's datasets/ (a compile definition, for a build
// run in place) or a datasets/ folder found relative to the executable (an installed or copied build).
#pragma once

#include <utility>
#include <vector>

#include <QString>
#include <QStringList>

namespace conescope {

// Folders that may hold the bundled meshes, most specific first.
QStringList datasetFolderCandidates();

// The mesh the window starts on when none is given: torus.off, else icosphere.off, from the first
// folder that has one. Empty when none is found.
QString defaultMeshPath();

// `name` in the first folder that has it, as an absolute path; empty when none has.
QString findDataset(const QString& name);

// File > Examples: the teaching meshes, each a menu label and a file name.
std::vector<std::pair<QString, QString>> exampleMeshes();

// The ready-made lessons (replay files in lessons/ beside the bundled meshes), sorted by name.
QStringList lessonFiles();

}  // namespace conescope
