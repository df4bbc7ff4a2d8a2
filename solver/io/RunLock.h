// The lock of an output folder: one writer at a time (flock on DIR/lbdem.lock).
#pragma once

#include <filesystem>
#include <string>

namespace lbdem::io {

/// Holds DIR/lbdem.lock with flock(LOCK_EX) for as long as it lives, and writes its process id
/// into the file. The kernel releases the lock when the process ends, however it ends, so a
/// killed writer never leaves a folder locked; a clean release empties the file again. The
/// descriptor is closed on exec, so that no child (Xvfb, a sweep's runs) keeps the lock alive.
class RunLock {
public:
    /// Lock dir, creating it and its lock file when missing. Throws InputError with one sentence
    /// naming the holder's pid when another process holds the lock, or naming the cause when
    /// the lock file cannot be created (a read-only folder).
    explicit RunLock(const std::filesystem::path& dir);
    ~RunLock();
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;

    /// The lock file's name inside a folder.
    static constexpr const char* kFileName = "lbdem.lock";

private:
    int m_fd = -1;
};

} // namespace lbdem::io
