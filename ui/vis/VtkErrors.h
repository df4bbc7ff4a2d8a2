// VTK's error reports caught as text, so that a failed read or write becomes one sentence of
// ours instead of VTK's multi-line trace on stderr.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

class vtkOutputWindow;

namespace lbdem::vis {

/// While alive, the errors and warnings of every VTK object go to this catcher instead of VTK's
/// output window and vtkLogger (both print on stderr); failed() tells whether there was an error.
/// Use it around a read or a write in the thread that owns VTK; catchers nest.
class VtkErrorCatcher {
public:
    VtkErrorCatcher();
    ~VtkErrorCatcher();
    VtkErrorCatcher(const VtkErrorCatcher&) = delete;
    VtkErrorCatcher& operator=(const VtkErrorCatcher&) = delete;

    /// True when an error was reported since the catcher was made.
    bool failed() const;
    /// The first error's message without VTK's file, line and class prefix ("" when none).
    std::string firstError() const;

private:
    class Window;
    vtkSmartPointer<Window> m_window;
    vtkSmartPointer<vtkOutputWindow> m_previous;
    int m_previousVerbosity; ///< vtkLogger's stderr verbosity before
};

} // namespace lbdem::vis
