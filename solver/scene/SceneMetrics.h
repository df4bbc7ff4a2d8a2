// The scalar metrics each scene reports, declared once, and which of them have a known answer.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>
#include <vector>

namespace lbdem::solver {

/// How a metric can be judged against an analytic or published answer.
enum class MetricReference {
    None,    ///< no known answer (compare runs with one another)
    Field,   ///< the run also reports NAME_reference, the analytic or published value
    IsError, ///< the metric is itself an error against the analytic or published answer
};

/// One metric of Simulation::metrics() (a timeseries.csv column, a key of summary.json "final").
struct MetricDecl {
    std::string name;
    MetricReference reference = MetricReference::None;
};

/// Suffix of the metric that holds another metric's reference value (drag_coefficient_reference).
inline constexpr const char* kReferenceSuffix = "_reference";

/// Every metric the scene of spec reports once it has run (FlowMetrics.cpp,
/// ColumnCollapseRunner.cpp).
std::vector<MetricDecl> sceneMetrics(const CaseSpec& spec);

/// True when the cavity compares with Ghia et al. (1982): Re = 100 with the velocity scaling.
bool ghiaReferenceApplies(const CaseSpec& spec);

/// True when the cylinder is Schäfer & Turek's (1996) benchmark 2D-1: Re = 20 in the 2.2 x 0.41
/// channel, so that C_D = 5.58 and Delta p = 0.1175 Pa (scaled) are the references.
bool schaeferTurekApplies(const CaseSpec& spec);

} // namespace lbdem::solver
