// Edit distance between words, used to suggest the nearest known key or command.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace lbdem::solver {

/// Levenshtein distance between two strings (insertions, deletions, substitutions cost 1).
int editDistance(std::string_view a, std::string_view b);

/// The candidate closest to word by edit distance; empty when none is within half its length + 2.
std::string nearestWord(std::string_view word, const std::vector<std::string>& candidates);

} // namespace lbdem::solver
