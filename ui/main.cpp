// conescope: the viewer, with --screenshot a headless render of one frame, or with --replay a
// replay file's steps played in the window.
#include <cstdio>
#include <iostream>

#include <QApplication>
#include <QFileInfo>
#include <QSurfaceFormat>
#include <QTimer>

#include <QVTKOpenGLNativeWidget.h>

#include "CommandLine.h"
#include "Datasets.h"
#include "MainWindow.h"
#include "ReplayPlayer.h"

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

    // A replay is read whole before any window opens: a bad file fails at once, naming the step.
    std::vector<ReplayStep> replay;
    if (!options.replay.isEmpty()) {
        try {
            replay = readReplayFile(options.replay);
        } catch (const ReplayError& error) {
            std::cerr << "conescope: " << error.what() << '\n';
            return 1;
        }
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
    // A replay starts from an empty window unless a mesh is given: its steps open what they need.
    const QString mesh = !options.mesh.isEmpty() || !options.replay.isEmpty() ? options.mesh : defaultMeshPath();
    if (!mesh.isEmpty()) window.openMesh(mesh);
    if (options.replay.isEmpty()) return application.exec();

    int exitCode = 0;
    ReplayPlayer player(window);
    // Errors go to the terminal, not into dialogs that would wait for a click.
    window.setErrorDialogsEnabled(false);
    QObject::connect(&player, &ReplayPlayer::finished, &application, [&]() {
        if (!options.stay) QCoreApplication::exit(0);
        window.setErrorDialogsEnabled(true);
    });
    QObject::connect(&player, &ReplayPlayer::failed, &application, [&](const QString& message) {
        std::cerr << "conescope: " << options.replay.toStdString() << ": " << message.toStdString() << '\n';
        exitCode = 1;
        if (!options.stay) QCoreApplication::exit(1);
        window.setErrorDialogsEnabled(true);
    });
    QTimer::singleShot(0, &player, [&]() { player.play(std::move(replay)); });
    const int code = application.exec();
    return exitCode != 0 ? exitCode : code;
}
