#include "scene/gltf_json_checks.h"

#include <algorithm>
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

// Members whose integers tinygltf reads into an int: indices of other entries, and enums. Numbers
// elsewhere (positions, min/max, weights, sizes and offsets, which tinygltf keeps in doubles or
// 64-bit sizes) may be any integer.
bool isIndexMember(const std::string& key) {
    static const char* const keys[] = {"scene",      "nodes",     "children", "mesh",   "camera",
                                       "skin",       "skeleton",  "joints",   "buffer", "bufferView",
                                       "indices",    "material",  "sampler",  "source", "index",
                                       "texCoord",   "input",     "output",   "node",   "light",
                                       "attributes", "targets",   "target",   "mode",   "componentType",
                                       "magFilter",  "minFilter", "wrapS",    "wrapT",  "inverseBindMatrices"};
    for (const char* index : keys)
        if (key == index) return true;
    return false;
}

bool isSizeMember(const std::string& key) {
    return key == "byteOffset" || key == "byteLength" || key == "count" || key == "byteStride";
}

// `key` is the member the value belongs to (for an array's elements, the array's). Integers are
// checked under an index member: itself, an array of indices ("children"), or an object whose members
// are all indices ("attributes", each of "targets").
void checkIntegers(const nlohmann::json& value, const std::string& jsonPath, const std::string& key,
                   const std::string& path) {
    if (value.is_number_integer()) {
        if (!isIndexMember(key)) return;
        const bool fits = value.is_number_unsigned() ? value.get<uint64_t>() <= uint64_t(INT_MAX)
                                                     : value.get<int64_t>() >= int64_t(INT_MIN);
        if (!fits)
            throw Error(path + ": " + jsonPath + " is " + value.dump() +
                        ", outside the 32-bit range this loader reads indices and enums in (" +
                        std::to_string(INT_MIN) + " to " + std::to_string(INT_MAX) + ")");
    } else if (value.is_array()) {
        for (size_t i = 0; i < value.size(); ++i)
            checkIntegers(value[i], jsonPath + "[" + std::to_string(i) + "]", key, path);
    } else if (value.is_object()) {
        const bool attributeMap = key == "attributes" || key == "targets";
        for (const auto& [member, memberValue] : value.items()) {
            if (member == "extras" || isSizeMember(member)) continue;
            if (key == "extensions" && member != "KHR_lights_punctual")
                continue;  // an extension the loader does not read may hold any number
            checkIntegers(memberValue, jsonPath.empty() ? member : jsonPath + "." + member,
                          attributeMap && memberValue.is_number_integer() ? "attributes" : member, path);
        }
    }
}

}  // namespace

void checkIntegerRanges(const nlohmann::json& document, const std::string& path) {
    checkIntegers(document, "", "", path);
}

void checkGlbContainer(const std::vector<uint8_t>& bytes, const std::string& path) {
    if (bytes.size() < 8) return;  // tinygltf reports the truncated header
    auto word = [&](size_t at) {
        uint32_t value = 0;
        std::memcpy(&value, bytes.data() + at, 4);  // little-endian, as the host (image_io.cpp asserts it)
        return value;
    };
    const uint32_t version = word(4);
    if (version != 2)
        throw Error(path + ": a binary glTF (GLB) of version " + std::to_string(version) +
                    "; only version 2 is supported");
    if (bytes.size() < 20) return;
    // tinygltf 2.7.0 checks the BIN chunk's length against the GLB's without the chunk's own 8-byte
    // header, and then copies up to 8 bytes from past the end of the file (tools/fuzz.sh's find,
    // tests/data/fuzz-regressions/glb-bin-chunk-header-uncounted.glb).
    const uint64_t end = std::min<uint64_t>(word(8), bytes.size());
    const uint64_t binChunk = 20 + uint64_t(word(12));  // after the header and the JSON chunk
    if (binChunk + 8 > end) return;                     // no BIN chunk header: tinygltf judges the rest
    const uint64_t binBytes = word(size_t(binChunk));
    if (binChunk + 8 + binBytes > end)
        throw Error(path + ": the GLB's BIN chunk says it holds " + std::to_string(binBytes) + " bytes, but only " +
                    std::to_string(end - binChunk - 8) + " follow its header");
}

}  // namespace vct
