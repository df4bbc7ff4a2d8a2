// The map of a study over two or more keys: which settings stayed bounded and which went unstable.
#pragma once

#include "campaign/StudyReport.h"

#include <filesystem>
#include <string>
#include <vector>

namespace lbdem::campaign {

/// Write OUT/study_map.md: a grid with a row per value of the first key and a column per
/// combination of the other keys' values, each cell "bounded" (the run finished), "unstable"
/// (the stability guard stopped it) or the row's status otherwise; returns the path written.
std::string writeStudyMap(const StudySpec& study, const std::vector<StudyRow>& rows,
                          const std::filesystem::path& out);

} // namespace lbdem::campaign
