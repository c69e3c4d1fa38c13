// Writing JSON by hand: a string literal with its escapes, and a number that stays valid JSON
// when it is not finite. Shared by `vct bench`'s reports and the path tracer's sidecars.
#pragma once

#include <string>

namespace vct {

// `text` as a quoted JSON string: quotes and backslashes escaped, control characters as \uXXXX.
std::string jsonString(const std::string& text);
// `value` with 6 significant digits, or null when it is NaN or infinite (JSON has neither).
std::string jsonNumber(double value);

}  // namespace vct
