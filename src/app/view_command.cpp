// vct view: placeholder until the view command lands; it says so instead of pretending to work.
#include "app/commands.h"
#include "error.h"

namespace vct {

int runView(const std::vector<std::string>&) { throw Error("'vct view' is not built yet"); }

}  // namespace vct
