// Makes this thread parse and print numbers the "C" way while VTK reads or writes (internal).
#pragma once

#include <clocale>
#include <locale.h>

namespace conescope {

// Qt applications call setlocale(LC_ALL, ""), and VTK's ASCII readers parse numbers with
// locale-dependent C functions: under a German locale vtkSTLReader fails on "0.5". uselocale()
// changes the numeric locale for the calling thread only, so other threads keep theirs.
class ScopedClassicNumericLocale {
public:
    ScopedClassicNumericLocale()
        : classic_(newlocale(LC_NUMERIC_MASK, "C", static_cast<locale_t>(0))),
          previous_(classic_ ? uselocale(classic_) : static_cast<locale_t>(0)) {}
    ~ScopedClassicNumericLocale() {
        if (!classic_) return;
        uselocale(previous_);
        freelocale(classic_);
    }
    ScopedClassicNumericLocale(const ScopedClassicNumericLocale&) = delete;
    ScopedClassicNumericLocale& operator=(const ScopedClassicNumericLocale&) = delete;

private:
    locale_t classic_;
    locale_t previous_;
};

}  // namespace conescope
