// The output folder of a run: is a run already there, make room for a new one, will it fit.
#pragma once

#include "solver/scene/Plan.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// True when dir holds the outputs of a run (case.toml, plan.json, summary.json,
/// timeseries.csv or checkpoint.h5).
bool holdsRun(const std::filesystem::path& dir);

/// Throw InputError (exit 2) when dir is a file, or holds a run and force is not given.
void refuseExistingRun(const std::filesystem::path& dir, bool force);

/// Make dir ready for a new run: refuse (InputError, exit 2) when it holds a run unless force,
/// in which case the old run's outputs (files and the vtk/, profiles/, frames/ folders) are
/// removed first; create it when missing. Other files in dir are left alone.
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
