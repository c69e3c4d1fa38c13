#include "view/recent_files.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>

namespace vct {

namespace fs = std::filesystem;

fs::path recentFilesPath() {
    // XDG Base Directory Specification: an empty or relative XDG_CONFIG_HOME is to be ignored.
    const char* config = std::getenv("XDG_CONFIG_HOME");
    if (config && fs::path(config).is_absolute()) return fs::path(config) / "vct" / "recent";
    const char* home = std::getenv("HOME");
    if (home && *home) return fs::path(home) / ".config" / "vct" / "recent";
    return {};
}

std::vector<std::string> readRecentFiles(const fs::path& file) {
    std::vector<std::string> recent;
    std::ifstream in(file);
    for (std::string line; recent.size() < kRecentFilesAtMost && std::getline(in, line);)
        if (!line.empty() && std::find(recent.begin(), recent.end(), line) == recent.end()) recent.push_back(line);
    return recent;
}

void rememberRecentFile(std::vector<std::string>& recent, const std::string& path) {
    std::error_code error;
    fs::path absolute = fs::absolute(path, error);
    const std::string entry = error ? path : absolute.lexically_normal().string();
    if (entry.find('\n') != std::string::npos) return;  // the file holds one path a line
    recent.erase(std::remove(recent.begin(), recent.end(), entry), recent.end());
    recent.insert(recent.begin(), entry);
    if (recent.size() > kRecentFilesAtMost) recent.resize(kRecentFilesAtMost);
}

std::string writeRecentFiles(const fs::path& file, const std::vector<std::string>& recent) {
    if (file.empty()) return "the recent files are not kept: neither XDG_CONFIG_HOME nor HOME is set";
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (error) return "cannot keep the recent files in '" + file.string() + "': " + error.message();
    std::ofstream out(file, std::ios::trunc);
    for (const std::string& path : recent) out << path << '\n';
    out.flush();
    if (!out) return "cannot keep the recent files in '" + file.string() + "': it cannot be written";
    return "";
}

}  // namespace vct
