// vct view under a virtual X server (xvfb-run) on whatever Vulkan device is present, with the
// validation layer on: the viewer starts, follows scripted input (src/view/input.h), and the
// screenshots it saves show what the input should have changed.
#include <gtest/gtest.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct Png {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;
};

Png readPng(const fs::path& path) {
    Png png;
    int channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &png.width, &png.height, &channels, 3);
    if (!pixels) return png;
    png.rgb.assign(pixels, pixels + size_t(png.width) * png.height * 3);
    stbi_image_free(pixels);
    return png;
}

double meanValue(const Png& png) {
    double sum = 0.0;
    for (unsigned char value : png.rgb) sum += value;
    return png.rgb.empty() ? 0.0 : sum / double(png.rgb.size());
}

// The rectangle [x0, x1) × [y0, y1) of `png`.
Png crop(const Png& png, int x0, int y0, int x1, int y1) {
    Png part;
    if (png.rgb.empty() || x1 > png.width || y1 > png.height) return part;
    part.width = x1 - x0;
    part.height = y1 - y0;
    for (int y = y0; y < y1; ++y)
        part.rgb.insert(part.rgb.end(), png.rgb.begin() + (size_t(y) * png.width + x0) * 3,
                        png.rgb.begin() + (size_t(y) * png.width + x1) * 3);
    return part;
}

// Fraction of pixels whose colour differs by more than a few steps in any channel.
double changedFraction(const Png& a, const Png& b) {
    if (a.width != b.width || a.height != b.height || a.rgb.empty()) return 1.0;
    size_t changed = 0;
    for (size_t i = 0; i < a.rgb.size(); i += 3)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) > 4) {
                ++changed;
                break;
            }
    return double(changed) / double(a.rgb.size() / 3);
}

void writeWhitePixel(const fs::path& file) {
    const unsigned char white[3] = {255, 255, 255};
    ASSERT_TRUE(stbi_write_png(file.c_str(), 1, 1, 3, white, 3));
}

std::string readText(const fs::path& file) {
    std::ifstream in(file);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// A glTF file of one triangle whose base colour is the texture "texture.png" beside it.
void writeTexturedTriangle(const fs::path& file) {
    std::ofstream(file)
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)"
        << R"(AACAvwAAgL8AAIC/AACAPwAAgL8AAIA/AAAAAAAAgD8AAAAA"}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
        << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-1,-1,-1],)"
        << R"("max":[1,1,1]}],"images":[{"uri":"texture.png"}],"textures":[{"source":0}],)"
        << R"("materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],)"
        << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],)"
        << R"("scenes":[{"nodes":[0]}],"scene":0})";
}

class View : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        directory = fs::temp_directory_path() / ("vct_view_test_" + std::string(test->name()));
        fs::remove_all(directory);
        fs::create_directories(directory);
    }

    // Runs `vct view` in `directory` (which is its XDG_CONFIG_HOME too: the recent files go there) on a small window with 64³ voxels, one bounce and one
    // sample a pixel (so that a frame changes only what the script changed: converging bounces
    // brighten the first frames, which View.ProgressiveBouncesSettleAndThenTheImageStays checks, and
    // still samples move the image's samples, View.AStillViewGathersItsSamplesThenIdles), each
    // frame's passes logged (--verbose); returns the exit code.
    // `hint`: start with the status bar's one-line hint to the guide, as a user does (the tests
    // otherwise pass --no-guide, so that screenshots with the panels show only what they test).
    // `autoExposure`: as a user starts it; the tests otherwise fix the exposure (--exposure 0, the
    // radiance as it is), so that a change of light shows as a change of brightness.
    // The exit code is the viewer's own, which a script under xvfb-run writes to a file: xvfb-run
    // answers 5 instead when it fails to remove its temporary folder, which it sometimes does after
    // a command that exits at once (View.ALightEntryForALightTheSceneLacksIsAnError failed so in two
    // of four full test runs).
    int runViewer(const std::string& arguments, bool hint = false, bool autoExposure = false) {
        const fs::path logPath = directory / "log.txt", exitCodePath = directory / "exit-code";
        fs::remove(exitCodePath);
        std::ofstream(directory / "run-viewer.sh")
            << VCT_EXECUTABLE " view --validate " << (autoExposure ? "" : "--verbose ") << (hint ? "" : "--no-guide ")
            << "--voxels 64 --shadow-map 512 --bounces 1 --still-samples 1 --width 320 --height 180 "
            << (autoExposure ? "" : "--exposure 0 ") << arguments << " > '" << logPath.string() << "' 2>&1\n"
            << "echo $? > '" << exitCodePath.string() << "'\n";
        const std::string command = "cd '" + directory.string() + "' && XDG_RUNTIME_DIR=/tmp XDG_CONFIG_HOME='" +
                                    directory.string() +
                                    "' " XVFB_RUN " -a -s '-screen 0 1024x768x24' bash run-viewer.sh";
        std::system(command.c_str());
        std::ifstream logFile(logPath);
        std::ostringstream text;
        text << logFile.rdbuf();
        log = text.str();
        int exitCode = -1;
        std::ifstream(exitCodePath) >> exitCode;
        return exitCode;
    }

    Png screenshot(const std::string& name) { return readPng(directory / name); }

    fs::path directory;
    std::string log;
};

// The panels cover much of a small window: the scripts hide them first (Tab), so the
// camera and sun get the mouse, and screenshots show the image alone.
constexpr const char* hidePanels = "0 key tab press; ";

TEST_F(View, StartsRendersAndSavesAScreenshotOfTheWindowSize) {
    ASSERT_EQ(runViewer("--screenshot shot.png --frames 3"), 0) << log;
    const Png png = screenshot("shot.png");
    ASSERT_FALSE(png.rgb.empty()) << log;
    EXPECT_EQ(png.width, 320);
    EXPECT_EQ(png.height, 180);
    EXPECT_GT(meanValue(png), 20.0) << "the Cornell box should not be black";
}

TEST_F(View, ScreenshotWithTheUiShowsThePanels) {
    ASSERT_EQ(runViewer("--width 640 --height 360 --screenshot plain.png --frames 2"), 0) << log;
    ASSERT_EQ(runViewer("--width 640 --height 360 --screenshot ui.png --frames 2 --screenshot-ui"), 0) << log;
    // Without the UI, the image alone: what is right of the settings (300 px). With it, the window,
    // whose left holds the settings and whose right the same image.
    const Png plain = screenshot("plain.png"), ui = screenshot("ui.png");
    EXPECT_EQ(plain.width, 640 - 300) << log;
    EXPECT_EQ(ui.width, 640);
    EXPECT_LT(changedFraction(crop(plain, 0, 0, 340, 300), crop(ui, 300, 0, 640, 300)), 0.001);
    EXPECT_GT(changedFraction(crop(plain, 0, 0, 300, 300), crop(ui, 0, 0, 300, 300)), 0.2);
}

TEST_F(View, FlyingAndLookingMoveTheCamera) {
    const std::string events =
        std::string(hidePanels) +
        "1 screenshot before.png; 2 key W down; 6 key W up; 6 mouse 160 90;"
        "7 button right down; 7 mouse 200 100; 8 button right up; 9 screenshot after.png; 10 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.05) << log;
}

TEST_F(View, ProgressiveBouncesSettleAndThenTheImageStays) {
    // The viewer's own bounces: one per frame until the light converges (a few frames at 64³),
    // then frames reuse the image. The later --bounces wins over the one runViewer passes.
    const std::string events =
        std::string(hidePanels) + "1 screenshot first.png; 60 screenshot settled.png; 62 screenshot still.png; 63 quit";
    ASSERT_EQ(runViewer("--bounces converged --events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("first.png"), screenshot("settled.png")), 0.05) << "later bounces add light";
    EXPECT_LT(changedFraction(screenshot("settled.png"), screenshot("still.png")), 0.001) << "settled";
}

TEST_F(View, ResetKeyReturnsToTheSceneCamera) {
    // The reset view's image is the start's once its reused diffuse light has all been traced
    // anew: four frames after the view last moved.
    const std::string events = std::string(hidePanels) +
                               "1 screenshot start.png; 2 key D down; 6 key D up; 7 screenshot moved.png;"
                               "8 key R press; 12 screenshot reset.png; 13 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("start.png"), screenshot("moved.png")), 0.05);
    EXPECT_LT(changedFraction(screenshot("start.png"), screenshot("reset.png")), 0.001);
}

TEST_F(View, OrbitModeDragTurnsAroundTheScene) {
    const std::string events = std::string(hidePanels) +
                               "1 screenshot before.png; 2 key O press; 3 mouse 100 90; 4 button left down;"
                               "5 mouse 180 90; 6 button left up; 7 scroll 2; 8 screenshot after.png; 9 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.05);
}

TEST_F(View, ASoftwareRasterizerStartsOnTheFastPresetUnlessOneIsGiven) {
    ASSERT_EQ(runViewer("--screenshot shot.png --frames 1"), 0) << log;
    const bool software = log.find("llvmpipe") != std::string::npos || log.find("SwiftShader") != std::string::npos;
    EXPECT_EQ(log.find("started on the fast preset") != std::string::npos, software) << log;
    ASSERT_EQ(runViewer("--preset balanced --screenshot shot.png --frames 1"), 0) << log;
    EXPECT_EQ(log.find("started on the fast preset"), std::string::npos) << log;
}

TEST_F(View, AStillViewGathersItsSamplesThenIdles) {
    // Sixteen samples a pixel over still frames: after the first frame, fifteen redraw the
    // G-buffer with the samples moved and add them to the mean; then nothing runs.
    ASSERT_EQ(runViewer("--still-samples 16 --screenshot still.png --frames 30"), 0) << log;
    EXPECT_NE(log.find("frame 1: ran gbuffer diffuse-cones shade resolve;"), std::string::npos) << log;
    EXPECT_NE(log.find("frame 15: ran gbuffer diffuse-cones shade resolve;"), std::string::npos) << log;
    EXPECT_EQ(log.find("frame 16: ran"), std::string::npos) << log;
    EXPECT_EQ(log.find("frame 29: ran"), std::string::npos) << log;
}

TEST_F(View, MovingTheSunReinjectsLightWithoutRevoxelizing) {
    const std::string events = std::string(hidePanels) +
                               "1 light 1 intensity 3; 2 screenshot before.png; 3 key left down; 8 key left up;"
                               "8 key up down; 12 key up up; 13 screenshot after.png; 14 quit";
    // The viewer's sun starts off (as `vct render`, the box has no sun): the script turns it on.
    ASSERT_EQ(runViewer("--verbose --events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.01);
    // Frame 0 builds everything; a frame that moved the sun re-injects but keeps the voxels.
    EXPECT_NE(log.find("frame 0: ran shadow voxelize inject"), std::string::npos) << log;
    // (On lavapipe the viewer starts on `fast`, whose diffuse cones have a pass of their own; the
    // camera did not move, so the G-buffer is kept.)
    EXPECT_NE(
        log.find("frame 5: ran shadow inject mips diffuse-cones shade; skipped voxelize bounce gbuffer resolve\n"),
        std::string::npos)
        << log;
}

TEST_F(View, CtrlDragMovesTheSun) {
    const std::string events = std::string(hidePanels) +
                               "1 light 1 intensity 3; 2 screenshot before.png; 2 mouse 100 90; 3 key ctrl down;"
                               "3 button left down; 4 mouse 160 60; 5 button left up; 5 key ctrl up;"
                               "6 screenshot after.png; 7 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.01);
}

TEST_F(View, ComponentKeysChangeTheImage) {
    // 1 = direct diffuse off: the box is lit only by indirect light and so is darker.
    const std::string events = std::string(hidePanels) +
                               "1 screenshot lit.png; 2 key 1 press; 3 screenshot no_direct.png; 4 key 1 press;"
                               "4 key V press; 5 screenshot base_colour.png; 6 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_LT(meanValue(screenshot("no_direct.png")), meanValue(screenshot("lit.png")) - 5.0);
    EXPECT_GT(changedFraction(screenshot("lit.png"), screenshot("base_colour.png")), 0.05);
}

TEST_F(View, ResizingAndMinimisingDoNotCrash) {
    const std::string events = std::string(hidePanels) +
                               "1 resize 400 240; 4 iconify; 8 restore; 12 resize 200 120; 16 screenshot small.png;"
                               "17 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    const Png png = screenshot("small.png");
    EXPECT_EQ(png.width, 200) << log;
    EXPECT_EQ(png.height, 120);
    EXPECT_GT(meanValue(png), 20.0);
}

TEST_F(View, ExtremeResizesKeepTheWindowAndTheScene) {
    // A zero size (which X refuses with BadValue, ending the process) minimises the window, which
    // waits; a 100000² window (X carries 16 bits: 65535²) is drawn at what the device can hold, the
    // window asked to shrink to it, instead of a swapchain of tens of gigabytes.
    const std::string events = std::string(hidePanels) +
                               "1 resize 0 0; 4 resize 320 180; 6 screenshot zero.png; 7 resize 100000 100000; "
                               "10 screenshot huge.png; 11 resize 200 120; 14 screenshot after.png; 15 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    const Png zero = screenshot("zero.png"), huge = screenshot("huge.png"), after = screenshot("after.png");
    EXPECT_EQ(zero.width, 320) << log;
    EXPECT_EQ(zero.height, 180);
    EXPECT_GT(huge.width, 320) << log;
    EXPECT_LE(huge.width, 16384);
    EXPECT_EQ(huge.width, huge.height) << "the aspect ratio is kept";
    EXPECT_NE(log.find("can draw; drawn at"), std::string::npos) << log;
    EXPECT_EQ(after.width, 200) << log;
    EXPECT_EQ(after.height, 120);
    EXPECT_GT(meanValue(after), 20.0) << "the scene is still there";
}

TEST_F(View, ABrokenDroppedFileKeepsTheSceneAndADroppedSceneLoads) {
    std::ofstream(directory / "broken.gltf") << "{ not json";
    const std::string events = std::string(hidePanels) +
                               "1 screenshot before.png; 2 drop broken.gltf; 3 screenshot kept.png;"
                               "4 drop cornell-emissive; 5 screenshot emissive.png; 6 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_NE(log.find("keeping cornell"), std::string::npos) << log;
    EXPECT_LT(changedFraction(screenshot("before.png"), screenshot("kept.png")), 0.001);
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("emissive.png")), 0.05);
}

TEST_F(View, ScreenshotKeyWritesAPngInTheCurrentFolder) {
    ASSERT_EQ(runViewer("--events '1 key F12 press; 2 quit'"), 0) << log;
    bool found = false;
    for (const fs::directory_entry& entry : fs::directory_iterator(directory))
        found |= entry.path().extension() == ".png" && readPng(entry.path()).width == 320;
    EXPECT_TRUE(found) << log;
}

TEST_F(View, BracketKeysFromAScriptStepThroughTheVoxelMips) {
    // V seven times: voxel radiance (albedo and normals are level-0 data). ] shows the next coarser
    // mip, [ the finer one again; ] past the last mip stays on it (the panels are hidden, so nothing
    // else clamps it; the validation layer would report a level past the image's).
    const std::string events =
        std::string(hidePanels) +
        "1 key V press; 2 key V press; 3 key V press; 4 key V press; 5 key V press;"
        "6 key V press; 7 key V press; 8 screenshot mip0.png; 9 key ] press; 10 screenshot mip1.png;"
        "11 key [ press; 12 screenshot back.png; 13 key ] press; 14 key ] press; 15 key ] press;"
        "16 key ] press; 17 key ] press; 18 key ] press; 19 key ] press; 20 key ] press;"
        "21 screenshot last.png; 22 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_GT(changedFraction(screenshot("mip0.png"), screenshot("mip1.png")), 0.05) << log;
    EXPECT_LT(changedFraction(screenshot("mip0.png"), screenshot("back.png")), 0.001) << log;
    EXPECT_FALSE(screenshot("last.png").rgb.empty()) << log;
}

TEST_F(View, TheCameraIgnoresTheMouseOverTheSettings) {
    // 640×360: the settings are docked on the left (300 px wide). A right-button drag over them
    // leaves the image as it was; the same drag over the image turns the camera.
    const std::string events =
        "1 screenshot before.png; 2 mouse 100 200; 3 button right down; 4 mouse 200 150; 5 mouse 250 120;"
        "6 button right up; 7 screenshot over_panel.png; 8 mouse 450 200; 9 button right down; 10 mouse 550 150;"
        "11 mouse 600 120; 12 button right up; 13 screenshot over_image.png; 14 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'"), 0) << log;
    EXPECT_LT(changedFraction(screenshot("before.png"), screenshot("over_panel.png")), 0.001) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("over_image.png")), 0.05) << log;
}

TEST_F(View, StartsWithAHintNotTheGuideAndF1OpensTheGuide) {
    // Beside the docked settings (x < 300) and above the status bar, the image is uncovered at
    // start: the panels' screenshot equals the plain one there. F1 covers it with the guide.
    const std::string events =
        "2 screenshot plain.png; 3 screenshot panels.png ui; 4 key F1 press; 5 screenshot guide.png ui; 6 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'", true), 0) << log;
    const Png plain = crop(screenshot("plain.png"), 30, 60, 250, 280);  // the image alone, from x = 300
    ASSERT_FALSE(plain.rgb.empty()) << log;
    EXPECT_LT(changedFraction(plain, crop(screenshot("panels.png"), 330, 60, 550, 280)), 0.001) << log;
    EXPECT_GT(changedFraction(plain, crop(screenshot("guide.png"), 330, 60, 550, 280)), 0.3) << log;
    // The hint is a line at the bottom, over the image.
    EXPECT_GT(changedFraction(crop(screenshot("plain.png"), 30, 340, 270, 360),
                              crop(screenshot("panels.png"), 330, 340, 570, 360)),
              0.05)
        << log;
}

TEST_F(View, TheSettingsAreOpaque) {
    // Flying changes the image; the settings' pixels stay as they were, as nothing shows through
    // (the translucent panels let a fifth of the image through).
    const std::string events =
        "2 screenshot before.png ui; 3 key W down; 7 key W up; 8 screenshot after.png ui; 9 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'"), 0) << log;
    const Png before = screenshot("before.png"), after = screenshot("after.png");
    EXPECT_GT(changedFraction(crop(before, 400, 60, 620, 280), crop(after, 400, 60, 620, 280)), 0.05) << log;
    // (Left of the scroll bar and above the status bar, which "saved before.png" grows.)
    EXPECT_LT(changedFraction(crop(before, 0, 40, 270, 300), crop(after, 0, 40, 270, 300)), 0.001) << log;
}

TEST_F(View, SceneWarningsAreShownInTheWindow) {
    // A triangle whose base-colour texture is missing loads with a warning: on stderr, and in a
    // window. With the texture there (1×1 white: the same colour as the fallback, so the same
    // image) there is no warning, and the panels' screenshots differ only by that window.
    writeTexturedTriangle(directory / "textured.gltf");
    // --light-dir: the file has no light, and the default sun's warning would be one more.
    const std::string arguments =
        "--scene textured.gltf --light-dir 0,-1,-1 --width 640 --height 360 --events '2 screenshot ";
    ASSERT_EQ(runViewer(arguments + "missing_plain.png; 3 screenshot missing_panels.png ui; 4 quit'"), 0) << log;
    EXPECT_NE(log.find("warning: textured.gltf: images[0]: 'texture.png' cannot be opened"), std::string::npos) << log;
    const unsigned char white[3] = {255, 255, 255};
    ASSERT_TRUE(stbi_write_png((directory / "texture.png").c_str(), 1, 1, 3, white, 3));
    ASSERT_EQ(runViewer(arguments + "found_plain.png; 3 screenshot found_panels.png ui; 4 quit'"), 0) << log;
    for (const char* name : {"missing_plain.png", "missing_panels.png", "found_plain.png", "found_panels.png"})
        ASSERT_FALSE(screenshot(name).rgb.empty()) << name << " was not saved\n" << log;
    EXPECT_EQ(log.find("warning:"), std::string::npos) << log;
    EXPECT_LT(changedFraction(screenshot("missing_plain.png"), screenshot("found_plain.png")), 0.001);
    EXPECT_GT(changedFraction(screenshot("missing_panels.png"), screenshot("found_panels.png")), 0.05)
        << "the warning is not shown in the window";
}

TEST_F(View, AFileLitOnlyByADimGlowGetsTheDefaultSunAndSkyAsRenderDoes) {
    // One triangle glowing at radiance 0.05: 2 % of the power the default sun brings onto it, a
    // trim rather than a lamp (DamagedHelmet's kind). Both commands add the default sun and sky,
    // and say so in the same words; before, the viewer added a sun of its own and render none.
    std::ofstream(directory / "glow.gltf")
        << R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,)"
        << R"(AACAvwAAgL8AAIC/AACAPwAAgL8AAIA/AAAAAAAAgD8AAAAA"}],"bufferViews":[{"buffer":0,"byteLength":36}],)"
        << R"("accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[-1,-1,-1],)"
        << R"("max":[1,1,1]}],"materials":[{"emissiveFactor":[0.05,0.05,0.05]}],)"
        << R"("meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],"nodes":[{"mesh":0}],)"
        << R"("scenes":[{"nodes":[0]}],"scene":0})";
    const std::string added =
        "its emissive surfaces send out 2.3% of the power the default sun brings (too "
        "little to light it), so a default sun and sky are added";
    ASSERT_EQ(runViewer("--scene glow.gltf --screenshot view.png --frames 2"), 0) << log;
    EXPECT_NE(log.find(added), std::string::npos) << log;
    const std::string render = "cd '" + directory.string() +
                               "' && " VCT_EXECUTABLE
                               " render --scene glow.gltf --voxels 64 --width 64 --height 64 --out render.pfm "
                               "> render.txt 2>&1";
    ASSERT_EQ(std::system(render.c_str()), 0) << readText(directory / "render.txt");
    EXPECT_NE(readText(directory / "render.txt").find(added), std::string::npos) << readText(directory / "render.txt");
}

TEST_F(View, DimmingALightInTheScenePanelRerunsOnlyTheLightPasses) {
    // 640×360, the Cornell box: light 0 is its point light, light 1 the viewer's sun. A click opens
    // light 0's node in the Lights section (a click on its header opens it first); a drag to the left across its intensity field takes the
    // intensity to 0 (the field clamps there). The box gets darker, and as when the arrow keys move
    // the sun, the light is re-injected while the voxels stay.
    const std::string events =
        "1 mouse 50 82; 2 button left down; 3 button left up; 4 screenshot before.png; 5 mouse 100 105;"
        "6 button left down; 7 button left up; 8 mouse 120 123; 9 button left down; 10 mouse 5 123;"
        "11 button left up; 12 screenshot panel.png ui; 13 screenshot after.png; 14 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'"), 0) << log;
    const Png before = screenshot("before.png"), after = screenshot("after.png");  // the image alone
    ASSERT_FALSE(after.rgb.empty()) << log;
    EXPECT_LT(meanValue(after), meanValue(before) - 10.0) << "the point light still shines\n" << log;
    EXPECT_NE(log.find("ran shadow inject mips diffuse-cones shade; skipped voxelize bounce gbuffer resolve\n"),
              std::string::npos)
        << log;
}

TEST_F(View, ALightEntryInAScriptSetsItsIntensity) {
    // The `light` entry writes what the panel's intensity field writes: 0 darkens the box, 4 (cd)
    // brightens it past the start (1 cd); the sun's goes through the sun control, as its field does
    // (it starts off, as `vct render` adds no sun to the box: 3 lux turns it on).
    const std::string events = std::string(hidePanels) +
                               "1 screenshot start.png; 2 light 0 intensity 0; 3 screenshot off.png;"
                               "4 light 0 intensity 4; 5 screenshot bright.png; 6 light 1 intensity 3;"
                               "7 screenshot sun.png; 8 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    const double start = meanValue(screenshot("start.png")), bright = meanValue(screenshot("bright.png"));
    EXPECT_LT(meanValue(screenshot("off.png")), start - 10.0) << log;
    EXPECT_GT(bright, start + 10.0) << log;
    EXPECT_GT(meanValue(screenshot("sun.png")), bright + 2.0) << log;
}

TEST_F(View, ASkyEntryInAScriptLightsTheSkyAndTheGround) {
    // The terrain under a black sky, then a blue one (what the scene panel's sky field writes): the
    // sky above the hills turns blue, and the ground, lit by it through the cones, brighter.
    const std::string events =
        std::string(hidePanels) + "1 screenshot black.png; 2 sky 0.2 0.4 0.8; 4 screenshot blue.png; 5 quit";
    ASSERT_EQ(runViewer("--scene terrain --events '" + events + "'"), 0) << log;
    const Png black = screenshot("black.png"), blue = screenshot("blue.png");
    const Png skyBefore = crop(black, 0, 0, 320, 12), skyAfter = crop(blue, 0, 0, 320, 12);
    ASSERT_FALSE(skyAfter.rgb.empty()) << log;
    EXPECT_LT(meanValue(skyBefore), 2.0) << log;
    double red = 0.0, blueChannel = 0.0;
    for (size_t i = 0; i < skyAfter.rgb.size(); i += 3) {
        red += skyAfter.rgb[i];
        blueChannel += skyAfter.rgb[i + 2];
    }
    EXPECT_GT(blueChannel, 1.5 * red) << log;
    EXPECT_GT(meanValue(skyAfter), 40.0) << log;
    EXPECT_GT(meanValue(crop(blue, 0, 120, 320, 180)), meanValue(crop(black, 0, 120, 320, 180)) + 5.0) << log;
}

TEST_F(View, TheCommandLinesSkyStaysForADroppedScene) {
    // --environment is the sky of every scene the viewer opens, as it would be for `vct render`:
    // the terrain dropped onto the Cornell box keeps the blue sky above its hills.
    const std::string events = std::string(hidePanels) + "1 drop terrain; 3 screenshot terrain.png; 4 quit";
    ASSERT_EQ(runViewer("--environment 0.1,0.2,0.8 --events '" + events + "'"), 0) << log;
    const Png sky = crop(screenshot("terrain.png"), 0, 0, 320, 12);
    ASSERT_FALSE(sky.rgb.empty()) << log;
    double red = 0.0, blue = 0.0;
    for (size_t i = 0; i < sky.rgb.size(); i += 3) {
        red += sky.rgb[i];
        blue += sky.rgb[i + 2];
    }
    EXPECT_GT(blue, 2.0 * red + 20.0 * double(sky.rgb.size() / 3)) << log;
}

TEST_F(View, ALightTheRendererRefusesIsKeptAsItWasAndSaidSo) {
    // A negative intensity, or one past what the voxels' float16 holds: the window shows why, the
    // light stays as it was (the same image), and the viewer goes on.
    const std::string events = std::string(hidePanels) +
                               "1 screenshot before.png; 2 light 0 intensity -1; 3 screenshot negative.png;"
                               "4 light 0 intensity 1e30; 5 screenshot huge.png; 6 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    EXPECT_NE(log.find("has a negative intensity or colour (the light is kept as it was)"), std::string::npos) << log;
    EXPECT_NE(log.find("brighter than this renderer represents"), std::string::npos) << log;
    EXPECT_LT(changedFraction(screenshot("before.png"), screenshot("negative.png")), 0.001);
    EXPECT_LT(changedFraction(screenshot("before.png"), screenshot("huge.png")), 0.001);
}

TEST_F(View, RecentFilesThatCannotBeSavedAreAWarningInTheWindow) {
    // A file where the config folder "vct" should be: the list cannot be written. The scene opens
    // all the same, and the warning is on stderr and in the window.
    writeTexturedTriangle(directory / "textured.gltf");
    writeWhitePixel(directory / "texture.png");
    std::ofstream(directory / "vct") << "not a folder";
    ASSERT_EQ(runViewer("--scene textured.gltf --light-dir 0,-1,-1 --width 640 --height 360 --events '"
                        "2 screenshot plain.png; 3 screenshot panels.png ui; 4 quit'"),
              0)
        << log;
    EXPECT_NE(log.find("warning: cannot keep the recent files in '" + (directory / "vct" / "recent").string() + "'"),
              std::string::npos)
        << log;
    // The warnings window is centred on the window, over the image right of the settings.
    EXPECT_GT(changedFraction(crop(screenshot("plain.png"), 10, 100, 270, 300),
                              crop(screenshot("panels.png"), 310, 100, 570, 300)),
              0.05)
        << "the warning is not shown in the window";
}

TEST_F(View, ALightEntryForALightTheSceneLacksIsAnError) {
    EXPECT_EQ(runViewer("--events '1 light 7 intensity 2; 2 quit'"), 1) << log;
    EXPECT_NE(log.find("the scene has no light 7 (it has 2, counted from 0)"), std::string::npos) << log;
    EXPECT_EQ(runViewer("--events '1 light 0 colour 2'"), 1) << log;
    EXPECT_NE(log.find("a light's intensity is what a script sets"), std::string::npos) << log;
}

// The smallest rectangle holding every pixel `keep(x, y)` picks; empty (x0 > x1) when none.
struct Rect {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    void add(int x, int y) { x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y); }
};

TEST_F(View, TheGridBoundsKeyDrawsTheVoxelGridsBoxAroundTheScene) {
    // O and the wheel back: orbiting far enough out that the whole grid is in view. G draws the
    // grid's box as amber lines over the image, G again hides it. The voxel grid holds the scene,
    // and fits it (the Cornell box is a cube, the grid a cube a little larger): the lines' bounding
    // rectangle holds every lit pixel of the plain image and is not much larger than theirs. The
    // plain image is taken once the view's reused diffuse light has settled (four frames).
    const std::string events = std::string(hidePanels) +
                               "1 key O press; 2 scroll -8; 8 screenshot plain.png; 9 key G press;"
                               "10 screenshot box.png; 11 key G press; 12 screenshot off.png; 13 quit";
    ASSERT_EQ(runViewer("--events '" + events + "'"), 0) << log;
    const Png plain = screenshot("plain.png"), box = screenshot("box.png");
    ASSERT_FALSE(box.rgb.empty()) << log;
    ASSERT_EQ(plain.width, box.width);
    Rect lines, scene;
    size_t changed = 0, amber = 0;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x) {
            const unsigned char* before = &plain.rgb[(size_t(y) * plain.width + x) * 3];
            const unsigned char* after = &box.rgb[(size_t(y) * plain.width + x) * 3];
            if (before[0] + before[1] + before[2] > 30) scene.add(x, y);
            if (std::abs(before[0] - after[0]) + std::abs(before[1] - after[1]) + std::abs(before[2] - after[2]) <= 12)
                continue;
            ++changed;
            lines.add(x, y);
            amber += after[0] > 220 && after[1] > 160 && after[1] < 240 && after[2] < 80;
        }
    const double pixels = double(plain.width) * plain.height;
    EXPECT_GT(changed / pixels, 0.002) << "no lines drawn\n" << log;
    EXPECT_LT(changed / pixels, 0.05) << "more than lines drawn";
    EXPECT_GT(double(amber), 0.95 * double(changed)) << "what changed is not the lines' colour";
    ASSERT_LE(scene.x0, scene.x1) << "the scene is not in view";
    EXPECT_LE(lines.x0, scene.x0);
    EXPECT_GE(lines.x1, scene.x1);
    EXPECT_LE(lines.y0, scene.y0);
    EXPECT_GE(lines.y1, scene.y1);
    EXPECT_LT(lines.x1 - lines.x0, 1.2 * (scene.x1 - scene.x0)) << "the box is far larger than the scene";
    EXPECT_LT(lines.y1 - lines.y0, 1.2 * (scene.y1 - scene.y0)) << "the box is far larger than the scene";
    EXPECT_LT(changedFraction(plain, screenshot("off.png")), 0.001) << "G again hides the box";
}

// Pixels of `png` whose red channel clearly dominates: the Cornell box's left wall.
size_t redPixels(const Png& png) {
    size_t count = 0;
    for (size_t i = 0; i + 2 < png.rgb.size(); i += 3)
        count += png.rgb[i] > 100 && png.rgb[i + 1] < png.rgb[i] / 3 && png.rgb[i + 2] < png.rgb[i] / 3;
    return count;
}

TEST_F(View, TheImageTakesTheWindowRightOfTheOpenSettings) {
    // 960×540 (the issue's window), settings docked on the left (300 px): the image is drawn beside
    // them, so the red wall, which they covered, shows; a screenshot without the UI is that image
    // alone (the profiler covers the top right of the window's, above y = 350). A click on
    // the title bar's arrow collapses the settings and the image takes the whole window again, as
    // Tab does; re-sizing the image keeps the voxels.
    const std::string events =
        "2 screenshot open.png; 3 screenshot open_ui.png ui; 4 mouse 10 10; 5 button left down; 6 button left up;"
        "8 screenshot collapsed.png; 9 key tab press; 10 screenshot hidden.png; 11 quit";
    ASSERT_EQ(runViewer("--width 960 --height 540 --events '" + events + "'"), 0) << log;
    const Png open = screenshot("open.png"), openUi = screenshot("open_ui.png");
    const Png collapsed = screenshot("collapsed.png");
    ASSERT_FALSE(collapsed.rgb.empty()) << log;
    EXPECT_EQ(open.width, 960 - 300) << log;
    EXPECT_LT(changedFraction(crop(open, 0, 360, 660, 480), crop(openUi, 300, 360, 960, 480)), 0.001)
        << "the image is not right of the settings";
    EXPECT_GT(redPixels(crop(openUi, 310, 0, 960, 480)), 2000u) << "the red wall is not beside the settings";
    EXPECT_GT(meanValue(crop(collapsed, 0, 30, 360, 540)), 20.0) << "collapsed settings leave the window to the image";
    EXPECT_LT(changedFraction(collapsed, screenshot("hidden.png")), 0.001) << "collapsed or hidden, the same image";
    EXPECT_NE(log.find("ran gbuffer diffuse-cones shade; skipped shadow voxelize inject mips bounce resolve"),
              std::string::npos)
        << log;
}

// 640×360: a click on the "Scene" header opens the section; its path field and Open button, and
// below them the recent files, are at these heights.
constexpr const char* openSceneSection = "2 mouse 50 59; 3 button left down; 4 button left up; ";

TEST_F(View, AFileTypedIntoTheSceneFieldOpensAndGoesToTheRecentFiles) {
    writeTexturedTriangle(directory / "textured.gltf");
    writeWhitePixel(directory / "texture.png");
    const std::string events = std::string(openSceneSection) +
                               "1 screenshot before.png; 5 mouse 150 168; 6 button left down; 7 button left up;"
                               "8 type textured.gltf; 9 mouse 260 168; 10 button left down; 11 button left up;"
                               "13 screenshot after.png; 14 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'"), 0) << log;
    EXPECT_NE(log.find("loading textured.gltf\n"), std::string::npos) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.05) << "still the Cornell box";
    // Kept as an absolute path, so it opens from any folder, in $XDG_CONFIG_HOME/vct/recent.
    EXPECT_EQ(readText(directory / "vct" / "recent"), (directory / "textured.gltf").string() + "\n") << log;
}

TEST_F(View, ARecentFileOpensWithAClickAndAMissingOneIsGreyedAndInert) {
    writeTexturedTriangle(directory / "textured.gltf");
    writeWhitePixel(directory / "texture.png");
    const std::string gone = (directory / "gone.gltf").string(), kept = (directory / "textured.gltf").string();
    fs::create_directories(directory / "vct");
    std::ofstream(directory / "vct" / "recent") << gone << "\n" << kept << "\n";
    // The list's first row is the missing file, the second the one that is there.
    const std::string events = std::string(openSceneSection) +
                               "1 screenshot before.png; 5 mouse 100 236; 6 button left down; 7 button left up;"
                               "8 screenshot still.png; 8 screenshot list.png ui; 9 mouse 100 253;"
                               "10 button left down; 11 button left up; 13 screenshot after.png; 14 quit";
    ASSERT_EQ(runViewer("--width 640 --height 360 --events '" + events + "'"), 0) << log;
    EXPECT_EQ(log.find("loading " + gone), std::string::npos) << log;
    EXPECT_LT(changedFraction(screenshot("before.png"), screenshot("still.png")), 0.001);
    EXPECT_NE(log.find("loading " + kept + "\n"), std::string::npos) << log;
    EXPECT_GT(changedFraction(screenshot("before.png"), screenshot("after.png")), 0.05) << "still the Cornell box";
    EXPECT_EQ(readText(directory / "vct" / "recent"), kept + "\n" + gone + "\n") << "opened moves it first";
}

TEST_F(View, StartsMostlyImageExposedForTheScene) {
    // 960×540, as a user starts it (automatic exposure, the hint to the guide): the image, right of
    // the compact settings and above the one-row status bar, is at least 65 % of the window, and
    // exposed for the scene whatever its units: the Cornell box's point light at 1 cd and at 100 cd
    // give the same picture.
    // (A script's frames are 1/30 s apart: by frame 60, 2 s, the exposure has followed the change.)
    const std::string events = "60 screenshot image.png; 61 quit";
    ASSERT_EQ(runViewer("--width 960 --height 540 --events '" + events + "'", true, true), 0) << log;
    const Png image = screenshot("image.png");
    ASSERT_FALSE(image.rgb.empty()) << log;
    EXPECT_GE(double(image.width) * image.height, 0.65 * 960.0 * 540.0) << image.width << "x" << image.height;
    const double grey = meanValue(image);
    EXPECT_GT(grey, 70.0) << log;
    EXPECT_LT(grey, 170.0) << log;
    ASSERT_EQ(runViewer("--width 960 --height 540 --events '1 light 0 intensity 100; " + events + "'", true, true), 0)
        << log;
    EXPECT_NEAR(meanValue(screenshot("image.png")), grey, 6.0) << log;
    EXPECT_EQ(log.find("frame 3: ran"), std::string::npos) << "a per-frame log without --verbose";
}

TEST_F(View, ABadScriptIsAnErrorNamingTheEntry) {
    EXPECT_EQ(runViewer("--events '1 jump'"), 1);
    EXPECT_NE(log.find("unknown action 'jump'"), std::string::npos) << log;
}

}  // namespace
