// Named arrays that hold a solver's complete state, for checkpoints (written by lbdem::io).
#pragma once

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace lbdem::solver {

/// The full double-precision state of a simulation as named flat arrays ("lattice/f",
/// "dem/x", ...). Modules save into it and restore from it; io writes it as HDF5 datasets.
struct StateArchive {
    std::map<std::string, std::vector<double>> reals;
    std::map<std::string, std::vector<std::int64_t>> integers;

    /// The real array called name; throws std::out_of_range naming it when absent.
    const std::vector<double>& real(const std::string& name) const;
    /// The integer array called name; throws std::out_of_range naming it when absent.
    const std::vector<std::int64_t>& integer(const std::string& name) const;
};

inline const std::vector<double>& StateArchive::real(const std::string& name) const {
    const auto found = reals.find(name);
    if (found == reals.end()) throw std::out_of_range("checkpoint has no array '" + name + "'");
    return found->second;
}

inline const std::vector<std::int64_t>& StateArchive::integer(const std::string& name) const {
    const auto found = integers.find(name);
    if (found == integers.end()) throw std::out_of_range("checkpoint has no array '" + name + "'");
    return found->second;
}

} // namespace lbdem::solver
