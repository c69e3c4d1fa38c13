// The command line's options as one table: each row holds an option's name, its help line and,
// for a render setting, how it is parsed and how its default is shown. `render`, `view` and
// `bench` pick their rows from it, so an option is written once for all three.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "app/arguments.h"
#include "render/settings.h"

namespace vct {

// The value of one given option, as its text (the option's row parses it, naming the option in any error).
struct OptionValue {
    const Arguments& arguments;
    const std::string& name;
    std::string text() const { return arguments.text(name, ""); }
};

struct Option {
    std::string name;   // "voxels" for --voxels
    std::string value;  // the value's shape in the help ("N", "FILE"); empty for a flag
    std::string help;
    // Sets render settings from the value; empty for options a command reads itself (--scene).
    std::function<void(const OptionValue&, RenderSettings&)> apply;
    // The setting as the option would spell it, for "(default …)" in the help.
    std::function<std::string(const RenderSettings&)> show;
};

// Every option `render` and `view` share: the render settings (--preset first, so the others
// override it), then scene, camera, light and device.
const std::vector<Option>& sharedOptions();
// The shared row called `name` (an unknown name is a programming error: std::out_of_range).
const Option& sharedOption(const std::string& name);

// The presets, one line each: what each is, its cost and its error (render --help).
std::string presetsHelp();

// "vct 0.1.0": CMake's project version.
std::string versionText();

// Every command takes --help (or -h) and --version besides its options.
Arguments parseArguments(const std::vector<std::string>& arguments, const std::vector<Option>& options);
// "  --voxels N               voxels per side … (default 128)", one line per option; defaults
// from `defaults`.
std::string optionsHelp(const std::vector<Option>& options, const RenderSettings& defaults);
// Answers --help (`usage`, the options with their defaults from `defaults`, then `footer`) and
// --version on stdout; true when either was asked for, and the command has nothing more to do.
bool answerHelpOrVersion(const Arguments& arguments, const std::string& usage, const std::vector<Option>& options,
                         const RenderSettings& defaults, const std::string& footer = "");
// `defaults` with every given setting option applied, in table order.
RenderSettings renderSettingsFromArguments(const Arguments& arguments, const std::vector<Option>& options,
                                           RenderSettings defaults = {});

}  // namespace vct
