// Starts a private Xvfb when DISPLAY is unset; -displayfd lets the server pick a free display
// number and tells us when it is ready to accept clients, so there is no polling or guessing.
#include "ui/vis/HeadlessDisplay.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <string>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

namespace lbdem::vis {

namespace {

constexpr const char* kMissingXvfb =
    "rendering needs an X display: set DISPLAY or install the xvfb package (apt install xvfb)";

/// Finds an executable named `name` on PATH.
std::string findOnPath(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::string rest = path ? path : "/usr/bin:/bin";
    while (!rest.empty()) {
        const auto colon = rest.find(':');
        const std::string dir = rest.substr(0, colon);
        rest = colon == std::string::npos ? "" : rest.substr(colon + 1);
        const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
        if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
    return {};
}

/// Reads the display number Xvfb writes to the pipe once it accepts connections; -1 on failure.
int readDisplayNumber(int fd) {
    std::string text;
    char buffer[32];
    while (text.find('\n') == std::string::npos) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    if (text.empty() || text.find_first_not_of("0123456789\n") != std::string::npos) return -1;
    return std::stoi(text);
}

/// Connects to the unix socket `path` (a leading '@' means the abstract namespace).
bool socketAnswers(const std::string& path) {
    const int fd = ::socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0) return false;
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    const bool abstract = path[0] == '@';
    std::memcpy(address.sun_path, path.c_str(), std::min(path.size(), sizeof address.sun_path - 1));
    if (abstract) address.sun_path[0] = '\0';
    const auto length =
        static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + path.size() + (abstract ? 0 : 1));
    const bool answered = ::connect(fd, reinterpret_cast<sockaddr*>(&address), length) == 0;
    ::close(fd);
    return answered;
}

/// False only for a local display (":N" or ":N.S") whose X socket does not answer; VTK would
/// abort on it. Remote displays (host:N) are trusted as given.
bool displayAnswers(const std::string& display) {
    if (display.empty() || display[0] != ':') return true;
    const std::string number = display.substr(1, display.find('.') - 1);
    if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) return true;
    const std::string socket = "/tmp/.X11-unix/X" + number;
    return socketAnswers("@" + socket) || socketAnswers(socket);
}

} // namespace

HeadlessDisplay::HeadlessDisplay() {
    const char* display = std::getenv("DISPLAY");
    // A stale DISPLAY (a closed session) is treated as none: VTK would abort on it.
    if (display && *display && displayAnswers(display)) return;
    if (display) m_previous = display;
    const std::string xvfb = findOnPath("Xvfb");
    if (xvfb.empty()) throw std::runtime_error(kMissingXvfb);
    int fds[2];
    if (::pipe(fds) != 0)
        throw std::runtime_error(std::string("cannot start Xvfb: ") + std::strerror(errno));
    const pid_t pid = ::fork();
    if (pid < 0)
        throw std::runtime_error(std::string("cannot start Xvfb: ") + std::strerror(errno));
    if (pid == 0) {
        // The server must not outlive us even if we are killed before the destructor runs.
        ::prctl(PR_SET_PDEATHSIG, SIGTERM);
        ::close(fds[0]);
        const std::string fd = std::to_string(fds[1]);
        ::execl(xvfb.c_str(), "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "1920x1080x24",
                "-nolisten", "tcp", "-noreset", static_cast<char*>(nullptr));
        ::_exit(127);
    }
    ::close(fds[1]);
    m_display = readDisplayNumber(fds[0]);
    ::close(fds[0]);
    m_pid = pid;
    if (m_display < 0) {
        ::kill(m_pid, SIGTERM);
        ::waitpid(m_pid, nullptr, 0);
        m_pid = -1;
        throw std::runtime_error("Xvfb did not start; check that the xvfb package works "
                                 "(try xvfb-run -a) or set DISPLAY");
    }
    ::setenv("DISPLAY", (":" + std::to_string(m_display)).c_str(), 1);
}

HeadlessDisplay::~HeadlessDisplay() {
    if (m_pid <= 0) return;
    ::kill(m_pid, SIGTERM);
    ::waitpid(m_pid, nullptr, 0);
    if (m_previous.empty())
        ::unsetenv("DISPLAY");
    else
        ::setenv("DISPLAY", m_previous.c_str(), 1);
}

void ensureDisplay() {
    // A function-local static: started once, destroyed (Xvfb stopped) at normal exit.
    static HeadlessDisplay display;
}

} // namespace lbdem::vis
