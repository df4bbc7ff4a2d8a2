// Writing a CaseSpec back as a complete, documented TOML case.
#pragma once

#include "solver/scene/CaseSpec.h"

#include <string>

namespace lbdem::io {

/// The whole case as TOML: every key, with its unit, range and documentation as comments.
std::string formatCase(const solver::CaseSpec& spec);

/// Write formatCase(spec) to path atomically (temporary file + rename); throws on I/O failure.
void writeCase(const solver::CaseSpec& spec, const std::string& path);

/// Write text to path atomically: a sibling temporary file renamed over it (removed when the
/// write fails), flushed to the disk first when durable (io::replaceFile).
void writeFileAtomically(const std::string& path, const std::string& text, bool durable = false);

} // namespace lbdem::io
