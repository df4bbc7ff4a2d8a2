// Skip, resume or start: the run folders of sweeps and studies.
#include "campaign/RunJobs.h"

#include "campaign/RunFolder.h"
#include "campaign/StudyReport.h"

namespace lbdem::campaign {

namespace fs = std::filesystem;

RunAction prepareRunJob(Job& job, const fs::path& dir, bool skipUnstable) {
    if (runFinished(dir) || (skipUnstable && runUnstable(dir))) return RunAction::Skip;
    fs::create_directories(dir);
    if (fs::exists(dir / "checkpoint.h5")) {
        job.argv = {job.argv.front(), "resume", dir.string(), "--quiet"};
        return RunAction::Resume;
    }
    if (holdsRun(dir)) job.argv.push_back("--force"); // a start that failed: nothing to continue
    return RunAction::Start;
}

} // namespace lbdem::campaign
