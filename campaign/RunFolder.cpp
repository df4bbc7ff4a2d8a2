// Output-folder checks of `lbdem run`: an existing run is never replaced silently, nothing but a
// run's own outputs is ever removed, a run that cannot fit in memory or on disk is refused before
// it starts.
#include "campaign/RunFolder.h"

#include "solver/core/Checksum.h"
#include "solver/core/InputError.h"
#include "solver/io/RunIdentity.h"
#include "solver/io/RunLock.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <regex>

namespace lbdem::campaign {

namespace fs = std::filesystem;

namespace {

// Files that only a run writes: one of them makes a folder a run's.
const char* const kMarkers[] = {"plan.json", "checkpoint.h5", "run.json"};
// The files a run writes at the top of its folder (each also as NAME.tmp.PID while written).
const char* const kRunFiles[] = {"case.toml",      "plan.json",     "summary.json",
                                 "timeseries.csv", "checkpoint.h5", "run.json"};
// Written beside a run's outputs and left in place: the lock, the log of a sweep or study.
const char* const kKeptFiles[] = {io::RunLock::kFileName, "log.txt"};

/// A folder a run writes, and the pattern of the files in it that are the run's.
struct RunSubfolder {
    const char* name;
    const char* files;
};
const RunSubfolder kRunFolders[] = {
    {"vtk", R"((particles|contacts|fluid|outline)(_[0-9]+\.vt[iu]|\.pvd)(\.tmp)?)"},
    {"profiles", R"((outline|pore_pressure_failure_plane)_[0-9]+\.csv(\.tmp\.[0-9]+)?)"},
    {"frames", R"(frame_[0-9]+\.png(\.tmp\.png)?)"},
};

bool isRunFile(const std::string& name) {
    for (const char* file : kRunFiles) {
        const std::string prefix = std::string(file) + ".tmp.";
        if (name == file ||
            (name.rfind(prefix, 0) == 0 && name.size() > prefix.size() &&
             name.find_first_not_of("0123456789", prefix.size()) == std::string::npos))
            return true;
    }
    return false;
}

const RunSubfolder* runSubfolder(const std::string& name) {
    for (const auto& folder : kRunFolders)
        if (name == folder.name) return &folder;
    return nullptr;
}

bool isKept(const std::string& name) {
    for (const char* file : kKeptFiles)
        if (name == file) return true;
    return false;
}

/// What a folder holds, sorted into a run's outputs and everything else.
struct Contents {
    bool run = false;                  ///< it holds a run (one of kMarkers is there)
    std::vector<fs::path> outputs;     ///< the files a run wrote (what --force removes)
    std::vector<std::string> others;   ///< everything else but kKeptFiles, as names
    std::vector<std::string> inTheWay; ///< the others whose name a run writes
    bool caseEdited = false;           ///< case.toml is no longer the one run.json names
};

/// True when dir/case.toml differs from the case its run wrote (run.json's hash).
bool caseEdited(const fs::path& dir) {
    try {
        const auto identity = io::readRunIdentity(dir);
        std::ifstream in(dir / "case.toml", std::ios::binary);
        if (!identity || !in) return false;
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        return solver::checksumOf(text) != identity->case_hash;
    } catch (const solver::InputError&) {
        return false; // a damaged run.json: nothing to compare with
    }
}

/// Sort a run subfolder's files: the run's own (when dir holds a run) and the others.
void inspectSubfolder(const fs::path& path, const RunSubfolder& folder, Contents& contents) {
    std::error_code error;
    const std::regex own(folder.files);
    for (const auto& entry : fs::directory_iterator(path, error)) {
        const std::string name = entry.path().filename().string();
        if (contents.run && entry.is_regular_file(error) && std::regex_match(name, own))
            contents.outputs.push_back(entry.path());
        else
            contents.others.push_back(std::string(folder.name) + "/" + name);
    }
}

Contents inspect(const fs::path& dir) {
    Contents contents;
    std::error_code error;
    for (const char* marker : kMarkers)
        contents.run = contents.run || fs::exists(dir / marker, error);
    for (const auto& entry : fs::directory_iterator(dir, error)) {
        const std::string name = entry.path().filename().string();
        const bool folder = entry.is_directory(error);
        if (isKept(name)) continue;
        if (!folder && isRunFile(name)) {
            if (contents.run) {
                contents.outputs.push_back(entry.path());
                continue;
            }
            contents.inTheWay.push_back(name);
        } else if (const RunSubfolder* subfolder = runSubfolder(name)) {
            if (contents.run && folder) {
                inspectSubfolder(entry.path(), *subfolder, contents);
                continue;
            }
            contents.inTheWay.push_back(name + (folder ? "/" : ""));
        }
        contents.others.push_back(name + (folder ? "/" : ""));
    }
    contents.caseEdited = contents.run && caseEdited(dir);
    return contents;
}

/// "a, b, c and 2 more" of a list of names.
std::string listOf(std::vector<std::string> names) {
    std::sort(names.begin(), names.end());
    std::string text;
    const std::size_t shown = std::min<std::size_t>(names.size(), 4);
    for (std::size_t k = 0; k < shown; ++k)
        text += (k > 0 ? ", " : "") + names[k];
    if (names.size() > shown) text += " and " + std::to_string(names.size() - shown) + " more";
    return text;
}

/// Physical memory of this machine [bytes] (0 when unknown).
double physicalMemory() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), pageSize = ::sysconf(_SC_PAGE_SIZE);
    return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize)
                                     : 0.0;
}

/// The nearest existing folder at or above dir.
fs::path existingAncestor(fs::path dir) {
    std::error_code error;
    dir = fs::absolute(dir, error);
    while (!dir.empty() && !fs::exists(dir, error) && dir != dir.parent_path())
        dir = dir.parent_path();
    return dir;
}

} // namespace

std::string formatBytes(double bytes) {
    char text[32];
    if (bytes >= 1024.0 * 1024 * 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f TiB", bytes / 1099511627776.0);
    else if (bytes >= 1024.0 * 1024 * 1024)
        std::snprintf(text, sizeof text, "%.1f GiB", bytes / 1073741824.0);
    else
        std::snprintf(text, sizeof text, "%.0f MiB", bytes / 1048576.0);
    return text;
}

bool holdsRun(const fs::path& dir) {
    std::error_code error;
    for (const char* marker : kMarkers)
        if (fs::exists(dir / marker, error)) return true;
    return false;
}

void refuseExistingRun(const fs::path& dir, bool force) {
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error))
        throw solver::InputError("the output folder " + dir.string() + " is a file");
    if (!fs::is_directory(dir, error)) return;
    const Contents contents = inspect(dir);
    if (contents.run && !force)
        throw solver::InputError(dir.string() + " holds a run; use lbdem resume " + dir.string() +
                                 ", or --force to replace it");
    if (contents.run && contents.caseEdited)
        throw solver::InputError((dir / "case.toml").string() +
                                 " was changed since its run wrote it, and --force would replace "
                                 "it; move it out of " +
                                 dir.string() + " first, or choose another --out");
    if (contents.run) return;
    // Not a run's folder: whatever is there is somebody's, and a run must neither replace it
    // (a case.toml, a frames/ folder of one's own) nor, with --force, remove anything.
    if (force && !contents.others.empty())
        throw solver::InputError(dir.string() +
                                 " holds no run (no plan.json or checkpoint.h5) "
                                 "but other files (" +
                                 listOf(contents.others) +
                                 "): --force replaces only a run's outputs; choose a new or empty "
                                 "--out");
    if (!contents.inTheWay.empty())
        throw solver::InputError(dir.string() + " holds " + listOf(contents.inTheWay) +
                                 ", which a run would overwrite, but no run (no plan.json or "
                                 "checkpoint.h5); choose another --out");
}

void prepareRunFolder(const fs::path& dir, bool force) {
    refuseExistingRun(dir, force);
    std::error_code error;
    if (fs::is_directory(dir, error) && holdsRun(dir)) {
        for (const auto& path : inspect(dir).outputs)
            fs::remove(path, error);
        for (const auto& folder : kRunFolders)
            if (fs::is_empty(dir / folder.name, error)) fs::remove(dir / folder.name, error);
    }
    fs::create_directories(dir, error);
    if (error || !fs::is_directory(dir))
        throw solver::InputError("cannot create the output folder " + dir.string() +
                                 (error ? ": " + error.message() : std::string()));
}

std::vector<std::string> resourceProblems(const solver::Plan& plan, const fs::path& dir) {
    std::vector<std::string> problems;
    const double memory = physicalMemory();
    if (memory > 0 && static_cast<double>(plan.memory_bytes) > memory)
        problems.push_back("the run needs about " +
                           formatBytes(static_cast<double>(plan.memory_bytes)) +
                           " of memory, more than this machine's " + formatBytes(memory) +
                           " (coarsen fluid.resolution or shrink the domain)");
    std::error_code error;
    const fs::path existing = existingAncestor(dir);
    const auto space = fs::space(existing, error);
    if (!error && static_cast<double>(plan.output_bytes) > static_cast<double>(space.available))
        problems.push_back(
            "the run writes up to " + formatBytes(static_cast<double>(plan.output_bytes)) +
            ", more than the " + formatBytes(static_cast<double>(space.available)) + " free in " +
            existing.string() + " (raise output.vtk_every or output.fluid_downsample)");
    return problems;
}

void checkResources(const solver::Plan& plan, const fs::path& dir, bool force, bool quiet) {
    for (const auto& problem : resourceProblems(plan, dir)) {
        if (!force) throw solver::InputError(problem + "; --force runs it anyway");
        if (!quiet) std::cerr << "warning: " << problem << "\n";
    }
}

} // namespace lbdem::campaign
