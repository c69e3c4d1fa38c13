// glTF 2.0 (.gltf/.glb) → vct::Scene, in four steps that each finish before the next begins:
//   1. read the scene file and vet every external URI against the file policy (file_policy.h);
//   2. parse with tinygltf, whose file-system callbacks can read only the vetted files and whose
//      image callback decodes the material textures' images (image_decoding.h), turning failures into notes;
//   3. validate the whole model (gltf_validate.h);
//   4. convert: flatten the node hierarchy of the default scene to world space.

#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <tuple>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "error.h"
#include "scene/file_policy.h"
#include "scene/gltf_accessor.h"
#include "scene/gltf_json_checks.h"
#include "scene/gltf_validate.h"
#include "scene/image_decoding.h"
#include "scene/load.h"
#include "scene/tangent_generation.h"

namespace vct {

namespace fs = std::filesystem;

namespace {

// Larger images are refused before decoding, so a hostile header cannot ask for gigabytes.
constexpr int kMaxImageSide = 16384;

std::string at(const std::string& base, size_t index) { return base + "[" + std::to_string(index) + "]"; }

// What the tinygltf callbacks share with the loader.
struct ParseContext {
    FilePolicy policy;
    std::string file;
    // tinygltf asks for "<base dir>/<its own decoding of the URI>"; only these paths exist for it.
    std::map<std::string, fs::path> vettedFiles;
    std::set<int> colorImages;                 // images worth decoding: those of the material textures
    std::map<int, std::string> imageProblems;  // why an image has no pixels
    // Each distinct image (file, buffer range or data URI) is decoded once, by its first entry;
    // later entries naming the same bytes point at that one.
    std::map<std::string, int> firstImageOf;  // what the bytes are → the image entry that decoded them
    std::map<int, int> sameImageAs;           // image entry → the entry holding its pixels
    uint64_t decodedImageBudget = 0;          // SceneBufferLimits::maxDecodedImageBytes
    uint64_t decodedImageBytes = 0;           // RGBA8 bytes of the images decoded (or being decoded) so far
    std::string sceneFolder;
    std::string fatal;  // a problem found inside a callback that must stop the load
    const tinygltf::Model* model = nullptr;
};

// tinygltf 2.7.0's own URI decoding (dlib's urldecode: '+' is a space), reproduced so the
// vetted path is the very string it will ask for.
std::string tinygltfUrlDecode(const std::string& uri) {
    std::string result;
    for (size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            result += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            auto hex = [](char c) -> int {
                if (c >= '0' && c <= '9') return c - '0';
                if (c >= 'a' && c <= 'f') return c - 'a' + 10;
                if (c >= 'A' && c <= 'F') return c - 'A' + 10;
                return 0;
            };
            result += char((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else {
            result += uri[i];
        }
    }
    return result;
}

// tinygltf's JoinPath.
std::string joinPath(const std::string& folder, const std::string& file) {
    if (folder.empty()) return file;
    return folder.back() == '/' ? folder + file : folder + "/" + file;
}

bool fileExists(const std::string& path, void* user) {
    return static_cast<ParseContext*>(user)->vettedFiles.count(path) != 0;
}

std::string expandFilePath(const std::string& path, void*) { return path; }  // no `~` or `$VAR` expansion

bool readWholeFile(std::vector<unsigned char>* bytes, std::string* error, const std::string& path, void* user) {
    const ParseContext& context = *static_cast<ParseContext*>(user);
    const auto vetted = context.vettedFiles.find(path);
    std::string problem = "was not vetted by the file policy";
    if (vetted != context.vettedFiles.end()) {
        // Resolve again: the file may have been swapped for a symlink since it was vetted.
        std::error_code code;
        if (fs::canonical(vetted->second, code) == vetted->second && !code &&
            readRegularFile(vetted->second, context.policy.maxFileBytes, *bytes, problem))
            return true;
    }
    if (error) *error = problem;
    return false;
}

bool refuseWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    if (error) *error = "the loader never writes files";
    return false;
}

// What an image's bytes are, so that entries naming the same ones are decoded once: the file a
// URI resolves to, the buffer range of a bufferView, or a data URI's own bytes.
std::string imageIdentity(const tinygltf::Image& image, const unsigned char* bytes, int size,
                          const ParseContext& context) {
    if (image.bufferView >= 0) {
        const tinygltf::BufferView& view = context.model->bufferViews[size_t(image.bufferView)];
        return "buffer " + std::to_string(view.buffer) + " bytes " + std::to_string(view.byteOffset) + "+" +
               std::to_string(view.byteLength);
    }
    if (!image.uri.empty()) {
        const auto vetted = context.vettedFiles.find(joinPath(context.sceneFolder, tinygltfUrlDecode(image.uri)));
        if (vetted != context.vettedFiles.end()) return "file " + vetted->second.string();
    }
    return "bytes " + std::string(reinterpret_cast<const char*>(bytes), size > 0 ? size_t(size) : 0);
}

// Decodes a material texture's image to RGBA8 (image_decoding.h, 16-bit PNGs reduced to 8 bits). A failure
// is noted for the loader to report as a warning; only a range the file does not hold stops the load.
bool loadImage(tinygltf::Image* image, const int imageIndex, std::string*, std::string*, int, int,
               const unsigned char* bytes, int size, void* user) {
    ParseContext& context = *static_cast<ParseContext*>(user);
    if (image->bufferView >= 0) {
        // tinygltf passes &buffer.data[byteOffset] without checking the range: check it before reading.
        const tinygltf::BufferView& view = context.model->bufferViews[size_t(image->bufferView)];
        const size_t bufferBytes = context.model->buffers[size_t(view.buffer)].data.size();
        if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset ||
            view.byteLength > size_t(INT32_MAX)) {
            context.fatal = context.file + ": " + at("images", size_t(imageIndex)) + ".bufferView: bufferView " +
                            std::to_string(image->bufferView) + " runs past the end of buffer " +
                            std::to_string(view.buffer);
            return false;
        }
    }
    if (!context.colorImages.count(imageIndex)) return true;  // not used by the renderer: not decoded
    const auto [first, isNew] = context.firstImageOf.emplace(imageIdentity(*image, bytes, size, context), imageIndex);
    if (!isNew) {
        context.sameImageAs[imageIndex] = first->second;
        return true;
    }
    const std::string name = image->uri.empty() ? "the embedded image" : "'" + image->uri + "'";
    ImageSize imageSize;
    const std::string unreadable = size > 0 ? readImageSize(bytes, size_t(size), imageSize) : "empty";
    if (!unreadable.empty()) {
        context.imageProblems[imageIndex] = name + " cannot be read: " + unreadable;
        return true;
    }
    const int width = imageSize.width, height = imageSize.height;
    if (width > kMaxImageSide || height > kMaxImageSide) {
        context.imageProblems[imageIndex] = name + " is " + std::to_string(width) + "×" + std::to_string(height) +
                                            ", larger than " + std::to_string(kMaxImageSide) + " on a side";
        return true;
    }
    // The header says what decoding will take: refuse before decoding when the scene's images
    // would exceed the budget (a 65 KB PNG can hold 8192² pixels, 256 MiB decoded).
    const uint64_t decodedBytes = uint64_t(width) * uint64_t(height) * 4;
    if (decodedBytes > context.decodedImageBudget - std::min(context.decodedImageBudget, context.decodedImageBytes)) {
        context.fatal = context.file + ": " + at("images", size_t(imageIndex)) + " (" + name + ", " +
                        std::to_string(width) + "×" + std::to_string(height) + ") would bring the decoded images to " +
                        bytesText(context.decodedImageBytes + decodedBytes) + ", over the budget of " +
                        bytesText(context.decodedImageBudget) + " for one scene's images";
        return false;
    }
    context.decodedImageBytes += decodedBytes;
    std::vector<uint8_t> pixels;
    const std::string undecodable = decodeImageRgba8(bytes, size_t(size), imageSize, pixels);
    if (!undecodable.empty()) {
        context.imageProblems[imageIndex] = name + " cannot be decoded: " + undecodable;
        return true;
    }
    image->width = imageSize.width;
    image->height = imageSize.height;
    image->component = 4;
    image->bits = 8;
    image->pixel_type = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
    image->image = std::move(pixels);
    return true;
}

// The JSON text of a .gltf, or of a .glb's first chunk; empty if the container is malformed
// (tinygltf then reports the problem in its own words).
std::string jsonText(const std::vector<uint8_t>& bytes, bool binary) {
    if (!binary) return std::string(bytes.begin(), bytes.end());
    if (bytes.size() < 20) return {};
    uint32_t chunkLength = 0, chunkType = 0;
    std::memcpy(&chunkLength, bytes.data() + 12, 4);
    std::memcpy(&chunkType, bytes.data() + 16, 4);
    if (chunkType != 0x4E4F534A || chunkLength > bytes.size() - 20) return {};  // "JSON"
    return std::string(bytes.begin() + 20, bytes.begin() + 20 + chunkLength);
}

// The member `key` of a JSON object, or null (a const operator[] on a missing key is undefined).
const nlohmann::json* member(const nlohmann::json* object, const char* key) {
    if (!object || !object->is_object()) return nullptr;
    const auto found = object->find(key);
    return found == object->end() ? nullptr : &*found;
}

// Step 1: applies the file policy to every buffer and image URI before tinygltf sees the file.
// A refused buffer stops the load; a refused image becomes a missing image (a warning).
void vetUris(const nlohmann::json& document, const fs::path& sceneFolder, ParseContext& context) {
    if (!document.is_object()) return;  // tinygltf reports broken JSON with its own message
    auto vet = [&](const char* list, bool required) {
        const auto found = document.find(list);
        if (found == document.end() || !found->is_array()) return;
        for (size_t i = 0; i < found->size(); ++i) {
            const nlohmann::json& entry = (*found)[i];
            const nlohmann::json* uriValue = member(&entry, "uri");
            if (!uriValue || !uriValue->is_string()) continue;
            const std::string uri = uriValue->get<std::string>();
            if (isDataUri(uri)) continue;
            const ResolvedUri resolved = resolveUri(context.policy, sceneFolder, uri);
            if (!resolved.problem.empty()) {
                const std::string problem = "'" + uri + "' " + resolved.problem;
                if (required) throw Error(context.file + ": " + at(list, i) + ".uri: " + problem);
                context.imageProblems[int(i)] = problem;
                continue;
            }
            std::error_code error;
            const uint64_t fileBytes = fs::file_size(resolved.path, error);
            const nlohmann::json* byteLength = member(&entry, "byteLength");
            if (required && !error && byteLength && byteLength->is_number_unsigned() &&
                byteLength->get<uint64_t>() > fileBytes)
                throw Error(context.file + ": " + at(list, i) + ": '" + uri + "' holds " + std::to_string(fileBytes) +
                            " bytes, fewer than its byteLength " + std::to_string(byteLength->get<uint64_t>()));
            context.vettedFiles[joinPath(sceneFolder.string(), tinygltfUrlDecode(uri))] = resolved.path;
        }
    };
    vet("buffers", true);
    vet("images", false);

    // Only the images of the material textures (base colour, emissive, metallic-roughness, normal,
    // occlusion) are decoded; the others are not used.
    const auto materials = document.find("materials");
    const auto textures = document.find("textures");
    if (materials == document.end() || !materials->is_array() || textures == document.end() || !textures->is_array())
        return;
    auto decode = [&](const nlohmann::json* textureInfo) {
        const nlohmann::json* index = member(textureInfo, "index");
        if (!index || !index->is_number_unsigned() || index->get<size_t>() >= textures->size()) return;
        const nlohmann::json* source = member(&(*textures)[index->get<size_t>()], "source");
        if (source && source->is_number_integer()) context.colorImages.insert(source->get<int>());
    };
    for (const nlohmann::json& material : *materials) {
        decode(member(member(&material, "pbrMetallicRoughness"), "baseColorTexture"));
        decode(member(member(&material, "pbrMetallicRoughness"), "metallicRoughnessTexture"));
        decode(member(&material, "normalTexture"));
        decode(member(&material, "emissiveTexture"));
        decode(member(&material, "occlusionTexture"));
    }
}

// Reads the scene file itself: it must be a regular file within the size limit.
std::vector<uint8_t> readSceneFile(const std::string& path, uint64_t maxFileBytes) {
    std::error_code error;
    if (!fs::exists(path, error)) throw Error(path + ": file not found");
    std::vector<uint8_t> bytes;
    std::string problem;
    // tinygltf takes the length as a 32-bit unsigned.
    if (!readRegularFile(path, std::min<uint64_t>(maxFileBytes, UINT32_MAX), bytes, problem))
        throw Error(path + ": the scene file " + problem);
    return bytes;
}

struct Parsed {
    tinygltf::Model model;
    std::map<int, std::string> imageProblems;  // why an image has no pixels
    std::map<int, int> sameImageAs;            // image entry → the entry that decoded the same bytes
};

// Steps 1 and 2.
Parsed parse(const std::string& path, const LoadOptions& options) {
    const std::vector<uint8_t> bytes = readSceneFile(path, options.maxFileBytes);
    const fs::path sceneFolder = fs::canonical(path).parent_path();

    ParseContext context;
    context.file = path;
    context.sceneFolder = sceneFolder.string();
    context.decodedImageBudget = options.bufferLimits.maxDecodedImageBytes;
    context.policy.maxFileBytes = options.maxFileBytes;
    std::error_code error;
    context.policy.root = options.allowedRoot.empty() ? sceneFolder : fs::canonical(options.allowedRoot, error);
    if (error) throw Error(path + ": the allowed folder '" + options.allowedRoot + "' " + error.message());

    const bool binary = bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
    if (binary) checkGlbContainer(bytes, path);
    const std::string json = jsonText(bytes, binary);
    checkJsonNesting(json, path);
    {
        const nlohmann::json document = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
        checkIntegerRanges(document, path);
        vetUris(document, sceneFolder, context);
    }

    Parsed result;
    tinygltf::Model& model = result.model;
    context.model = &model;
    tinygltf::TinyGLTF gltf;
    gltf.SetFsCallbacks({&fileExists, &expandFilePath, &readWholeFile, &refuseWrite, &context});
    gltf.SetImageLoader(&loadImage, &context);
    std::string errors, warnings;
    const bool parsed =
        binary ? gltf.LoadBinaryFromMemory(&model, &errors, &warnings, bytes.data(), unsigned(bytes.size()),
                                           sceneFolder.string())
               : gltf.LoadASCIIFromString(&model, &errors, &warnings, reinterpret_cast<const char*>(bytes.data()),
                                          unsigned(bytes.size()), sceneFolder.string());
    if (!context.fatal.empty()) throw Error(context.fatal);
    if (!parsed) {
        while (!errors.empty() && errors.back() == '\n') errors.pop_back();
        for (size_t newline = errors.find('\n'); newline != std::string::npos; newline = errors.find('\n'))
            errors.replace(newline, 1, "; ");  // one line per message
        throw Error(path +
                    ": not a valid glTF file: " + (errors.empty() ? std::string("tinygltf gave no reason") : errors));
    }
    result.imageProblems = std::move(context.imageProblems);
    result.sameImageAs = std::move(context.sameImageAs);
    return result;
}

// Step 4.
struct Converter {
    const tinygltf::Model& model;
    const std::map<int, std::string>& imageProblems;
    const std::map<int, int>& sameImageAs;
    const LoadOptions& options;
    Scene& scene;
    // (glTF image, sRGB, sampler's wrapS, wrapT, nearest magnification) → Scene::textures index or -1
    std::map<std::tuple<int, bool, TextureWrap, TextureWrap, bool>, int> sceneTextureOfImage;
    int defaultMaterial = -1;
    std::set<uint32_t> warnedNoTexCoord1;  // materials named in a "has no TEXCOORD_1" warning

    void warn(const std::string& path, const std::string& problem) {
        const std::string message = scene.name + ": " + path + ": " + problem;
        if (options.strict) throw Error(message + " (strict loading turns this warning into an error)");
        scene.warnings.push_back(message);
    }

    // What a model looks like without an extension, for those that change its appearance.
    static std::string withoutExtension(const std::string& name) {
        static const std::map<std::string, std::string> effects = {
            {"KHR_materials_transmission", "transmissive surfaces are drawn opaque"},
            {"KHR_materials_volume", "volumes are drawn as opaque surfaces"},
            {"KHR_materials_clearcoat", "the clear coat layer is not drawn"},
            {"KHR_materials_sheen", "the sheen layer is not drawn"},
            {"KHR_materials_ior", "every dielectric has the default index of refraction 1.5"},
            {"KHR_materials_iridescence", "the iridescence is not drawn"},
            {"KHR_materials_anisotropy", "highlights are drawn isotropic"},
            {"KHR_draco_mesh_compression",
             "Draco-compressed meshes are drawn only where the file also holds them "
             "uncompressed"},
            {"EXT_meshopt_compression", "meshopt-compressed data is read from its uncompressed fallback"},
        };
        const auto found = effects.find(name);
        return found == effects.end() ? "" : ": " + found->second;
    }

    // One warning per extension the renderer does not honour: those listed in extensionsUsed and
    // those a material, texture, mesh, node or buffer view names without the list saying so.
    void warnAboutExtensions() {
        std::vector<std::pair<std::string, std::string>> named;  // extension, where first met
        for (size_t i = 0; i < model.extensionsUsed.size(); ++i)
            named.emplace_back(model.extensionsUsed[i], at("extensionsUsed", i));
        auto collect = [&](const tinygltf::ExtensionMap& extensions, const std::string& path) {
            for (const auto& [name, value] : extensions) named.emplace_back(name, path + ".extensions." + name);
        };
        collect(model.extensions, "");
        for (size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& material = model.materials[i];
            const std::string path = at("materials", i);
            collect(material.extensions, path);
            collect(material.pbrMetallicRoughness.baseColorTexture.extensions,
                    path + ".pbrMetallicRoughness.baseColorTexture");
            collect(material.pbrMetallicRoughness.metallicRoughnessTexture.extensions,
                    path + ".pbrMetallicRoughness.metallicRoughnessTexture");
            collect(material.normalTexture.extensions, path + ".normalTexture");
            collect(material.occlusionTexture.extensions, path + ".occlusionTexture");
            collect(material.emissiveTexture.extensions, path + ".emissiveTexture");
        }
        for (size_t i = 0; i < model.textures.size(); ++i) collect(model.textures[i].extensions, at("textures", i));
        for (size_t i = 0; i < model.bufferViews.size(); ++i)
            collect(model.bufferViews[i].extensions, at("bufferViews", i));
        for (size_t i = 0; i < model.nodes.size(); ++i) collect(model.nodes[i].extensions, at("nodes", i));
        for (size_t m = 0; m < model.meshes.size(); ++m)
            for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p)
                collect(model.meshes[m].primitives[p].extensions, at(at("meshes", m) + ".primitives", p));

        const std::vector<std::string>& supported = supportedGltfExtensions();
        std::set<std::string> warned;
        for (const auto& [name, path] : named) {
            if (std::find(supported.begin(), supported.end(), name) != supported.end()) continue;
            if (!warned.insert(name).second) continue;
            warn(path.rfind('.', 0) == 0 ? path.substr(1) : path,
                 "extension " + name + " is not supported and is ignored" + withoutExtension(name));
        }
    }

    // A glTF sampler's wrap mode (an unknown value, already warned about by validation, repeats).
    static TextureWrap textureWrap(int glWrap) {
        return glWrap == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE     ? TextureWrap::ClampToEdge
               : glWrap == TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT ? TextureWrap::MirroredRepeat
                                                                 : TextureWrap::Repeat;
    }

    // The Scene texture of a glTF texture, decoded once per image and use (sRGB colour or linear
    // data) and sampler; -1 if there is none or its image could not be read (`fallback` says what is
    // used instead). Without a sampler a texture repeats and is filtered linearly (glTF 2.0 §5.26).
    // minFilter is not read: every texture is minified trilinearly through its mip chain.
    int sceneTexture(const std::string& materialPath, int textureIndex, const std::string& fallback, bool srgb) {
        if (textureIndex < 0) return -1;
        const tinygltf::Texture& gltfTexture = model.textures[size_t(textureIndex)];
        const int source = gltfTexture.source;
        if (source < 0) return -1;
        TextureWrap wrapS = TextureWrap::Repeat, wrapT = TextureWrap::Repeat;
        bool nearestMagnification = false;
        if (gltfTexture.sampler >= 0 && size_t(gltfTexture.sampler) < model.samplers.size()) {
            const tinygltf::Sampler& sampler = model.samplers[size_t(gltfTexture.sampler)];
            wrapS = textureWrap(sampler.wrapS);
            wrapT = textureWrap(sampler.wrapT);
            nearestMagnification = sampler.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST;
        }
        const auto same = sameImageAs.find(source);
        const int imageIndex = same != sameImageAs.end() ? same->second : source;  // decoded once, shared
        const auto key = std::tuple{imageIndex, srgb, wrapS, wrapT, nearestMagnification};
        const auto known = sceneTextureOfImage.find(key);
        if (known != sceneTextureOfImage.end()) return known->second;

        const tinygltf::Image& image = model.images[size_t(imageIndex)];
        const std::string description = image.uri.empty() ? "embedded image" : "'" + image.uri + "'";
        int index = -1;
        if (image.image.empty() || image.component != 4 || image.bits != 8) {
            const auto noted = imageProblems.find(imageIndex);
            const std::string problem =
                noted != imageProblems.end() ? noted->second : description + " could not be read";
            warn(at("images", size_t(imageIndex)), problem + "; " + materialPath + " falls back to its " + fallback);
        } else {
            Texture texture;
            texture.name = image.uri.empty() ? at("images", size_t(imageIndex)) : image.uri;
            texture.width = uint32_t(image.width);
            texture.height = uint32_t(image.height);
            texture.rgba8 = image.image;
            texture.srgb = srgb;
            texture.wrapS = wrapS;
            texture.wrapT = wrapT;
            texture.nearestMagnification = nearestMagnification;
            index = int(scene.textures.size());
            scene.textures.push_back(std::move(texture));
        }
        sceneTextureOfImage[key] = index;
        return index;
    }

    // The material's reference to a texture from a glTF textureInfo at `path` (any slot's: they share
    // index, texCoord and extensions): the texture, decoded once per image as sRGB colour or linear
    // data, and where it is read. `fallback` says what stands in for an image that cannot be read.
    template <typename TextureInfo>
    TextureReference textureReference(size_t material, const std::string& path, const TextureInfo& info, bool srgb,
                                      const std::string& fallback) {
        TextureReference reference;
        reference.index = sceneTexture(at("materials", material), info.index, fallback, srgb);
        if (reference.index < 0) return reference;
        int texCoord = info.texCoord;
        std::string texCoordPath = path + ".texCoord";
        // KHR_texture_transform (its values were checked by the validator).
        const auto found = info.extensions.find("KHR_texture_transform");
        if (found != info.extensions.end() && found->second.IsObject()) {
            const tinygltf::Value& transform = found->second;
            auto pair = [&](const char* key, glm::vec2 fallbackValue) {
                if (!transform.Has(key)) return fallbackValue;
                const tinygltf::Value& value = transform.Get(key);
                return glm::vec2(float(value.Get(0).GetNumberAsDouble()), float(value.Get(1).GetNumberAsDouble()));
            };
            reference.offset = pair("offset", glm::vec2(0.0f));
            reference.scale = pair("scale", glm::vec2(1.0f));
            if (transform.Has("rotation")) reference.rotation = float(transform.Get("rotation").GetNumberAsDouble());
            if (transform.Has("texCoord")) {
                texCoord = transform.Get("texCoord").GetNumberAsInt();
                texCoordPath = path + ".extensions.KHR_texture_transform.texCoord";
            }
        }
        if (texCoord != 0 && texCoord != 1) {
            warn(texCoordPath, "TEXCOORD_" + std::to_string(texCoord) +
                                   " is not read (only TEXCOORD_0 and TEXCOORD_1 are); the texture is sampled with "
                                   "TEXCOORD_0");
            texCoord = 0;
        }
        reference.texCoord = uint32_t(texCoord);
        return reference;
    }

    static double extensionNumber(const tinygltf::ExtensionMap& extensions, const char* extension, const char* key,
                                  double fallback) {
        const auto found = extensions.find(extension);
        if (found == extensions.end() || !found->second.IsObject() || !found->second.Has(key)) return fallback;
        return found->second.Get(key).GetNumberAsDouble();
    }

    // glTF's alphaMode names; another is read as OPAQUE (the default) with a warning.
    AlphaMode alphaMode(const std::string& path, const std::string& name) {
        if (name == "MASK") return AlphaMode::Mask;
        if (name == "BLEND") return AlphaMode::Blend;
        if (name != "OPAQUE")
            warn(path + ".alphaMode", "'" + name + "' is not a glTF alpha mode; the material is drawn opaque");
        return AlphaMode::Opaque;
    }

    void convertMaterials() {
        for (size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& source = model.materials[i];
            const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
            Material material;
            material.name = source.name;
            if (pbr.baseColorFactor.size() == 4)
                material.baseColorFactor = glm::vec4(glm::make_vec4(pbr.baseColorFactor.data()));
            const std::string path = at("materials", i);
            material.baseColorTexture = textureReference(i, path + ".pbrMetallicRoughness.baseColorTexture",
                                                         pbr.baseColorTexture, true, "base colour factor");
            material.emissiveTexture =
                textureReference(i, path + ".emissiveTexture", source.emissiveTexture, true, "emissive factor");
            material.metallic = float(pbr.metallicFactor);
            material.roughness = float(pbr.roughnessFactor);
            material.metallicRoughnessTexture =
                textureReference(i, path + ".pbrMetallicRoughness.metallicRoughnessTexture",
                                 pbr.metallicRoughnessTexture, false, "metallic and roughness factors");
            material.normalTexture = textureReference(i, path + ".normalTexture", source.normalTexture, false,
                                                      "interpolated vertex normals");
            material.normalScale = float(source.normalTexture.scale);
            material.occlusionTexture = textureReference(i, path + ".occlusionTexture", source.occlusionTexture, false,
                                                         "unoccluded indirect light");
            material.occlusionStrength = float(source.occlusionTexture.strength);
            material.specularWeight =
                float(extensionNumber(source.extensions, "KHR_materials_specular", "specularFactor", 1.0));
            const double strength =
                extensionNumber(source.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
            if (source.emissiveFactor.size() == 3)
                material.emission = glm::vec3(glm::make_vec3(source.emissiveFactor.data()) * strength);
            material.doubleSided = source.doubleSided;
            material.alphaMode = alphaMode(path, source.alphaMode);
            material.alphaCutoff = float(source.alphaCutoff);
            scene.materials.push_back(std::move(material));
        }
    }

    // The names of the material's textures that are read with TEXCOORD_1, "" if none is.
    static std::string slotsReadingTexCoord1(const Material& material) {
        std::string names;
        for (const auto& [reference, name] : {std::pair{&material.baseColorTexture, "baseColorTexture"},
                                              {&material.metallicRoughnessTexture, "metallicRoughnessTexture"},
                                              {&material.normalTexture, "normalTexture"},
                                              {&material.occlusionTexture, "occlusionTexture"},
                                              {&material.emissiveTexture, "emissiveTexture"}})
            if (reference->index >= 0 && reference->texCoord == 1)
                names += (names.empty() ? "" : ", ") + std::string(name);
        return names;
    }

    int materialOf(const tinygltf::Primitive& primitive) {
        if (primitive.material >= 0) return primitive.material;
        if (defaultMaterial < 0) {
            defaultMaterial = int(scene.materials.size());
            Material fallback;
            fallback.name = "default";
            fallback.doubleSided = false;  // glTF's default material, as its doubleSided defaults
            scene.materials.push_back(fallback);
        }
        return defaultMaterial;
    }

    static glm::dmat4 localTransform(const tinygltf::Node& node) {
        if (node.matrix.size() == 16) return glm::make_mat4(node.matrix.data());  // column-major, as glTF
        glm::dmat4 transform(1.0);
        if (node.translation.size() == 3)
            transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
        if (node.rotation.size() == 4) {
            const glm::dquat rotation(node.rotation[3], node.rotation[0], node.rotation[1],
                                      node.rotation[2]);  // xyzw
            transform *= glm::mat4_cast(glm::normalize(rotation));
        }
        if (node.scale.size() == 3) transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
        return transform;
    }

    // Triangles as glTF §3.7.2.1 assembles them from each mode; empty for points and lines.
    static std::vector<uint32_t> triangleCorners(int mode, const std::vector<uint32_t>& indices) {
        std::vector<uint32_t> corners;
        const size_t n = indices.size();
        if (mode == TINYGLTF_MODE_TRIANGLES || mode == -1) {
            corners.assign(indices.begin(), indices.begin() + ptrdiff_t(n - n % 3));
        } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
            for (size_t i = 0; i + 2 < n; ++i) {
                const size_t odd = i % 2;
                corners.insert(corners.end(), {indices[i], indices[i + 1 + odd], indices[i + 2 - odd]});
            }
        } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
            for (size_t i = 0; i + 2 < n; ++i)
                corners.insert(corners.end(), {indices[i + 1], indices[i + 2], indices[0]});
        }
        return corners;
    }

    void addPrimitive(const std::string& path, const tinygltf::Primitive& primitive, const glm::dmat4& world) {
        const int mode = primitive.mode;
        if (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
            mode != TINYGLTF_MODE_TRIANGLE_FAN) {
            warn(path + ".mode", "points and lines are not rendered; the primitive is skipped");
            return;
        }
        if (!primitive.attributes.count("POSITION")) {
            warn(path + ".attributes", "has no POSITION; the primitive is skipped");
            return;
        }
        const glm::dmat3 linear(world);
        const double determinant = glm::determinant(linear);
        if (determinant == 0.0 || !std::isfinite(determinant)) {
            warn(path, "the node's transform is singular (zero scale); the primitive is skipped");
            return;
        }
        const std::vector<float> positions = readAccessorFloats(model, primitive.attributes.at("POSITION"));
        const size_t vertexCount = positions.size() / 3;
        std::vector<uint32_t> indices;
        if (primitive.indices >= 0) {
            indices = readAccessorIndices(model, primitive.indices);
        } else {
            indices.resize(vertexCount);
            for (size_t i = 0; i < vertexCount; ++i) indices[i] = uint32_t(i);
        }
        if ((mode == -1 || mode == TINYGLTF_MODE_TRIANGLES) && indices.size() % 3 != 0)
            warn(path, std::to_string(indices.size()) + " indices are not a whole number of triangles; the last " +
                           std::to_string(indices.size() % 3) + " are ignored");
        const std::vector<uint32_t> corners = triangleCorners(mode, indices);

        auto readAttribute = [&](const char* name) {
            const auto attribute = primitive.attributes.find(name);
            return attribute != primitive.attributes.end() ? readAccessorFloats(model, attribute->second)
                                                           : std::vector<float>{};
        };
        const std::vector<float> normals = readAttribute("NORMAL");
        // glTF 2.0 §3.7.2.1: without normals (flat shading) the file's tangents are ignored.
        const std::vector<float> tangents = normals.empty() ? std::vector<float>{} : readAttribute("TANGENT");
        const std::vector<float> uvs = readAttribute("TEXCOORD_0");
        std::vector<float> uvs1 = readAttribute("TEXCOORD_1");
        const uint32_t material = uint32_t(materialOf(primitive));
        if (uvs1.empty()) {
            const std::string slots = slotsReadingTexCoord1(scene.materials[material]);
            if (!slots.empty() && warnedNoTexCoord1.insert(material).second)
                warn(path + ".attributes", "has no TEXCOORD_1, which " + at("materials", material) + "'s " + slots +
                                               " reads; TEXCOORD_0 stands in for it here and on the material's "
                                               "other primitives without one");
            uvs1 = uvs;
        }
        const glm::dmat3 normalMatrix = glm::inverseTranspose(linear);

        std::vector<Vertex> vertices(vertexCount);
        for (size_t i = 0; i < vertexCount; ++i) {
            Vertex& vertex = vertices[i];
            vertex.position = glm::vec3(world * glm::dvec4(glm::make_vec3(&positions[3 * i]), 1.0));
            if (!normals.empty()) {
                const glm::dvec3 normal = normalMatrix * glm::dvec3(glm::make_vec3(&normals[3 * i]));
                const double length = glm::length(normal);
                vertex.normal = length > 0.0 ? glm::vec3(normal / length) : glm::vec3(0.0f);
            }
            if (!uvs.empty()) {
                vertex.u = uvs[2 * i];
                vertex.v = uvs[2 * i + 1];
            }
            if (!uvs1.empty()) vertex.uv1 = glm::vec2(uvs1[2 * i], uvs1[2 * i + 1]);
            if (!tangents.empty()) vertex.tangent = worldTangent(linear, glm::make_vec4(&tangents[4 * i]));
        }

        const bool mirrored = determinant < 0.0;  // a mirroring transform turns front faces into back faces
        // A normal texture read at TEXCOORD_0 follows vertex tangents; where the file gives none they
        // are generated (and may split up to every vertex in two).
        const TextureReference& normalTexture = scene.materials[material].normalTexture;
        const bool generatesTangents = !normals.empty() && tangents.empty() && !uvs.empty() &&
                                       normalTexture.index >= 0 && normalTexture.texCoord == 0;
        if (scene.vertices.size() + std::max(vertexCount * (generatesTangents ? 2 : 1), corners.size()) > UINT32_MAX)
            throw Error(scene.name + ": " + path + ": the scene has more vertices than 32-bit indices can address");
        const uint32_t base = uint32_t(scene.vertices.size());
        if (!normals.empty()) scene.vertices.insert(scene.vertices.end(), vertices.begin(), vertices.end());
        for (size_t t = 0; t + 2 < corners.size(); t += 3) {
            uint32_t a = corners[t], b = corners[t + 1], c = corners[t + 2];
            if (mirrored) std::swap(b, c);
            const glm::vec3 faceNormal = faceNormalOf(vertices[a].position, vertices[b].position, vertices[c].position);
            if (normals.empty()) {
                // Flat shading: three vertices of its own per triangle, all with the face normal.
                const uint32_t first = uint32_t(scene.vertices.size());
                for (uint32_t corner : {a, b, c}) {
                    Vertex vertex = vertices[corner];
                    vertex.normal = faceNormal;
                    scene.vertices.push_back(vertex);
                }
                scene.indices.insert(scene.indices.end(), {first, first + 1, first + 2});
            } else {
                for (uint32_t corner : {a, b, c}) {
                    Vertex& vertex = scene.vertices[base + corner];
                    if (vertex.normal == glm::vec3(0.0f)) vertex.normal = faceNormal;  // a zero normal in the file
                }
                scene.indices.insert(scene.indices.end(), {base + a, base + b, base + c});
            }
            scene.triangleMaterials.push_back(material);
        }
        if (generatesTangents)
            generateTangents(scene.vertices, scene.indices, scene.indices.size() - corners.size() / 3 * 3);
    }

    // A TANGENT in world space: its direction through the node's linear transform, and its
    // handedness turned over by a mirroring one (which turns the normal's side over too). Zero (the
    // tangent derived per pixel instead) where it has no direction.
    static glm::vec4 worldTangent(const glm::dmat3& linear, const glm::vec4& tangent) {
        const glm::dvec3 direction = linear * glm::dvec3(glm::vec3(tangent));
        const double length = glm::length(direction);
        if (!(length > 0.0)) return glm::vec4(0.0f);
        const double handedness = (tangent.w < 0.0f ? -1.0 : 1.0) * (glm::determinant(linear) < 0.0 ? -1.0 : 1.0);
        return glm::vec4(glm::vec3(direction / length), float(handedness));
    }

    static glm::vec3 faceNormalOf(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
        const glm::dvec3 normal = glm::cross(glm::dvec3(b - a), glm::dvec3(c - a));
        const double length = glm::length(normal);
        return length > 0.0 ? glm::vec3(normal / length) : glm::vec3(0.0f, 0.0f, 1.0f);
    }

    // The node's −Z axis in world space, normalised; false for a degenerate transform.
    static bool worldForward(const glm::dmat4& world, glm::dvec3& forward) {
        forward = glm::dmat3(world) * glm::dvec3(0.0, 0.0, -1.0);
        const double length = glm::length(forward);
        if (!(length > 0.0) || !std::isfinite(length)) return false;
        forward /= length;
        return true;
    }

    void addCamera(const std::string& path, const tinygltf::Node& node, const glm::dmat4& world) {
        const tinygltf::Camera& source = model.cameras[size_t(node.camera)];
        if (source.type != "perspective") {
            warn(at("cameras", size_t(node.camera)), "orthographic cameras are not supported; the camera is skipped");
            return;
        }
        glm::dvec3 forward;
        glm::dvec3 up = glm::dmat3(world) * glm::dvec3(0.0, 1.0, 0.0);
        const bool placed = worldForward(world, forward);
        up -= glm::dot(up, forward) * forward;  // orthogonalised against forward (Gram–Schmidt)
        if (!placed || !(glm::length(up) > 0.0)) {
            warn(path, "the camera's transform is degenerate; the camera is skipped");
            return;
        }
        Camera camera;
        camera.name = source.name.empty() ? node.name : source.name;
        camera.position = glm::vec3(world[3]);
        camera.forward = glm::vec3(forward);
        camera.up = glm::vec3(glm::normalize(up));
        camera.yfov = float(source.perspective.yfov);
        camera.znear = float(source.perspective.znear);
        camera.zfar = float(source.perspective.zfar);
        scene.cameras.push_back(camera);
    }

    void addLight(const std::string& path, int lightIndex, const glm::dmat4& world) {
        const tinygltf::Light& source = model.lights[size_t(lightIndex)];
        Light light;
        light.name = source.name;
        light.type = source.type == "directional" ? LightType::Directional
                     : source.type == "spot"      ? LightType::Spot
                                                  : LightType::Point;
        if (source.color.size() == 3) light.color = glm::vec3(glm::make_vec3(source.color.data()));
        light.intensity = float(source.intensity);
        light.range = float(source.range);
        light.position = glm::vec3(world[3]);
        glm::dvec3 direction;
        if (!worldForward(world, direction)) {
            if (light.type != LightType::Point) {
                warn(path, "the light's transform is degenerate; the light is skipped");
                return;
            }
            direction = glm::dvec3(0.0, 0.0, -1.0);
        }
        light.direction = glm::vec3(direction);
        if (light.type == LightType::Spot) {
            light.innerConeAngle = float(source.spot.innerConeAngle);
            light.outerConeAngle = float(source.spot.outerConeAngle);
        }
        scene.lights.push_back(light);
    }

    // Depth-first, parents before children, iteratively (a hostile file may nest nodes very deeply).
    void convertNodes() {
        std::vector<std::pair<int, glm::dmat4>> pending;
        const std::vector<int> roots = gltfRootNodes(model);
        for (auto root = roots.rbegin(); root != roots.rend(); ++root) pending.emplace_back(*root, glm::dmat4(1.0));
        while (!pending.empty()) {
            const auto [index, parentWorld] = pending.back();
            pending.pop_back();
            const tinygltf::Node& node = model.nodes[size_t(index)];
            const std::string path = at("nodes", size_t(index));
            const glm::dmat4 world = parentWorld * localTransform(node);
            if (node.mesh >= 0) {
                const tinygltf::Mesh& mesh = model.meshes[size_t(node.mesh)];
                for (size_t p = 0; p < mesh.primitives.size(); ++p)
                    addPrimitive(at(at("meshes", size_t(node.mesh)) + ".primitives", p), mesh.primitives[p], world);
            }
            if (node.camera >= 0) addCamera(path, node, world);
            const auto light = node.extensions.find("KHR_lights_punctual");
            if (light != node.extensions.end()) addLight(path, light->second.Get("light").GetNumberAsInt(), world);
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child)
                pending.emplace_back(*child, world);
        }
    }
};

Scene load(const std::string& path, const LoadOptions& options) {
    const Parsed parsed = parse(path, options);
    validateGltf(parsed.model, path, options.bufferLimits);

    Scene scene;
    scene.name = path;
    Converter converter{parsed.model, parsed.imageProblems, parsed.sameImageAs, options, scene};
    converter.warnAboutExtensions();
    converter.convertMaterials();
    converter.convertNodes();
    if (scene.materials.empty()) converter.materialOf(tinygltf::Primitive());  // never empty
    return scene;
}

}  // namespace

Scene loadGltf(const std::string& path, const LoadOptions& options) {
    // Whatever goes wrong below, the caller gets one vct::Error that names the file.
    try {
        return load(path, options);
    } catch (const Error& error) {
        if (std::string(error.what()).rfind(path + ":", 0) == 0) throw;
        throw Error(path + ": " + error.what());
    } catch (const std::bad_alloc&) {
        throw Error(path + ": not enough memory to load the file");
    } catch (const std::exception& error) {
        throw Error(path + ": " + error.what());
    }
}

}  // namespace vct
