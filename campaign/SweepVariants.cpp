// The controlled-experiment table of a sweep with variants.
#include "campaign/SweepVariants.h"

#include <cmath>
#include <cstddef>
#include <string>

namespace lbdem::campaign {

namespace {

/// The metrics of the table, in its column order (the case's own figures of the issue).
constexpr EnsembleMetric kColumns[] = {EnsembleMetric::KePeak,      EnsembleMetric::TKePeak,
                                       EnsembleMetric::RunoutAt3Tc, EnsembleMetric::FroudeAt3Tc,
                                       EnsembleMetric::PoreAt1Tc,   EnsembleMetric::RunoutFinal,
                                       EnsembleMetric::PackingFinal};

/// The case a variant belongs to: its name before "__".
std::string baseName(const EnsembleCase& c) {
    const auto cut = c.name.rfind("__");
    return cut == std::string::npos ? c.name : c.name.substr(0, cut);
}

const EnsembleCase* referenceOf(const std::vector<EnsembleCase>& cases, const EnsembleCase& c) {
    const std::string& reference = cases.front().variant;
    for (const auto& other : cases)
        if (other.variant == reference && baseName(other) == baseName(c)) return &other;
    return nullptr;
}

const Spread& metricSpread(const EnsembleCase& c, EnsembleMetric m) {
    return c.spread[static_cast<std::size_t>(m)];
}

/// value / reference value, NaN where either is missing or the reference is zero.
double ratio(const EnsembleCase& c, const EnsembleCase* reference, EnsembleMetric m) {
    if (!reference) return std::nan("");
    const Spread &a = metricSpread(c, m), &b = metricSpread(*reference, m);
    if (a.count == 0 || b.count == 0 || b.mean == 0) return std::nan("");
    return a.mean / b.mean;
}

std::string status(const EnsembleCase& c) {
    std::string text = std::to_string(c.finished) + "/" + std::to_string(c.runs.size());
    if (c.unstable > 0) text += ", " + std::to_string(c.unstable) + " unstable";
    if (c.endReached > 0) text += ", " + std::to_string(c.endReached) + " at the end";
    return text;
}

} // namespace

std::string variantsMarkdown(const std::vector<EnsembleCase>& cases) {
    std::string md = "| case | variant | finished |";
    std::string rule = "|---|---|---|";
    for (const EnsembleMetric m : kColumns) {
        md += std::string(" ") + metricHeading(m) + " |";
        rule += "---|";
    }
    md += "\n" + rule + "\n";
    for (const auto& c : cases) {
        const EnsembleCase* reference = referenceOf(cases, c);
        md += "| " + baseName(c) + " | " + c.variant + " | " + status(c) + " |";
        for (const EnsembleMetric m : kColumns) {
            std::string cell = meanCell(metricSpread(c, m), metricPattern(m));
            const double r = ratio(c, reference, m);
            if (reference != &c && std::isfinite(r)) cell += " (x" + number(r, "%.2f") + ")";
            md += " " + cell + " |";
        }
        md += "\n";
    }
    return md;
}

std::string variantsCsv(const std::vector<EnsembleCase>& cases) {
    std::string csv = "case,variant,runs,finished,unstable,front_at_end";
    for (const EnsembleMetric m : kColumns)
        csv += std::string(",") + metricKey(m) + "," + metricKey(m) + "_over_reference";
    csv += "\n";
    for (const auto& c : cases) {
        const EnsembleCase* reference = referenceOf(cases, c);
        csv += baseName(c) + "," + c.variant + "," + std::to_string(c.runs.size()) + "," +
               std::to_string(c.finished) + "," + std::to_string(c.unstable) + "," +
               std::to_string(c.endReached);
        for (const EnsembleMetric m : kColumns) {
            const Spread& s = metricSpread(c, m);
            csv += "," + (s.count ? number(s.mean, "%.6g") : "") + "," +
                   number(ratio(c, reference, m), "%.6g");
        }
        csv += "\n";
    }
    return csv;
}

} // namespace lbdem::campaign
