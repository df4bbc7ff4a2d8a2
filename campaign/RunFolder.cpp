// Output-folder checks of `lbdem run`: an existing run is never replaced silently, a run that
// cannot fit in memory or on disk is refused before it starts.
#include "campaign/RunFolder.h"

#include "solver/core/InputError.h"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace lbdem::campaign {

namespace fs = std::filesystem;

namespace {

const char* const kRunFiles[] = {"case.toml", "plan.json", "summary.json", "timeseries.csv",
                                 "checkpoint.h5"};
const char* const kRunFolders[] = {"vtk", "profiles", "frames"};

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
    for (const char* name : kRunFiles)
        if (fs::exists(dir / name, error)) return true;
    return false;
}

void refuseExistingRun(const fs::path& dir, bool force) {
    std::error_code error;
    if (fs::exists(dir, error) && !fs::is_directory(dir, error))
        throw solver::InputError("the output folder " + dir.string() + " is a file");
    if (holdsRun(dir) && !force)
        throw solver::InputError(dir.string() + " holds a run; use lbdem resume " + dir.string() +
                                 ", or --force to replace it");
}

void prepareRunFolder(const fs::path& dir, bool force) {
    refuseExistingRun(dir, force);
    std::error_code error;
    if (holdsRun(dir)) {
        for (const char* name : kRunFiles)
            fs::remove(dir / name, error);
        for (const char* name : kRunFolders)
            fs::remove_all(dir / name, error);
        for (const auto& entry : fs::directory_iterator(dir, error))
            if (entry.path().filename().string().rfind("checkpoint.h5.tmp.", 0) == 0)
                fs::remove(entry.path(), error);
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
