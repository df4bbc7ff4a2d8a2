// The list of case keys, grouped by section.
#pragma once

namespace lbdem::solver {

class CaseSchema;

/// Declare every case key of this build on schema, section by section, in file order.
void declareCaseKeys(CaseSchema& schema);

} // namespace lbdem::solver
