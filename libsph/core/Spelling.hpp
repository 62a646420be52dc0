// "Did you mean": the valid word nearest to a misspelt one, for keywords (Dictionary) and
// model names (Registry).
#pragma once

#include <string>
#include <vector>

namespace sph {

// Levenshtein distance, case-insensitive: a misspelling is a letter or two away.
std::size_t editDistance(const std::string& a, const std::string& b);

// The candidate whose spelling is nearest to `word`, with up to a third of its letters wrong
// (at least one); empty when none is that near. The first of equally near candidates.
std::string nearestSpelling(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sph
