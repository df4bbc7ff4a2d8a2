// The output folder of a run: is a run already there, make room for a new one, will it fit.
#pragma once

#include "solver/scene/Plan.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// True when dir holds a run: a file that only a run writes (plan.json, checkpoint.h5, run.json).
bool holdsRun(const std::filesystem::path& dir);

/// Throw InputError (exit 2) when a run may not go into dir: dir is a file; it holds a run and
/// force is not given, or force is given but its case.toml was edited since the run wrote it;
/// it holds no run but files a run would overwrite (case.toml, vtk/, ...), or, with force,
/// any file at all (a lock file or a sweep's log.txt aside). Changes nothing.
void refuseExistingRun(const std::filesystem::path& dir, bool force);

/// Make dir ready for a new run after refuseExistingRun's checks: when it holds a run (force),
/// remove the old run's outputs and nothing else (its files, and in vtk/, profiles/, frames/
/// the files named as a run names them, each folder when it is left empty); create dir when
/// missing. The caller holds dir's RunLock.
void prepareRunFolder(const std::filesystem::path& dir, bool force);

/// Sentences about a plan that does not fit this machine: memory above its physical memory,
/// outputs above the free space of the file system that holds dir (or its nearest existing
/// parent). Empty when it fits.
std::vector<std::string> resourceProblems(const solver::Plan& plan,
                                          const std::filesystem::path& dir);

/// Throw InputError with the first resource problem unless force (then warn on stderr).
void checkResources(const solver::Plan& plan, const std::filesystem::path& dir, bool force,
                    bool quiet);

/// A byte count for people: "812 MiB", "26.1 GiB".
std::string formatBytes(double bytes);

} // namespace lbdem::campaign
