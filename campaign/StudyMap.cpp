// Study map (Markdown) from the rows of a study over two or more keys.
#include "campaign/StudyMap.h"

#include "solver/io/CaseWriter.h"

namespace lbdem::campaign {

namespace {

/// What a cell of the map says about one setting.
std::string cellText(const StudyRow& row) {
    if (row.status == "finished" || row.status == "no metric") return "bounded";
    return row.status; // unstable, or unfinished / missing / unreadable: not known
}

} // namespace

std::string writeStudyMap(const StudySpec& study, const std::vector<StudyRow>& rows,
                          const std::filesystem::path& out) {
    // The product lists the first key slowest: each of its values owns `columns` consecutive
    // settings, the other keys' combinations in the same order.
    std::size_t columns = 0;
    while (columns < study.settings.size() &&
           study.settings[columns].values[0] == study.settings[0].values[0])
        ++columns;
    std::string others;
    for (std::size_t k = 1; k < study.keys.size(); ++k)
        others += (k > 1 ? ", " : "") + study.keys[k];
    std::string md = "# Stability map of " + study.caseName + "\n\n";
    md += "bounded: the run reached its last step; unstable: the stability guard stopped it (see "
          "study.md for the diagnosis). Rows: " +
          study.keys[0] + "; columns: " + others + ".\n\n";
    md += "| " + study.keys[0] + " \\ " + others + " |";
    std::string rule = "|---|";
    for (std::size_t c = 0; c < columns; ++c) {
        std::string heading;
        for (std::size_t k = 1; k < study.keys.size(); ++k)
            heading += (k > 1 ? ", " : "") + study.settings[c].values[k];
        md += " " + heading + " |";
        rule += "---|";
    }
    md += "\n" + rule + "\n";
    for (std::size_t start = 0; start < rows.size(); start += columns) {
        md += "| " + study.settings[start].values[0] + " |";
        for (std::size_t c = 0; c < columns && start + c < rows.size(); ++c)
            md += " " + cellText(rows[start + c]) + " |";
        md += "\n";
    }
    const std::string path = (out / "study_map.md").string();
    io::writeFileAtomically(path, md);
    return path;
}

} // namespace lbdem::campaign
