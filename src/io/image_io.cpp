#include "io/image_io.h"

#include <stb/stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "error.h"
#include "io/display_transform.h"
#include "io/output_paths.h"
#include "io/temporary_files.h"

namespace vct {

static_assert(std::endian::native == std::endian::little, "PFM writing assumes a little-endian host");

void writeFileAtomically(const std::string& path, const std::string& bytes) { writeFilesAtomically({{path, bytes}}); }

std::string pfmBytes(const Image& image) {
    std::string bytes = "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
    const size_t rowFloats = size_t(image.width) * 3;
    for (uint32_t row = 0; row < image.height; ++row) {
        const float* source = image.rgb.data() + size_t(image.height - 1 - row) * rowFloats;  // bottom row first
        bytes.append(reinterpret_cast<const char*>(source), rowFloats * sizeof(float));
    }
    return bytes;
}

void writePfm(const std::string& path, const Image& image) { writeFileAtomically(path, pfmBytes(image)); }

Image readPfm(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open '" + path + "'");
    std::string magic;
    double scale = 0.0;
    Image image;
    in >> magic >> image.width >> image.height >> scale;
    in.get();  // the single whitespace character after the scale
    if (!in || magic != "PF" || image.width == 0 || image.height == 0 || image.width > 65536 || image.height > 65536)
        throw Error("'" + path + "' is not an RGB PFM file");
    if (scale > 0.0) throw Error("'" + path + "' is a big-endian PFM, which is not supported");
    const size_t rowFloats = size_t(image.width) * 3;
    image.rgb.resize(rowFloats * image.height);
    for (uint32_t row = 0; row < image.height; ++row) {
        float* target = image.rgb.data() + size_t(image.height - 1 - row) * rowFloats;
        in.read(reinterpret_cast<char*>(target), std::streamsize(rowFloats * sizeof(float)));
    }
    if (!in) throw Error("'" + path + "' is truncated");
    return image;
}

void writePng(const std::string& path, const Image& image, const DisplayTransform& display) {
    std::vector<uint8_t> pixels(size_t(image.width) * image.height * 3);
    auto finite = [](float value) { return std::isfinite(value) ? value : 0.0f; };
    for (size_t i = 0; i + 2 < pixels.size(); i += 3) {
        const glm::vec3 radiance(finite(image.rgb[i]), finite(image.rgb[i + 1]), finite(image.rgb[i + 2]));
        const glm::vec3 mapped = glsl::toneMap(radiance * display.exposure, uint32_t(display.curve));
        for (int c = 0; c < 3; ++c) pixels[i + c] = uint8_t(std::lround(255.0f * glsl::encodeSrgb(mapped[c])));
    }
    std::string bytes;
    auto append = [](void* context, void* data, int size) {
        static_cast<std::string*>(context)->append(static_cast<const char*>(data), size_t(size));
    };
    if (!stbi_write_png_to_func(append, &bytes, int(image.width), int(image.height), 3, pixels.data(),
                                int(image.width * 3)))
        throw Error("cannot encode PNG for '" + path + "'");
    writeFileAtomically(path, bytes);
}

void writeImage(const std::string& path, const Image& image, const DisplayTransform& display) {
    const size_t nonFinite =
        size_t(std::count_if(image.rgb.begin(), image.rgb.end(), [](float value) { return !std::isfinite(value); }));
    if (nonFinite > 0)
        throw Error("not writing '" + path + "': the image holds " + std::to_string(nonFinite) +
                    " values that are not finite numbers (NaN or infinity)");
    if (endsWithIgnoringCase(path, ".pfm")) return writePfm(path, image);
    if (endsWithIgnoringCase(path, ".png")) return writePng(path, image, display);
    throw Error("cannot write '" + path + "': the output must end in .pfm or .png");
}

void writeImage(const std::string& path, const Image& image) { writeImage(path, image, DisplayTransform{}); }

}  // namespace vct
