// Regression guards are told apart from tests of targets. A bound that records today's figure
// rather than what the renderer should reach says so ("regression guard" in the test), sits in a
// suite whose name ends in `Guard` (ctest labels those tests `guard`: `ctest -L guard` runs them,
// `-LE guard` the rest), and names the target beside it. Read from the test sources, so that a
// guard cannot pass for a target.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace vct::test {
namespace {

const char* const kGuardPhrase = "regression guard";
const char* const kGuardSuffix = "Guard";

struct TestSource {
    std::string file, suite, name;
    std::string text;  // from its TEST line to the next one, lower case
};

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

// Each `TEST(Suite, Name)` or `TEST_F(Suite, Name)` that starts a line. (Read by hand: std::regex
// sets off GCC 12's -Wmaybe-uninitialized inside libstdc++ under the sanitizers' build.)
std::vector<TestSource> testsOf(const std::filesystem::path& file) {
    std::ifstream in(file);
    std::stringstream contents;
    contents << in.rdbuf();
    const std::string source = contents.str();
    std::vector<TestSource> tests;
    std::vector<size_t> starts;
    for (size_t at = source.find("\nTEST"); at != std::string::npos; at = source.find("\nTEST", at + 1)) {
        size_t open = at + 5;
        if (source.compare(open, 2, "_F") == 0) open += 2;
        if (source.compare(open, 1, "(") != 0) continue;
        const size_t comma = source.find(", ", open);
        const size_t close = source.find(')', open);
        if (comma == std::string::npos || close == std::string::npos || comma > close) continue;
        tests.push_back({file.filename().string(), source.substr(open + 1, comma - open - 1),
                         source.substr(comma + 2, close - comma - 2), ""});
        starts.push_back(at);
    }
    starts.push_back(source.size());
    for (size_t i = 0; i < tests.size(); ++i)
        tests[i].text = lowerCase(source.substr(starts[i], starts[i + 1] - starts[i]));
    return tests;
}

std::vector<TestSource> everyTest() {
    std::vector<TestSource> tests;
    for (const char* folder : {"cpu", "gpu", "view"}) {
        const std::filesystem::path path = std::filesystem::path(VCT_SOURCE_DIR) / "tests" / folder;
        for (const auto& entry : std::filesystem::directory_iterator(path))
            if (entry.path().extension() == ".cpp") {
                std::vector<TestSource> found = testsOf(entry.path());
                tests.insert(tests.end(), found.begin(), found.end());
            }
    }
    return tests;
}

bool isGuardSuite(const std::string& suite) {
    const std::string suffix = kGuardSuffix;
    return suite.size() > suffix.size() && suite.compare(suite.size() - suffix.size(), suffix.size(), suffix) == 0;
}

TEST(RegressionGuards, AreInSuitesOfTheirOwnAndNameTheirTargets) {
    const std::vector<TestSource> tests = everyTest();
    ASSERT_GT(tests.size(), 100u) << "the test sources were not found under " << VCT_SOURCE_DIR;
    size_t guards = 0;
    for (const TestSource& test : tests) {
        const std::string where = test.file + ": " + test.suite + "." + test.name;
        const bool saysGuard = test.text.find(kGuardPhrase) != std::string::npos;
        if (saysGuard) {
            EXPECT_TRUE(isGuardSuite(test.suite))
                << where << " says \"" << kGuardPhrase << "\": its suite ends in " << kGuardSuffix;
        }
        if (isGuardSuite(test.suite)) {
            ++guards;
            EXPECT_TRUE(saysGuard) << where << " is in a guard suite: its bound says \"" << kGuardPhrase << "\"";
            EXPECT_NE(test.text.find("target"), std::string::npos) << where << ": a guard names its target";
        }
    }
    EXPECT_GE(guards, 5u);
}

}  // namespace
}  // namespace vct::test
