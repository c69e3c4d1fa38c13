#include "bench/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "bench/pareto.h"
#include "bench/svg_plot.h"
#include "io/json_text.h"
#include "render/setting_table.h"

namespace vct::bench {
namespace {

std::string number(double value) {
    if (!std::isfinite(value)) return "";
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", value);
    return text;
}

// CSV fields hold no commas or quotes except in scene paths; quote those.
std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

double passTime(const FrameTiming& timing, const std::string& name) {
    for (const PassTime& pass : timing.passes)
        if (pass.name == name) return pass.milliseconds;
    return 0.0;
}

// Pass names in the order they first ran, over all measurements.
std::vector<std::string> passNames(const std::vector<Measurement>& measurements) {
    std::vector<std::string> names;
    for (const Measurement& m : measurements)
        for (const FrameTiming* timing : {&m.staticFrame, &m.lightChangeFrame})
            for (const PassTime& pass : timing->passes)
                if (std::find(names.begin(), names.end(), pass.name) == names.end()) names.push_back(pass.name);
    return names;
}

const char* kModes[] = {"full", "direct", "indirect"};
constexpr double kSmallestError = 1e-12;  // a perfect scene must not make a geometric mean zero

const ImageError& modeError(const ModeErrors& errors, int mode) {
    return mode == 0 ? errors.full : mode == 1 ? errors.direct : errors.indirect;
}

std::string jsonError(const ImageError& e) {
    return "{\"relmse\": " + jsonNumber(e.relMse) + ", \"rmse\": " + jsonNumber(e.rmse) +
           ", \"luminance_ratio\": " + jsonNumber(e.luminanceRatio) + ", \"share_off\": " + jsonNumber(e.shareOff) +
           "}";
}

// The settings the bench records, each under its key: a named value as its name, else the number.
std::string jsonSettings(const RenderSettings& settings) {
    std::string json;
    for (const SettingRow& row : settingTable()) {
        if (!row.benchKey) continue;
        const double value = row.get(settings);
        json += (json.empty() ? "{" : ", ") + jsonString(row.benchKey) + ": " +
                (namedValue(row, value) ? jsonString(settingText(row, value)) : jsonNumber(value));
    }
    return json + "}";
}

std::string jsonTiming(const FrameTiming& timing) {
    std::string json = "{\"gpu_ms\": " + jsonNumber(timing.gpuMilliseconds) +
                       ", \"cpu_ms\": " + jsonNumber(timing.cpuMilliseconds) + ", \"passes_ms\": {";
    for (size_t i = 0; i < timing.passes.size(); ++i)
        json += (i ? ", " : "") + jsonString(timing.passes[i].name) + ": " + jsonNumber(timing.passes[i].milliseconds);
    return json + "}}";
}

}  // namespace

std::vector<SettingSummary> summarize(const std::vector<Measurement>& measurements) {
    std::vector<SettingSummary> summary;
    std::vector<size_t> sceneCounts;
    for (const Measurement& m : measurements) {
        auto found = std::find_if(summary.begin(), summary.end(),
                                  [&](const SettingSummary& s) { return s.label == m.setting.label; });
        if (found == summary.end()) {
            summary.push_back({m.setting.label, m.setting.preset});
            sceneCounts.push_back(0);
            found = summary.end() - 1;
        }
        SettingSummary& s = *found;
        if (s.preset.empty()) s.preset = m.setting.preset;
        ++sceneCounts[size_t(found - summary.begin())];
        s.staticMilliseconds += m.staticFrame.gpuMilliseconds;
        s.lightChangeMilliseconds += m.lightChangeFrame.cpuMilliseconds;
        s.deviceMegabytes = std::max(s.deviceMegabytes, double(m.deviceMemoryBytes) / (1024.0 * 1024.0));
        if (m.errors) {
            // Sums of logarithms: geometric means, so no one scene's scale of error dominates.
            ++s.scenesWithReference;
            s.relMseFull += std::log(std::max(m.errors->full.relMse, kSmallestError));
            s.relMseDirect += std::log(std::max(m.errors->direct.relMse, kSmallestError));
            s.relMseIndirect += std::log(std::max(m.errors->indirect.relMse, kSmallestError));
            s.luminanceRatioIndirect += std::log(std::max(m.errors->indirect.luminanceRatio, kSmallestError));
            // A scene without shadows (NaN) has nothing to add to it.
            if (std::isfinite(m.errors->shadowedIndirectRatio)) {
                ++s.scenesWithShadows;
                s.shadowedRatioIndirect += std::log(std::max(m.errors->shadowedIndirectRatio, kSmallestError));
            }
        }
    }
    std::vector<CostAndError> points;
    for (size_t i = 0; i < summary.size(); ++i) {
        SettingSummary& s = summary[i];
        s.staticMilliseconds /= double(sceneCounts[i]);
        s.lightChangeMilliseconds /= double(sceneCounts[i]);
        const double withReference = s.scenesWithReference ? double(s.scenesWithReference) : NAN;
        s.relMseFull = std::exp(s.relMseFull / withReference);
        s.relMseDirect = std::exp(s.relMseDirect / withReference);
        s.relMseIndirect = std::exp(s.relMseIndirect / withReference);
        s.luminanceRatioIndirect = std::exp(s.luminanceRatioIndirect / withReference);
        s.shadowedRatioIndirect =
            std::exp(s.shadowedRatioIndirect / (s.scenesWithShadows ? double(s.scenesWithShadows) : NAN));
        points.push_back({s.staticMilliseconds, s.relMseFull});
    }
    for (size_t index : paretoFront(points)) summary[index].onFront = true;
    return summary;
}

std::string toCsv(const std::vector<Measurement>& measurements) {
    const std::vector<std::string> passes = passNames(measurements);
    std::ostringstream csv;
    csv << "scene,setting,preset,";
    for (const SettingRow& row : settingTable())
        if (row.benchKey) csv << row.benchKey << ",";
    csv << "static_gpu_ms,static_cpu_ms,light_change_gpu_ms,light_change_cpu_ms,voxelize_ms,light_change_and_voxelize_"
           "ms,"
           "device_mb,finite";
    for (const char* mode : kModes)
        csv << "," << mode << "_relmse," << mode << "_rmse," << mode << "_luminance_ratio," << mode << "_share_off";
    csv << ",shadowed_indirect_luminance_ratio";
    for (const std::string& pass : passes) csv << ",static_" << pass << "_ms";
    for (const std::string& pass : passes) csv << ",light_change_" << pass << "_ms";
    csv << "\n";
    for (const Measurement& m : measurements) {
        const RenderSettings& s = m.setting.settings;
        csv << csvField(m.scene) << "," << m.setting.label << "," << m.setting.preset << ",";
        for (const SettingRow& row : settingTable())
            if (row.benchKey) csv << settingText(row, s) << ",";
        csv << number(m.staticFrame.gpuMilliseconds) << "," << number(m.staticFrame.cpuMilliseconds) << ","
            << number(m.lightChangeFrame.gpuMilliseconds) << "," << number(m.lightChangeFrame.cpuMilliseconds) << ","
            << number(m.voxelizeMilliseconds) << ","
            << number(m.lightChangeFrame.cpuMilliseconds + m.voxelizeMilliseconds) << ","
            << number(double(m.deviceMemoryBytes) / (1024.0 * 1024.0)) << "," << (m.imagesFinite ? 1 : 0);
        for (int mode = 0; mode < 3; ++mode) {
            if (!m.errors) {
                csv << ",,,,";
                continue;
            }
            const ImageError& e = modeError(*m.errors, mode);
            csv << "," << number(e.relMse) << "," << number(e.rmse) << "," << number(e.luminanceRatio) << ","
                << number(e.shareOff);
        }
        csv << "," << (m.errors ? number(m.errors->shadowedIndirectRatio) : std::string());
        for (const std::string& pass : passes) csv << "," << number(passTime(m.staticFrame, pass));
        for (const std::string& pass : passes) csv << "," << number(passTime(m.lightChangeFrame, pass));
        csv << "\n";
    }
    return csv.str();
}

std::string toJson(const std::vector<Measurement>& measurements, const std::vector<SettingSummary>& summary,
                   const RunInfo& info) {
    std::ostringstream json;
    json << "{\n  \"device\": " << jsonString(info.device) << ",\n  \"width\": " << info.width
         << ",\n  \"height\": " << info.height << ",\n  \"frames\": " << info.frames
         << ",\n  \"warmup_frames\": " << info.warmupFrames << ",\n  \"seconds\": " << jsonNumber(info.seconds)
         << ",\n  \"references\": {";
    bool first = true;
    for (const auto& [scene, r] : info.references) {
        json << (first ? "\n    " : ",\n    ") << jsonString(scene) << ": {\"direct_spp\": " << r.directSpp
             << ", \"direct_relative_noise\": " << jsonNumber(r.directNoise) << ", \"indirect_spp\": " << r.indirectSpp
             << ", \"indirect_relative_noise\": " << jsonNumber(r.indirectNoise) << "}";
        first = false;
    }
    json << "\n  },\n  \"results\": [";
    for (size_t i = 0; i < measurements.size(); ++i) {
        const Measurement& m = measurements[i];
        const RenderSettings& s = m.setting.settings;
        json << (i ? ",\n    " : "\n    ") << "{\"scene\": " << jsonString(m.scene)
             << ", \"setting\": " << jsonString(m.setting.label) << ", \"preset\": " << jsonString(m.setting.preset)
             << ",\n     \"settings\": " << jsonSettings(s) << ",\n     \"static\": " << jsonTiming(m.staticFrame)
             << ", \"settle_frames\": " << m.settleFrames << ", \"settle_ms\": " << jsonNumber(m.settleMilliseconds)
             << ",\n     \"light_change\": " << jsonTiming(m.lightChangeFrame)
             << (m.lightMovingFrame ? ",\n     \"light_moving\": " + jsonTiming(*m.lightMovingFrame) +
                                          ", \"bounce_slices\": " + std::to_string(m.bounceSlices)
                                    : std::string())
             << ",\n     \"camera_moving\": " << jsonTiming(m.cameraMovingFrame)
             << ", \"camera_moving_worst_ms\": " << jsonNumber(m.cameraMovingWorstMilliseconds)
             << ",\n     \"voxelize_ms\": " << jsonNumber(m.voxelizeMilliseconds) << ", \"bounces\": " << m.bounces
             << ", \"bounces_converged\": " << (m.bouncesConverged ? "true" : "false")
             << ", \"ms_per_bounce\": " << jsonNumber(m.bounceMilliseconds)
             << ", \"device_memory_bytes\": " << m.deviceMemoryBytes
             << ", \"finite\": " << (m.imagesFinite ? "true" : "false") << ",\n     \"error\": ";
        if (m.errors)
            json << "{\"full\": " << jsonError(m.errors->full)
                 << ",\n               \"direct\": " << jsonError(m.errors->direct)
                 << ",\n               \"indirect\": " << jsonError(m.errors->indirect)
                 << ",\n               \"shadowed_indirect_luminance_ratio\": "
                 << jsonNumber(m.errors->shadowedIndirectRatio) << "}}";
        else json << "null}";
    }
    json << "\n  ],\n  \"summary\": [";
    for (size_t i = 0; i < summary.size(); ++i) {
        const SettingSummary& s = summary[i];
        json << (i ? ",\n    " : "\n    ") << "{\"setting\": " << jsonString(s.label)
             << ", \"preset\": " << jsonString(s.preset) << ", \"static_gpu_ms\": " << jsonNumber(s.staticMilliseconds)
             << ", \"light_change_ms\": " << jsonNumber(s.lightChangeMilliseconds)
             << ", \"device_mb\": " << jsonNumber(s.deviceMegabytes)
             << ", \"relmse_full\": " << jsonNumber(s.relMseFull)
             << ", \"relmse_direct\": " << jsonNumber(s.relMseDirect)
             << ", \"relmse_indirect\": " << jsonNumber(s.relMseIndirect)
             << ", \"luminance_ratio_indirect\": " << jsonNumber(s.luminanceRatioIndirect)
             << ", \"shadowed_luminance_ratio_indirect\": " << jsonNumber(s.shadowedRatioIndirect)
             << ", \"scenes_with_reference\": " << s.scenesWithReference
             << ", \"on_front\": " << (s.onFront ? "true" : "false") << "}";
    }
    json << "\n  ]\n}\n";
    return json.str();
}

std::string toSvg(const std::vector<SettingSummary>& summary, const RunInfo& info) {
    std::vector<PlotPoint> points;
    for (const SettingSummary& s : summary)
        points.push_back({s.label, s.staticMilliseconds, s.relMseFull, s.onFront, s.preset});
    char note[256];
    std::snprintf(note, sizeof note,
                  "%s, %ux%u, median of %u frames; times: mean, relMSE: geometric mean over %zu scene(s)",
                  info.device.c_str(), info.width, info.height, info.frames, info.references.size());
    return plotErrorAgainstTime(points,
                                {"vct bench: error against frame time", "GPU time of a static frame, ms (log)",
                                 "relMSE of full light against the path tracer (log)", note, settingLabelLegend()});
}

std::string summaryTable(const std::vector<SettingSummary>& summary) {
    std::ostringstream table;
    char line[256];
    std::snprintf(line, sizeof line, "%-30s %-9s %9s %9s %8s %9s %9s %9s %7s %7s\n", "setting", "preset", "static ms",
                  "light ms", "MB", "relMSE", "direct", "indirect", "ind.lum", "shadow");
    table << line;
    for (const SettingSummary& s : summary) {
        const auto field = [](double value, int decimals) {
            char text[32];
            if (!std::isfinite(value)) return std::string("-");
            std::snprintf(text, sizeof text, "%.*f", decimals, value);
            return std::string(text);
        };
        std::snprintf(line, sizeof line, "%-30s %-9s %9.1f %9.1f %8.1f %9s %9s %9s %7s %7s%s\n", s.label.c_str(),
                      s.preset.c_str(), s.staticMilliseconds, s.lightChangeMilliseconds, s.deviceMegabytes,
                      field(s.relMseFull, 4).c_str(), field(s.relMseDirect, 4).c_str(),
                      field(s.relMseIndirect, 4).c_str(), field(s.luminanceRatioIndirect, 2).c_str(),
                      field(s.shadowedRatioIndirect, 2).c_str(), s.onFront ? "  *front" : "");
        table << line;
    }
    return table.str();
}

}  // namespace vct::bench
