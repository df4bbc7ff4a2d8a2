// A ParaView .pvd collection file that grows by one data set per output time.
#pragma once

#include <string>
#include <vector>

namespace lbdem::vis {

/// One time step of a .pvd series: the time in seconds and the file relative to the .pvd.
struct PvdEntry {
    double time_s = 0;
    std::string file;
};

/// Appends entries to a .pvd file and rewrites it atomically (temporary file + rename), so a run
/// killed at any moment leaves a valid collection listing only files that were fully written.
class PvdSeries {
public:
    /// A series written to `path`; existing entries are kept when `resume` is true (a resumed
    /// run), otherwise the file starts empty at the first append.
    explicit PvdSeries(std::string path, bool resume = false);

    /// Adds `file` (relative to the .pvd's folder) at `time_s` and rewrites the .pvd.
    void append(double time_s, const std::string& file);
    /// Drops the entries after `time_s` (a resumed run writes them again) and rewrites the .pvd.
    void dropAfter(double time_s);
    /// The entries written so far, in order of appending.
    const std::vector<PvdEntry>& entries() const { return m_entries; }
    /// Where the .pvd lives.
    const std::string& path() const { return m_path; }

private:
    void rewrite() const;

    std::string m_path;
    std::vector<PvdEntry> m_entries;
};

/// The entries of an existing .pvd file, in file order; throws std::runtime_error naming the file
/// when it is missing or not a VTKFile of type Collection.
std::vector<PvdEntry> readPvd(const std::string& path);

/// Writes `text` to `path` through a temporary file in the same folder and a rename.
void writeTextAtomically(const std::string& path, const std::string& text);

} // namespace lbdem::vis
