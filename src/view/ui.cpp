#include "view/ui.h"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <vector>

#include "render/presets.h"
#include "render/setting_table.h"
#include "scene/load.h"
#include "view/scene_panel.h"

namespace vct {
namespace {

// The docked settings window's width, and about the profiler's: a window narrower than both hides
// the profiler.
constexpr float kSettingsWidth = 300.0f;
constexpr float kProfilerWidth = 330.0f;

}  // namespace

void FrameHistory::add(float frameMs, const FrameStats& stats) {
    frameMilliseconds.push_back(frameMs);
    gpuMilliseconds.push_back(float(stats.gpuMilliseconds()));
    while (frameMilliseconds.size() > length) frameMilliseconds.pop_front();
    while (gpuMilliseconds.size() > length) gpuMilliseconds.pop_front();
    // Exponential moving average over roughly the last 20 frames each pass ran in.
    for (const PassTime& pass : stats.passes) {
        auto found = passAverage.find(pass.name);
        if (found == passAverage.end()) passAverage[pass.name] = float(pass.milliseconds);
        else found->second += 0.05f * (float(pass.milliseconds) - found->second);
    }
    lastFrameIdle = stats.plan.passes.empty();
    if (!lastFrameIdle) last = stats;
}

float FrameHistory::averageFrameMilliseconds() const {
    if (frameMilliseconds.empty()) return 0.0f;
    const size_t count = std::min<size_t>(frameMilliseconds.size(), 30);
    float sum = 0.0f;
    for (size_t i = frameMilliseconds.size() - count; i < frameMilliseconds.size(); ++i) sum += frameMilliseconds[i];
    return sum / float(count);
}

// A combo box over `count` values: `text(i)` names the i-th, `chosen` is the index chosen (or
// -1); returns the index picked this frame, or -1.
template <typename Text>
static int comboOf(const char* label, const std::string& current, int count, int chosen, Text text) {
    int picked = -1;
    if (!ImGui::BeginCombo(label, current.c_str())) return picked;
    for (int i = 0; i < count; ++i)
        if (ImGui::Selectable(text(i).c_str(), i == chosen)) picked = i;
    ImGui::EndCombo();
    return picked;
}

// One setting's widget, as its row says (src/render/setting_table.h): the same range and names as
// its command-line option. A hover shows the option's help.
static void settingWidget(const SettingRow& row, RenderSettings& settings) {
    if (!row.label || row.widget == SettingWidget::None) return;
    const double value = row.get(settings);
    double edited = value;
    const std::string current = settingText(row, value);
    switch (row.widget) {
        case SettingWidget::None: break;
        case SettingWidget::Choice: {
            int chosen = -1;
            for (size_t i = 0; i < row.names.size(); ++i)
                if (row.names[i].value == value) chosen = int(i);
            const int picked = comboOf(row.label, current, int(row.names.size()), chosen,
                                       [&](int i) { return std::string(row.names[size_t(i)].name); });
            if (picked >= 0) edited = row.names[size_t(picked)].value;
            break;
        }
        case SettingWidget::PowerOfTwo: {
            const int count = int(std::log2(row.max / row.min)) + 1;
            auto power = [&](int i) { return row.min * std::exp2(double(i)); };
            const int picked = comboOf(row.label, current, count, int(std::log2(value / row.min)),
                                       [&](int i) { return settingText(row, power(i)); });
            if (picked >= 0) edited = power(picked);
            break;
        }
        case SettingWidget::Slider:
            if (row.whole) {
                // A named value below the range (0 bounces: converged) is the slider's first stop.
                int lowest = int(row.min);
                for (const NamedValue& named : row.names) lowest = std::min(lowest, int(named.value));
                int whole = int(value);
                const NamedValue* named = namedValue(row, value);
                if (ImGui::SliderInt(row.label, &whole, lowest, int(row.max), named ? named->name : row.format))
                    edited = std::clamp(whole, lowest, int(row.max));
            } else {
                float number = float(value);
                if (ImGui::SliderFloat(row.label, &number, float(row.min), float(row.max), row.format))
                    edited = std::clamp(double(number), row.min, row.max);
            }
            break;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("--%s: %s", row.option, row.help);
    if (edited != value) row.set(settings, edited);
}

// Every setting of `group`, in the table's order.
static void settingWidgets(SettingGroup group, RenderSettings& settings) {
    for (const SettingRow& row : settingTable())
        if (row.group == group) settingWidget(row, settings);
}

// Text in the disabled colour, wrapped at the window's edge instead of cut there.
static void wrappedNote(const char* text) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", text);
    ImGui::PopStyleColor();
}

// A button on the current line if it fits before the window's edge, else on the next.
static bool flowingButton(const char* label, bool first) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float width = ImGui::CalcTextSize(label).x + 2.0f * style.FramePadding.x;
    const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
    if (!first && ImGui::GetItemRectMax().x + style.ItemSpacing.x + width <= right) ImGui::SameLine();
    return ImGui::Button(label);
}

// The recent files, newest first: a click opens one; a file that is gone is greyed and does nothing.
static void recentFilesList(ViewerState& state) {
    if (state.recentFiles.empty()) return;
    ImGui::TextDisabled("recent:");
    for (size_t i = 0; i < state.recentFiles.size(); ++i) {
        const std::string& path = state.recentFiles[i];
        const std::filesystem::path file(path);
        std::error_code error;
        const bool present = std::filesystem::is_regular_file(file, error);
        // The name first, then whether it is gone: a long folder is cut at the window's edge.
        const std::string folder = "  " + file.parent_path().string();
        ImGui::PushID(int(i));
        if (present) {
            if (ImGui::Selectable((file.filename().string() + folder).c_str())) state.requestedScene = path;
        } else {
            ImGui::TextDisabled("%s (missing)%s", file.filename().string().c_str(), folder.c_str());
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", path.c_str());
        ImGui::PopID();
    }
}

static void sceneSection(ViewerState& state) {
    if (!ImGui::CollapsingHeader("Scene")) return;
    ImGui::Text("%s", state.sceneName.c_str());
    bool first = true;
    for (const std::string& name : builtinSceneNames()) {
        if (flowingButton(name.c_str(), first)) state.requestedScene = name;
        first = false;
    }
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Open").x -
                            2.0f * style.FramePadding.x - style.ItemSpacing.x);
    ImGui::InputText("##glTF path", state.scenePathField, sizeof state.scenePathField);
    // Enter in the field opens, as the button does.
    const bool enter = ImGui::IsItemDeactivated() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter));
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && state.scenePathField[0] != '\0')
        state.requestedScene = state.scenePathField;
    wrappedNote("a .gltf/.glb path, or drop the file on the window");
    recentFilesList(state);
}

static void shadingSection(ViewerState& state, const UiFacts& facts) {
    RenderSettings& settings = state.settings;
    if (!ImGui::CollapsingHeader("Shading")) return;
    ImGui::Checkbox("auto exposure", &state.autoExposure);
    ImGui::SameLine();
    // Dragging the exposure fixes it where it is.
    if (ImGui::SliderFloat("##exposure", &state.exposureStops, -12.0f, 12.0f, "%+.2f EV")) state.autoExposure = false;
    int curve = int(state.toneCurve);
    ImGui::Combo("tone curve", &curve, "PBR Neutral\0ACES\0");
    state.toneCurve = ToneCurve(curve);
    settingWidget(settingRow("mode"), settings);
    // Two columns, each component labelled with its key (1…8, in the table's order).
    for (size_t i = 0; i < componentTable().size(); ++i) {
        const ComponentInfo& component = componentTable()[i];
        if (i % 2 == 1) ImGui::SameLine(0.5f * ImGui::GetWindowContentRegionMax().x);
        const std::string label = std::to_string(i + 1) + " " + component.label;
        ImGui::Checkbox(label.c_str(), &(settings.shading.components.*component.member));
    }
    settingWidget(settingRow("ambient"), settings);
    int view = int(settings.shading.debugView);
    ImGui::Combo(
        "view (V)", &view,
        [](void*, int index, const char** text) {
            *text = debugViewLabel(DebugView(index));
            return true;
        },
        nullptr, int(debugViewCount));
    settings.shading.debugView = DebugView(view);
    int mip = int(settings.shading.debugVoxelMip);
    ImGui::SliderInt("radiance view mip", &mip, 0, int(facts.voxelMips) - 1);
    settings.shading.debugVoxelMip = uint32_t(std::clamp(mip, 0, int(facts.voxelMips) - 1));
    ImGui::Checkbox("voxel grid bounds (G)", &state.showGridBounds);
}

static void coneSection(RenderSettings& settings) {
    if (!ImGui::CollapsingHeader("Cones")) return;
    settingWidgets(SettingGroup::Cones, settings);
    bool skipEmptySpace = settings.shading.skipEmptySpace.value_or(true);  // the viewer resolves it at start
    if (ImGui::Checkbox("skip empty space", &skipEmptySpace)) settings.shading.skipEmptySpace = skipEmptySpace;
}

static void resolutionSection(ViewerState& state) {
    RenderSettings& settings = state.settings;
    if (!ImGui::CollapsingHeader("Resolution")) return;
    wrappedNote("all but the render scale build a new renderer");
    int scale = state.renderScale >= 1.0f ? 0 : state.renderScale >= 0.5f ? 1 : 2;
    ImGui::Combo("render scale", &scale,
                 "1 (window size)\0"
                 "1/2\0"
                 "1/4\0");
    state.renderScale = scale == 0 ? 1.0f : scale == 1 ? 0.5f : 0.25f;
    settingWidgets(SettingGroup::Voxels, settings);
    settingWidgets(SettingGroup::Shadows, settings);
    settingWidgets(SettingGroup::Image, settings);
}

// One row: the preset last chosen; choosing one brings its quality settings.
static void presetRow(ViewerState& state) {
    if (!ImGui::BeginCombo("preset", state.presetName.c_str())) {
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("vct render --help says what each costs and how accurate it is");
        return;
    }
    for (const auto& [name, preset] : renderPresets()) {
        if (!ImGui::Selectable(name.c_str(), name == state.presetName)) continue;
        state.presetName = name;
        // A preset brings its quality settings; the view (mode, toggles, debug view) stays.
        RenderSettings applied = preset;
        applied.image.width = state.settings.image.width;
        applied.image.height = state.settings.image.height;
        applied.shading.mode = state.settings.shading.mode;
        applied.shading.components = state.settings.shading.components;
        applied.shading.debugView = state.settings.shading.debugView;
        applied.shading.debugVoxelMip = 0;
        state.settings = applied;
    }
    ImGui::EndCombo();
}

void drawSettingsWindow(ViewerState& state, const UiFacts& facts) {
    // Docked to the left edge from the top to the status bar, opaque, and collapsible by its title
    // bar's arrow; what does not fit scrolls. The camera ignores the mouse over it (WantCaptureMouse).
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(viewport->Pos, ImGuiCond_Always);
    ImGui::SetNextWindowSize(
        ImVec2(std::min(kSettingsWidth, viewport->Size.x), std::max(viewport->Size.y - state.statusBarHeight, 60.0f)),
        ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    const bool open =
        ImGui::Begin("Settings (Tab hides, F1 guide)", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    // The image goes right of the open settings (Viewer::imageArea); collapsed, only the title bar
    // covers it.
    state.settingsWidth = open ? ImGui::GetWindowWidth() : 0.0f;
    if (!open) {
        ImGui::End();
        return;
    }
    // Controls take what the labels (up to "local shadow map") leave.
    ImGui::PushItemWidth(-ImGui::CalcTextSize("local shadow map ").x);
    presetRow(state);
    sceneSection(state);
    drawLightsSection(state);
    drawMaterialsSection(state);
    shadingSection(state, facts);
    coneSection(state.settings);
    resolutionSection(state);
    if (ImGui::CollapsingHeader("Camera and window")) {
        ImGui::Text("%s mode (O toggles), fly speed %.2f m/s", state.cameraIsOrbiting ? "orbit" : "fly",
                    state.cameraSpeed);
        if (ImGui::Button("reset camera (R)")) state.requestCameraReset = true;
        ImGui::Checkbox("profiler (F2)", &state.showProfiler);
        ImGui::Checkbox("vsync", &state.vsync);
        ImGui::Checkbox("screenshots include the UI", &state.screenshotWithUi);
        if (ImGui::Button("screenshot (F12)")) state.requestScreenshot = true;
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

void drawStatusBar(ViewerState& state) {
    static const char* const hint = "F1 controls | Tab panels | right mouse + WASD fly | drop a .glb to open";
    const bool showHint = state.showHint && !state.guideOpened;
    if (state.notice.empty() && !showHint) {
        state.statusBarHeight = 0.0f;
        return;
    }
    // One row across the bottom: the notice, then the hint; a notice too long for the row is cut
    // there and shown whole in a tooltip.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x, viewport->Pos.y + viewport->Size.y), ImGuiCond_Always,
                            ImVec2(0.0f, 1.0f));
    ImGui::SetNextWindowSize(ImVec2(viewport->Size.x, ImGui::GetFrameHeight()), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("##status", nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    if (!state.notice.empty()) {
        ImGui::TextUnformatted(state.notice.c_str());
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", state.notice.c_str());
        if (showHint) ImGui::SameLine(0.0f, 24.0f);
    }
    if (showHint) ImGui::TextDisabled("%s", hint);
    state.statusBarHeight = ImGui::GetWindowSize().y;
    ImGui::End();
}

void drawProfilerWindow(ViewerState& state, const UiFacts& facts) {
    // A small opaque overlay in the top right corner. Where it would cover the settings (a window
    // getting narrower than both), it is hidden; the settings' "profiler" box shows it again.
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const bool narrow = viewport->Size.x < kSettingsWidth + kProfilerWidth;
    if (narrow && !state.wasNarrow) state.showProfiler = false;
    state.wasNarrow = narrow;
    if (!state.showProfiler) return;
    ImGui::SetNextWindowPos(ImVec2(viewport->Pos.x + viewport->Size.x, viewport->Pos.y), ImGuiCond_Always,
                            ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(1.0f);
    ImGui::Begin("Profiler", &state.showProfiler, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove);
    const FrameHistory& history = state.history;
    const float average = history.averageFrameMilliseconds();
    ImGui::Text("frame %.1f ms (%.1f fps), averaged", average, average > 0.0f ? 1000.0f / average : 0.0f);
    const std::vector<float> frames(history.frameMilliseconds.begin(), history.frameMilliseconds.end());
    const std::vector<float> gpu(history.gpuMilliseconds.begin(), history.gpuMilliseconds.end());
    if (!frames.empty() && ImGui::TreeNode("history")) {
        ImGui::PlotLines("frame ms", frames.data(), int(frames.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(240, 40));
        ImGui::PlotLines("GPU ms", gpu.data(), int(gpu.size()), 0, nullptr, 0.0f, FLT_MAX, ImVec2(240, 40));
        ImGui::TreePop();
    }
    if (ImGui::BeginTable("passes", 3, ImGuiTableFlags_SizingFixedFit)) {
        ImGui::TableSetupColumn("pass");
        ImGui::TableSetupColumn("last drawn");
        ImGui::TableSetupColumn("average");
        ImGui::TableHeadersRow();
        for (Pass pipelinePass : kPipelineOrder) {  // in the order the frame runs them
            const std::string name = passName(pipelinePass);
            const auto found = history.passAverage.find(name);
            if (found == history.passAverage.end()) continue;
            const float averageMs = found->second;
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted(name.c_str());
            ImGui::TableNextColumn();
            bool ran = false;
            for (const PassTime& pass : history.last.passes)
                if (pass.name == name) {
                    ImGui::Text("%8.2f ms", pass.milliseconds);
                    ran = true;
                }
            if (!ran) ImGui::TextDisabled("skipped");
            ImGui::TableNextColumn();
            ImGui::Text("%8.2f ms", averageMs);
        }
        ImGui::EndTable();
    }
    if (history.lastFrameIdle) ImGui::TextDisabled("this frame: nothing changed, image reused");
    ImGui::Text("present (tone map + UI) %.2f ms GPU", history.presentMilliseconds);
    ImGui::Separator();
    ImGui::Text("window %ux%u, image %ux%u, %s", facts.width, facts.height, facts.renderWidth, facts.renderHeight,
                facts.presentMode.c_str());
    ImGui::Text("voxels %u^3 = %s, %u mips", facts.voxelResolution, voxelCountText(facts.voxelResolution).c_str(),
                facts.voxelMips);
    ImGui::Text("%zu triangles, %zu lights", facts.triangles, facts.lights);
    ImGui::Text("device memory %.1f MiB", double(facts.deviceMemoryBytes) / (1024.0 * 1024.0));
    ImGui::TextDisabled("%s", facts.deviceName.c_str());
    ImGui::End();
}

void drawErrorWindow(ViewerState& state) {
    if (state.error.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, 8.0f), ImGuiCond_Always, ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(200, 0), ImVec2(viewport->Size.x * 0.8f, viewport->Size.y * 0.5f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.35f, 0.05f, 0.05f, 0.92f));
    ImGui::Begin("Error", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushTextWrapPos(viewport->Size.x * 0.75f);
    ImGui::TextUnformatted(state.error.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("dismiss")) state.error.clear();
    ImGui::End();
    ImGui::PopStyleColor();
}

void drawWarningsWindow(ViewerState& state) {
    if (state.warnings.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(
        ImVec2(viewport->Pos.x + viewport->Size.x * 0.5f, viewport->Pos.y + viewport->Size.y * 0.3f), ImGuiCond_Always,
        ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(200, 0), ImVec2(viewport->Size.x * 0.8f, viewport->Size.y * 0.5f));
    ImGui::PushStyleColor(ImGuiCol_WindowBg, ImVec4(0.30f, 0.22f, 0.02f, 1.0f));
    ImGui::Begin("Warnings", nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse);
    ImGui::PushTextWrapPos(viewport->Size.x * 0.75f);
    for (const std::string& warning : state.warnings) ImGui::TextWrapped("- %s", warning.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::Button("dismiss")) state.warnings.clear();
    ImGui::End();
    ImGui::PopStyleColor();
}

std::string voxelCountText(uint32_t resolution) {
    const uint64_t count = uint64_t(resolution) * resolution * resolution;
    char text[32];
    if (count < 1000000) std::snprintf(text, sizeof text, "%llu", static_cast<unsigned long long>(count));
    else std::snprintf(text, sizeof text, "%.1f M", double(count) / 1e6);
    return text;
}

void drawGuideWindow(ViewerState& state) {
    // Centred, opaque, at most the window's size less a margin: the descriptions wrap, and what
    // does not fit scrolls (so the guide takes the mouse while it is over it).
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float width = std::min(640.0f, viewport->Size.x - 16.0f);
    ImGui::SetNextWindowPos(
        ImVec2(viewport->Pos.x + viewport->Size.x * 0.5f, viewport->Pos.y + viewport->Size.y * 0.5f), ImGuiCond_Always,
        ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, viewport->Size.y - 16.0f));
    ImGui::SetNextWindowBgAlpha(1.0f);
    state.guideOpened = true;  // the status bar's hint to it has done its work
    ImGui::Begin("Guide (F1 or H hides it)", &state.showGuide,
                 ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove);
    static const char* const rows[][2] = {
        {"right mouse + drag", "look around"},
        {"W A S D", "fly forward, left, back, right (hold right mouse or not)"},
        {"Q / E", "down / up"},
        {"Shift", "4x faster"},
        {"mouse wheel", "fly speed; zoom in orbit mode"},
        {"O", "orbit around the scene centre (drag with either button)"},
        {"R", "reset to the scene camera"},
        {"arrow keys", "move the sun (left/right azimuth, up/down elevation)"},
        {"Ctrl + left drag", "move the sun"},
        {"1 .. 8",
         "toggle direct diffuse, direct specular, indirect diffuse, indirect specular, ambient occlusion, emission, "
         "shadows, area lights"},
        {"M", "mode: full, direct, indirect"},
        {"V", "next view: lit, base colour, normal, depth, AO, voxels"},
        {"[ / ]", "voxel mip shown by the voxel radiance view"},
        {"L", "animate the sun"},
        {"G", "draw the voxel grid's box: amber lines over the image, edges behind the scene included"},
        {"F12 or P", "screenshot (PNG in the current folder)"},
        {"Tab", "hide or show the panels"},
        {"F2", "the profiler: each pass's GPU time"},
        {"F1 or H", "this guide"},
        {"drop a file",
         "load a .gltf/.glb scene; or type its path under Settings > Scene, which lists the recent ones"},
        {"Esc", "quit"},
    };
    if (ImGui::BeginTable("controls", 2)) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthFixed);
        ImGui::TableSetupColumn("does", ImGuiTableColumnFlags_WidthStretch);
        for (const auto& row : rows) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "%s", row[0]);
            ImGui::TableNextColumn();
            ImGui::TextWrapped("%s", row[1]);
        }
        ImGui::EndTable();
    }
    ImGui::End();
}

}  // namespace vct
