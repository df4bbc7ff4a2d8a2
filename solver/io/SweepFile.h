// Sweep files: a list of case files (and shared overrides) run together by `lbdem sweep`.
#pragma once

#include <string>
#include <vector>

namespace lbdem::io {

/// One variant of a controlled-experiment sweep: its name and the overrides that define it.
struct SweepVariant {
    std::string name;                   ///< appended to each case's name: CASE__NAME
    std::vector<std::string> overrides; ///< "section.key=value" applied on top of the sweep's `set`
};

/// A parsed sweep file; case paths are resolved against the sweep file's folder.
struct SweepSpec {
    std::string name;                   ///< sweep name (table and figure titles)
    std::vector<std::string> cases;     ///< case files, absolute or relative to the cwd
    std::vector<std::string> overrides; ///< "section.key=value" applied to every case
    std::vector<int> seeds; ///< packing seeds (grains.seed) of each case; empty: the case's own
    std::vector<SweepVariant> variants; ///< each case run once per variant; empty: as it is
};

/// Parse a sweep file (`sweep = 1`, `name`, `cases = [...]`, optional `set = [...]` and
/// `seeds = [1, 2, 3]`: each case run once per packing seed, no seed twice; optional
/// `[[variants]]` tables with `name` and `set`: each case run once per variant, the first being
/// the reference the others are compared with);
/// throws InputError naming file, line and key.
SweepSpec loadSweep(const std::string& path);

} // namespace lbdem::io
