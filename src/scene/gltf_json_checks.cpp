#include "scene/gltf_json_checks.h"

#include <climits>
#include <cstring>
#include <nlohmann/json.hpp>

#include "error.h"

namespace vct {

void checkJsonNesting(const std::string& text, const std::string& path) {
    size_t depth = 0;
    bool inString = false, escaped = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            if (escaped) escaped = false;
            else if (c == '\\') escaped = true;
            else if (c == '"') inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kMaxJsonDepth)
                throw Error(path + ": the JSON nests more than " + std::to_string(kMaxJsonDepth) +
                            " levels deep (at byte " + std::to_string(i) + "), more than this loader accepts");
        } else if ((c == ']' || c == '}') && depth > 0) {
            --depth;
        }
    }
}

namespace {

// Members tinygltf reads into 64-bit sizes, not ints.
bool isSizeMember(const std::string& key) {
    return key == "byteOffset" || key == "byteLength" || key == "count" || key == "byteStride";
}

void checkIntegers(const nlohmann::json& value, const std::string& jsonPath, const std::string& path) {
    if (value.is_number_integer()) {
        const bool fits = value.is_number_unsigned() ? value.get<uint64_t>() <= uint64_t(INT_MAX)
                                                     : value.get<int64_t>() >= int64_t(INT_MIN);
        if (!fits)
            throw Error(path + ": " + jsonPath + " is " + value.dump() +
                        ", outside the 32-bit range this loader reads indices and enums in (" +
                        std::to_string(INT_MIN) + " to " + std::to_string(INT_MAX) + ")");
    } else if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i)
            checkIntegers(value[i], jsonPath + "[" + std::to_string(i) + "]", path);
    } else if (value.is_object()) {
        for (const auto& [key, member] : value.items()) {
            if (key == "extras" || isSizeMember(key)) continue;
            if (jsonPath.size() >= 10 && jsonPath.compare(jsonPath.size() - 10, 10, "extensions") == 0 &&
                key != "KHR_lights_punctual")
                continue;  // an extension the loader does not read may hold any number
            checkIntegers(member, jsonPath.empty() ? key : jsonPath + "." + key, path);
        }
    }
}

}  // namespace

void checkIntegerRanges(const nlohmann::json& document, const std::string& path) { checkIntegers(document, "", path); }

void checkGlbVersion(const std::vector<uint8_t>& bytes, const std::string& path) {
    if (bytes.size() < 8) return;  // tinygltf reports the truncated header
    uint32_t version = 0;
    std::memcpy(&version, bytes.data() + 4, 4);  // little-endian, as the host (image_io.cpp asserts it)
    if (version != 2)
        throw Error(path + ": a binary glTF (GLB) of version " + std::to_string(version) +
                    "; only version 2 is supported");
}

}  // namespace vct
