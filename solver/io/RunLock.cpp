// flock(2) on DIR/lbdem.lock, with the holder's pid in the file for the refusal's sentence.
#include "solver/io/RunLock.h"

#include "solver/core/InputError.h"

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fcntl.h>
#include <string>
#include <sys/file.h>
#include <thread>
#include <unistd.h>

namespace lbdem::io {

namespace fs = std::filesystem;

namespace {

/// The pid the holder wrote into the lock file: it writes it right after taking the lock, so
/// wait a moment for it before saying the holder is unknown.
std::string holderPid(int fd) {
    for (int attempt = 0; attempt < 20; ++attempt) {
        char text[32] = {};
        const ssize_t length = ::pread(fd, text, sizeof text - 1, 0);
        std::string pid(text, length > 0 ? static_cast<std::size_t>(length) : 0);
        while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' '))
            pid.pop_back();
        if (!pid.empty() && pid.find_first_not_of("0123456789") == std::string::npos) return pid;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return {};
}

} // namespace

RunLock::RunLock(const fs::path& dir) {
    std::error_code error;
    fs::create_directories(dir, error);
    const std::string path = (dir / kFileName).string();
    m_fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (m_fd < 0)
        throw solver::InputError("cannot lock the folder " + dir.string() + ": cannot open " +
                                 path + ": " + std::strerror(errno));
    if (::flock(m_fd, LOCK_EX | LOCK_NB) != 0) {
        const int cause = errno;
        const std::string pid = cause == EWOULDBLOCK ? holderPid(m_fd) : std::string();
        ::close(m_fd);
        m_fd = -1;
        if (cause != EWOULDBLOCK)
            throw solver::InputError("cannot lock the folder " + dir.string() + " (" + path +
                                     "): " + std::strerror(cause));
        throw solver::InputError(dir.string() + " is in use by another lbdem process (" +
                                 (pid.empty() ? std::string("pid unknown") : "pid " + pid) +
                                 ", which holds " + path +
                                 "); wait for it to end or stop it, then try again");
    }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(m_fd, 0) != 0 ||
        ::pwrite(m_fd, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
        const int cause = errno;
        ::close(m_fd);
        m_fd = -1;
        throw solver::InputError("cannot lock the folder " + dir.string() + ": cannot write " +
                                 path + ": " + std::strerror(cause));
    }
}

RunLock::~RunLock() {
    if (m_fd < 0) return;
    // Emptied while still held, so that no later writer's pid is erased.
    (void)::ftruncate(m_fd, 0);
    ::close(m_fd);
}

} // namespace lbdem::io
