// The scenes the viewer opened lately, newest first, as absolute paths: the Scene section lists
// them, and they outlive the viewer in $XDG_CONFIG_HOME/vct/recent (~/.config/vct/recent when that
// is unset), one path a line. Failing to read or write that file costs only the list, never the
// viewer: the functions report instead of throwing.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace vct {

constexpr size_t kRecentFilesAtMost = 10;

// Where the list is kept; empty when neither XDG_CONFIG_HOME nor HOME is set.
std::filesystem::path recentFilesPath();

// The list in `file`, at most kRecentFilesAtMost paths; none when it does not exist or cannot be read.
std::vector<std::string> readRecentFiles(const std::filesystem::path& file);

// Puts `path` (made absolute) first, dropping an older entry of it and what passes the limit.
void rememberRecentFile(std::vector<std::string>& recent, const std::string& path);

// Writes the list, creating the folder; "" on success, else a sentence naming the file and the problem.
std::string writeRecentFiles(const std::filesystem::path& file, const std::vector<std::string>& recent);

}  // namespace vct
