// conescope: the viewer, or with --screenshot a headless render of one frame.
#include <cstdio>
#include <iostream>

#include <QApplication>
#include <QFileInfo>
#include <QSurfaceFormat>

#include <QVTKOpenGLNativeWidget.h>

#include "CommandLine.h"
#include "Datasets.h"
#include "MainWindow.h"

namespace {

QStringList argumentList(int argc, char** argv) {
    QStringList arguments;
    for (int i = 0; i < argc; ++i) arguments << QString::fromLocal8Bit(argv[i]);
    return arguments;
}

void setApplicationNames() {
    QCoreApplication::setOrganizationName(QStringLiteral("ConeScope"));
    QCoreApplication::setApplicationName(QStringLiteral("conescope"));
    QCoreApplication::setApplicationVersion(QStringLiteral(CONESCOPE_VERSION));
}

}  // namespace

int main(int argc, char** argv) {
    using namespace conescope;
    const CommandLineResult parsed = parseCommandLine(argumentList(argc, argv));
    if (parsed.action == CommandLineResult::Action::ExitSuccess) {
        std::cout << parsed.message.toStdString() << '\n';
        return 0;
    }
    if (parsed.action == CommandLineResult::Action::ExitFailure) {
        std::cerr << "conescope: " << parsed.message.toStdString() << "\n(see conescope --help)\n";
        return 1;
    }
    const AppOptions& options = parsed.options;

    if (!options.screenshot.isEmpty()) {
        // No window: the scene renders off screen. The application object only locates the datasets.
        QCoreApplication application(argc, argv);
        setApplicationNames();
        return runHeadlessScreenshot(options);
    }

    // The GL format VTK needs, before the application creates any context.
    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    setApplicationNames();
    MainWindow window;
    window.setSettings(options.settings);
    window.setFaceColoring(options.coloring);
    if (options.eye) window.setInitialEye(*options.eye);
    if (options.layers) showOnly(*options.layers, window);
    window.show();
    const QString mesh = options.mesh.isEmpty() ? defaultMeshPath() : options.mesh;
    if (!mesh.isEmpty()) window.openMesh(mesh);
    return application.exec();
}
