// Bounded reads of regular input files and durable, atomic replacement of output files (POSIX).
#include "solver/io/SafeFile.h"

#include "solver/core/InputError.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace lbdem::io {

namespace fs = std::filesystem;

namespace {

/// Closes a file descriptor when it goes out of scope.
class Descriptor {
public:
    explicit Descriptor(int fd) : m_fd(fd) {}
    ~Descriptor() {
        if (m_fd >= 0) ::close(m_fd);
    }
    Descriptor(const Descriptor&) = delete;
    Descriptor& operator=(const Descriptor&) = delete;
    int get() const { return m_fd; }
    /// Close now and return 0, or -1 with errno set (a deferred write error shows here).
    int close() {
        const int result = ::close(m_fd);
        m_fd = -1;
        return result;
    }

private:
    int m_fd;
};

/// What kind of file a mode is, for a message about a file that is not a regular one.
const char* kindOf(mode_t mode) {
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode) || S_ISBLK(mode)) return "a device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

/// Write all of bytes to fd; false with errno set on failure.
bool writeAll(int fd, const std::string& bytes) {
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t written = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        done += static_cast<std::size_t>(written);
    }
    return true;
}

} // namespace

std::string readInputFile(const std::string& path, const std::string& what, std::size_t maxBytes) {
    // O_NONBLOCK: opening a FIFO without a writer must not wait for one.
    Descriptor fd(::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC));
    struct stat info {};
    if (fd.get() < 0 || ::fstat(fd.get(), &info) != 0) {
        const int error = errno;
        if (error == ENOENT) throw solver::InputError(path + ": no such " + what);
        throw solver::InputError(path + ": cannot open the " + what + " (" + std::strerror(error) +
                                 ")");
    }
    if (S_ISDIR(info.st_mode)) throw solver::InputError(path + " is a folder, not a " + what);
    if (!S_ISREG(info.st_mode))
        throw solver::InputError(path + " is " + kindOf(info.st_mode) + ": a " + what +
                                 " must be a regular file");
    if (static_cast<std::uintmax_t>(info.st_size) > maxBytes)
        throw solver::InputError(path + " holds " + std::to_string(info.st_size) +
                                 " bytes, more than the " + std::to_string(maxBytes) + " a " +
                                 what + " may hold");
    // Read at most one byte past the limit: a file growing while it is read is refused too.
    std::string text(maxBytes + 1, '\0');
    std::size_t size = 0;
    while (size < text.size()) {
        const ssize_t got = ::read(fd.get(), text.data() + size, text.size() - size);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0)
            throw solver::InputError(path + ": cannot read the " + what + " (" +
                                     std::strerror(errno) + ")");
        if (got == 0) break;
        size += static_cast<std::size_t>(got);
    }
    if (size > maxBytes)
        throw solver::InputError(path + " holds more than the " + std::to_string(maxBytes) +
                                 " bytes a " + what + " may hold");
    text.resize(size);
    return text;
}

std::string writeFailureCause(const std::string& path, int error) {
    std::error_code spaceError;
    const fs::path parent = fs::path(path).parent_path();
    const auto space = fs::space(parent.empty() ? fs::path(".") : parent, spaceError);
    if (error == ENOSPC || error == EDQUOT ||
        (!spaceError && space.available < (std::uintmax_t(1) << 20)))
        return "the disk is full";
    return error != 0 ? std::strerror(error) : "unknown cause";
}

void requireWritableFolder(const std::string& dir) {
    std::error_code error;
    fs::path existing = fs::absolute(dir, error);
    while (!existing.empty() && !fs::exists(existing, error) && existing != existing.parent_path())
        existing = existing.parent_path();
    // A file where the folder should be is the caller's to refuse ("is a file").
    if (!fs::is_directory(existing, error) || ::access(existing.c_str(), W_OK | X_OK) == 0) return;
    const int cause = errno;
    throw solver::InputError("cannot write in " +
                             (existing == fs::absolute(dir, error) ? dir : existing.string()) +
                             " (" + std::strerror(cause) + "): choose another output folder");
}

void syncFile(const std::string& path) {
    Descriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (fd.get() < 0 || ::fsync(fd.get()) != 0)
        throw std::runtime_error("cannot flush " + path +
                                 " to the disk: " + writeFailureCause(path, errno));
}

void syncParentFolder(const std::string& path) {
    const fs::path parent = fs::path(path).parent_path();
    Descriptor fd(
        ::open(parent.empty() ? "." : parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
    if (fd.get() >= 0) ::fsync(fd.get()); // EINVAL where a file system cannot: nothing to do
}

void replaceFile(const std::string& path, const std::string& bytes, bool durable) {
    const std::string temporary = path + ".tmp." + std::to_string(::getpid());
    int error = 0;
    {
        Descriptor fd(::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
        if (fd.get() < 0 || !writeAll(fd.get(), bytes) || (durable && ::fsync(fd.get()) != 0) ||
            fd.close() != 0)
            error = errno;
    }
    if (error == 0 && std::rename(temporary.c_str(), path.c_str()) != 0) {
        error = errno;
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot rename " + temporary + " to " + path + ": " +
                                 std::strerror(error));
    }
    if (error != 0) {
        std::remove(temporary.c_str());
        throw std::runtime_error("cannot write " + path + ": " + writeFailureCause(path, error));
    }
    if (durable) syncParentFolder(path);
}

} // namespace lbdem::io
