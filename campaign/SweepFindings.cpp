// The paper's findings, seed by seed, from the ensemble of a sweep.
#include "campaign/SweepFindings.h"

#include "campaign/SweepFigureCase.h"
#include "campaign/SweepVariants.h"
#include "solver/io/CaseWriter.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <set>

namespace lbdem::campaign {

namespace {

enum class Outcome { Holds, Fails, Undecided, None };

/// Compares the runs of two cases that share a seed (both finished): the outcome for one seed.
using PairTest = std::function<Outcome(const EnsembleRun& a, const EnsembleRun& b)>;

double valueOf(const EnsembleRun& run, EnsembleMetric metric) {
    return run.values[static_cast<std::size_t>(metric)];
}

/// "a's metric exceeds b's". With runoutBounds, a runout whose front reached the domain's end
/// is a lower bound: a > b is then undecided when b is such a bound, and a <= b when a is.
PairTest exceeds(EnsembleMetric metric, bool runoutBounds = false) {
    return [=](const EnsembleRun& a, const EnsembleRun& b) {
        const double va = valueOf(a, metric), vb = valueOf(b, metric);
        if (!std::isfinite(va) || !std::isfinite(vb)) return Outcome::None;
        const bool holds = va > vb;
        if (runoutBounds && ((holds && b.endReached) || (!holds && a.endReached)))
            return Outcome::Undecided;
        return holds ? Outcome::Holds : Outcome::Fails;
    };
}

/// "a's and b's metric differ by less than tolerance".
PairTest within(EnsembleMetric metric, double tolerance) {
    return [=](const EnsembleRun& a, const EnsembleRun& b) {
        const double va = valueOf(a, metric), vb = valueOf(b, metric);
        if (!std::isfinite(va) || !std::isfinite(vb)) return Outcome::None;
        return std::abs(va - vb) < tolerance ? Outcome::Holds : Outcome::Fails;
    };
}

void tally(Finding& finding, Outcome outcome) {
    finding.holds += outcome == Outcome::Holds;
    finding.fails += outcome == Outcome::Fails;
    finding.undecided += outcome == Outcome::Undecided;
}

std::string slopeText(double slope) {
    char text[32];
    std::snprintf(text, sizeof text, "%g deg", slope);
    return text;
}

/// The finished run of a case with a seed; null if there is none.
const EnsembleRun* finishedRun(const EnsembleCase& c, int seed) {
    for (const auto& run : c.runs)
        if (run.seed == seed && run.status == "finished") return &run;
    return nullptr;
}

/// Finds cases by packing name ("dense", "loose"), slope and medium.
class CaseIndex {
public:
    explicit CaseIndex(const std::vector<EnsembleCase>& cases) : m_cases(cases) {
        for (const auto& c : cases)
            m_slopes.insert(c.slope_deg);
    }
    const EnsembleCase* find(const std::string& packing, double slope, bool submerged) const {
        for (const auto& c : m_cases)
            if (packingName(c.packing) == packing && c.slope_deg == slope &&
                c.submerged == submerged)
                return &c;
        return nullptr;
    }
    const std::set<double>& slopes() const { return m_slopes; }

private:
    const std::vector<EnsembleCase>& m_cases;
    std::set<double> m_slopes;
};

/// One kind of case: packing name and medium.
struct Kind {
    const char* packing;
    bool submerged;
};

/// A finding that compares case a with case b at each slope, seed by seed.
void atEachSlope(const CaseIndex& index, const std::string& statement, Kind a, Kind b,
                 const PairTest& test, std::vector<Finding>& findings) {
    for (const double slope : index.slopes()) {
        const auto* ca = index.find(a.packing, slope, a.submerged);
        const auto* cb = index.find(b.packing, slope, b.submerged);
        if (!ca || !cb) continue;
        Finding finding{statement, slopeText(slope)};
        for (const auto& run : ca->runs) {
            const auto* rb = finishedRun(*cb, run.seed);
            if (run.status == "finished" && rb) tally(finding, test(run, *rb));
        }
        if (finding.seeds() > 0) findings.push_back(finding);
    }
}

/// "runout grows with slope" for one kind: per seed, each steeper slope runs further.
void growsWithSlope(const CaseIndex& index, Kind kind, std::vector<Finding>& findings) {
    std::vector<const EnsembleCase*> bySlope;
    for (const double slope : index.slopes())
        if (const auto* c = index.find(kind.packing, slope, kind.submerged)) bySlope.push_back(c);
    if (bySlope.size() < 2) return;
    const std::string where =
        slopeText(bySlope.front()->slope_deg) + " to " + slopeText(bySlope.back()->slope_deg);
    Finding finding{std::string(kind.packing) + (kind.submerged ? ", submerged" : ", dry") +
                        ": runout grows with slope",
                    where};
    const auto steeper = exceeds(EnsembleMetric::RunoutFinal, true);
    for (const auto& first : bySlope.front()->runs) {
        Outcome outcome = Outcome::Holds;
        for (std::size_t k = 1; k < bySlope.size(); ++k) {
            const auto* lower = finishedRun(*bySlope[k - 1], first.seed);
            const auto* higher = finishedRun(*bySlope[k], first.seed);
            const Outcome step = lower && higher ? steeper(*higher, *lower) : Outcome::None;
            if (step == Outcome::None || step == Outcome::Fails) {
                outcome = step; // a missing run leaves the seed out; one decided failure settles it
                break;
            }
            if (step == Outcome::Undecided) outcome = Outcome::Undecided;
        }
        tally(finding, outcome);
    }
    if (finding.seeds() > 0) findings.push_back(finding);
}

/// A finding that one kind's metric lies above (or below) a threshold at each slope, seed by seed.
void thresholdAtEachSlope(const CaseIndex& index, const std::string& statement, Kind kind,
                          EnsembleMetric metric, double threshold, bool above,
                          std::vector<Finding>& findings) {
    for (const double slope : index.slopes()) {
        const auto* c = index.find(kind.packing, slope, kind.submerged);
        if (!c) continue;
        Finding finding{statement, slopeText(slope)};
        for (const auto& run : c->runs) {
            const double value = valueOf(run, metric);
            if (run.status == "finished" && std::isfinite(value))
                tally(finding, (above ? value > threshold : value < threshold) ? Outcome::Holds
                                                                               : Outcome::Fails);
        }
        if (finding.seeds() > 0) findings.push_back(finding);
    }
}

/// "holds for k of n seeds" with the undecided ones named.
std::string inWords(const Finding& f) {
    std::string text = "holds for " + std::to_string(f.holds) + " of " + std::to_string(f.seeds()) +
                       (f.seeds() == 1 ? " seed" : " seeds");
    if (f.undecided > 0)
        text += " (" + std::to_string(f.undecided) + " undecided: a front at the domain's end)";
    return text;
}

} // namespace

std::vector<Finding> computeFindings(const std::vector<EnsembleCase>& allCases) {
    // In a controlled-experiment sweep the findings are those of the reference (first) variant.
    if (allCases.empty()) return {};
    std::vector<EnsembleCase> cases;
    for (const auto& c : allCases)
        if (c.variant == allCases.front().variant) cases.push_back(c);
    const CaseIndex index(cases);
    std::vector<Finding> findings;
    const Kind denseDry{"dense", false}, denseWet{"dense", true}, looseDry{"loose", false},
        looseWet{"loose", true};
    const auto runout = exceeds(EnsembleMetric::RunoutFinal, true);
    atEachSlope(index, "dense: dry runout longer than submerged", denseDry, denseWet, runout,
                findings);
    atEachSlope(index, "loose: submerged runout longer than dry", looseWet, looseDry, runout,
                findings);
    atEachSlope(index, "submerged: loose runout longer than dense", looseWet, denseWet, runout,
                findings);
    for (const Kind kind : {denseDry, denseWet, looseDry, looseWet})
        growsWithSlope(index, kind, findings);
    for (const Kind dry : {denseDry, looseDry}) {
        const Kind wet{dry.packing, true};
        const std::string name = dry.packing;
        atEachSlope(index, name + ": submerged peak E_k/E_p0 lower than dry", dry, wet,
                    exceeds(EnsembleMetric::KePeak), findings);
        atEachSlope(index, name + ": submerged peak E_k/E_p0 later than dry", wet, dry,
                    exceeds(EnsembleMetric::TKePeak), findings);
    }
    // Hydroplaning of the front sets in above Fr of about 0.3-0.4 (Mohrig et al. 1998).
    thresholdAtEachSlope(index, "loose, submerged: Fr_d at 3 tau_c above 0.4", looseWet,
                         EnsembleMetric::FroudeAt3Tc, 0.4, true, findings);
    atEachSlope(index, "submerged: loose Fr_d at 3 tau_c above dense", looseWet, denseWet,
                exceeds(EnsembleMetric::FroudeAt3Tc), findings);
    atEachSlope(index, "submerged: loose front further than dense at 3 tau_c", looseWet, denseWet,
                exceeds(EnsembleMetric::RunoutAt3Tc), findings);
    // Dense columns dilate as they fail (suction), loose ones contract (excess pressure).
    thresholdAtEachSlope(index,
                         "dense, submerged: pore pressure on the failure plane negative at 1 tau_c",
                         denseWet, EnsembleMetric::PoreAt1Tc, 0.0, false, findings);
    thresholdAtEachSlope(index,
                         "loose, submerged: pore pressure on the failure plane positive at 1 tau_c",
                         looseWet, EnsembleMetric::PoreAt1Tc, 0.0, true, findings);
    for (const bool submerged : {false, true})
        atEachSlope(index,
                    std::string(submerged ? "submerged" : "dry") +
                        ": dense and loose end within 0.01 in packing",
                    {"dense", submerged}, {"loose", submerged},
                    within(EnsembleMetric::PackingFinal, 0.01), findings);
    return findings;
}

std::string findingsCsv(const std::vector<Finding>& findings) {
    std::string csv = "finding,where,holds,fails,undecided,seeds\n";
    for (const auto& f : findings)
        csv += "\"" + f.statement + "\"," + f.where + "," + std::to_string(f.holds) + "," +
               std::to_string(f.fails) + "," + std::to_string(f.undecided) + "," +
               std::to_string(f.seeds()) + "\n";
    return csv;
}

std::string findingsMarkdown(const std::vector<Finding>& findings) {
    if (findings.empty())
        return "No finding of the paper can be checked with the cases of this sweep.\n";
    std::string md =
        "Each finding is checked seed by seed, between runs of the same packing seed that both "
        "finished.\n\n| finding | slope | seeds |\n|---|---|---|\n";
    for (const auto& f : findings)
        md += "| " + f.statement + " | " + f.where + " | " + inWords(f) + " |\n";
    return md;
}

SweepEnsembleReport sweepEnsembleReport(const std::vector<SweepEntry>& entries,
                                        const std::filesystem::path& out) {
    SweepEnsembleReport report;
    bool ensemble = false, variants = false;
    for (const auto& entry : entries) {
        ensemble = ensemble || entry.seed > 0;
        variants = variants || !entry.variant.empty();
    }
    if (!ensemble && !variants) return report;
    const auto cases = gatherEnsemble(entries);
    if (variants) {
        io::writeFileAtomically((out / "variants.csv").string(), variantsCsv(cases));
        report.files.push_back((out / "variants.csv").string());
        report.markdown +=
            "## Controlled experiments\n\nEach case under each variant; \"(xR)\": R times the "
            "reference variant's value (the first, `" +
            cases.front().variant + "`). \"finished\": runs finished of those planned.\n\n" +
            variantsMarkdown(cases) + "\n";
    }
    if (ensemble) {
        const auto findings = computeFindings(cases);
        report.csv = ensembleCsv(cases);
        io::writeFileAtomically((out / "sweep.csv").string(), report.csv);
        io::writeFileAtomically((out / "findings.csv").string(), findingsCsv(findings));
        report.files.push_back((out / "sweep.csv").string());
        report.files.push_back((out / "findings.csv").string());
        report.markdown +=
            "## Ensemble over packing seeds\n\nEach case over its seeds, from the runs that "
            "finished: mean ± sample standard deviation, and min–max. \"(end: k)\": k fronts "
            "reached the domain's end, so their runouts are lower bounds.\n\n" +
            ensembleMarkdown(cases) + "\n## Findings\n\n" + findingsMarkdown(findings) + "\n";
    }
    report.markdown += "## Runs\n\n";
    return report;
}

} // namespace lbdem::campaign
