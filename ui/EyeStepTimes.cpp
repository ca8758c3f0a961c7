#include "EyeStepTimes.h"

#include <QCoreApplication>

namespace conescope {

namespace {

QString ms(double seconds) { return QString::number(1000.0 * seconds, 'f', 1); }

}  // namespace

QString describe(const EyeStepTimes& times) {
    return QCoreApplication::translate("EyeStepTimes", "Eye step %1 ms: cull+scene %2, panels %3, Gauss map %4, 3D view %5, eye view %6")
        .arg(ms(times.total()), ms(times.cullAndScene), ms(times.panels), ms(times.gaussMap), ms(times.observerView),
             ms(times.eyeView));
}

}  // namespace conescope
