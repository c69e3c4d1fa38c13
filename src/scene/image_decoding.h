#pragma once

// Decoding a glTF texture's image: PNG or JPEG, the two formats glTF 2.0 §3.8.3 allows, by libpng
// and libjpeg-turbo. They replace stb_image for the files a user opens: both are fuzzed
// continuously by their projects, where stb_image 2.27 (Debian 12's) reads out of bounds on a JPEG
// with a corrupt Huffman table and decodes formats glTF does not allow (GIF, PSD, TGA...).
//
// As glTF says, an image's colour space information (gAMA, iCCP, sRGB chunks, ICC profiles) is
// ignored: the bytes are returned as stored, 16-bit channels reduced to their high byte.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace vct {

struct ImageSize {
    int width = 0;
    int height = 0;
};

// The width and height its header gives, without decoding the pixels; "" on success, else why
// not ("not a PNG or JPEG image", "a corrupt PNG: ...").
std::string readImageSize(const uint8_t* bytes, size_t size, ImageSize& imageSize);

// The pixels as RGBA8, rows top to bottom, alpha 255 where the image has none; "" on success, else why not.
std::string decodeImageRgba8(const uint8_t* bytes, size_t size, ImageSize& imageSize, std::vector<uint8_t>& rgba8);

}  // namespace vct
