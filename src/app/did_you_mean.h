// "Did you mean": the known name closest to a mistyped one, for error messages.
#pragma once

#include <string>
#include <vector>

namespace vct {

// The number of single-character insertions, deletions and substitutions between a and b.
size_t editDistance(const std::string& a, const std::string& b);

// " (did you mean 'NAME'?)" for the candidate within two edits of `typed` (or a third of its
// length, for long names), the closest first; "" when none is that close.
std::string didYouMean(const std::string& typed, const std::vector<std::string>& candidates,
                       const std::string& prefix = "");

}  // namespace vct
