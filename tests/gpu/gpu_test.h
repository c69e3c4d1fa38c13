// GPU tests share one Vulkan context with the validation layer on; every validation message
// (error or warning) fails the test that caused it.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "gpu/context.h"
#include "io/image_io.h"
#include "render/presets.h"
#include "render/renderer.h"
#include "render/settings.h"

namespace vct::test {

GpuContext& gpu();

// Whether two images are the same, bit for bit.
inline bool sameImages(const Image& a, const Image& b) {
    return a.rgb.size() == b.rgb.size() && std::memcmp(a.rgb.data(), b.rgb.data(), a.rgb.size() * sizeof(float)) == 0;
}

// The largest difference of any channel between two images of one size, relative to the
// reference's mean.
inline double largestDifference(const Image& image, const Image& reference) {
    double largest = 0.0, sum = 0.0;
    for (size_t i = 0; i < image.rgb.size(); ++i) {
        largest = std::max(largest, double(std::abs(image.rgb[i] - reference.rgb[i])));
        sum += reference.rgb[i];
    }
    return largest / (sum / double(reference.rgb.size()));
}

// Renders frames while `renderer` is settling, at most `limit` of them: how many it rendered.
// (Renderer::renderSettled renders one first, settling or not.)
inline uint32_t renderWhileSettling(Renderer& renderer, uint32_t limit) {
    uint32_t frames = 0;
    for (; renderer.settling() && frames < limit; ++frames) renderer.renderFrame();
    return frames;
}

// What the small render tests start from: a square image of `size` pixels, one sample a pixel, a
// 32³ grid, small shadow maps (256² for suns, 128² for the rest) and `mode`.
inline RenderSettings smallRenderSettings(uint32_t size, RenderMode mode) {
    RenderSettings settings;
    settings.image.width = size;
    settings.image.height = size;
    settings.image.supersample = 1;
    settings.resources.voxelResolution = 32;
    settings.resources.sunShadowMapSize = 256;
    settings.resources.localShadowMapSize = 128;
    settings.shading.mode = mode;
    return settings;
}

// `settings` seen as the `walls` preset sees: ray visibility (ResourceSettings::rayVisibility) and
// that preset's diffuse cone aperture.
inline RenderSettings withRayVisibility(RenderSettings settings) {
    settings.resources.rayVisibility = true;
    settings.shading.diffuseConeAperture = findRenderPreset("walls")->shading.diffuseConeAperture;
    return settings;
}

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { gpu().clearValidationMessages(); }
    void TearDown() override {
        for (const std::string& message : gpu().validationMessages()) ADD_FAILURE() << message;
    }
};

}  // namespace vct::test
