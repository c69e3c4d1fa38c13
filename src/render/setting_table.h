// Each render setting once, as one row: its member, its command-line name and help, its label and
// widget in the viewer, its range, and whether and under which key `vct bench` records it. The
// options and their help (src/app/options.cpp), the viewer's panels (src/view/ui.cpp), the bench's
// labels, CSV and JSON (src/bench) and the README's option table are all made from these rows, so a
// new setting is a member (settings.h) and a row (setting_table.cpp).
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "render/settings.h"

namespace vct {

// Where a setting shows in the viewer, and in which table of the README it is listed.
enum class SettingGroup { Image, Light, Voxels, Cones, Shadows };

// How the viewer edits it.
enum class SettingWidget {
    None,        // command line only (the image size: the window sets it)
    Slider,      // whole or real numbers in [min, max]; a named value shows its name
    PowerOfTwo,  // a list of the powers of two in [min, max]
    Choice,      // a list of the names
};

// A value the command line and the bench spell by name ("converged" for 0 bounces).
struct NamedValue {
    const char* name;
    double value;
    const char* labelPart;  // in the bench's label, after the row's tag: "conv" gives "bconv"
};

// The row's member, reached through RenderSettings and read and written as a double (exact for
// every whole number a setting takes).
struct SettingAccess {
    double (*get)(const RenderSettings&);
    void (*set)(RenderSettings&, double);
};

// Written with designated initializers: a row names what it sets and leaves the rest at these.
struct SettingRow {
    const char* option;  // --option
    const char* shape;   // the value in the help: "N", "DEGREES", "full|half|quarter"
    const char* help;
    SettingGroup group;
    SettingAccess access;
    const char* label = nullptr;  // in the viewer; nullptr: command line only
    SettingWidget widget = SettingWidget::Slider;
    const char* format = "%.2f";  // the viewer's slider format, "%.0f deg"; "%d" for whole numbers
    double min = 0.0, max = 0.0;  // the numbers it takes, besides its names
    bool whole = false;           // whole numbers only
    bool powerOfTwo = false;      // powers of two only
    std::vector<NamedValue> names = {};
    bool namesOnly = false;          // no numbers: one of `names`
    const char* benchKey = nullptr;  // the bench's CSV column and JSON key; nullptr: not recorded
    const char* labelTag = "";       // the bench's label: "v" makes "v64"
    bool alwaysInLabel = false;      // in every label; the others where they differ from the bench's base
    const char* legend = nullptr;    // the label explained: "v64 = 64³ voxels"

    double get(const RenderSettings& settings) const { return access.get(settings); }
    void set(RenderSettings& settings, double value) const { access.set(settings, value); }
};

// Every row, in the order the help and the README list them.
const std::vector<SettingRow>& settingTable();
// The row of --`option` (an unknown name is a programming error: std::out_of_range).
const SettingRow& settingRow(const std::string& option);

// The name `value` has in the row, or nullptr.
const NamedValue* namedValue(const SettingRow& row, double value);
// The value as the command line spells it: its name, or the number ("%g").
std::string settingText(const SettingRow& row, double value);
inline std::string settingText(const SettingRow& row, const RenderSettings& settings) {
    return settingText(row, row.get(settings));
}
// What the row takes, for its errors: "a whole number from 1 to 32", "full, half or quarter",
// "converged or a whole number from 1 to 32", "a power of two from 32 to 512".
std::string settingDomain(const SettingRow& row);
// `text` as the row takes it (a name, or a number in its range); nullopt where it is neither.
std::optional<double> parseSetting(const SettingRow& row, const std::string& text);
// The bench label's part for the row: its tag and its value, "v64", "bconv", "rays".
std::string labelPart(const SettingRow& row, double value);

// The rows as the README's option table (Markdown), defaults from `defaults`: a test holds the
// README to it.
std::string settingsMarkdown(const RenderSettings& defaults);
// A number as the tables write it ("%g": 0.25, 4096, 1e+09).
std::string shortNumber(double value);
// `text` for a Markdown table cell: its bars escaped.
std::string markdownCell(std::string text);

// The accessor of RenderSettings::*part's ::*member, for a row.
template <auto part, auto member>
constexpr SettingAccess settingField() {
    return {[](const RenderSettings& s) { return double((s.*part).*member); },
            [](RenderSettings& s, double value) {
                using T = std::remove_reference_t<decltype((s.*part).*member)>;
                if constexpr (std::is_floating_point_v<T>) (s.*part).*member = T(value);
                else (s.*part).*member = T(static_cast<long long>(value));
            }};
}

}  // namespace vct
