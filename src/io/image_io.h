// Image files: PFM for linear radiance, PNG for people.
//
// Images in memory are RGB float, rows top-to-bottom (row 0 is the top of the picture).
// Files are written to a temporary file beside the target and renamed, so an interrupted
// run never leaves a truncated file or clobbers a good one, nor (temporary_files.h) a temporary file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "luminance.h"

namespace vct {

struct Image {
    uint32_t width = 0;
    uint32_t height = 0;
    std::vector<float> rgb;  // width × height × 3, top row first

    float* pixel(uint32_t x, uint32_t y) { return &rgb[(size_t(y) * width + x) * 3]; }
    const float* pixel(uint32_t x, uint32_t y) const { return &rgb[(size_t(y) * width + x) * 3]; }
};

// Rec. 709 luminance of the pixel at `rgb`.
inline double luminance(const float* rgb) { return glsl::luminance(glm::dvec3(rgb[0], rgb[1], rgb[2])); }

// Writes standard PFM: "PF", little-endian (scale −1), rows bottom-to-top.
void writePfm(const std::string& path, const Image& image);
std::string pfmBytes(const Image& image);  // what writePfm writes
Image readPfm(const std::string& path);

struct DisplayTransform;  // io/display_transform.h

// Writes an 8-bit sRGB PNG: radiance × the display's exposure, its tone curve, sRGB encoding.
void writePng(const std::string& path, const Image& image, const DisplayTransform& display);

// Writes PFM or PNG depending on the extension; throws vct::Error for anything else, and, writing
// nothing, for an image holding NaN or infinity (a render gone wrong must not pass for an image).
// A PNG goes through `display`.
void writeImage(const std::string& path, const Image& image, const DisplayTransform& display);
void writeImage(const std::string& path, const Image& image);  // a PNG at exposure 1, PBR Neutral

// Writes `bytes` to `path` through a temporary file and an atomic rename; the temporary file is
// removed on a signal (temporary_files.h).
void writeFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace vct
