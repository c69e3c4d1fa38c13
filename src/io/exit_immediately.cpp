#include "io/exit_immediately.h"

#include <cstdio>
#include <cstdlib>

#include "io/temporary_files.h"

namespace vct {
namespace {

std::string errorLinePrefix = "vct";

}  // namespace

void setErrorLinePrefix(const std::string& prefix) { errorLinePrefix = prefix; }

void exitImmediately(const std::string& sentence) {
    std::fprintf(stderr, "%s: error: %s\n", errorLinePrefix.c_str(), sentence.c_str());
    std::fflush(stderr);
    removeTemporaryFiles();
    std::_Exit(1);
}

}  // namespace vct
