// Ending the process without unwinding the stack, for the one failure where unwinding is unsafe:
// the GPU did not finish within --gpu-timeout and still reads and writes buffers and images that
// the destructors on the stack would free under it (lavapipe then crashed).
#pragma once

#include <string>

namespace vct {

// What the error line starts with, "vct render" say (main sets it once).
void setErrorLinePrefix(const std::string& prefix);

// Prints "PREFIX: error: SENTENCE", removes the temporary files registered for a signal (no
// OUT.tmp.PID is left), and ends the process with exit code 1 at once.
[[noreturn]] void exitImmediately(const std::string& sentence);

}  // namespace vct
