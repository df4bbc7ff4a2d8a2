// Cross-key rules of a case.
#include "solver/scene/CaseValidation.h"

#include "solver/scene/SceneKind.h"

namespace lbdem::solver {

namespace {

/// Longest case name: it becomes a folder name.
constexpr std::size_t kMaxNameLength = 100;

/// Why name cannot be a folder name under results/ (empty when it can): letters, digits, '.',
/// '_' and '-', not starting with '.', at most kMaxNameLength characters.
std::string nameProblem(const std::string& name) {
    if (name.empty()) return "is empty; the outputs go to a folder of this name";
    if (name.size() > kMaxNameLength)
        return "is longer than " + std::to_string(kMaxNameLength) + " characters";
    if (name.front() == '.') return "must not start with '.'; it becomes a folder name";
    for (const char c : name) {
        const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                          (c >= '0' && c <= '9') || c == '.' || c == '_' || c == '-';
        if (!safe)
            return "may hold only letters, digits, '.', '_' and '-' (it becomes a folder name)";
    }
    return {};
}

} // namespace

std::vector<CaseProblem> validateCase(const CaseSpec& spec) {
    std::vector<CaseProblem> problems;
    if (const std::string problem = nameProblem(spec.name); !problem.empty())
        problems.push_back({"name", problem});
    if (spec.scene == SceneKind::ColumnCollapse) {
        if (spec.grains.count < 1)
            problems.push_back(
                {"grains.count", "must be at least 1: a column collapse needs grains"});
        // The generator refuses 0.9 itself (a hexagonal packing is 0.907): say so with the key.
        if (spec.grains.packing >= 0.9)
            problems.push_back({"grains.packing", "must be below 0.9: random discs do not pack "
                                                  "that densely (dense 0.83, loose 0.79)"});
        if (spec.domain.gravity_m_s2 <= 0)
            problems.push_back({"domain.gravity_m_s2",
                                "must be positive: the column settles under gravity and "
                                "time is counted in tau_c = sqrt(H_i / g)"});
    }
    if (spec.fluid.magic_lambda_links_only &&
        (spec.scene != SceneKind::ColumnCollapse ||
         spec.coupling.method != coupling::CouplingMethod::BounceBack || spec.fluid.s_q == 1.0))
        problems.push_back({"fluid.magic_lambda_links_only",
                            "needs a column collapse with coupling.method = \"bounce_back\" and "
                            "fluid.s_q other than 1 (the links' nodes are re-relaxed from it)"});
    if (spec.fluid.tau != 0.0 && spec.fluid.tau <= 0.5)
        problems.push_back(
            {"fluid.tau", "must exceed 0.5 (or be 0 to derive it from target_mach)"});
    if (spec.grains.count > 0 &&
        spec.grains.tangential_stiffness_n_m > spec.grains.normal_stiffness_n_m * 10)
        problems.push_back({"grains.tangential_stiffness_n_m",
                            "is more than ten times the normal stiffness, which is unphysical"});
    if (spec.run.output_interval_tc > spec.run.end_tc && spec.run.end_tc > 0)
        problems.push_back(
            {"run.output_interval_tc", "is longer than run.end_tc: nothing would be written"});
    return problems;
}

} // namespace lbdem::solver
