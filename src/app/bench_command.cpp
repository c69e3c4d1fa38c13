// vct bench: placeholder until the bench command lands; it says so instead of pretending to work.
#include "app/commands.h"
#include "error.h"

namespace vct {

int runBench(const std::vector<std::string>&) { throw Error("'vct bench' is not built yet"); }

}  // namespace vct
