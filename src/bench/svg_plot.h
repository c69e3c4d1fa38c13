// Error against time as an SVG scatter plot: both axes logarithmic, each setting a numbered point
// (a key beside the plot names it, and notes under the key explain its labels), the Pareto front
// drawn as a staircase, presets highlighted. The canvas grows to hold the key.
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
    // Lines under the key that explain its labels' abbreviations ("v64  64³ voxels").
    std::vector<std::string> keyNotes;
};

// The width of `text` in the plot's 12 px sans-serif, estimated high (0.62 em a character, a
// little more than DejaVu Sans' widest lowercase run), so the canvas grows rather than clips.
double estimatedTextWidth(const std::string& text);

std::string plotErrorAgainstTime(const std::vector<PlotPoint>& points, const PlotText& text);

// Escapes &, <, > and quotes for SVG text and attributes.
std::string escapeXml(const std::string& text);

}  // namespace vct::bench
