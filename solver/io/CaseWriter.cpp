// Formatting a case as documented TOML, and atomic file writes.
#include "solver/io/CaseWriter.h"

#include "solver/io/SafeFile.h"
#include "solver/scene/CaseSchema.h"

namespace lbdem::io {

using solver::CaseSchema;

namespace {

std::string commentFor(const solver::ParamDecl& decl) {
    std::string comment = "# " + decl.doc;
    const std::string range = decl.describeRange();
    if (decl.unit != "-" && !decl.unit.empty()) comment += " [" + decl.unit + "]";
    if (!range.empty()) comment += " (" + range + ")";
    return comment;
}

} // namespace

std::string formatCase(const solver::CaseSpec& spec) {
    const auto& schema = CaseSchema::instance();
    std::string text = "# lbdem case file: every key with its unit, allowed range and meaning.\n";
    for (const auto& section : schema.sections()) {
        if (!section.empty()) text += "\n[" + section + "]\n";
        for (const auto& decl : schema.params()) {
            if (decl.section != section) continue;
            text += commentFor(decl) + "\n";
            text += decl.key + " = " + solver::formatTomlValue(decl.get(spec)) + "\n";
        }
    }
    return text;
}

void writeFileAtomically(const std::string& path, const std::string& text, bool durable) {
    replaceFile(path, text, durable);
}

void writeCase(const solver::CaseSpec& spec, const std::string& path) {
    writeFileAtomically(path, formatCase(spec));
}

} // namespace lbdem::io
