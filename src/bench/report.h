// What `vct bench` writes: a CSV row and a JSON object per (scene, setting), a summary per
// setting over the scenes with its place on the Pareto front, and a short table for the terminal.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "bench/measure.h"

namespace vct::bench {

// One setting over all scenes. Times are arithmetic means over scenes; errors and ratios are
// geometric means over the scenes with a reference, so a scene whose relMSE is 10× everyone
// else's (light leaking in the sun room) does not decide the front alone.
struct SettingSummary {
    std::string label, preset;
    double staticMilliseconds = 0.0;                                    // mean of the static frame's GPU time
    double lightChangeMilliseconds = 0.0;                               // ... of the frame after a light change
    double deviceMegabytes = 0.0;                                       // the largest over scenes
    double relMseFull = 0.0, relMseDirect = 0.0, relMseIndirect = 0.0;  // geometric means
    double luminanceRatioIndirect = 0.0;  // geometric mean of indirect luminance / reference
    double shadowedRatioIndirect = 0.0;   // ... and of that ratio in the shadows (shadowedLuminanceRatio)
    size_t scenesWithReference = 0, scenesWithShadows = 0;
    bool onFront = false;  // Pareto-optimal in (staticMilliseconds, relMseFull)
};

struct RunInfo {
    std::string device;
    uint32_t width = 0, height = 0, frames = 0, warmupFrames = 0;
    double seconds = 0.0;
    std::map<std::string, References> references;  // by scene, for the noise it reached
};

std::vector<SettingSummary> summarize(const std::vector<Measurement>& measurements);

std::string toCsv(const std::vector<Measurement>& measurements);
std::string toJson(const std::vector<Measurement>& measurements, const std::vector<SettingSummary>& summary,
                   const RunInfo& info);
std::string toSvg(const std::vector<SettingSummary>& summary, const RunInfo& info);
// A table with one line per setting (the summary), front and presets marked.
std::string summaryTable(const std::vector<SettingSummary>& summary);

}  // namespace vct::bench
