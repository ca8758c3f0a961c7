// conescope-bench-eye: what one step of a dragged eye costs in the window (issue 33, item 6). Opens
// each mesh in the application's window, moves the eye around the mesh in small steps as a drag does
// (Session::moveEyeSoon, then the event loop) and reports per step the median of: the cull and scene
// update (CPU, Session::eyeSeconds), the window's parts (MainWindow::eyeStepTimes) and the whole step
// until the event loop is idle again. Run under xvfb-run; --samples sets the views' multisampling
// (by default what the application chooses: none on a software renderer, ui/Multisampling.h).
//   xvfb-run -a -s "-screen 0 1280x1024x24" conescope-bench-eye --mesh M.off [--subdivide N] [--steps N]
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <vector>

#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkOpenGLRenderWindow.h>

#include "BenchSupport.h"
#include "MainWindow.h"
#include "Multisampling.h"
#include "core/Pipeline.h"
#include "io/MeshReader.h"
#include "io/MeshWriter.h"

using namespace conescope;

namespace {

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

// The eye turned by `radians` about the vertical axis through `centre`.
glm::dvec3 turned(const glm::dvec3& eye, const glm::dvec3& centre, double radians) {
    const glm::dvec3 d = eye - centre;
    return centre + glm::dvec3(d.x * std::cos(radians) + d.z * std::sin(radians), d.y, -d.x * std::sin(radians) + d.z * std::cos(radians));
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app("Time one eye step of the window (CPU work and end to end)");
    std::string meshPath;
    size_t subdivide = 0;
    int steps = 24;
    int samples = -1;
    int width = 1280, height = 720;
    app.add_option("--mesh", meshPath, "mesh file")->required();
    app.add_option("--subdivide", subdivide, "subdivide 1->4 until at least this many triangles (0: as it is)");
    app.add_option("--steps", steps, "eye steps measured (3 degrees each)")->capture_default_str();
    app.add_option("--samples", samples, "multisamples of the views (-1: as the application chooses, Multisampling.h)")
        ->capture_default_str();
    app.add_option("--width", width, "window width")->capture_default_str();
    app.add_option("--height", height, "window height")->capture_default_str();
    CLI11_PARSE(app, argc, argv);

    QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
    QApplication application(argc, argv);
    if (samples < 0) samples = viewMultisamples();
    vtkOpenGLRenderWindow::SetGlobalMaximumNumberOfMultiSamples(samples);
    std::string opened = meshPath;
    const std::filesystem::path scratch = std::filesystem::temp_directory_path() / "conescope-bench-eye.off";
    if (subdivide > 0) {
        writeOff(bench::subdivideToAtLeast(readMesh(meshPath), subdivide), scratch.string());
        opened = scratch.string();
    }
    MainWindow window;
    window.setErrorDialogsEnabled(false);
    window.resize(width, height);
    window.show();
    const bool loaded = window.openMeshBlocking(QString::fromStdString(opened));
    if (subdivide > 0) std::filesystem::remove(scratch);
    if (!loaded) {
        std::cerr << "could not open " << meshPath << ": " << window.lastError().toStdString() << "\n";
        return 1;
    }
    QApplication::processEvents();
    Session& session = window.session();
    const glm::dvec3 centre(session.preparedMesh()->box.center());
    std::vector<double> core, cull, panels, gauss, observer, eyeView, whole;
    glm::dvec3 eye = session.eyePosition();
    for (int step = 0; step <= steps; ++step) {
        eye = turned(eye, centre, 3.0 * M_PI / 180.0);
        const auto start = std::chrono::steady_clock::now();
        session.moveEyeSoon(eye);
        QApplication::processEvents();
        QApplication::processEvents();
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (step == 0) continue;  // the first step pays for first-use allocations
        // The core's part of cull+scene alone: the same measureEye the session calls.
        const auto coreStart = std::chrono::steady_clock::now();
        const EyeMeasurement again = measureEye(*session.preparedMesh(), *session.clusters(), session.measurement()->eye,
                                                displayedTest(session.settings()));
        core.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - coreStart).count());
        if (again.culled != session.measurement()->culled) {
            std::cerr << "measureEye gave other decisions than the window shows\n";
            return 1;
        }
        const EyeStepTimes& times = window.eyeStepTimes();
        cull.push_back(times.cullAndScene);
        panels.push_back(times.panels);
        gauss.push_back(times.gaussMap);
        observer.push_back(times.observerView);
        eyeView.push_back(times.eyeView);
        whole.push_back(seconds);
    }
    const auto ms = [](double s) { return 1000.0 * s; };
    std::printf("%s | %zu triangles | %d clusters | samples %d | %dx%d | steps %d\n", meshPath.c_str(),
                size_t(session.preparedMesh()->triangles), int(session.clusters()->partition.clusterCount), samples, width,
                height, steps);
    std::printf("median ms: cull+scene %.1f (core measureEye %.1f) | panels %.1f | Gauss map %.1f | 3D view %.1f | eye view %.1f | "
                "end to end %.1f (rest: event loop, widget paint %.1f)\n",
                ms(median(cull)), ms(median(core)), ms(median(panels)), ms(median(gauss)), ms(median(observer)), ms(median(eyeView)), ms(median(whole)),
                ms(median(whole) - median(cull) - median(panels) - median(gauss) - median(observer) - median(eyeView)));
    return 0;
}
