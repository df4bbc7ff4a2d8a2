// Cross-key rules of a case.
#include "solver/scene/CaseValidation.h"

namespace lbdem::solver {

std::vector<CaseProblem> validateCase(const CaseSpec& spec) {
    std::vector<CaseProblem> problems;
    if (spec.fluid.tau != 0.0 && spec.fluid.tau <= 0.5)
        problems.push_back({"fluid.tau", "must exceed 0.5 (or be 0 to derive it from target_mach)"});
    if (spec.grains.count > 0 && spec.grains.tangential_stiffness_n_m > spec.grains.normal_stiffness_n_m * 10)
        problems.push_back({"grains.tangential_stiffness_n_m",
                            "is more than ten times the normal stiffness, which is unphysical"});
    if (spec.run.output_interval_tc > spec.run.end_tc && spec.run.end_tc > 0)
        problems.push_back({"run.output_interval_tc", "is longer than run.end_tc: nothing would be written"});
    return problems;
}

} // namespace lbdem::solver
