// The one exception type of the project: a sentence for the user, naming the thing and the problem.
// Thrown where the problem is found, caught once in main(), printed, exit code 1.
#pragma once

#include <stdexcept>
#include <string>

namespace vct {

struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace vct
