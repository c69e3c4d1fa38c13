// Descriptor slots and specialization-constant ids are named once (shaders_glsl/bindings.h): no
// shader declares, and no C++ fills, a slot by a bare number, so a resource cannot have one
// number in one shader and another in the next.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace vct {
namespace {

const std::filesystem::path kSourceDir = std::filesystem::path(VCT_TEST_DATA_DIR) / ".." / "..";

// "file:line: text" for each line of the files under `folder` ending in one of `extensions` that
// matches `pattern`.
std::vector<std::string> matchingLines(const std::string& folder, const std::vector<std::string>& extensions,
                                       const std::regex& pattern) {
    std::vector<std::string> found;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kSourceDir / folder)) {
        const std::string name = entry.path().filename().string();
        bool wanted = false;
        for (const std::string& extension : extensions)
            wanted |= name.size() > extension.size() && name.ends_with(extension);
        if (!wanted) continue;
        std::ifstream file(entry.path());
        std::string line;
        for (int number = 1; std::getline(file, line); ++number)
            if (std::regex_search(line, pattern)) found.push_back(name + ":" + std::to_string(number) + ": " + line);
    }
    return found;
}

std::string joined(const std::vector<std::string>& lines) {
    std::ostringstream text;
    for (const std::string& line : lines) text << "\n  " << line;
    return text.str();
}

TEST(NamedBindings, NoShaderDeclaresASlotOrAConstantIdByNumber) {
    const std::vector<std::string> bare =
        matchingLines("shaders_glsl", {".glsl"}, std::regex(R"((binding|constant_id)\s*=\s*[0-9])"));
    EXPECT_TRUE(bare.empty()) << "use the names in shaders_glsl/bindings.h:" << joined(bare);
}

TEST(NamedBindings, NoPassFillsASlotByNumber) {
    const std::vector<std::string> bare = matchingLines(
        "src", {".cpp", ".h"},
        std::regex(R"(\.(buffer|buffers|storageImage|storageImages|sampledImage|sampledImages)\(\s*[0-9])"));
    EXPECT_TRUE(bare.empty()) << "use the names in shaders_glsl/bindings.h:" << joined(bare);
}

}  // namespace
}  // namespace vct
