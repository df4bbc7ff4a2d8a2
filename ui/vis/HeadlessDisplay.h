// Makes an X display available for VTK rendering: Debian's VTK 9.1 has no EGL/OSMesa back end.
#pragma once

#include <string>
#include <sys/types.h>

namespace lbdem::vis {

/// Keeps an X display for the lifetime of the object: the caller's DISPLAY when it answers,
/// otherwise a private Xvfb started on a free display number and stopped by the destructor.
/// The server is also told to stop when the creating thread ends (PR_SET_PDEATHSIG, so a killed
/// process leaves no Xvfb behind): create it on a thread that outlives the rendering, e.g. main.
class HeadlessDisplay {
public:
    /// Uses DISPLAY if set and (for a local display) its socket answers; otherwise starts Xvfb
    /// and sets DISPLAY, or throws std::runtime_error with one sentence naming the package.
    HeadlessDisplay();
    /// Stops the private Xvfb (if one was started) and restores DISPLAY as it was.
    ~HeadlessDisplay();
    HeadlessDisplay(const HeadlessDisplay&) = delete;
    HeadlessDisplay& operator=(const HeadlessDisplay&) = delete;

    /// True when this object started its own Xvfb.
    bool startedXvfb() const { return m_pid > 0; }
    /// The display number of the private Xvfb, or -1 when the caller's DISPLAY is used.
    int displayNumber() const { return m_display; }

private:
    pid_t m_pid = -1;
    int m_display = -1;
    std::string m_previous;
};

/// Makes sure DISPLAY names a working X server for the rest of the process: a process-wide
/// HeadlessDisplay is started on the first call when DISPLAY is unset (and stopped at exit).
/// Throws std::runtime_error naming the xvfb package when that is impossible.
void ensureDisplay();

} // namespace lbdem::vis
