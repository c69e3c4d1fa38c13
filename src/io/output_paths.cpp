#include "io/output_paths.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "error.h"

namespace vct {
namespace {

namespace fs = std::filesystem;

std::string extensionList(const std::vector<std::string>& extensions) {
    std::string list;
    for (size_t i = 0; i < extensions.size(); ++i)
        list += (i == 0 ? "" : i + 1 == extensions.size() ? " or " : ", ") + extensions[i];
    return list;
}

// access() rather than trying a file: nothing is created before the work is done. It answers for
// the real user, which is the one that writes here (vct is not setuid).
bool mayWriteInto(const fs::path& folder) { return access(folder.c_str(), W_OK | X_OK) == 0; }

}  // namespace

bool endsWithIgnoringCase(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() &&
           std::equal(suffix.begin(), suffix.end(), text.end() - long(suffix.size()),
                      [](char a, char b) { return std::tolower(uint8_t(a)) == std::tolower(uint8_t(b)); });
}

void checkOutputFile(const std::string& path, const std::vector<std::string>& extensions) {
    const std::string refusal = "cannot write '" + path + "': ";
    if (path.empty()) throw Error("the output path is empty");
    if (std::none_of(extensions.begin(), extensions.end(),
                     [&](const std::string& extension) { return endsWithIgnoringCase(path, extension); }))
        throw Error(refusal + "the output must end in " + extensionList(extensions));
    std::error_code error;
    if (fs::is_directory(path, error)) throw Error(refusal + "it is a folder");
    const fs::path parent = fs::path(path).parent_path();
    const fs::path folder = parent.empty() ? fs::path(".") : parent;
    const fs::file_status status = fs::status(folder, error);
    if (!fs::exists(status)) throw Error(refusal + "the folder '" + folder.string() + "' does not exist");
    if (!fs::is_directory(status)) throw Error(refusal + "'" + folder.string() + "' is not a folder");
    if (!mayWriteInto(folder))
        throw Error(refusal + "no permission to write into the folder '" + folder.string() + "'");
}

void prepareOutputFolder(const std::string& folder) {
    if (folder.empty()) throw Error("the output folder is empty");
    std::error_code error;
    fs::create_directories(folder, error);
    if (error) throw Error("cannot create the output folder '" + folder + "': " + error.message());
    if (!fs::is_directory(folder, error)) throw Error("the output folder '" + folder + "' is not a folder");
    if (!mayWriteInto(folder)) throw Error("no permission to write into the output folder '" + folder + "'");
}

}  // namespace vct
