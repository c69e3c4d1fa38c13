#include "view/scene_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/scene_limits.h"

namespace vct {

const char* lightTypeName(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional";
        case LightType::Point: return "point";
        case LightType::Spot: return "spot";
    }
    return "?";
}

// "1 viewer sun (directional)": the number is the one a script's `light` entry names.
static std::string lightLabel(const Light& light, size_t index) {
    const std::string name = light.name.empty() ? "light" : light.name;
    return std::to_string(index) + " " + name + " (" + lightTypeName(light.type) + ")";
}

// Intensity drags in steps of about 0.5 % of the value, so 0.01 cd and 100 000 lux both move smoothly;
// never below zero (the renderer refuses negative light), and up to what the loader accepts: a cap
// of its own would clamp a brighter lamp from a file at the first touch.
static void intensityDrag(const char* label, float& intensity) {
    ImGui::DragFloat(label, &intensity, std::max(0.005f * intensity, 0.001f), 0.0f, float(kBrightestRepresentable),
                     "%.3f", ImGuiSliderFlags_AlwaysClamp);
}

static void sunNode(ViewerState& state, Light& sun) {
    ImGui::SliderFloat("azimuth", &state.sun.azimuthDegrees, 0.0f, 360.0f, "%.0f deg");
    ImGui::SliderFloat("elevation", &state.sun.elevationDegrees, -89.0f, 89.0f, "%.0f deg");
    intensityDrag("intensity (lux)", state.sun.intensity);
    ImGui::ColorEdit3("colour", &sun.color.x, ImGuiColorEditFlags_Float);
    const glm::vec3 travel = state.sun.travelDirection();
    ImGui::TextDisabled("shines along (%.2f, %.2f, %.2f);", travel.x, travel.y, travel.z);
    ImGui::TextDisabled("the arrow keys and Ctrl + left drag steer it");
    ImGui::Checkbox("animate (L)", &state.sun.animate);
    ImGui::SliderFloat("animation speed", &state.sun.animateDegreesPerSecond, -90.0f, 90.0f, "%.0f deg/s");
}

static void localLightNode(Light& light, float sceneSize) {
    intensityDrag("intensity (cd)", light.intensity);
    ImGui::ColorEdit3("colour", &light.color.x, ImGuiColorEditFlags_Float);
    // About a hundredth of the scene per 100 pixels dragged.
    ImGui::DragFloat3("position", &light.position.x, 1e-4f * sceneSize, 0.0f, 0.0f, "%.3f");
    if (light.type == LightType::Spot) {
        glm::vec3 direction = light.direction;
        // A direction edited to zero keeps the old one: the spot must point somewhere.
        if (ImGui::DragFloat3("direction", &direction.x, 0.01f, -1.0f, 1.0f, "%.2f") && glm::length(direction) > 1e-3f)
            light.direction = glm::normalize(direction);
        ImGui::TextDisabled("cone %.0f-%.0f deg", glm::degrees(light.innerConeAngle),
                            glm::degrees(light.outerConeAngle));
    }
    if (light.range > 0.0f) ImGui::TextDisabled("range %.2f m", light.range);
}

void drawLightsSection(ViewerState& state) {
    if (!ImGui::CollapsingHeader("Lights")) return;
    for (size_t i = 0; i < state.lights.size(); ++i) {
        Light& light = state.lights[i];
        const bool isSun = i == state.sunIndex;
        ImGui::PushID(int(i));
        if (ImGui::TreeNodeEx(lightLabel(light, i).c_str(), isSun ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
            if (isSun) {
                sunNode(state, light);
            } else if (light.type == LightType::Directional) {
                intensityDrag("intensity (lux)", light.intensity);
                ImGui::ColorEdit3("colour", &light.color.x, ImGuiColorEditFlags_Float);
                ImGui::TextDisabled("shines along (%.2f, %.2f, %.2f)", light.direction.x, light.direction.y,
                                    light.direction.z);
            } else {
                localLightNode(light, state.sceneSize);
            }
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (ImGui::TreeNodeEx("sky", state.environment != glm::vec3(0.0f) ? ImGuiTreeNodeFlags_DefaultOpen : 0)) {
        // Radiance, not a display colour: HDR values, dragged in small steps. With an environment
        // image it is the factor on the image's radiance.
        if (!state.skyImage.empty()) ImGui::TextWrapped("image: %s", state.skyImage.c_str());
        if (state.skyImageSun) ImGui::TextWrapped("its sun is lit as a sun, with a shadow map");
        ImGui::ColorEdit3(state.skyImage.empty() ? "radiance" : "factor", &state.environment.x,
                          ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
        state.environment = glm::max(state.environment, glm::vec3(0.0f));
        // Turned about +Y, counter-clockwise seen from above (--environment-rotation).
        if (!state.skyImage.empty()) ImGui::SliderAngle("rotation", &state.skyRotation, -180.0f, 180.0f);
        ImGui::TreePop();
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Emissive surfaces light the scene too: see Materials.");
    ImGui::PopStyleColor();
}

void drawMaterialsSection(const ViewerState& state) {
    const std::string header = "Materials (" + std::to_string(state.materials.size()) + ")";
    if (!ImGui::CollapsingHeader(header.c_str())) return;
    const ImGuiTableFlags flags = ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_ScrollY;
    const float height = std::min(12.0f, float(state.materials.size()) + 1.5f) * ImGui::GetTextLineHeightWithSpacing();
    if (!ImGui::BeginTable("materials", 5, flags, ImVec2(0.0f, height))) return;
    ImGui::TableSetupScrollFreeze(0, 1);
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch);
    ImGui::TableSetupColumn("base");
    ImGui::TableSetupColumn("metal");
    ImGui::TableSetupColumn("rough");
    ImGui::TableSetupColumn("emissive");
    ImGui::TableHeadersRow();
    const ImGuiColorEditFlags swatch = ImGuiColorEditFlags_NoAlpha | ImGuiColorEditFlags_Float;
    const ImVec2 swatchSize(ImGui::GetFontSize(), ImGui::GetFontSize());
    for (size_t i = 0; i < state.materials.size(); ++i) {
        const Material& material = state.materials[i];
        ImGui::PushID(int(i));
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(material.name.empty() ? ("material " + std::to_string(i)).c_str()
                                                     : material.name.c_str());
        ImGui::TableNextColumn();
        const glm::vec4 base = material.baseColorFactor;
        ImGui::ColorButton("base colour", ImVec4(base.r, base.g, base.b, 1.0f), swatch, swatchSize);
        if (material.baseColorTexture.index >= 0) {
            ImGui::SameLine();
            ImGui::TextDisabled("tex");
        }
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", material.metallic);
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", material.roughness);
        ImGui::TableNextColumn();
        // Emission is radiance (it can exceed 1): the swatch shows its hue, the number its strength.
        const float strongest = std::max({material.emission.r, material.emission.g, material.emission.b});
        if (strongest > 0.0f) {
            const glm::vec3 hue = material.emission / strongest;
            ImGui::ColorButton("emissive hue", ImVec4(hue.r, hue.g, hue.b, 1.0f), swatch, swatchSize);
            ImGui::SameLine();
            ImGui::Text("%.3g%s", strongest, material.emissiveTexture.index >= 0 ? " tex" : "");
        } else {
            ImGui::TextDisabled("-");
        }
        ImGui::PopID();
    }
    ImGui::EndTable();
}

}  // namespace vct
