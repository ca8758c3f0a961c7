#include "Datasets.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace conescope {

QStringList datasetFolderCandidates() {
    QStringList folders;
    if (QCoreApplication::instance()) {
        // build/ui/conescope -> ../../datasets; an install puts datasets next to bin/ or in share/.
        const QDir executable(QCoreApplication::applicationDirPath());
        for (const char* relative : {"datasets", "../datasets", "../../datasets", "../share/conescope/datasets"})
            folders << QDir::cleanPath(executable.filePath(QString::fromLatin1(relative)));
    }
#ifdef CONESCOPE_SOURCE_DIR
    folders << QDir::cleanPath(QStringLiteral(CONESCOPE_SOURCE_DIR) + QStringLiteral("/datasets"));
#endif
    folders.removeDuplicates();
    return folders;
}

QString defaultMeshPath() {
    for (const QString& name : {QStringLiteral("torus.off"), QStringLiteral("icosphere.off")})
        for (const QString& folder : datasetFolderCandidates()) {
            const QFileInfo file(QDir(folder).filePath(name));
            if (file.isFile()) return file.absoluteFilePath();
        }
    return {};
}

}  // namespace conescope
