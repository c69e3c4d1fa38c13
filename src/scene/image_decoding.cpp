#include "scene/image_decoding.h"

#include <png.h>
#include <turbojpeg.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>

namespace vct {

namespace {

bool isPng(const uint8_t* bytes, size_t size) { return size >= 8 && png_sig_cmp(bytes, 0, 8) == 0; }

bool isJpeg(const uint8_t* bytes, size_t size) {
    return size >= 3 && bytes[0] == 0xFF && bytes[1] == 0xD8 && bytes[2] == 0xFF;  // SOI, then a marker
}

// ---- PNG. libpng reports an error by longjmp to the last setjmp on its png_struct: each call that
// may fail runs inside a function of its own that holds no C++ object across the jump.

struct PngSource {
    const uint8_t* bytes;
    size_t size;
    size_t read = 0;
    char problem[200] = "";
};

void readPngBytes(png_structp png, png_bytep out, png_size_t length) {
    PngSource& source = *static_cast<PngSource*>(png_get_io_ptr(png));
    if (length > source.size - source.read) png_error(png, "the data ends inside the image");
    std::memcpy(out, source.bytes + source.read, length);
    source.read += length;
}

[[noreturn]] void pngFailed(png_structp png, png_const_charp message) {
    PngSource& source = *static_cast<PngSource*>(png_get_error_ptr(png));
    std::snprintf(source.problem, sizeof source.problem, "%s", message);
    png_longjmp(png, 1);
}

void pngWarned(png_structp, png_const_charp) {}  // an ancillary chunk dropped; decoding goes on

// Reads the header and asks for 8-bit RGBA whatever the image holds (and no gamma correction).
bool readPngHeader(png_structp png, png_infop info) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    const int colorType = png_get_color_type(png, info);
    const bool transparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    if (colorType == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (colorType == PNG_COLOR_TYPE_GRAY && png_get_bit_depth(png, info) < 8) png_set_expand_gray_1_2_4_to_8(png);
    if (transparency) png_set_tRNS_to_alpha(png);
    if (png_get_bit_depth(png, info) == 16) png_set_strip_16(png);
    if (!(colorType & PNG_COLOR_MASK_COLOR)) png_set_gray_to_rgb(png);
    if (!(colorType & PNG_COLOR_MASK_ALPHA) && !transparency) png_set_filler(png, 0xFF, PNG_FILLER_AFTER);
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    return true;
}

bool readPngRows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    return true;
}

uint32_t bigEndian32(const uint8_t* bytes) {
    return uint32_t(bytes[0]) << 24 | uint32_t(bytes[1]) << 16 | uint32_t(bytes[2]) << 8 | uint32_t(bytes[3]);
}

// The size in the PNG's first chunk, IHDR (PNG specification §11.2.2), read without libpng, which
// reads on to the first image data: the budget check needs no more of the file than its header.
std::string readPngSize(const uint8_t* bytes, size_t size, ImageSize& imageSize) {
    if (size < 8 + 8 + 13 || bigEndian32(bytes + 8) != 13 || std::memcmp(bytes + 12, "IHDR", 4) != 0)
        return "a corrupt PNG: it does not start with its header chunk";
    const uint32_t width = bigEndian32(bytes + 16), height = bigEndian32(bytes + 20);
    if (width == 0 || height == 0 || width > PNG_UINT_31_MAX || height > PNG_UINT_31_MAX)
        return "a corrupt PNG: its header gives a size of " + std::to_string(width) + "×" + std::to_string(height);
    imageSize = {int(width), int(height)};
    return "";
}

std::string decodePng(const uint8_t* bytes, size_t size, ImageSize& imageSize, std::vector<uint8_t>* rgba8) {
    if (!rgba8) return readPngSize(bytes, size, imageSize);
    PngSource source{bytes, size};
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &source, pngFailed, pngWarned);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    struct Release {
        png_structp& png;
        png_infop& info;
        ~Release() { png_destroy_read_struct(&png, &info, nullptr); }
    } release{png, info};
    if (!info) return "libpng could not allocate its state";
    png_set_read_fn(png, &source, readPngBytes);
    if (!readPngHeader(png, info)) return std::string("a corrupt PNG: ") + source.problem;
    imageSize = {int(png_get_image_width(png, info)), int(png_get_image_height(png, info))};
    const size_t rowBytes = size_t(imageSize.width) * 4;
    if (png_get_rowbytes(png, info) != rowBytes) return "a PNG libpng cannot turn into 8-bit RGBA";
    rgba8->resize(rowBytes * size_t(imageSize.height));
    std::vector<png_bytep> rows(size_t(imageSize.height));
    for (size_t y = 0; y < rows.size(); ++y) rows[y] = rgba8->data() + y * rowBytes;
    if (!readPngRows(png, rows.data())) return std::string("a corrupt PNG: ") + source.problem;
    return "";
}

// ---- JPEG, through libjpeg-turbo's TurboJPEG interface.

std::string decodeJpeg(const uint8_t* bytes, size_t size, ImageSize& imageSize, std::vector<uint8_t>* rgba8) {
    struct Handle {
        tjhandle handle = tjInitDecompress();
        ~Handle() {
            if (handle) tjDestroy(handle);
        }
    } decompressor;
    if (!decompressor.handle) return "libjpeg-turbo could not start";
    int width = 0, height = 0, subsampling = 0, colorspace = 0;
    if (tjDecompressHeader3(decompressor.handle, bytes, (unsigned long)size, &width, &height, &subsampling,
                            &colorspace) != 0)
        return std::string("a corrupt JPEG: ") + tjGetErrorStr2(decompressor.handle);
    imageSize = {width, height};
    if (!rgba8) return "";
    rgba8->resize(size_t(width) * size_t(height) * 4);
    // TJFLAG_LIMITSCANS: a progressive JPEG of more than 500 scans, a way to make decoding take
    // minutes, is refused. A warning (a truncated or slightly corrupt stream) leaves what it decoded.
    if (tjDecompress2(decompressor.handle, bytes, (unsigned long)size, rgba8->data(), width, 0, height, TJPF_RGBA,
                      TJFLAG_LIMITSCANS) != 0 &&
        tjGetErrorCode(decompressor.handle) != TJERR_WARNING)
        return std::string("a corrupt JPEG: ") + tjGetErrorStr2(decompressor.handle);
    return "";
}

std::string decode(const uint8_t* bytes, size_t size, ImageSize& imageSize, std::vector<uint8_t>* rgba8) {
    if (isPng(bytes, size)) return decodePng(bytes, size, imageSize, rgba8);
    if (isJpeg(bytes, size)) return decodeJpeg(bytes, size, imageSize, rgba8);
    return "not a PNG or JPEG image, the formats glTF allows";
}

}  // namespace

std::string readImageSize(const uint8_t* bytes, size_t size, ImageSize& imageSize) {
    return decode(bytes, size, imageSize, nullptr);
}

std::string decodeImageRgba8(const uint8_t* bytes, size_t size, ImageSize& imageSize, std::vector<uint8_t>& rgba8) {
    return decode(bytes, size, imageSize, &rgba8);
}

}  // namespace vct
