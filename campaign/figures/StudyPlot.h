// The figure of a study: error against wall time on log-log axes, one labelled point per setting
// (one series per value of the first key when more than one key is varied).
#pragma once

#include "campaign/StudyReport.h"

#include <string>
#include <vector>

namespace lbdem::campaign {

/// True when this build can draw study.png (built with VTK, LBDEM_GUI=ON).
bool studyPlotAvailable();

/// Draw the error of each row against its wall time into the PNG file path, a series per value
/// of the first key when several keys are varied; returns false (and draws nothing) without VTK
/// or when no row has a positive error and wall time.
bool writeStudyPlot(const StudySpec& study, const std::vector<StudyRow>& rows,
                    const std::string& path);

} // namespace lbdem::campaign
