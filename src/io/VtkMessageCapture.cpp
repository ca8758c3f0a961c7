#include "io/VtkMessageCapture.h"

#include <algorithm>
#include <mutex>
#include <regex>

#include <vtkCommand.h>
#include <vtkLogger.h>
#include <vtkObject.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

namespace conescope {

namespace {

// The capture active on this thread; VTK readers run on the calling thread, so a reader used on a
// worker thread is captured there without disturbing the GUI thread.
thread_local VtkMessageCapture* activeCapture = nullptr;

// Global VTK output window: records into the active capture, otherwise hands the message to the
// window that was installed before us.
class CapturingOutputWindow : public vtkOutputWindow {
public:
    static CapturingOutputWindow* New();
    vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);

    void SetPrevious(vtkOutputWindow* previous) { previous_ = previous; }

    void DisplayErrorText(const char* text) override {
        if (activeCapture) return activeCapture->recordError(text ? text : "");
        if (previous_) previous_->DisplayErrorText(text);
    }
    void DisplayWarningText(const char* text) override {
        if (activeCapture) return activeCapture->recordWarning(text ? text : "");
        if (previous_) previous_->DisplayWarningText(text);
    }
    void DisplayGenericWarningText(const char* text) override {
        if (activeCapture) return activeCapture->recordWarning(text ? text : "");
        if (previous_) previous_->DisplayGenericWarningText(text);
    }
    void DisplayDebugText(const char* text) override {
        if (activeCapture) return;
        if (previous_) previous_->DisplayDebugText(text);
    }
    void DisplayText(const char* text) override {
        if (activeCapture) return;
        if (previous_) previous_->DisplayText(text);
    }

private:
    vtkSmartPointer<vtkOutputWindow> previous_;
};

vtkStandardNewMacro(CapturingOutputWindow);

// Puts a CapturingOutputWindow in place unless it already is; checked on every capture because the
// GUI may install its own window later, which we then wrap in turn.
void installCapturingOutputWindow() {
    // vtkLogger prints errors to stderr on its own, before and besides the output window; with it
    // off, VTK output outside a capture still reaches the previous window (stderr by default).
    static std::once_flag loggerSilenced;
    std::call_once(loggerSilenced, [] { vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); });
    static std::mutex installMutex;
    std::lock_guard<std::mutex> lock(installMutex);
    vtkOutputWindow* current = vtkOutputWindow::GetInstance();
    if (CapturingOutputWindow::SafeDownCast(current)) return;
    vtkSmartPointer<CapturingOutputWindow> window = vtkSmartPointer<CapturingOutputWindow>::New();
    window->SetPrevious(current);
    vtkOutputWindow::SetInstance(window);
}

// Observer callback: VTK passes the formatted message as call data.
class CaptureObserver : public vtkCommand {
public:
    static CaptureObserver* New() { return new CaptureObserver; }
    void SetCapture(VtkMessageCapture* capture) { capture_ = capture; }
    void Execute(vtkObject*, unsigned long event, void* callData) override {
        if (!capture_) return;
        std::string text = callData ? static_cast<const char*>(callData) : "";
        if (event == vtkCommand::ErrorEvent)
            capture_->recordError(text);
        else
            capture_->recordWarning(text);
    }

private:
    VtkMessageCapture* capture_ = nullptr;
};

}  // namespace

VtkMessageCapture::VtkMessageCapture() {
    installCapturingOutputWindow();
    vtkSmartPointer<CaptureObserver> observer = vtkSmartPointer<CaptureObserver>::New();
    observer->SetCapture(this);
    observer_ = observer;
    enclosing_ = activeCapture;
    activeCapture = this;
}

VtkMessageCapture::~VtkMessageCapture() {
    // Watched objects may outlive us (a caller's smart pointer); make the observer inert.
    static_cast<CaptureObserver*>(observer_.Get())->SetCapture(nullptr);
    activeCapture = enclosing_;
}

void VtkMessageCapture::watch(vtkObject* object) {
    if (!object) return;
    object->AddObserver(vtkCommand::ErrorEvent, observer_);
    object->AddObserver(vtkCommand::WarningEvent, observer_);
}

void VtkMessageCapture::recordError(const std::string& rawMessage) { errors_.push_back(cleanVtkMessage(rawMessage)); }

void VtkMessageCapture::recordWarning(const std::string& rawMessage) {
    warnings_.push_back(cleanVtkMessage(rawMessage));
}

std::string VtkMessageCapture::summary() const {
    const std::vector<std::string>& messages = errors_.empty() ? warnings_ : errors_;
    std::string joined;
    size_t shown = 0;
    // "Algorithm X returned failure" from the executive only repeats that something failed.
    bool hasSpecificMessage = std::any_of(messages.begin(), messages.end(), [](const std::string& message) {
        return !message.empty() && message.find("returned failure") == std::string::npos;
    });
    for (const std::string& message : messages) {
        if (message.empty() || joined.find(message) != std::string::npos) continue;
        if (hasSpecificMessage && message.find("returned failure") != std::string::npos) continue;
        if (++shown > 3) {
            joined += "; ...";
            break;
        }
        joined += (joined.empty() ? "" : "; ") + message;
    }
    return joined;
}

std::string cleanVtkMessage(const std::string& rawMessage) {
    std::string message = rawMessage;
    // Drop the "ERROR: In file, line N" source location line.
    static const std::regex sourceLocation(R"(^\s*(ERROR|Warning|Generic Warning): In [^\n]*\n)");
    message = std::regex_replace(message, sourceLocation, "");
    static const std::regex objectPointer(R"( ?\(0x[0-9a-fA-F]+\))");
    message = std::regex_replace(message, objectPointer, "");
    // The executive appends a dump of the pipeline request, which says nothing about the file.
    size_t request = message.find(" for request:");
    if (request != std::string::npos) message.erase(request);
    for (char& c : message)
        if (c == '\n' || c == '\r' || c == '\t') c = ' ';
    size_t first = message.find_first_not_of(' ');
    size_t last = message.find_last_not_of(' ');
    if (first == std::string::npos) return "";
    message = message.substr(first, last - first + 1);
    static const std::regex repeatedSpaces(" {2,}");
    return std::regex_replace(message, repeatedSpaces, " ");
}

}  // namespace conescope
