// Image files: PFM is the measured output, so its layout is checked byte by byte.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

#include "error.h"
#include "io/display_transform.h"
#include "io/image_io.h"

namespace {

std::string temporaryPath(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("vct_image_io_" + name)).string();
}

vct::Image twoByTwo() {
    vct::Image image;
    image.width = 2;
    image.height = 2;
    image.rgb = {1, 2, 3, 4,  5,  6,    // top row
                 7, 8, 9, 10, 11, 12};  // bottom row
    return image;
}

TEST(ImageIo, PfmIsLittleEndianWithBottomRowFirst) {
    const std::string path = temporaryPath("layout.pfm");
    vct::writePfm(path, twoByTwo());
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string header = "PF\n2 2\n-1.0\n";
    ASSERT_EQ(bytes.substr(0, header.size()), header);
    ASSERT_EQ(bytes.size(), header.size() + 12 * sizeof(float));
    float first = 0.0f;
    std::memcpy(&first, bytes.data() + header.size(), sizeof(float));
    EXPECT_EQ(first, 7.0f) << "the first stored row must be the bottom row";
    std::remove(path.c_str());
}

TEST(ImageIo, PfmRoundTripsExactly) {
    const std::string path = temporaryPath("roundtrip.pfm");
    const vct::Image original = twoByTwo();
    vct::writePfm(path, original);
    const vct::Image read = vct::readPfm(path);
    EXPECT_EQ(read.width, 2u);
    EXPECT_EQ(read.height, 2u);
    EXPECT_EQ(read.rgb, original.rgb);
    std::remove(path.c_str());
}

TEST(ImageIo, FailedWriteLeavesThePreviousFileIntact) {
    const std::string path = temporaryPath("keep.pfm");
    vct::writePfm(path, twoByTwo());
    EXPECT_THROW(vct::writeImage(path + ".exr", twoByTwo()), vct::Error);  // unsupported: nothing written
    EXPECT_THROW(vct::writePfm("/nonexistent-folder/x.pfm", twoByTwo()), vct::Error);
    EXPECT_EQ(vct::readPfm(path).rgb, twoByTwo().rgb);
    std::remove(path.c_str());
}

TEST(ImageIo, PngIsWrittenWithSignature) {
    const std::string path = temporaryPath("picture.png");
    vct::writeImage(path, twoByTwo(), vct::DisplayTransform{0.5f, vct::ToneCurve::Aces});
    std::ifstream in(path, std::ios::binary);
    char signature[8] = {};
    in.read(signature, 8);
    EXPECT_EQ(std::memcmp(signature, "\x89PNG\r\n\x1a\n", 8), 0);
    std::remove(path.c_str());
}

TEST(ImageIo, TruncatedPfmIsRefused) {
    const std::string path = temporaryPath("truncated.pfm");
    {
        std::ofstream out(path, std::ios::binary);
        out << "PF\n4 4\n-1.0\n"
            << "abc";
    }
    EXPECT_THROW(vct::readPfm(path), vct::Error);
    std::remove(path.c_str());
}

TEST(ImageIo, ImageWithNonFiniteValuesIsRefusedAndNothingIsWritten) {
    for (const char* name : {"non-finite.pfm", "non-finite.png"}) {
        const std::string path = temporaryPath(name);
        std::filesystem::remove(path);
        vct::Image image = twoByTwo();
        image.rgb[4] = std::numeric_limits<float>::quiet_NaN();
        image.rgb[7] = std::numeric_limits<float>::infinity();
        try {
            vct::writeImage(path, image);
            ADD_FAILURE() << name << " was written";
        } catch (const vct::Error& error) {
            EXPECT_NE(std::string(error.what()).find("the image holds 2 values that are not finite numbers"),
                      std::string::npos)
                << error.what();
        }
        EXPECT_FALSE(std::filesystem::exists(path)) << name;
    }
}

}  // namespace
