// Turns VTK's error reporting (vtkErrorMacro -> observers or the global output window) into data
// we can put into an exception. Internal to conescope_io.
#pragma once

#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkCommand;
class vtkObject;

namespace conescope {

// While one of these lives, VTK errors and warnings raised on this thread by watched objects (their
// ErrorEvent/WarningEvent observers) or by anything else (through the global output window) are
// recorded here instead of being printed. Outside any capture, the output window forwards to the
// window that was installed before, so the rest of the program keeps VTK's usual behaviour.
// The first capture also turns vtkLogger's own stderr output off for the whole process (it would
// print every error a second time, bypassing the output window); VTK errors outside a capture
// still reach the previous output window, which prints them to stderr by default.
class VtkMessageCapture {
public:
    VtkMessageCapture();
    ~VtkMessageCapture();
    VtkMessageCapture(const VtkMessageCapture&) = delete;
    VtkMessageCapture& operator=(const VtkMessageCapture&) = delete;

    // Observes ErrorEvent and WarningEvent on object (a reader, its executive, a writer).
    void watch(vtkObject* object);

    void recordError(const std::string& rawMessage);
    void recordWarning(const std::string& rawMessage);

    bool hasErrors() const { return !errors_.empty(); }
    const std::vector<std::string>& errors() const { return errors_; }
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Errors (or, if none, warnings) as one line: "first; second; ...".
    std::string summary() const;

private:
    std::vector<std::string> errors_;
    std::vector<std::string> warnings_;
    vtkSmartPointer<vtkCommand> observer_;
    VtkMessageCapture* enclosing_ = nullptr;
};

// "ERROR: In /build/.../vtkPLYReader.cxx, line 93\nvtkPLYReader (0x55d0): Could not open\n\n"
// becomes "vtkPLYReader: Could not open": no source location, no pointer, one line.
std::string cleanVtkMessage(const std::string& rawMessage);

}  // namespace conescope
