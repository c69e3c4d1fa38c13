#include "io/exit_immediately.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "io/temporary_files.h"

namespace vct {
namespace {

std::string errorLinePrefix = "vct";

}  // namespace

void setErrorLinePrefix(const std::string& prefix) { errorLinePrefix = prefix; }

void exitImmediately(const std::string& sentence) {
    // On a terminal, first erase a progress line the command may be drawing (app/progress_line.h).
    std::fprintf(stderr, "%s%s: error: %s\n", isatty(STDERR_FILENO) == 1 ? "\r\033[K" : "", errorLinePrefix.c_str(),
                 sentence.c_str());
    std::fflush(stderr);
    removeTemporaryFiles();
    std::_Exit(1);
}

}  // namespace vct
