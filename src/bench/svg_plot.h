// Error against time as an SVG scatter plot: both axes logarithmic, each setting a numbered point
// (a key beside the plot names it), the Pareto front drawn as a staircase, presets highlighted.
// Plain SVG 1.1, no scripts or fonts to load.
#pragma once

#include <string>
#include <vector>

namespace vct::bench {

struct PlotPoint {
    std::string label;  // in the key beside the plot; the point shows its number
    double x = 0.0;     // > 0 (log axis); points that are not are left out
    double y = 0.0;     // > 0
    bool onFront = false;
    std::string preset;  // non-empty: drawn larger, in the preset colour, with its name
};

struct PlotText {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    std::string note;  // a line under the title (machine, image size...)
};

std::string plotErrorAgainstTime(const std::vector<PlotPoint>& points, const PlotText& text);

// Escapes &, <, > and quotes for SVG text and attributes.
std::string escapeXml(const std::string& text);

}  // namespace vct::bench
