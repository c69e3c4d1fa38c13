// The subcommands of `vct`.
#pragma once

#include <string>
#include <vector>

namespace vct {

int runRender(const std::vector<std::string>& arguments);
int runView(const std::vector<std::string>& arguments);
int runBench(const std::vector<std::string>& arguments);

}  // namespace vct
