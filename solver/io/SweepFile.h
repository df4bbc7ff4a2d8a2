// Sweep files: a list of case files (and shared overrides) run together by `lbdem sweep`.
#pragma once

#include <string>
#include <vector>

namespace lbdem::io {

/// A parsed sweep file; case paths are resolved against the sweep file's folder.
struct SweepSpec {
    std::string name;                   ///< sweep name (table and figure titles)
    std::vector<std::string> cases;     ///< case files, absolute or relative to the cwd
    std::vector<std::string> overrides; ///< "section.key=value" applied to every case
};

/// Parse a sweep file (`sweep = 1`, `name`, `cases = [...]`, optional `set = [...]`);
/// throws InputError naming file, line and key.
SweepSpec loadSweep(const std::string& path);

} // namespace lbdem::io
