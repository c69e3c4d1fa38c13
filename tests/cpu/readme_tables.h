// The README's generated tables: the text between a begin and an end marker must be what the code
// makes. VCT_UPDATE_README=1 writes it there instead.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace vct::test {

inline void expectReadmeTable(const std::string& begin, const std::string& end, const std::string& expected) {
    const std::string path = std::string(VCT_TEST_DATA_DIR) + "/../../README.md";
    std::ifstream file(path);
    ASSERT_TRUE(file) << path;
    std::stringstream text;
    text << file.rdbuf();
    std::string readme = text.str();
    const size_t from = readme.find(begin), to = readme.find(end);
    ASSERT_NE(from, std::string::npos) << "README.md has no '" << begin << "'";
    ASSERT_NE(to, std::string::npos) << "README.md has no '" << end << "'";
    const std::string written = readme.substr(from + begin.size(), to - from - begin.size());
    if (written != expected && std::getenv("VCT_UPDATE_README")) {
        readme.replace(from + begin.size(), to - from - begin.size(), expected);
        std::ofstream(path) << readme;
        return;
    }
    EXPECT_EQ(written, expected) << "run the test with VCT_UPDATE_README=1 to write the table the code makes";
}

}  // namespace vct::test
