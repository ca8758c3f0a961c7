#include "Multisampling.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QString>

#include <vtkOpenGLRenderWindow.h>

namespace conescope {

namespace {

QString rendererName() {
    QOpenGLContext context;
    QOffscreenSurface surface;
    surface.create();
    if (!context.create() || !context.makeCurrent(&surface)) return {};
    const auto* name = reinterpret_cast<const char*>(context.functions()->glGetString(GL_RENDERER));
    const QString result = name ? QString::fromLatin1(name) : QString();
    context.doneCurrent();
    return result;
}

}  // namespace

int viewMultisamples() {
    bool given = false;
    const int samples = qEnvironmentVariableIntValue("CONESCOPE_SAMPLES", &given);
    if (given && samples >= 0) return samples;
    const QString renderer = rendererName().toLower();
    const bool software = renderer.contains(QLatin1String("llvmpipe")) || renderer.contains(QLatin1String("softpipe")) ||
                          renderer.contains(QLatin1String("swrast"));
    return software ? 0 : 8;
}

void applyViewMultisamples() { vtkOpenGLRenderWindow::SetGlobalMaximumNumberOfMultiSamples(viewMultisamples()); }

}  // namespace conescope
