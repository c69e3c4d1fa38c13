// Every input the fuzzer (tests/fuzz, tools/fuzz.sh) ever found a problem with is kept in
// tests/data/fuzz-regressions/ and loaded here as the fuzzer loads it: written as scene.glb when it
// starts with the GLB magic, else as scene.gltf, into a folder of its own. Each must load or be
// refused with a vct::Error naming the file; a crash or a sanitizer report (tools/sanitize.sh runs
// this under ASan and UBSan) fails the run. The fuzzer's seeds are held to the same rule.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "error.h"
#include "gltf_test_helpers.h"
#include "scene/load.h"

namespace vct::test {
namespace {

std::vector<fs::path> filesIn(const fs::path& folder) {
    std::vector<fs::path> files;
    if (fs::is_directory(folder))
        for (const fs::directory_entry& entry : fs::directory_iterator(folder))
            if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

// Loads `input` the way the fuzzer does; returns "" when it loads, else the refusal's message.
std::string loadAsTheFuzzerDoes(const fs::path& input) {
    std::ifstream in(input, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    TempFolder folder;
    const fs::path file = folder.write(binary ? "scene.glb" : "scene.gltf", bytes);
    LoadOptions options;
    options.maxFileBytes = uint64_t(64) << 20;
    try {
        const Scene scene = loadGltf(file.string(), options);
        (void)scene.bounds();
        return "";
    } catch (const Error& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(file.string()), std::string::npos)
            << input.filename() << ": the refusal does not name the file: " << message;
        return message.empty() ? "(empty message)" : message;
    }
}

TEST(FuzzRegressions, EveryInputTheFuzzerFoundLoadsOrIsRefusedCleanly) {
    const std::vector<fs::path> files = filesIn(fs::path(VCT_TEST_DATA_DIR) / "fuzz-regressions");
    for (const fs::path& file : files) {
        const std::string refusal = loadAsTheFuzzerDoes(file);
        std::printf("[ fuzz regression ] %s: %s\n", file.filename().c_str(),
                    refusal.empty() ? "loaded" : refusal.c_str());
    }
    if (files.empty()) GTEST_SKIP() << "no fuzz regressions recorded yet";
}

TEST(FuzzRegressions, TheFuzzerSeedsLoadExceptTheOneWhoseBufferIsMissing) {
    const std::vector<fs::path> seeds = filesIn(fs::path(VCT_SOURCE_DIR) / "tests" / "fuzz" / "seeds");
    ASSERT_FALSE(seeds.empty());
    for (const fs::path& seed : seeds) {
        const std::string refusal = loadAsTheFuzzerDoes(seed);
        if (seed.filename() == "quad_external_buffer.gltf")
            EXPECT_NE(refusal.find("buffers[0]"), std::string::npos) << refusal;
        else EXPECT_EQ(refusal, "") << seed.filename();
    }
}

}  // namespace
}  // namespace vct::test
