// The viewer's recent files (src/view/recent_files.h): newest first, each path once, at most ten,
// kept where the XDG Base Directory Specification says, and a file that cannot be written is a
// sentence, not a crash.
#include "view/recent_files.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>

namespace {

namespace fs = std::filesystem;

fs::path freshDirectory(const std::string& name) {
    const fs::path directory = fs::temp_directory_path() / ("vct_recent_" + name + "_" + std::to_string(getpid()));
    fs::remove_all(directory);
    fs::create_directories(directory);
    return directory;
}

TEST(RecentFiles, TheNewestComesFirstOnceAndTheListKeepsTen) {
    std::vector<std::string> recent;
    for (int i = 0; i < 12; ++i) vct::rememberRecentFile(recent, "/scenes/" + std::to_string(i) + ".glb");
    vct::rememberRecentFile(recent, "/scenes/5.glb");
    ASSERT_EQ(recent.size(), vct::kRecentFilesAtMost);
    EXPECT_EQ(recent.front(), "/scenes/5.glb");
    EXPECT_EQ(recent[1], "/scenes/11.glb");
    EXPECT_EQ(std::count(recent.begin(), recent.end(), "/scenes/5.glb"), 1);
    EXPECT_EQ(std::count(recent.begin(), recent.end(), "/scenes/0.glb"), 0) << "the oldest went";
}

TEST(RecentFiles, RelativePathsAreKeptAbsoluteSoTheyOpenFromAnyFolder) {
    std::vector<std::string> recent;
    vct::rememberRecentFile(recent, "models/../box.gltf");
    ASSERT_EQ(recent.size(), 1u);
    EXPECT_EQ(recent.front(), (fs::current_path() / "box.gltf").string());
}

TEST(RecentFiles, WrittenThenReadBackInOrder) {
    const fs::path file = freshDirectory("round_trip") / "vct" / "recent";
    const std::vector<std::string> recent = {"/a/one.glb", "/b/two.gltf"};
    EXPECT_EQ(vct::writeRecentFiles(file, recent), "") << "the folder is created";
    EXPECT_EQ(vct::readRecentFiles(file), recent);
    EXPECT_TRUE(vct::readRecentFiles(file.parent_path() / "absent").empty());
}

TEST(RecentFiles, AFileThatCannotBeWrittenIsASentenceNamingIt) {
    const fs::path directory = freshDirectory("blocked");
    std::ofstream(directory / "vct") << "a file where the folder should be";
    const std::string problem = vct::writeRecentFiles(directory / "vct" / "recent", {"/a/one.glb"});
    EXPECT_NE(problem.find("cannot keep the recent files in '" + (directory / "vct" / "recent").string() + "'"),
              std::string::npos)
        << problem;
}

TEST(RecentFiles, KeptUnderXdgConfigHomeElseUnderHomesConfig) {
    const char* savedConfig = std::getenv("XDG_CONFIG_HOME");
    const char* savedHome = std::getenv("HOME");
    const std::string saved = savedConfig ? savedConfig : "", home = savedHome ? savedHome : "";
    setenv("XDG_CONFIG_HOME", "/tmp/config", 1);
    EXPECT_EQ(vct::recentFilesPath(), fs::path("/tmp/config/vct/recent"));
    setenv("XDG_CONFIG_HOME", "relative", 1);  // the specification says to ignore it
    setenv("HOME", "/home/someone", 1);
    EXPECT_EQ(vct::recentFilesPath(), fs::path("/home/someone/.config/vct/recent"));
    if (savedConfig) setenv("XDG_CONFIG_HOME", saved.c_str(), 1);
    else unsetenv("XDG_CONFIG_HOME");
    if (savedHome) setenv("HOME", home.c_str(), 1);
}

}  // namespace
