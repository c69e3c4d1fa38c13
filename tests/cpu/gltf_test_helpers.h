// Small glTF files written by the tests themselves, so each test shows the input it specifies.
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

namespace vct::test {

// Each component of `actual` within `tolerance` of `expected`'s.
inline void expectNear(const glm::vec3& actual, const glm::vec3& expected, float tolerance = 1e-5f) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

namespace fs = std::filesystem;
using nlohmann::json;

// A fresh folder under the system's temporary folder, removed with everything in it at the end.
struct TempFolder {
    fs::path path;
    TempFolder() {
        std::string pattern = (fs::temp_directory_path() / "vct-gltf-XXXXXX").string();
        path = mkdtemp(pattern.data());
    }
    ~TempFolder() {
        std::error_code ignored;
        fs::remove_all(path, ignored);
    }
    fs::path write(const std::string& name, const std::string& bytes) const {
        const fs::path file = path / name;
        fs::create_directories(file.parent_path());
        std::ofstream(file, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
        return file;
    }
};

inline std::string base64(const std::string& bytes) {
    static const char* alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t group = uint32_t(uint8_t(bytes[i])) << 16;
        if (i + 1 < bytes.size()) group |= uint32_t(uint8_t(bytes[i + 1])) << 8;
        if (i + 2 < bytes.size()) group |= uint32_t(uint8_t(bytes[i + 2]));
        out += alphabet[(group >> 18) & 63];
        out += alphabet[(group >> 12) & 63];
        out += i + 1 < bytes.size() ? alphabet[(group >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? alphabet[group & 63] : '=';
    }
    return out;
}

// The CRC-32 a PNG chunk ends with, of its type and data (PNG specification §5.5).
inline uint32_t pngCrc32(const std::string& typeAndData) {
    uint32_t crc = 0xFFFFFFFFu;
    for (unsigned char byte : typeAndData) {
        crc ^= byte;
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

inline std::string bigEndian32(uint32_t value) {
    return std::string{char(value >> 24), char(value >> 16), char(value >> 8), char(value)};
}

// A PNG chunk: its length, type, data and CRC.
inline std::string pngChunk(const std::string& type, const std::string& data) {
    return bigEndian32(uint32_t(data.size())) + type + data + bigEndian32(pngCrc32(type + data));
}

// A PNG with stored (uncompressed) deflate blocks: enough to test 8- and 16-bit decoding.
// `samples` holds width × height × channels values (big-endian when 16-bit, as PNG stores them).
inline std::string encodePng(uint32_t width, uint32_t height, int channels, int bitDepth,
                             const std::vector<uint16_t>& samples) {
    std::string raw;  // filter byte 0 then the samples of each row
    for (uint32_t y = 0; y < height; ++y) {
        raw += '\0';
        for (uint32_t i = 0; i < width * uint32_t(channels); ++i) {
            const uint16_t sample = samples[y * width * uint32_t(channels) + i];
            if (bitDepth == 16) raw += char(sample >> 8);
            raw += char(sample & 0xFF);
        }
    }
    std::string zlib = "\x78\x01";
    for (size_t offset = 0; offset < raw.size() || offset == 0; offset += 65535) {
        const size_t length = std::min<size_t>(65535, raw.size() - offset);
        const bool last = offset + length >= raw.size();
        zlib += char(last ? 1 : 0);
        zlib += char(length & 0xFF);
        zlib += char(length >> 8);
        zlib += char(~length & 0xFF);
        zlib += char((~length >> 8) & 0xFF);
        zlib += raw.substr(offset, length);
        if (last) break;
    }
    uint32_t a = 1, b = 0;  // Adler-32
    for (unsigned char byte : raw) {
        a = (a + byte) % 65521;
        b = (b + a) % 65521;
    }
    zlib += bigEndian32((b << 16) | a);
    const char colorType = "\0\4\2\6"[channels - 1];  // grey, grey + alpha, RGB, RGBA
    const std::string header =
        bigEndian32(width) + bigEndian32(height) + char(bitDepth) + colorType + std::string(3, '\0');
    return std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", header) + pngChunk("IDAT", zlib) +
           pngChunk("IEND", "");
}

// Builds a glTF document: JSON plus one binary buffer that the write functions place in a .bin
// file, a data: URI or a .glb's BIN chunk. Tests may edit `document` directly for hostile cases.
struct GltfBuilder {
    json document = {{"asset", {{"version", "2.0"}}}};
    std::string bin;

    int append(const char* list, json value) {
        json& array = document[list];
        if (array.is_null()) array = json::array();
        array.push_back(std::move(value));
        return int(array.size()) - 1;
    }

    int addBufferView(const void* data, size_t bytes, size_t stride = 0) {
        while (bin.size() % 4) bin += '\0';
        json view = {{"buffer", 0}, {"byteOffset", bin.size()}, {"byteLength", bytes}};
        if (stride) view["byteStride"] = stride;
        bin.append(static_cast<const char*>(data), bytes);
        return append("bufferViews", view);
    }

    template <typename T>
    int addAccessor(const std::vector<T>& values, int componentType, const char* type, size_t count,
                    bool normalized = false) {
        const int view = addBufferView(values.data(), values.size() * sizeof(T));
        json accessor = {{"bufferView", view}, {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) accessor["normalized"] = true;
        return append("accessors", accessor);
    }

    int addVec3(const std::vector<glm::vec3>& values) {
        std::vector<float> flat;
        for (const glm::vec3& v : values) flat.insert(flat.end(), {v.x, v.y, v.z});
        return addAccessor(flat, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC3", values.size());
    }

    int addVec4(const std::vector<glm::vec4>& values) {
        std::vector<float> flat;
        for (const glm::vec4& v : values) flat.insert(flat.end(), {v.x, v.y, v.z, v.w});
        return addAccessor(flat, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC4", values.size());
    }

    int addVec2(const std::vector<glm::vec2>& values) {
        std::vector<float> flat;
        for (const glm::vec2& v : values) flat.insert(flat.end(), {v.x, v.y});
        return addAccessor(flat, TINYGLTF_COMPONENT_TYPE_FLOAT, "VEC2", values.size());
    }

    int addIndices(const std::vector<uint32_t>& indices, int componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT) {
        if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
            return addAccessor(std::vector<uint8_t>(indices.begin(), indices.end()), componentType, "SCALAR",
                               indices.size());
        if (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT)
            return addAccessor(std::vector<uint16_t>(indices.begin(), indices.end()), componentType, "SCALAR",
                               indices.size());
        return addAccessor(indices, componentType, "SCALAR", indices.size());
    }

    // A mesh of one primitive; `attributes` maps names to accessors, e.g. {{"POSITION", 0}}.
    int addMesh(const json& attributes, int indices = -1, int material = -1, int mode = -1) {
        json primitive = {{"attributes", attributes}};
        if (indices >= 0) primitive["indices"] = indices;
        if (material >= 0) primitive["material"] = material;
        if (mode >= 0) primitive["mode"] = mode;
        return append("meshes", {{"primitives", json::array({primitive})}});
    }

    int addNode(const json& node) { return append("nodes", node); }

    void setScene(const std::vector<int>& roots) {
        document["scenes"] = json::array({{{"nodes", roots}}});
        document["scene"] = 0;
    }

    enum class BufferStorage { File, DataUri };

    // Writes NAME.gltf (and NAME.bin beside it unless the buffer is a data: URI).
    fs::path writeGltf(const TempFolder& folder, const std::string& name, BufferStorage storage = BufferStorage::File) {
        json copy = document;
        if (!bin.empty()) {
            const std::string uri = storage == BufferStorage::DataUri
                                        ? "data:application/octet-stream;base64," + base64(bin)
                                        : name + ".bin";
            copy["buffers"] = json::array({{{"uri", uri}, {"byteLength", bin.size()}}});
            if (storage == BufferStorage::File) folder.write(name + ".bin", bin);
        }
        return folder.write(name + ".gltf", copy.dump());
    }

    // Writes NAME.glb: the JSON chunk and the buffer as the BIN chunk.
    fs::path writeGlb(const TempFolder& folder, const std::string& name) {
        json copy = document;
        std::string binary = bin;
        while (binary.size() % 4) binary += '\0';
        if (!bin.empty()) copy["buffers"] = json::array({{{"byteLength", bin.size()}}});
        std::string text = copy.dump();
        while (text.size() % 4) text += ' ';
        auto le32 = [](uint32_t value) {
            std::string out(4, '\0');
            std::memcpy(out.data(), &value, 4);
            return out;
        };
        std::string glb = "glTF" + le32(2) + le32(0) + le32(uint32_t(text.size())) + "JSON" + text;
        if (!binary.empty()) glb += le32(uint32_t(binary.size())) + std::string("BIN\0", 4) + binary;
        const std::string length = le32(uint32_t(glb.size()));
        glb.replace(8, 4, length);
        return folder.write(name + ".glb", glb);
    }
};

// One triangle in the z = 0 plane facing +Z: (0,0,0), (1,0,0), (0,1,0), on node 0 of scene 0.
inline GltfBuilder triangleScene() {
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    const int normals = gltf.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int mesh = gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}});
    gltf.setScene({gltf.addNode({{"mesh", mesh}})});
    return gltf;
}

// A 2 × 2 quad in the z = 0 plane facing +Z (x, y ∈ [−1, 1]) with u = (x + 1)/2 and v = (1 − y)/2,
// so a texture's left column lies at x = −1 and its top row at y = 1; material 0, which the test
// fills in; and a camera at z = 2 looking at it, whose view the quad fills (30° vertical field).
inline GltfBuilder quadFacingCamera() {
    GltfBuilder gltf;
    const int positions = gltf.addVec3({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}});
    const int normals = gltf.addVec3({{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}});
    const int uvs = gltf.addVec2({{0, 1}, {1, 1}, {1, 0}, {0, 0}});
    const int indices = gltf.addIndices({0, 1, 2, 0, 2, 3});
    const int mesh =
        gltf.addMesh({{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}}, indices, /*material=*/0);
    gltf.document["materials"] = json::array({json::object()});
    gltf.document["cameras"] = json::array(
        {{{"type", "perspective"}, {"perspective", {{"yfov", 0.5235988}, {"znear", 0.1}, {"aspectRatio", 1.0}}}}});
    gltf.setScene({gltf.addNode({{"mesh", mesh}}), gltf.addNode({{"camera", 0}, {"translation", {0, 0, 2}}})});
    return gltf;
}

// An RGBA8 PNG `width` × 1 whose left half is black and right half white, as a data: URI.
inline std::string halfBlackHalfWhitePngUri(uint32_t width) {
    std::vector<uint16_t> samples;
    for (uint32_t x = 0; x < width; ++x) {
        const uint16_t value = x < width / 2 ? 0 : 255;
        samples.insert(samples.end(), {value, value, value, 255});
    }
    return "data:image/png;base64," + base64(encodePng(width, 1, 4, 8, samples));
}

}  // namespace vct::test
