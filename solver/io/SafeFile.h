// Files read and written with care: input files of a bounded size that must be regular files,
// outputs replaced atomically and flushed to the disk before the rename.
#pragma once

#include <cstddef>
#include <string>

namespace lbdem::io {

/// The most bytes a case or sweep file may hold: far above any real one (a complete documented
/// case is under 20 kB), small enough that a wrong path cannot fill the memory.
constexpr std::size_t kMaxInputFileBytes = std::size_t(1) << 20;

/// The whole content of the input file at path. Throws InputError (one sentence naming path and
/// what, e.g. "case file") when it is missing, a folder, not a regular file (a FIFO, a device
/// such as /dev/zero, a socket: refused without reading or waiting), or larger than maxBytes.
std::string readInputFile(const std::string& path, const std::string& what,
                          std::size_t maxBytes = kMaxInputFileBytes);

/// Replace path by bytes through a temporary file in the same folder (PATH.tmp.PID) renamed over
/// it; with durable the data reach the disk (fsync) before the rename and the rename after it.
/// On failure the temporary file is removed, path is left as it was, and std::runtime_error
/// says in one sentence which file and why ("the disk is full").
void replaceFile(const std::string& path, const std::string& bytes, bool durable);

/// Flush the file at path to the disk (fsync), e.g. after a library wrote and closed it; throws
/// std::runtime_error naming the file and the cause.
void syncFile(const std::string& path);

/// Flush the folder that holds path, so that a rename into it survives a crash of the machine;
/// file systems that cannot sync a folder are left as they are.
void syncParentFolder(const std::string& path);

/// Throw InputError (exit 2) when the output folder dir cannot be written: the folder, or the
/// nearest existing folder above it where it does not exist yet, is read-only or not ours.
void requireWritableFolder(const std::string& dir);

/// Why a write into path failed with errno value error, in words: "the disk is full" when the
/// file system that holds path has less than a MiB left or said so, else the system's text.
std::string writeFailureCause(const std::string& path, int error);

} // namespace lbdem::io
