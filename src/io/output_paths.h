// Output paths checked before any work: a render that can only fail when it writes its image
// should fail at once, naming the path the user gave, not after loading and rendering.
#pragma once

#include <string>
#include <vector>

namespace vct {

// Whether `text` ends in `suffix` (".png"), compared without case.
bool endsWithIgnoringCase(const std::string& text, const std::string& suffix);

// Throws vct::Error ("cannot write 'PATH': ...") unless `path` ends in one of `extensions`
// (".png", compared without case), is not a folder, and lies in a folder that exists and that
// this process may write into.
void checkOutputFile(const std::string& path, const std::vector<std::string>& extensions);

// Creates `folder` (and its parents) if it does not exist; throws vct::Error naming it when it
// cannot, when it is not a folder, or when this process may not write into it.
void prepareOutputFolder(const std::string& folder);

}  // namespace vct
