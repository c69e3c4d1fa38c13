// The setting table (src/render/setting_table.h) is where the command line, the viewer, the bench
// and the README learn each setting: its rows must be unambiguous, take every value the presets
// use, and the README's option table must be the one it makes.
#include <gtest/gtest.h>

#include <set>

#include "bench/matrix.h"
#include "readme_tables.h"
#include "render/presets.h"
#include "render/setting_table.h"

namespace vct {
namespace {

TEST(SettingTable, NamesKeysAndLabelTagsAreEachUsedOnce) {
    std::set<std::string> options, keys, tags, labels;
    for (const SettingRow& row : settingTable()) {
        EXPECT_TRUE(options.insert(row.option).second) << row.option;
        if (row.label) {
            EXPECT_TRUE(labels.insert(row.label).second) << row.label;
        }
        if (!row.benchKey) continue;
        EXPECT_TRUE(keys.insert(row.benchKey).second) << row.benchKey;
        EXPECT_NE(row.legend, nullptr) << row.option << ": the bench's label part needs its legend";
        if (row.labelTag[0] != '\0') {
            EXPECT_TRUE(tags.insert(row.labelTag).second) << row.labelTag;
        }
    }
}

TEST(SettingTable, EveryPresetsValueIsOneTheRowTakesAndSpellsBack) {
    std::vector<std::pair<std::string, RenderSettings>> settings = renderPresets();
    settings.push_back({"the renderer's defaults", RenderSettings{}});
    for (const auto& [name, preset] : settings)
        for (const SettingRow& row : settingTable()) {
            const double value = row.get(preset);
            const std::string text = settingText(row, value);
            const std::optional<double> parsed = parseSetting(row, text);
            ASSERT_TRUE(parsed.has_value())
                << name << ": --" << row.option << " " << text << " is not in " << settingDomain(row);
            // Written back through the row, the member holds the same value (as the member's type
            // holds it: "0.95" is not the double nearest the float 0.95f).
            RenderSettings copy = preset;
            row.set(copy, *parsed);
            EXPECT_EQ(copy, preset) << name << ": --" << row.option;
        }
}

TEST(SettingTable, ValuesOutsideARowsDomainAreRefused) {
    EXPECT_FALSE(parseSetting(settingRow("voxels"), "48"));  // not a power of two
    EXPECT_FALSE(parseSetting(settingRow("voxels"), "1024"));
    EXPECT_FALSE(parseSetting(settingRow("cones"), "2.5"));
    EXPECT_FALSE(parseSetting(settingRow("cones"), "0"));
    EXPECT_FALSE(parseSetting(settingRow("cone-aperture"), "nan"));
    EXPECT_FALSE(parseSetting(settingRow("cone-aperture"), "40deg"));
    EXPECT_FALSE(parseSetting(settingRow("mode"), "1"));     // names only
    EXPECT_FALSE(parseSetting(settingRow("bounces"), "0"));  // spelt "converged"
    EXPECT_EQ(parseSetting(settingRow("bounces"), "converged"), double(kConvergedBounces));
    EXPECT_EQ(parseSetting(settingRow("diffuse-resolution"), "quarter"), 4.0);
    EXPECT_EQ(settingDomain(settingRow("bounces")), "converged or a whole number from 1 to 32");
    EXPECT_EQ(settingDomain(settingRow("mode")), "full, direct or indirect");
}

TEST(SettingTable, TwoSettingsTheBenchRecordsApartGetTwoLabels) {
    // Each recorded row changed alone, from the matrix's base to another value it takes.
    const RenderSettings base = bench::defaultMatrix(RenderSettings{}).front().settings;
    std::set<std::string> labels = {bench::settingLabel(base)};
    for (const SettingRow& row : settingTable()) {
        if (!row.benchKey) continue;
        RenderSettings changed = base;
        const double value = row.get(base);
        const double other = !row.names.empty() && row.names.front().value != value ? row.names.front().value
                             : row.namesOnly                                        ? row.names.back().value
                             : value != row.max                                     ? row.max
                                                                                    : row.min;
        row.set(changed, other);
        ASSERT_NE(changed, base) << row.option;
        EXPECT_TRUE(labels.insert(bench::settingLabel(changed)).second)
            << "--" << row.option << " " << settingText(row, other) << ": " << bench::settingLabel(changed);
    }
}

// The README's settings table, between its markers. VCT_UPDATE_README=1 writes it instead.
TEST(SettingTable, TheReadmesOptionTableIsTheOneTheRowsMake) {
    test::expectReadmeTable("<!-- settings table: made from src/render/setting_table.cpp -->\n",
                            "<!-- end of the settings table -->", settingsMarkdown(*findRenderPreset(kDefaultPreset)));
}

}  // namespace
}  // namespace vct
