// Checks on a glTF file's raw bytes and JSON, made before tinygltf parses it: what tinygltf would
// mishandle (recursing into deep nesting, wrapping a large index into a negative int, taking a GLB
// of any version) is refused here, with the file's own values in the sentence.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vct {

// JSON nested deeper than this is refused before any parser sees it: tinygltf converts nested
// values recursively, and about 20 000 levels (in `extras`, say) overflow the stack, where 10 000
// still load. Real glTF files nest a few dozen levels.
inline constexpr size_t kMaxJsonDepth = 1000;

// Throws vct::Error naming `path` and the byte where `text` nests deeper than kMaxJsonDepth.
void checkJsonNesting(const std::string& text, const std::string& path);

// Throws vct::Error "PATH: nodes[0].mesh is 2147483648, outside the 32-bit range..." for an index
// or enum that tinygltf would wrap into a negative int. Numbers it keeps in doubles or 64-bit sizes
// (positions, min/max, byte offsets, lengths, counts), `extras` and extensions the loader does not
// read are not checked.
void checkIntegerRanges(const nlohmann::json& document, const std::string& path);

// A .glb starts with "glTF", a version and a length; throws vct::Error naming `path` for any version
// but 2, or for a BIN chunk that says it holds more than the file has after its header.
void checkGlbContainer(const std::vector<uint8_t>& bytes, const std::string& path);

}  // namespace vct
