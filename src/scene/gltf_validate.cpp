#include "scene/gltf_validate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <set>

#include "error.h"
#include "gpu_types.h"
#include "scene/gltf_accessor.h"

namespace vct {

namespace {

constexpr double kPi = 3.14159265358979323846;
// No accessor may describe more elements than this, even one of zeros without a buffer view:
// a hostile count would otherwise ask for an impossible allocation.
constexpr size_t kMaxAccessorCount = size_t(1) << 28;

std::string at(const std::string& base, size_t index) { return base + "[" + std::to_string(index) + "]"; }

bool allFinite(const std::vector<double>& values) {
    return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

std::string formatNumber(double value) {
    char text[32];
    std::snprintf(text, sizeof(text), "%g", value);
    return text;
}

// The bytes the last element of an accessor occupies: a matrix's last column needs no padding after it.
size_t lastElementBytes(int type, int componentType) {
    const size_t componentBytes = componentByteSize(componentType);
    if (type == TINYGLTF_TYPE_MAT2 && componentBytes == 1) return 4 + 2;
    if (type == TINYGLTF_TYPE_MAT3 && componentBytes == 1) return 4 + 4 + 3;
    if (type == TINYGLTF_TYPE_MAT3 && componentBytes == 2) return 8 + 8 + 6;
    return accessorElementBytes(type, componentType);
}

struct Validator {
    const tinygltf::Model& model;
    const std::string& file;
    bool quantized = false;         // KHR_mesh_quantization widens the attribute component types
    std::set<int> finiteAccessors;  // accessors whose values were already checked to be finite
    std::map<int, uint32_t> largestIndex;

    [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
        throw Error(file + ": " + path + ": " + problem);
    }

    // A reference to object `index` of a list with `size` entries; -1 means "absent" when optional.
    void checkReference(const std::string& path, int index, size_t size, const char* what, bool optional) const {
        if (optional && index == -1) return;
        if (index < 0 || size_t(index) >= size)
            fail(path, std::string(what) + " " + std::to_string(index) + " does not exist (the file has " +
                           std::to_string(size) + ")");
    }

    void checkFiniteArray(const std::string& path, const std::vector<double>& values, size_t expectedSize) const {
        if (values.empty()) return;  // absent: the glTF default applies
        if (values.size() != expectedSize)
            fail(path, "has " + std::to_string(values.size()) + " numbers, expected " + std::to_string(expectedSize));
        if (!allFinite(values)) fail(path, "holds a value that is not a finite number");
    }

    void checkNumber(const std::string& path, double value, double min, double max) const {
        if (!std::isfinite(value)) fail(path, "is not a finite number");
        if (value < min || value > max)
            fail(path, formatNumber(value) + " is outside [" + formatNumber(min) + ", " + formatNumber(max) + "]");
    }

    void checkNonNegative(const std::string& path, double value) const {
        if (!std::isfinite(value)) fail(path, "is not a finite number");
        if (value < 0.0) fail(path, formatNumber(value) + " is negative");
    }

    void checkAsset() const {
        if (model.asset.version.rfind("2.", 0) != 0)
            fail("asset.version", "is '" + model.asset.version + "'; only glTF 2.0 is supported");
        const std::vector<std::string>& supported = supportedGltfExtensions();
        for (size_t i = 0; i < model.extensionsRequired.size(); ++i) {
            const std::string& name = model.extensionsRequired[i];
            if (std::find(supported.begin(), supported.end(), name) == supported.end())
                fail(at("extensionsRequired", i), "the file requires extension " + name + ", which is not supported");
        }
    }

    void checkBufferViews() const {
        for (size_t i = 0; i < model.bufferViews.size(); ++i) {
            const tinygltf::BufferView& view = model.bufferViews[i];
            const std::string path = at("bufferViews", i);
            checkReference(path + ".buffer", view.buffer, model.buffers.size(), "buffer", false);
            const size_t bufferBytes = model.buffers[size_t(view.buffer)].data.size();
            if (view.byteLength == 0) fail(path + ".byteLength", "must be at least 1");
            if (view.byteOffset > bufferBytes || view.byteLength > bufferBytes - view.byteOffset)
                fail(path, "bytes " + std::to_string(view.byteOffset) + " to " +
                               std::to_string(uint64_t(view.byteOffset) + view.byteLength) +
                               " run past the end of buffer " + std::to_string(view.buffer) + ", which holds " +
                               std::to_string(bufferBytes) + " bytes");
            if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0))
                fail(path + ".byteStride", std::to_string(view.byteStride) + " is not a multiple of 4 in [4, 252]");
        }
    }

    // `count` elements `stride` apart, starting at `byteOffset`, must fit in the buffer view.
    void checkRange(const std::string& path, int bufferView, size_t byteOffset, size_t stride, size_t count,
                    size_t elementBytes) const {
        const size_t viewBytes = model.bufferViews[size_t(bufferView)].byteLength;
        const unsigned __int128 end =
            (unsigned __int128)byteOffset + (unsigned __int128)stride * (count - 1) + elementBytes;
        if (end > viewBytes)
            fail(path, std::to_string(count) + " elements of " + std::to_string(elementBytes) + " bytes, " +
                           std::to_string(stride) + " apart from offset " + std::to_string(byteOffset) +
                           ", need more than the " + std::to_string(viewBytes) + " bytes of bufferView " +
                           std::to_string(bufferView));
    }

    void checkAccessors() const {
        for (size_t i = 0; i < model.accessors.size(); ++i) {
            const tinygltf::Accessor& accessor = model.accessors[i];
            const std::string path = at("accessors", i);
            if (componentByteSize(accessor.componentType) == 0)
                fail(path + ".componentType", std::to_string(accessor.componentType) + " is not a glTF component type");
            if (accessorComponentCount(accessor.type) == 0) fail(path + ".type", "is not a glTF accessor type");
            if (accessor.normalized && (accessor.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                                        accessor.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(path + ".normalized", "must not be true for " + componentTypeName(accessor.componentType));
            if (accessor.count == 0) fail(path + ".count", "must be at least 1");
            if (accessor.count > kMaxAccessorCount)
                fail(path + ".count", std::to_string(accessor.count) + " is more than this loader accepts (" +
                                          std::to_string(kMaxAccessorCount) + ")");
            const size_t elementBytes = accessorElementBytes(accessor.type, accessor.componentType);
            if (accessor.bufferView != -1) {
                checkReference(path + ".bufferView", accessor.bufferView, model.bufferViews.size(), "bufferView",
                               false);
                const size_t viewStride = model.bufferViews[size_t(accessor.bufferView)].byteStride;
                if (viewStride != 0 && viewStride < elementBytes)
                    fail(path, "elements of " + std::to_string(elementBytes) + " bytes do not fit the byteStride " +
                                   std::to_string(viewStride) + " of bufferView " +
                                   std::to_string(accessor.bufferView));
                checkRange(path, accessor.bufferView, accessor.byteOffset, viewStride ? viewStride : elementBytes,
                           accessor.count, lastElementBytes(accessor.type, accessor.componentType));
            }
            if (accessor.sparse.isSparse) checkSparse(path + ".sparse", accessor, elementBytes);
        }
    }

    void checkSparse(const std::string& path, const tinygltf::Accessor& accessor, size_t elementBytes) const {
        const auto& sparse = accessor.sparse;
        if (sparse.count < 1 || size_t(sparse.count) > accessor.count)
            fail(path + ".count",
                 std::to_string(sparse.count) + " is outside [1, " + std::to_string(accessor.count) + "]");
        const size_t count = size_t(sparse.count);
        const int indexType = sparse.indices.componentType;
        if (indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE && indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
            indexType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
            fail(path + ".indices.componentType", componentTypeName(indexType) + " is not an unsigned integer type");
        checkReference(path + ".indices.bufferView", sparse.indices.bufferView, model.bufferViews.size(), "bufferView",
                       false);
        checkReference(path + ".values.bufferView", sparse.values.bufferView, model.bufferViews.size(), "bufferView",
                       false);
        if (sparse.indices.byteOffset < 0) fail(path + ".indices.byteOffset", "is negative");
        if (sparse.values.byteOffset < 0) fail(path + ".values.byteOffset", "is negative");
        const size_t indexBytes = componentByteSize(indexType);
        checkRange(path + ".indices", sparse.indices.bufferView, size_t(sparse.indices.byteOffset), indexBytes, count,
                   indexBytes);
        checkRange(path + ".values", sparse.values.bufferView, size_t(sparse.values.byteOffset), elementBytes, count,
                   elementBytes);
    }

    // Which component types an attribute may use (glTF 2.0 §3.7.2.1, KHR_mesh_quantization).
    bool attributeFormatAllowed(const std::string& name, const tinygltf::Accessor& accessor) const {
        const int type = accessor.type;
        const int component = accessor.componentType;
        const bool normalized = accessor.normalized;
        const bool isFloat = component == TINYGLTF_COMPONENT_TYPE_FLOAT;
        const bool unsignedNormalized = normalized && (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                                       component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        const bool signedNormalized =
            normalized && (component == TINYGLTF_COMPONENT_TYPE_BYTE || component == TINYGLTF_COMPONENT_TYPE_SHORT);
        const bool smallInteger =
            component != TINYGLTF_COMPONENT_TYPE_FLOAT && component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        if (name == "POSITION") return type == TINYGLTF_TYPE_VEC3 && (isFloat || (quantized && smallInteger));
        if (name == "NORMAL") return type == TINYGLTF_TYPE_VEC3 && (isFloat || (quantized && signedNormalized));
        if (name == "TANGENT") return type == TINYGLTF_TYPE_VEC4 && (isFloat || (quantized && signedNormalized));
        if (name.rfind("TEXCOORD_", 0) == 0)
            return type == TINYGLTF_TYPE_VEC2 && (isFloat || unsignedNormalized || (quantized && smallInteger));
        if (name.rfind("COLOR_", 0) == 0)
            return (type == TINYGLTF_TYPE_VEC3 || type == TINYGLTF_TYPE_VEC4) && (isFloat || unsignedNormalized);
        if (name.rfind("JOINTS_", 0) == 0)
            return type == TINYGLTF_TYPE_VEC4 && !normalized &&
                   (component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                    component == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        if (name.rfind("WEIGHTS_", 0) == 0)
            return type == TINYGLTF_TYPE_VEC4 && (isFloat || unsignedNormalized || (quantized && signedNormalized));
        return true;  // application-specific attributes ("_NAME") are not read
    }

    // Reads an accessor whose ranges were checked; what the reader still refuses (a sparse index past
    // the count) is reported at `path`.
    std::vector<float> readFloats(const std::string& path, int accessorIndex) const {
        try {
            return readAccessorFloats(model, accessorIndex);
        } catch (const Error& error) {
            fail(path, error.what());
        }
    }

    std::vector<uint32_t> readIndices(const std::string& path, int accessorIndex) const {
        try {
            return readAccessorIndices(model, accessorIndex);
        } catch (const Error& error) {
            fail(path, error.what());
        }
    }

    void checkFiniteValues(const std::string& path, int accessorIndex) {
        if (!finiteAccessors.insert(accessorIndex).second) return;
        const std::vector<float> values = readFloats(path, accessorIndex);
        const int components = accessorComponentCount(model.accessors[size_t(accessorIndex)].type);
        for (size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]))
                fail(path, "element " + std::to_string(i / size_t(components)) + " holds " + formatNumber(values[i]) +
                               ", not a finite number");
    }

    void checkPrimitive(const std::string& path, const tinygltf::Primitive& primitive) {
        if (primitive.mode < -1 || primitive.mode > TINYGLTF_MODE_TRIANGLE_FAN)
            fail(path + ".mode", std::to_string(primitive.mode) + " is not a glTF primitive mode");
        checkReference(path + ".material", primitive.material, model.materials.size(), "material", true);
        // A primitive without POSITION is valid glTF; the loader skips it with a warning. Its other
        // attributes are checked against the first one instead.
        const auto position = primitive.attributes.find("POSITION");
        const auto reference = position != primitive.attributes.end() ? position : primitive.attributes.begin();
        if (reference == primitive.attributes.end()) fail(path + ".attributes", "has no attributes");

        size_t vertexCount = 0;
        for (const auto& [name, accessorIndex] : primitive.attributes) {
            const std::string attributePath = path + ".attributes." + name;
            checkReference(attributePath, accessorIndex, model.accessors.size(), "accessor", false);
            const tinygltf::Accessor& accessor = model.accessors[size_t(accessorIndex)];
            if (!attributeFormatAllowed(name, accessor))
                fail(attributePath,
                     "accessor " + std::to_string(accessorIndex) + " is " + accessorTypeName(accessor.type) + " of " +
                         (accessor.normalized ? "normalized " : "") + componentTypeName(accessor.componentType) +
                         ", which glTF does not allow for " + name);
            if (name == reference->first) vertexCount = accessor.count;
        }
        for (const auto& [name, accessorIndex] : primitive.attributes)
            if (model.accessors[size_t(accessorIndex)].count != vertexCount)
                fail(path + ".attributes." + name,
                     "has " + std::to_string(model.accessors[size_t(accessorIndex)].count) + " elements but " +
                         reference->first + " has " + std::to_string(vertexCount));
        for (size_t t = 0; t < primitive.targets.size(); ++t)
            for (const auto& [name, accessorIndex] : primitive.targets[t])
                checkReference(at(path + ".targets", t) + "." + name, accessorIndex, model.accessors.size(), "accessor",
                               false);
        if (primitive.indices != -1) {
            checkReference(path + ".indices", primitive.indices, model.accessors.size(), "accessor", false);
            const tinygltf::Accessor& accessor = model.accessors[size_t(primitive.indices)];
            const int component = accessor.componentType;
            if (accessor.type != TINYGLTF_TYPE_SCALAR || (component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                                          component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                                          component != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
                fail(path + ".indices", "accessor " + std::to_string(primitive.indices) + " is " +
                                            accessorTypeName(accessor.type) + " of " + componentTypeName(component) +
                                            "; indices must be SCALAR unsigned integers");
        }
    }

    // The values the loader reads: finite positions, normals and texture coordinates, and
    // indices inside the vertex count. Read only once the geometry is known to fit.
    void checkPrimitiveValues(const std::string& path, const tinygltf::Primitive& primitive) {
        for (const char* name : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0", "TEXCOORD_1"}) {
            const auto attribute = primitive.attributes.find(name);
            if (attribute != primitive.attributes.end())
                checkFiniteValues(path + ".attributes." + name, attribute->second);
        }
        const size_t vertexCount = model.accessors[size_t(primitive.attributes.begin()->second)].count;
        if (primitive.indices != -1) checkIndices(path + ".indices", primitive.indices, vertexCount);
    }

    void checkIndices(const std::string& path, int accessorIndex, size_t vertexCount) {
        auto found = largestIndex.find(accessorIndex);
        if (found == largestIndex.end()) {
            const std::vector<uint32_t> indices = readIndices(path, accessorIndex);
            found = largestIndex.emplace(accessorIndex, *std::max_element(indices.begin(), indices.end())).first;
        }
        if (found->second >= vertexCount)
            fail(path,
                 "index " + std::to_string(found->second) + " is past the vertex count " + std::to_string(vertexCount));
    }

    void checkMeshes() {
        for (size_t m = 0; m < model.meshes.size(); ++m)
            for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p)
                checkPrimitive(at(at("meshes", m) + ".primitives", p), model.meshes[m].primitives[p]);
    }

    void checkMeshValues() {
        for (size_t m = 0; m < model.meshes.size(); ++m)
            for (size_t p = 0; p < model.meshes[m].primitives.size(); ++p)
                checkPrimitiveValues(at(at("meshes", m) + ".primitives", p), model.meshes[m].primitives[p]);
    }

    // The vertices and indices the loader would build, from the accessors' counts alone, checked
    // against the buffer limits before anything is read: a file of a few hundred bytes can name
    // 2²⁸ vertices, and reading them would take about 86 bytes each.
    void checkGeometryFits(const SceneBufferLimits& limits) const {
        uint64_t vertices = 0, indices = 0, verticesInFile = 0;
        const auto add = [](uint64_t& total, uint64_t more) {
            total = more > UINT64_MAX - total ? UINT64_MAX : total + more;
        };
        std::vector<int> pending = gltfRootNodes(model);
        while (!pending.empty()) {
            const tinygltf::Node& node = model.nodes[size_t(pending.back())];
            pending.pop_back();
            pending.insert(pending.end(), node.children.begin(), node.children.end());
            if (node.mesh < 0) continue;
            for (const tinygltf::Primitive& primitive : model.meshes[size_t(node.mesh)].primitives) {
                const auto position = primitive.attributes.find("POSITION");
                const int mode = primitive.mode;
                if (position == primitive.attributes.end() ||
                    (mode != -1 && mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                     mode != TINYGLTF_MODE_TRIANGLE_FAN))
                    continue;  // skipped by the loader
                const uint64_t positions = model.accessors[size_t(position->second)].count;
                const uint64_t corners =
                    primitive.indices >= 0 ? uint64_t(model.accessors[size_t(primitive.indices)].count) : positions;
                const uint64_t triangles = mode == -1 || mode == TINYGLTF_MODE_TRIANGLES ? corners / 3
                                           : corners >= 2                                ? corners - 2
                                                                                         : 0;
                // Without normals every triangle gets three vertices of its own (flat shading).
                add(vertices, primitive.attributes.count("NORMAL") ? positions : 3 * triangles);
                add(verticesInFile, positions);
                add(indices, 3 * triangles);
            }
        }
        checkSceneBufferFits(file + ": ", vertices, sizeof(glsl::GpuVertex), "vertices", limits, verticesInFile);
        checkSceneBufferFits(file + ": ", indices, sizeof(uint32_t), "triangle corners (indices)", limits);
    }

    // Any slot's textureInfo: the texture exists, and its texCoord and KHR_texture_transform hold
    // numbers the loader can read.
    template <typename TextureInfo>
    void checkTextureReference(const std::string& path, const TextureInfo& info) const {
        checkReference(path + ".index", info.index, model.textures.size(), "texture", true);
        if (info.texCoord < 0) fail(path + ".texCoord", std::to_string(info.texCoord) + " is negative");
        const auto found = info.extensions.find("KHR_texture_transform");
        if (found == info.extensions.end()) return;
        const std::string transformPath = path + ".extensions.KHR_texture_transform";
        const tinygltf::Value& transform = found->second;
        if (!transform.IsObject()) fail(transformPath, "is not an object");
        for (const char* key : {"offset", "scale"}) {
            if (!transform.Has(key)) continue;
            const tinygltf::Value& pair = transform.Get(key);
            if (!pair.IsArray() || pair.ArrayLen() != 2 || !pair.Get(0).IsNumber() || !pair.Get(1).IsNumber())
                fail(transformPath + "." + key, "is not an array of two numbers");
            if (!std::isfinite(pair.Get(0).GetNumberAsDouble()) || !std::isfinite(pair.Get(1).GetNumberAsDouble()))
                fail(transformPath + "." + key, "holds a value that is not a finite number");
        }
        if (transform.Has("rotation")) {
            const tinygltf::Value& rotation = transform.Get("rotation");
            if (!rotation.IsNumber()) fail(transformPath + ".rotation", "is not a number");
            if (!std::isfinite(rotation.GetNumberAsDouble()))
                fail(transformPath + ".rotation", "is not a finite number");
        }
        if (transform.Has("texCoord")) {
            const tinygltf::Value& texCoord = transform.Get("texCoord");
            if (!texCoord.IsInt() || texCoord.GetNumberAsInt() < 0)
                fail(transformPath + ".texCoord", "is not a non-negative integer");
        }
    }

    void checkMaterials() const {
        for (size_t i = 0; i < model.materials.size(); ++i) {
            const tinygltf::Material& material = model.materials[i];
            const std::string path = at("materials", i);
            const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
            checkFiniteArray(path + ".pbrMetallicRoughness.baseColorFactor", pbr.baseColorFactor, 4);
            for (double component : pbr.baseColorFactor)
                if (component < 0.0 || component > 1.0)
                    fail(path + ".pbrMetallicRoughness.baseColorFactor",
                         formatNumber(component) + " is outside [0, 1]");
            checkNumber(path + ".pbrMetallicRoughness.metallicFactor", pbr.metallicFactor, 0.0, 1.0);
            checkNumber(path + ".pbrMetallicRoughness.roughnessFactor", pbr.roughnessFactor, 0.0, 1.0);
            checkFiniteArray(path + ".emissiveFactor", material.emissiveFactor, 3);
            for (double component : material.emissiveFactor)
                if (component < 0.0) fail(path + ".emissiveFactor", formatNumber(component) + " is negative");
            checkTextureReference(path + ".pbrMetallicRoughness.baseColorTexture", pbr.baseColorTexture);
            checkTextureReference(path + ".pbrMetallicRoughness.metallicRoughnessTexture",
                                  pbr.metallicRoughnessTexture);
            checkTextureReference(path + ".emissiveTexture", material.emissiveTexture);
            checkTextureReference(path + ".normalTexture", material.normalTexture);
            checkTextureReference(path + ".occlusionTexture", material.occlusionTexture);
            checkNumber(path + ".occlusionTexture.strength", material.occlusionTexture.strength, 0.0, 1.0);
            checkNonNegative(path + ".alphaCutoff", material.alphaCutoff);  // glTF: minimum 0
            checkExtensionNumber(material.extensions, path, "KHR_materials_emissive_strength", "emissiveStrength", 0.0,
                                 std::numeric_limits<double>::max());
            const double emission =
                *std::max_element(material.emissiveFactor.begin(), material.emissiveFactor.end()) *
                extensionNumber(material.extensions, "KHR_materials_emissive_strength", "emissiveStrength", 1.0);
            if (emission > kBrightestRepresentable)
                fail(path + ".emissiveFactor", "with its strength, an emission of " + formatNumber(emission) +
                                                   ", brighter than this renderer represents (" +
                                                   formatNumber(kBrightestRepresentable) + ")");
            checkExtensionNumber(material.extensions, path, "KHR_materials_specular", "specularFactor", 0.0, 1.0);
        }
    }

    // The number `key` of `extension`, or `fallback` where there is none (checkExtensionNumber
    // has made sure that what is there is a number).
    static double extensionNumber(const tinygltf::ExtensionMap& extensions, const std::string& extension,
                                  const std::string& key, double fallback) {
        const auto found = extensions.find(extension);
        if (found == extensions.end() || !found->second.IsObject() || !found->second.Has(key)) return fallback;
        return found->second.Get(key).GetNumberAsDouble();
    }

    void checkExtensionNumber(const tinygltf::ExtensionMap& extensions, const std::string& path,
                              const std::string& extension, const std::string& key, double min, double max) const {
        const auto found = extensions.find(extension);
        if (found == extensions.end() || !found->second.IsObject() || !found->second.Has(key)) return;
        const tinygltf::Value& value = found->second.Get(key);
        const std::string valuePath = path + ".extensions." + extension + "." + key;
        if (!value.IsNumber()) fail(valuePath, "is not a number");
        checkNumber(valuePath, value.GetNumberAsDouble(), min, max);
    }

    void checkTexturesAndImages() const {
        for (size_t i = 0; i < model.textures.size(); ++i) {
            checkReference(at("textures", i) + ".source", model.textures[i].source, model.images.size(), "image", true);
            checkReference(at("textures", i) + ".sampler", model.textures[i].sampler, model.samplers.size(), "sampler",
                           true);
        }
        for (size_t i = 0; i < model.images.size(); ++i)
            checkReference(at("images", i) + ".bufferView", model.images[i].bufferView, model.bufferViews.size(),
                           "bufferView", true);
    }

    void checkCameras() const {
        for (size_t i = 0; i < model.cameras.size(); ++i) {
            const tinygltf::Camera& camera = model.cameras[i];
            const std::string path = at("cameras", i);
            if (camera.type == "perspective") {
                const tinygltf::PerspectiveCamera& perspective = camera.perspective;
                const std::string p = path + ".perspective";
                if (!std::isfinite(perspective.yfov) || perspective.yfov <= 0.0 || perspective.yfov >= kPi)
                    fail(p + ".yfov", formatNumber(perspective.yfov) + " is not an angle in (0, π)");
                if (!std::isfinite(perspective.znear) || perspective.znear <= 0.0)
                    fail(p + ".znear", formatNumber(perspective.znear) + " is not a positive distance");
                if (!std::isfinite(perspective.zfar) ||
                    (perspective.zfar != 0.0 && perspective.zfar <= perspective.znear))
                    fail(p + ".zfar", formatNumber(perspective.zfar) + " is not a distance beyond znear");
                if (!std::isfinite(perspective.aspectRatio) || perspective.aspectRatio < 0.0)
                    fail(p + ".aspectRatio", formatNumber(perspective.aspectRatio) + " is not a positive ratio");
            } else if (camera.type == "orthographic") {
                const tinygltf::OrthographicCamera& ortho = camera.orthographic;
                if (!allFinite({ortho.xmag, ortho.ymag, ortho.znear, ortho.zfar}))
                    fail(path + ".orthographic", "holds a value that is not a finite number");
            } else {
                fail(path + ".type", "'" + camera.type + "' is neither 'perspective' nor 'orthographic'");
            }
        }
    }

    void checkLights() const {
        for (size_t i = 0; i < model.lights.size(); ++i) {
            const tinygltf::Light& light = model.lights[i];
            const std::string path = at("extensions.KHR_lights_punctual.lights", i);
            if (light.type != "directional" && light.type != "point" && light.type != "spot")
                fail(path + ".type", "'" + light.type + "' is not directional, point or spot");
            checkFiniteArray(path + ".color", light.color, 3);
            for (double component : light.color)
                if (component < 0.0) fail(path + ".color", formatNumber(component) + " is negative");
            checkNonNegative(path + ".intensity", light.intensity);
            const double brightest =
                light.intensity *
                (light.color.size() == 3 ? *std::max_element(light.color.begin(), light.color.end()) : 1.0);
            if (brightest > kBrightestRepresentable)
                fail(path + ".intensity", formatNumber(light.intensity) + " times its colour is " +
                                              formatNumber(brightest) + ", brighter than this renderer represents (" +
                                              formatNumber(kBrightestRepresentable) + ")");
            checkNonNegative(path + ".range", light.range);
            if (light.type == "spot") {
                checkNumber(path + ".spot.outerConeAngle", light.spot.outerConeAngle, 0.0, kPi / 2);
                checkNumber(path + ".spot.innerConeAngle", light.spot.innerConeAngle, 0.0, light.spot.outerConeAngle);
                if (light.spot.innerConeAngle >= light.spot.outerConeAngle)
                    fail(path + ".spot.innerConeAngle", "must be smaller than outerConeAngle");
            }
        }
    }

    // The light a node carries through KHR_lights_punctual, or -1.
    int nodeLight(const std::string& path, const tinygltf::Node& node) const {
        const auto found = node.extensions.find("KHR_lights_punctual");
        if (found == node.extensions.end()) return -1;
        const tinygltf::Value& light = found->second.IsObject() ? found->second.Get("light") : tinygltf::Value();
        if (!light.IsInt()) fail(path + ".extensions.KHR_lights_punctual.light", "is not a light index");
        checkReference(path + ".extensions.KHR_lights_punctual.light", light.GetNumberAsInt(), model.lights.size(),
                       "light", false);
        return light.GetNumberAsInt();
    }

    void checkNodes() const {
        const size_t nodeCount = model.nodes.size();
        std::vector<int> parent(nodeCount, -1);
        for (size_t i = 0; i < nodeCount; ++i) {
            const tinygltf::Node& node = model.nodes[i];
            const std::string path = at("nodes", i);
            checkReference(path + ".mesh", node.mesh, model.meshes.size(), "mesh", true);
            checkReference(path + ".camera", node.camera, model.cameras.size(), "camera", true);
            checkReference(path + ".skin", node.skin, model.skins.size(), "skin", true);
            nodeLight(path, node);
            checkFiniteArray(path + ".matrix", node.matrix, 16);
            checkFiniteArray(path + ".translation", node.translation, 3);
            checkFiniteArray(path + ".rotation", node.rotation, 4);
            checkFiniteArray(path + ".scale", node.scale, 3);
            if (node.rotation.size() == 4) {
                const double length =
                    std::sqrt(node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                              node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3]);
                if (!(length > 1e-6) || !std::isfinite(length)) fail(path + ".rotation", "is not a unit quaternion");
            }
            for (size_t c = 0; c < node.children.size(); ++c) {
                const int child = node.children[c];
                const std::string childPath = at(path + ".children", c);
                checkReference(childPath, child, nodeCount, "node", false);
                if (parent[size_t(child)] != -1)
                    fail(childPath, "node " + std::to_string(child) + " already has parent node " +
                                        std::to_string(parent[size_t(child)]) + "; a node may have only one parent");
                parent[size_t(child)] = int(i);
            }
        }
        // With one parent each, a node that no root reaches hangs below a cycle: find it by walking up.
        std::vector<char> reached(nodeCount, 0);
        std::vector<size_t> pending;
        for (size_t i = 0; i < nodeCount; ++i)
            if (parent[i] == -1) pending.push_back(i);
        while (!pending.empty()) {
            const size_t node = pending.back();
            pending.pop_back();
            reached[node] = 1;
            for (int child : model.nodes[node].children) pending.push_back(size_t(child));
        }
        for (size_t i = 0; i < nodeCount; ++i) {
            if (reached[i]) continue;
            std::vector<char> seen(nodeCount, 0);
            size_t node = i;
            while (!seen[node]) {
                seen[node] = 1;
                node = size_t(parent[node]);
            }
            fail(at("nodes", node), "is its own ancestor: the node hierarchy has a cycle");
        }
    }

    void checkScenes() const {
        checkReference("scene", model.defaultScene, model.scenes.size(), "scene", true);
        std::vector<char> hasParent(model.nodes.size(), 0);
        for (const tinygltf::Node& node : model.nodes)
            for (int child : node.children) hasParent[size_t(child)] = 1;
        for (size_t s = 0; s < model.scenes.size(); ++s) {
            std::set<int> listed;
            for (size_t n = 0; n < model.scenes[s].nodes.size(); ++n) {
                const int node = model.scenes[s].nodes[n];
                const std::string path = at(at("scenes", s) + ".nodes", n);
                checkReference(path, node, model.nodes.size(), "node", false);
                if (hasParent[size_t(node)])
                    fail(path, "node " + std::to_string(node) + " is a child, not a root node");
                if (!listed.insert(node).second) fail(path, "node " + std::to_string(node) + " is listed twice");
            }
        }
    }
};

}  // namespace

const std::vector<std::string>& supportedGltfExtensions() {
    static const std::vector<std::string> names = {"KHR_lights_punctual", "KHR_materials_emissive_strength",
                                                   "KHR_materials_specular", "KHR_mesh_quantization",
                                                   "KHR_texture_transform"};
    return names;
}

std::vector<int> gltfRootNodes(const tinygltf::Model& model) {
    if (!model.scenes.empty()) return model.scenes[size_t(std::max(model.defaultScene, 0))].nodes;
    std::vector<char> isChild(model.nodes.size(), 0);
    for (const tinygltf::Node& node : model.nodes)
        for (int child : node.children) isChild[size_t(child)] = 1;
    std::vector<int> roots;
    for (size_t i = 0; i < model.nodes.size(); ++i)
        if (!isChild[i]) roots.push_back(int(i));
    return roots;
}

void validateGltf(const tinygltf::Model& model, const std::string& file, const SceneBufferLimits& limits) {
    Validator validator{model, file};
    const auto& used = model.extensionsUsed;
    validator.quantized = std::find(used.begin(), used.end(), "KHR_mesh_quantization") != used.end();
    validator.checkAsset();
    validator.checkBufferViews();
    validator.checkAccessors();
    validator.checkMaterials();
    validator.checkTexturesAndImages();
    validator.checkCameras();
    validator.checkLights();
    validator.checkMeshes();
    validator.checkNodes();
    validator.checkScenes();
    validator.checkGeometryFits(limits);
    validator.checkMeshValues();
}

}  // namespace vct
