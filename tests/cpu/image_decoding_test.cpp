// The texture decoder (src/scene/image_decoding.h): glTF's two formats to RGBA8 as stored.
#include "scene/image_decoding.h"

#include <gtest/gtest.h>
#include <turbojpeg.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "gltf_test_helpers.h"

namespace vct {
namespace {

const uint8_t* bytesOf(const std::string& text) { return reinterpret_cast<const uint8_t*>(text.data()); }

std::string decodes(const std::string& file, ImageSize& size, std::vector<uint8_t>& rgba8) {
    return decodeImageRgba8(bytesOf(file), file.size(), size, rgba8);
}

TEST(ImageDecoding, EveryPngLayoutBecomesRgba8AsStored) {
    // One pixel (200, 100, 50, 150) in each colour type and depth; 16-bit samples keep their high byte.
    struct Layout {
        int channels;
        std::vector<uint16_t> samples8;
        std::vector<uint8_t> expected;
    };
    const std::vector<Layout> layouts = {
        {1, {200}, {200, 200, 200, 255}},
        {2, {200, 150}, {200, 200, 200, 150}},
        {3, {200, 100, 50}, {200, 100, 50, 255}},
        {4, {200, 100, 50, 150}, {200, 100, 50, 150}},
    };
    for (const Layout& layout : layouts)
        for (int depth : {8, 16}) {
            std::vector<uint16_t> samples = layout.samples8;
            if (depth == 16)
                for (uint16_t& sample : samples) sample = uint16_t(sample << 8 | 0x7F);
            ImageSize size;
            std::vector<uint8_t> rgba8;
            EXPECT_EQ(decodes(test::encodePng(1, 1, layout.channels, depth, samples), size, rgba8), "");
            EXPECT_EQ(size.width, 1);
            EXPECT_EQ(size.height, 1);
            EXPECT_EQ(rgba8, layout.expected) << layout.channels << " channels of " << depth << " bits";
        }
}

TEST(ImageDecoding, APngsGammaIsIgnoredAsGltfSays) {
    // glTF 2.0 §3.8.3: colour space information in the image is ignored. A gAMA of 1.0 after the
    // header would have libpng's gamma handling re-encode the samples; they come back as stored.
    std::string png = test::encodePng(2, 1, 3, 8, {10, 20, 30, 128, 64, 32});
    png.insert(8 + 25, test::pngChunk("gAMA", test::bigEndian32(100000)));  // 1.0, after the signature and IHDR
    ImageSize size;
    std::vector<uint8_t> rgba8;
    ASSERT_EQ(decodes(png, size, rgba8), "");
    EXPECT_EQ(rgba8, (std::vector<uint8_t>{10, 20, 30, 255, 128, 64, 32, 255}));
}

TEST(ImageDecoding, AJpegDecodesToItsColours) {
    // A 16×16 JPEG of one colour at quality 95: every pixel within a few levels of it.
    const std::vector<uint8_t> colour = {200, 100, 50};
    std::vector<uint8_t> pixels;
    for (int i = 0; i < 16 * 16; ++i) pixels.insert(pixels.end(), colour.begin(), colour.end());
    tjhandle encoder = tjInitCompress();
    ASSERT_NE(encoder, nullptr);
    unsigned char* jpeg = nullptr;
    unsigned long jpegBytes = 0;
    ASSERT_EQ(tjCompress2(encoder, pixels.data(), 16, 0, 16, TJPF_RGB, &jpeg, &jpegBytes, TJSAMP_444, 95, 0), 0);
    const std::string file(reinterpret_cast<const char*>(jpeg), jpegBytes);
    tjFree(jpeg);
    tjDestroy(encoder);

    ImageSize size;
    EXPECT_EQ(readImageSize(bytesOf(file), file.size(), size), "");
    EXPECT_EQ(size.width, 16);
    EXPECT_EQ(size.height, 16);
    std::vector<uint8_t> rgba8;
    ASSERT_EQ(decodes(file, size, rgba8), "");
    ASSERT_EQ(rgba8.size(), 16u * 16 * 4);
    for (size_t i = 0; i < rgba8.size(); i += 4) {
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgba8[i + c], colour[c], 3) << "pixel " << i / 4;
        EXPECT_EQ(rgba8[i + 3], 255);
    }
}

TEST(ImageDecoding, FormatsGltfDoesNotAllowAreRefused) {
    ImageSize size;
    std::vector<uint8_t> rgba8;
    for (const std::string& file : {std::string("GIF89a\1\0\1\0\0\0\0;"), std::string("BM\0\0\0\0"), std::string()})
        EXPECT_EQ(decodes(file, size, rgba8), "not a PNG or JPEG image, the formats glTF allows");
}

TEST(ImageDecoding, ACutPngIsCorruptAndItsHeaderStillReads) {
    const std::string png = test::encodePng(4, 4, 4, 8, std::vector<uint16_t>(64, 7));
    const std::string cut = png.substr(0, png.find("IDAT") + 10);
    ImageSize size;
    EXPECT_EQ(readImageSize(bytesOf(cut), cut.size(), size), "");
    EXPECT_EQ(size.width, 4);
    std::vector<uint8_t> rgba8;
    EXPECT_EQ(decodes(cut, size, rgba8), "a corrupt PNG: the data ends inside the image");
    EXPECT_NE(decodes(png.substr(0, 20), size, rgba8).find("a corrupt PNG: "), std::string::npos);
}

}  // namespace
}  // namespace vct
