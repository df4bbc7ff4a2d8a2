// What a sweep or study does with the folder of each of its runs: skip it, continue it, or start
// it afresh; so that a campaign can be stopped and started again at any moment.
#pragma once

#include "campaign/JobRunner.h"

#include <filesystem>

namespace lbdem::campaign {

/// What becomes of one run of a campaign.
enum class RunAction {
    Skip,   ///< it has finished (or the stability guard stopped it, when asked to skip those)
    Resume, ///< its folder holds a checkpoint: `lbdem resume` continues it
    Start,  ///< nothing to continue: `lbdem run` starts it (replacing a start that failed)
};

/// Decide what to do with the run in dir whose fresh start is job (`lbdem run ... --out dir`):
/// Skip when dir's summary.json says it finished, or, with skipUnstable, that the stability guard
/// stopped it; else create dir and, when it holds a checkpoint, turn job into
/// `lbdem resume dir --quiet` (Resume), or add --force when dir holds the outputs of a start that
/// left no checkpoint (Start).
RunAction prepareRunJob(Job& job, const std::filesystem::path& dir, bool skipUnstable);

} // namespace lbdem::campaign
