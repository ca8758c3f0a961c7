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

QString findDataset(const QString& name) {
    for (const QString& folder : datasetFolderCandidates()) {
        const QFileInfo file(QDir(folder).filePath(name));
        if (file.isFile()) return file.absoluteFilePath();
    }
    return {};
}

QString defaultMeshPath() {
    for (const QString& name : {QStringLiteral("torus.off"), QStringLiteral("icosphere.off")})
        if (QString path = findDataset(name); !path.isEmpty()) return path;
    return {};
}

std::vector<std::pair<QString, QString>> exampleMeshes() {
    return {{QCoreApplication::translate("Datasets", "&Cylinder"), QStringLiteral("cylinder.off")},
            {QCoreApplication::translate("Datasets", "&Sphere"), QStringLiteral("icosphere.off")},
            {QCoreApplication::translate("Datasets", "&Bumpy plane"), QStringLiteral("bumpy-plane.off")},
            {QCoreApplication::translate("Datasets", "&Torus"), QStringLiteral("torus.off")}};
}

QStringList lessonFiles() {
    for (const QString& folder : datasetFolderCandidates()) {
        const QDir lessons(QDir(folder).filePath(QStringLiteral("lessons")));
        const QStringList names = lessons.entryList({QStringLiteral("*.json")}, QDir::Files, QDir::Name);
        if (names.isEmpty()) continue;
        QStringList paths;
        for (const QString& name : names) paths << lessons.absoluteFilePath(name);
        return paths;
    }
    return {};
}

}  // namespace conescope
