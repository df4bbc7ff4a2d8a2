// An output window that keeps VTK's first error message and prints nothing.
#include "ui/vis/VtkErrors.h"

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

namespace lbdem::vis {

class VtkErrorCatcher::Window : public vtkOutputWindow {
public:
    static Window* New() { return new Window; }
    void DisplayErrorText(const char* text) override {
        if (!failed) message = text ? text : "";
        failed = true;
    }
    // Warnings and plain text of a failed read or write add nothing to our sentence.
    void DisplayText(const char*) override {}
    void DisplayWarningText(const char*) override {}
    void DisplayGenericWarningText(const char*) override {}
    void DisplayDebugText(const char*) override {}

    bool failed = false;
    std::string message;
};

VtkErrorCatcher::VtkErrorCatcher()
    : m_window(vtkSmartPointer<Window>::New()), m_previous(vtkOutputWindow::GetInstance()),
      m_previousVerbosity(static_cast<int>(vtkLogger::GetCurrentVerbosityCutoff())) {
    vtkOutputWindow::SetInstance(m_window);
    // The pipeline's own reports (vtkExecutive: "returned failure for request", with a dump of
    // the request) go straight to vtkLogger's stderr sink, not through the output window.
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkErrorCatcher::~VtkErrorCatcher() {
    // lbdem logs to no other sink, so the cutoff read before was the stderr sink's level.
    vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(m_previousVerbosity));
    vtkOutputWindow::SetInstance(m_previous);
}

bool VtkErrorCatcher::failed() const {
    return m_window->failed;
}

std::string VtkErrorCatcher::firstError() const {
    // VTK's text: "ERROR: In FILE, line N\nCLASS (ADDRESS): MESSAGE\n\n".
    std::string text = m_window->message;
    if (const auto colon = text.find("): "); colon != std::string::npos) text.erase(0, colon + 3);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    if (const auto newline = text.find('\n'); newline != std::string::npos) text.resize(newline);
    return text;
}

} // namespace lbdem::vis
