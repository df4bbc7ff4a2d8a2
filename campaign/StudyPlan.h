// The plan of a study: one case over the cartesian product of several keys' values, each
// setting a run of its own, checked before any run starts.
#pragma once

#include "campaign/JobRunner.h"
#include "campaign/StudyReport.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// What a study is asked for (the options of `lbdem study`).
struct StudyRequest {
    std::string casePath;               ///< the case file
    std::vector<std::string> overrides; ///< "section.key=value" applied to every setting
    std::vector<std::string> varies;    ///< "KEY=V1,V2,...", one per varied key
    std::string metric;                 ///< the summary.json number to compare; "": the scene's
    std::string reference;              ///< "analytic", "finest" or "" (analytic when known)
    std::filesystem::path out;          ///< the study's folder: one run folder per setting
};

/// A planned study and the job that starts each of its settings afresh (`lbdem run`), in the
/// order of study.settings.
struct StudyPlan {
    StudySpec study;
    std::vector<Job> jobs;
};

/// Check every KEY=V1,V2,... against the schema, load, plan and check each setting of the
/// product (the first key slowest) and resolve the metric; lbdem is the executable the jobs
/// start. Throws InputError naming the option, key and value before anything runs.
StudyPlan planStudy(const StudyRequest& request, const std::string& lbdem);

} // namespace lbdem::campaign
