// vct bench's error metrics and Pareto front on inputs whose answers are known by hand.
#include <cmath>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "bench/metrics.h"
#include "bench/pareto.h"
#include "bench/svg_plot.h"
#include "error.h"

namespace vct::bench {
namespace {

Image uniformImage(uint32_t width, uint32_t height, float value) {
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.assign(size_t(width) * height * 3, value);
    return image;
}

void setPixel(Image& image, uint32_t x, uint32_t y, float value) {
    for (int c = 0; c < 3; ++c) image.pixel(x, y)[c] = value;
}

TEST(BenchMetrics, IdenticalImagesHaveNoError) {
    const Image reference = uniformImage(4, 3, 0.7f);
    const ImageError error = compareImages(reference, reference);
    EXPECT_EQ(error.relMse, 0.0);
    EXPECT_EQ(error.rmse, 0.0);
    EXPECT_DOUBLE_EQ(error.luminanceRatio, 1.0);
    EXPECT_EQ(error.shareOff, 0.0);
}

TEST(BenchMetrics, TwiceTheReferenceGivesKnownValues) {
    // r = 1 everywhere, x = 2: relMSE = 1 / (1 + (0.1 · 1)²), RMSE = 1, ratio 2, every pixel off.
    const ImageError error = compareImages(uniformImage(8, 8, 2.0f), uniformImage(8, 8, 1.0f));
    EXPECT_NEAR(error.relMse, 1.0 / 1.01, 1e-12);
    EXPECT_NEAR(error.rmse, 1.0, 1e-12);
    EXPECT_NEAR(error.luminanceRatio, 2.0, 1e-12);
    EXPECT_EQ(error.shareOff, 1.0);
}

TEST(BenchMetrics, HandComputedTwoPixelImage) {
    // Reference: one white pixel (luminance 1) and one black; the image is 10 % brighter on the white.
    Image reference = uniformImage(2, 1, 0.0f), image = uniformImage(2, 1, 0.0f);
    setPixel(reference, 0, 0, 1.0f);
    setPixel(image, 0, 0, 1.1f);
    const ImageError error = compareImages(image, reference);
    // Mean channel value 0.5, so ε = 0.05²; three channels of 0.1² / (1 + ε) over six channels.
    EXPECT_NEAR(error.relMse, 0.5 * 0.01 / (1.0 + 0.0025), 1e-6);
    EXPECT_NEAR(error.rmse, std::sqrt(0.005), 1e-6);
    EXPECT_NEAR(error.luminanceRatio, 1.1, 1e-6);
    // Off by 0.1 against a tolerance of 0.1 · 1 + 0.01 · 0.5 = 0.105: not off.
    EXPECT_EQ(error.shareOff, 0.0);
}

TEST(BenchMetrics, BlackPixelsWithinTheAbsoluteFloorAreNotOff) {
    // Mean reference luminance 0.5: the floor is 0.005 on the black pixel.
    Image reference = uniformImage(2, 1, 0.0f);
    setPixel(reference, 0, 0, 1.0f);
    Image image = reference;
    setPixel(image, 1, 0, 0.004f);
    EXPECT_EQ(compareImages(image, reference).shareOff, 0.0);
    setPixel(image, 1, 0, 0.006f);
    EXPECT_EQ(compareImages(image, reference).shareOff, 0.5);
}

TEST(BenchMetrics, RelativeMetricsDoNotDependOnTheUnitOfRadiance) {
    Image reference = uniformImage(3, 3, 0.2f), image = uniformImage(3, 3, 0.25f);
    setPixel(reference, 1, 1, 0.0f);
    setPixel(image, 2, 0, 0.05f);
    const ImageError small = compareImages(image, reference);
    for (float& v : reference.rgb) v *= 1000.0f;
    for (float& v : image.rgb) v *= 1000.0f;
    const ImageError large = compareImages(image, reference);
    EXPECT_NEAR(large.relMse, small.relMse, 1e-6 * small.relMse);  // float rounding of × 1000
    EXPECT_NEAR(large.luminanceRatio, small.luminanceRatio, 1e-6);
    EXPECT_EQ(large.shareOff, small.shareOff);
    EXPECT_NEAR(large.rmse, 1000.0 * small.rmse, 1e-3 * small.rmse);
}

TEST(BenchMetrics, NonFinitePixelsCountAsOffAndPropagate) {
    const Image reference = uniformImage(2, 2, 1.0f);
    Image image = reference;
    image.pixel(0, 0)[1] = std::numeric_limits<float>::quiet_NaN();
    const ImageError error = compareImages(image, reference);
    EXPECT_EQ(error.shareOff, 0.25);
    EXPECT_TRUE(std::isnan(error.relMse));
}

TEST(BenchMetrics, DifferentSizesAreAnError) {
    EXPECT_THROW(compareImages(uniformImage(2, 2, 1.0f), uniformImage(2, 3, 1.0f)), Error);
}

TEST(BenchMetrics, FullReferenceIsTheSumOfDirectAndIndirect) {
    const Image sum = addImages(uniformImage(2, 2, 0.25f), uniformImage(2, 2, 0.5f));
    for (float v : sum.rgb) EXPECT_EQ(v, 0.75f);
}

TEST(BenchMetrics, TheShadowedRatioCountsOnlyPixelsTheDirectLightMisses) {
    // Four pixels: two lit (direct 1), two in shadow (direct 0 and 0.04, under a tenth of the mean
    // 0.51). The image's indirect light is right where it is lit and half of it in the shadows.
    Image direct = uniformImage(4, 1, 1.0f), reference = uniformImage(4, 1, 0.2f), image = uniformImage(4, 1, 0.2f);
    setPixel(direct, 2, 0, 0.04f);
    setPixel(direct, 3, 0, 0.0f);
    setPixel(reference, 2, 0, 0.3f);
    setPixel(reference, 3, 0, 0.1f);
    setPixel(image, 2, 0, 0.15f);
    setPixel(image, 3, 0, 0.05f);
    EXPECT_NEAR(shadowedLuminanceRatio(image, reference, direct), 0.5, 1e-6);
    // The whole image's ratio hides it: (0.2 + 0.2 + 0.15 + 0.05) / 0.8.
    EXPECT_NEAR(compareImages(image, reference).luminanceRatio, 0.75, 1e-6);
    // A threshold above the lit pixels counts them too.
    EXPECT_NEAR(shadowedLuminanceRatio(image, reference, direct, 2.0), 0.6 / 0.8, 1e-6);
}

TEST(BenchMetrics, AnImageWithoutShadowsHasNoShadowedRatio) {
    const Image lit = uniformImage(3, 3, 1.0f);
    EXPECT_TRUE(std::isnan(shadowedLuminanceRatio(lit, lit, lit)));
    EXPECT_THROW(shadowedLuminanceRatio(uniformImage(2, 2, 1.0f), lit, lit), Error);
}

TEST(ParetoFront, KeepsOnlyPointsNoOtherBeatsOnBothAxes) {
    const std::vector<CostAndError> points = {
        {1.0, 5.0},  // 0: cheapest
        {2.0, 3.0},  // 1
        {3.0, 4.0},  // 2: beaten by 1
        {4.0, 1.0},  // 3
        {2.0, 3.0},  // 4: duplicate of 1, not kept twice
        {5.0, 1.0},  // 5: as good as 3 but dearer
        {4.0, 2.0},  // 6: as dear as 3 but worse
    };
    EXPECT_EQ(paretoFront(points), (std::vector<size_t>{0, 1, 3}));
}

TEST(ParetoFront, IgnoresNonFinitePointsAndHandlesEmptyInput) {
    EXPECT_TRUE(paretoFront({}).empty());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(paretoFront({{1.0, nan}, {2.0, 1.0}, {nan, 0.1}}), (std::vector<size_t>{1}));
}

TEST(SvgPlot, DrawsEveryPointTheFrontAndEscapesLabels) {
    const std::string svg = plotErrorAgainstTime({{"a<b", 10.0, 0.1, true, ""},
                                                  {"c", 100.0, 0.01, true, "quality"},
                                                  {"d", 50.0, 0.5, false, ""},
                                                  {"skipped", 0.0, 1.0, false, ""}},
                                                 {"title", "x", "y", "note & more"});
    EXPECT_EQ(svg.rfind("<svg", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_NE(svg.find("<polyline"), std::string::npos);
    EXPECT_NE(svg.find("a&lt;b"), std::string::npos);
    EXPECT_NE(svg.find("note &amp; more"), std::string::npos);
    EXPECT_NE(svg.find("2 quality"), std::string::npos);        // a preset is labelled with its name
    EXPECT_NE(svg.find("2  c  (quality)"), std::string::npos);  // and so is its line in the key
    EXPECT_EQ(svg.find("skipped"), std::string::npos);          // x = 0 has no place on a log axis
    size_t circles = 0;
    for (size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
    EXPECT_EQ(circles, 3u + 3u);  // three points and the legend's three
}

// The key's long labels and the notes under it lie inside the canvas: each left-anchored text's
// start plus 0.6 em a character (12 px sans-serif) is within the SVG's width. The 0.6 em is the
// test's own bound, not the plot's estimate.
TEST(SvgPlot, KeyAndItsNotesFitInsideTheCanvas) {
    const std::string longLabel = "v128 c16 a120 s0.25 aniso bconv ss4 sm16384 d4 and then some more";
    const std::string svg =
        plotErrorAgainstTime({{longLabel, 10.0, 0.1, true, "quality"}, {"v32 c1", 20.0, 0.2, false, ""}},
                             {"title", "x", "y", "note", {"labels: v64 = 64³ voxels, c6 = 6 diffuse cones, and more"}});
    // (Parsed by hand: std::regex trips GCC 12's -Wmaybe-uninitialized in the sanitizer build.)
    auto number = [&](size_t tag, size_t tagEnd, const std::string& name) {
        const size_t at = svg.find(" " + name + "=\"", tag);
        EXPECT_LT(at, tagEnd) << name << " missing in " << svg.substr(tag, tagEnd - tag);
        return at < tagEnd ? std::stod(svg.substr(at + name.size() + 3)) : 0.0;
    };
    const size_t svgTag = svg.find("<svg ");
    ASSERT_NE(svgTag, std::string::npos);
    const size_t svgTagEnd = svg.find('>', svgTag);
    const double width = number(svgTag, svgTagEnd, "width"), height = number(svgTag, svgTagEnd, "height");
    size_t checked = 0;
    bool sawNote = false;
    for (size_t tag = svg.find("<text "); tag != std::string::npos; tag = svg.find("<text ", tag + 1)) {
        const size_t tagEnd = svg.find('>', tag), close = svg.find("</text>", tag);
        ASSERT_NE(close, std::string::npos);
        const std::string attributes = svg.substr(tag, tagEnd - tag);
        const std::string content = svg.substr(tagEnd + 1, close - tagEnd - 1);
        if (attributes.find("text-anchor") != std::string::npos) continue;  // centred or right-aligned
        if (content.find('<') != std::string::npos) continue;
        size_t characters = 0;
        for (unsigned char c : content) characters += (c & 0xC0) != 0x80;
        const double bold = attributes.find("bold") != std::string::npos ? 1.1 : 1.0;
        EXPECT_LE(number(tag, tagEnd, "x") + 12.0 * 0.6 * bold * double(characters), width) << content;
        EXPECT_LE(number(tag, tagEnd, "y"), height) << content;
        sawNote = sawNote || content.find("v64 = 64³ voxels") != std::string::npos;
        ++checked;
    }
    EXPECT_GE(checked, 4u);  // the key's title, its two lines and the note at least
    EXPECT_TRUE(sawNote) << "the key's notes are not drawn";
}

}  // namespace
}  // namespace vct::bench
