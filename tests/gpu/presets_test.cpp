// The presets `render --help` lists say what the committed bench run measured for them, and the
// default is the most accurate of those whose light change fits a still's budget.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "render/presets.h"

namespace vct {
namespace {

TEST(Presets, TheHelpsFiguresAreTheCommittedBenchRunsAndTheDefaultIsTheMostAccurate) {
    // The whole run measures every preset.
    std::ifstream file(std::string(VCT_TEST_DATA_DIR) + "/../../docs/bench.json");
    ASSERT_TRUE(file) << "docs/bench.json";
    const nlohmann::json bench = nlohmann::json::parse(file);
    size_t checked = 0;
    const PresetSummary* mostAccurate = nullptr;  // of those a still can afford (kStillBudgetMs)
    for (const PresetSummary& preset : presetSummaries()) {
        ASSERT_TRUE(findRenderPreset(preset.name).has_value()) << preset.name;
        bool affordable = false;
        for (const nlohmann::json& row : bench.at("summary")) {
            if (row.value("preset", "") != preset.name) continue;
            EXPECT_NEAR(preset.stillFrameMs, row.at("static_gpu_ms").get<double>(), 0.06) << preset.name;
            EXPECT_NEAR(preset.fullRelMse, row.at("relmse_full").get<double>(), 6e-5) << preset.name;
            affordable = row.at("light_change_ms").get<double>() <= kStillBudgetMs;
            ++checked;
        }
        if (affordable && (!mostAccurate || preset.fullRelMse < mostAccurate->fullRelMse)) mostAccurate = &preset;
    }
    EXPECT_EQ(checked, presetSummaries().size()) << "every preset is in the committed run";
    ASSERT_NE(mostAccurate, nullptr);
    EXPECT_STREQ(mostAccurate->name, kDefaultPreset);
}

}  // namespace
}  // namespace vct
