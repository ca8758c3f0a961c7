#include "UiTestSupport.h"

#include <fstream>
#include <sstream>

#include <QDir>
#include <QFileInfo>
#include <QProcess>

#include "io/MeshReader.h"

namespace conescope::testing {

QString datasetPath(const char* name) { return QDir(QStringLiteral(CONESCOPE_DATASETS_DIR)).filePath(QLatin1String(name)); }

RunStatistics statisticsInProcess(const QString& meshPath, const Settings& settings) {
    return runStatistics(readMesh(meshPath.toStdString()), settings, QFileInfo(meshPath).fileName().toStdString());
}

nlohmann::json readJsonFile(const QString& path) {
    std::ifstream in(path.toStdString());
    return nlohmann::json::parse(in);
}

namespace {
std::vector<std::string> splitCsvLine(const std::string& line) {
    std::vector<std::string> cells;
    std::stringstream stream(line);
    std::string cell;
    while (std::getline(stream, cell, ',')) cells.push_back(cell);
    return cells;
}
}  // namespace

std::vector<std::map<std::string, std::string>> readCsvTable(const QString& path) {
    std::ifstream in(path.toStdString());
    std::string line;
    std::vector<std::map<std::string, std::string>> rows;
    std::vector<std::string> header;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        if (header.empty()) {
            header = splitCsvLine(line);
            continue;
        }
        const std::vector<std::string> cells = splitCsvLine(line);
        std::map<std::string, std::string> row;
        for (size_t i = 0; i < header.size() && i < cells.size(); ++i) row[header[i]] = cells[i];
        rows.push_back(row);
    }
    return rows;
}

nlohmann::json withoutTimings(nlohmann::json document) {
    if (document.is_object()) document.erase("ns_per_cluster");
    if (document.is_object() || document.is_array())
        for (auto item = document.begin(); item != document.end(); ++item) *item = withoutTimings(*item);
    return document;
}

int runProgram(const QString& program, const QStringList& arguments, QString* errors) {
    QProcess process;
    process.start(program, arguments);
    if (!process.waitForFinished(120000)) return -1;
    if (errors) *errors = QString::fromLocal8Bit(process.readAllStandardError());
    return process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
}

QString eyeArgument(const glm::dvec3& eye) {
    return QStringLiteral("%1,%2,%3").arg(eye.x, 0, 'g', 17).arg(eye.y, 0, 'g', 17).arg(eye.z, 0, 'g', 17);
}

QStringList cliSettingsArguments(const Settings& settings) {
    QStringList names;
    QStringList arguments{QStringLiteral("--builder"), QString::fromStdString(toString(settings.builder)),
                          QStringLiteral("--max-verts"), QString::number(settings.limits.maxVertices),
                          QStringLiteral("--max-tris"), QString::number(settings.limits.maxTriangles),
                          QStringLiteral("--clusters"), QString::number(settings.clusterCount),
                          QStringLiteral("--normal-weight"), QString::number(settings.normalWeight, 'g', 17),
                          QStringLiteral("--cone-weight"), QString::number(double(settings.meshoptConeWeight), 'g', 9),
                          QStringLiteral("--sphere"), QString::fromStdString(toString(settings.sphere))};
    if (settings.conesPerCluster > 1) arguments << QStringLiteral("--cones-per-cluster") << QString::number(settings.conesPerCluster);
    // The orbit's size and distance mean nothing for a single eye (the CLI refuses both together).
    if (!settings.eye)
        arguments << QStringLiteral("--views") << QString::number(settings.views) << QStringLiteral("--distance")
                  << QString::number(settings.distance, 'g', 17);
    for (ConeMethod cone : settings.cones) names << QString::fromStdString(toString(cone));
    arguments << QStringLiteral("--cone") << names.join(QLatin1Char(','));
    names.clear();
    for (CullTest test : settings.tests) names << QString::fromStdString(toString(test));
    arguments << QStringLiteral("--test") << names.join(QLatin1Char(','));
    if (settings.eye) arguments << QStringLiteral("--eye=") + eyeArgument(*settings.eye);
    if (settings.orthographic) arguments << QStringLiteral("--ortho");
    if (settings.fixWinding) arguments << QStringLiteral("--fix-winding");
    if (!settings.clusterFile.empty()) arguments << QStringLiteral("--cluster-file") << QString::fromStdString(settings.clusterFile);
    return arguments;
}

}  // namespace conescope::testing
