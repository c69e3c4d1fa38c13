// Settings and scenes a device cannot hold are refused before anything is allocated, with a
// message naming the device limit and what would fit. The limits are faked by handing the check
// a modified copy of the device's own, so no test needs a huge allocation.
#include <string>

#include "error.h"
#include "gpu/vk_check.h"
#include "gpu_test.h"
#include "gpu_types.h"
#include "render/renderer.h"
#include "render/renderer_limits.h"
#include "scene/load.h"

namespace vct::test {
namespace {

RenderSettings smallSettings() { return smallRenderSettings(32, RenderMode::Full); }

// The message of the vct::Error `check` throws, or "" when it throws none.
template <typename Check>
std::string refusal(Check check) {
    try {
        check();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

class Limits : public GpuTest {
protected:
    VkPhysicalDeviceLimits limits = gpu().properties.limits;
    VkPhysicalDeviceMemoryProperties memory = gpu().memoryProperties;
    const Scene cornell = loadScene("cornell");

    std::string check(const Scene& scene, const RenderSettings& settings) {
        return refusal([&] { checkRendererLimits(limits, memory, "a small GPU", scene, settings); });
    }
};

TEST_F(Limits, TheDeviceHoldsTheDefaultsAndTheSmallTestSettings) {
    EXPECT_EQ(check(cornell, RenderSettings{}), "");
    EXPECT_EQ(check(cornell, smallSettings()), "");
}

TEST_F(Limits, VoxelGridBeyondMaxImageDimension3DIsRefusedNamingTheLimitAndWhatFits) {
    limits.maxImageDimension3D = 200;
    RenderSettings settings = smallSettings();
    settings.resources.voxelResolution = 256;
    const std::string message = check(cornell, settings);
    EXPECT_NE(message.find("256³ voxel grid"), std::string::npos) << message;
    EXPECT_NE(message.find("maxImageDimension3D of 200"), std::string::npos) << message;
    EXPECT_NE(message.find("--voxels 128 fits"), std::string::npos) << message;
    settings.resources.voxelResolution = 128;
    EXPECT_EQ(check(cornell, settings), "");
}

TEST_F(Limits, VoxelResolutionMustBeAPowerOfTwoInRange) {
    RenderSettings settings = smallSettings();
    for (uint32_t resolution : {0u, 16u, 48u, 100u, 1000u, 1024u}) {
        settings.resources.voxelResolution = resolution;
        const std::string message = check(cornell, settings);
        EXPECT_NE(message.find("power of two from 32 to 512, not " + std::to_string(resolution)), std::string::npos)
            << message;
    }
}

TEST_F(Limits, ShadowMapsBeyondMaxImageDimension2DAreRefusedNamingTheOption) {
    limits.maxImageDimension2D = 2048;
    RenderSettings settings = smallSettings();
    settings.resources.sunShadowMapSize = 4096;
    std::string message = check(cornell, settings);
    EXPECT_NE(message.find("4096² sun shadow map"), std::string::npos) << message;
    EXPECT_NE(message.find("maxImageDimension2D of 2048"), std::string::npos) << message;
    EXPECT_NE(message.find("--shadow-map 2048 fits"), std::string::npos) << message;

    settings = smallSettings();
    settings.resources.localShadowMapSize = 4096;
    limits.maxFramebufferHeight = 1024;  // the tightest limit is the one named
    message = check(cornell, settings);
    EXPECT_NE(message.find("maxFramebufferHeight of 1024"), std::string::npos) << message;
    EXPECT_NE(message.find("--local-shadow-map 1024 fits"), std::string::npos) << message;
}

TEST_F(Limits, ImageWhoseSupersampledTargetsExceedTheDeviceIsRefused) {
    limits.maxFramebufferWidth = 1000;
    RenderSettings settings = smallSettings();
    settings.image.width = 600;
    settings.image.supersample = 2;
    const std::string message = check(cornell, settings);
    EXPECT_NE(message.find("1200 samples across"), std::string::npos) << message;
    EXPECT_NE(message.find("maxFramebufferWidth of 1000"), std::string::npos) << message;
    EXPECT_NE(message.find("--width 500 fits"), std::string::npos) << message;
    settings.image.width = 500;
    EXPECT_EQ(check(cornell, settings), "");
}

TEST_F(Limits, SceneWhoseBuffersExceedMaxStorageBufferRangeIsRefused) {
    // A device whose storage buffers hold 256 KiB: enough for a 32³ grid's sums (128 KiB each),
    // not for 10 000 vertices of 64 bytes (the extra vertices are unused, which is allowed).
    limits.maxStorageBufferRange = 256 * 1024;
    ASSERT_EQ(sizeof(glsl::GpuVertex), 64u);
    Scene large = cornell;
    large.vertices.resize(10000, cornell.vertices.front());
    const std::string message = check(large, smallSettings());
    EXPECT_NE(message.find("scene 'cornell': its 10000 vertices need 625 KiB"), std::string::npos) << message;
    EXPECT_NE(message.find("maxStorageBufferRange of 256 KiB; at most 4096 vertices fit"), std::string::npos)
        << message;
    EXPECT_EQ(check(cornell, smallSettings()), "");
}

TEST_F(Limits, TooLittleDeviceMemoryIsRefusedWithASettingThatFits) {
    // One device-local heap of 96 MiB: the defaults (128³ voxels, 4096² sun map, 512² × 4 samples)
    // need several hundred MiB, 32³ voxels with smaller shadow maps fit.
    memory.memoryHeapCount = 1;
    memory.memoryHeaps[0].size = VkDeviceSize(96) << 20;
    memory.memoryHeaps[0].flags = VK_MEMORY_HEAP_DEVICE_LOCAL_BIT;
    RenderSettings settings;
    settings.resources.voxelResolution = 64;
    const std::string message = check(cornell, settings);
    EXPECT_NE(message.find("of GPU memory"), std::string::npos) << message;
    EXPECT_NE(message.find("96 MiB heap of a small GPU"), std::string::npos) << message;
    EXPECT_NE(message.find("fits"), std::string::npos) << message;
}

TEST_F(Limits, RendererRefusesBeforeAllocatingAnything) {
    RenderSettings settings = smallSettings();
    settings.image.width = gpu().properties.limits.maxImageDimension2D + 1;
    const std::string message = refusal([&] { Renderer renderer(gpu(), cornell, settings); });
    EXPECT_NE(message.find(gpu().deviceName()), std::string::npos) << message;
    EXPECT_NE(message.find("samples across"), std::string::npos) << message;
}

TEST_F(Limits, ALightBrighterThanFloatsCarryIsRefusedNamingTheScene) {
    // Accepted, a light of 1e38 rendered NaN and infinite pixels.
    Renderer renderer(gpu(), cornell, smallSettings());
    std::vector<Light> lights = renderer.lights();
    lights[0].intensity = 1e38f;
    const std::string message = refusal([&] { renderer.setLights(lights); });
    EXPECT_NE(message.find("scene 'cornell': light 0"), std::string::npos) << message;
    EXPECT_NE(message.find("brighter than this renderer represents (1e+20)"), std::string::npos) << message;
}

TEST_F(Limits, DeviceLostAndOutOfMemorySayWhatHappened) {
    const std::string lost = refusal([] { throwVkError(VK_ERROR_DEVICE_LOST, "vkQueueSubmit2(...)", "x.cpp", 1); });
    EXPECT_EQ(lost.rfind("the GPU device was lost", 0), 0u) << lost;
    const std::string outOfMemory =
        refusal([] { throwVkError(VK_ERROR_OUT_OF_DEVICE_MEMORY, "vkAllocateMemory(...)", "x.cpp", 1); });
    EXPECT_EQ(outOfMemory.rfind("out of memory", 0), 0u) << outOfMemory;
    EXPECT_NE(outOfMemory.find("--voxels"), std::string::npos) << outOfMemory;
}

// The context throws after creating its instance: it destroys the instance first (a leak would
// show in a LeakSanitizer build, tools/sanitize.sh style).
TEST(GpuContextFailure, ANamedDeviceThatDoesNotExistIsAClearError) {
    ContextOptions options;
    options.deviceName = "no such GPU";
    const std::string message = refusal([&] { GpuContext context(options); });
    EXPECT_NE(message.find("not the requested device 'no such GPU'"), std::string::npos) << message;
}

}  // namespace
}  // namespace vct::test
