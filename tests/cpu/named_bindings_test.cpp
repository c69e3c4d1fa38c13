// Descriptor slots and specialization-constant ids are named once (shaders_glsl/bindings.h): no
// shader declares, and no C++ fills, a slot by a bare number, so a resource cannot have one
// number in one shader and another in the next.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vct {
namespace {

const std::filesystem::path kSourceDir = std::filesystem::path(VCT_TEST_DATA_DIR) / ".." / "..";

// Whether `line` holds one of `words` followed, past spaces, by `separator`, spaces and a digit:
// "binding = 3", ".buffer(3". (Not std::regex: g++ 12 warns inside it under the sanitizers.)
bool numberAfter(const std::string& line, const std::vector<std::string>& words, char separator) {
    for (const std::string& word : words)
        for (size_t at = line.find(word); at != std::string::npos; at = line.find(word, at + 1)) {
            size_t i = at + word.size();
            while (i < line.size() && line[i] == ' ') ++i;
            if (i >= line.size() || line[i] != separator) continue;
            ++i;
            while (i < line.size() && line[i] == ' ') ++i;
            if (i < line.size() && line[i] >= '0' && line[i] <= '9') return true;
        }
    return false;
}

// "file:line: text" for each line of the files under `folder` ending in one of `extensions` that
// holds one of `words`, `separator` and a number.
std::vector<std::string> matchingLines(const std::string& folder, const std::vector<std::string>& extensions,
                                       const std::vector<std::string>& words, char separator) {
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
            if (numberAfter(line, words, separator)) found.push_back(name + ":" + std::to_string(number) + ": " + line);
    }
    return found;
}

std::string joined(const std::vector<std::string>& lines) {
    std::ostringstream text;
    for (const std::string& line : lines) text << "\n  " << line;
    return text.str();
}

TEST(NamedBindings, NoShaderDeclaresASlotOrAConstantIdByNumber) {
    const std::vector<std::string> bare = matchingLines("shaders_glsl", {".glsl"}, {"binding", "constant_id"}, '=');
    EXPECT_TRUE(bare.empty()) << "use the names in shaders_glsl/bindings.h:" << joined(bare);
}

TEST(NamedBindings, NoPassFillsASlotByNumber) {
    const std::vector<std::string> bare = matchingLines(
        "src", {".cpp", ".h"},
        {".buffer", ".buffers", ".storageImage", ".storageImages", ".sampledImage", ".sampledImages"}, '(');
    EXPECT_TRUE(bare.empty()) << "use the names in shaders_glsl/bindings.h:" << joined(bare);
}

}  // namespace
}  // namespace vct
