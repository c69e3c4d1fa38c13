#include "scene/gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include "error.h"

namespace vct {

int accessorComponentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

size_t componentByteSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

size_t accessorElementBytes(int type, int componentType) {
    const size_t componentBytes = componentByteSize(componentType);
    // Matrix columns start on 4-byte boundaries.
    if (type == TINYGLTF_TYPE_MAT2 && componentBytes == 1) return 8;
    if (type == TINYGLTF_TYPE_MAT3 && componentBytes == 1) return 12;
    if (type == TINYGLTF_TYPE_MAT3 && componentBytes == 2) return 24;
    return componentBytes * size_t(accessorComponentCount(type));
}

std::string componentTypeName(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return "BYTE";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return "UNSIGNED_BYTE";
        case TINYGLTF_COMPONENT_TYPE_SHORT: return "SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return "UNSIGNED_SHORT";
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return "UNSIGNED_INT";
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return "FLOAT";
        default: return "component type " + std::to_string(componentType);
    }
}

std::string accessorTypeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "type " + std::to_string(type);
    }
}

// The bytes of `count` elements of `elementBytes` each, `stride` apart, starting `byteOffset`
// into a buffer view; throws rather than return a range the buffer does not hold.
static const uint8_t* viewBytes(const tinygltf::Model& model, int bufferViewIndex, size_t byteOffset, size_t stride,
                                size_t count, size_t elementBytes) {
    if (bufferViewIndex < 0 || size_t(bufferViewIndex) >= model.bufferViews.size())
        throw Error("accessor reads bufferView " + std::to_string(bufferViewIndex) + ", which does not exist");
    const tinygltf::BufferView& view = model.bufferViews[size_t(bufferViewIndex)];
    if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
        throw Error("bufferView reads buffer " + std::to_string(view.buffer) + ", which does not exist");
    const std::vector<unsigned char>& data = model.buffers[size_t(view.buffer)].data;
    const unsigned __int128 end =
        (unsigned __int128)byteOffset + (unsigned __int128)stride * (count ? count - 1 : 0) + elementBytes;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset ||
        (count > 0 && end > view.byteLength))
        throw Error("accessor reads past the end of its buffer");
    return data.data() + view.byteOffset + byteOffset;
}

static double readComponent(const uint8_t* source, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t value;
            std::memcpy(&value, source, 1);
            return normalized ? std::max(value / 127.0, -1.0) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? source[0] / 255.0 : source[0];
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t value;
            std::memcpy(&value, source, 2);
            return normalized ? std::max(value / 32767.0, -1.0) : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t value;
            std::memcpy(&value, source, 2);
            return normalized ? value / 65535.0 : value;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t value;
            std::memcpy(&value, source, 4);
            return value;
        }
        case TINYGLTF_COMPONENT_TYPE_FLOAT: {
            float value;
            std::memcpy(&value, source, 4);
            return value;
        }
        default: throw Error("unknown component type " + std::to_string(componentType));
    }
}

// Reads every component of every element as double (exact for all glTF component types), with
// sparse substitution applied. An accessor without a buffer view starts as zeros (glTF §3.6.2.3).
static std::vector<double> readAccessor(const tinygltf::Model& model, int accessorIndex) {
    if (accessorIndex < 0 || size_t(accessorIndex) >= model.accessors.size())
        throw Error("accessor " + std::to_string(accessorIndex) + " does not exist");
    const tinygltf::Accessor& accessor = model.accessors[size_t(accessorIndex)];
    const size_t components = size_t(accessorComponentCount(accessor.type));
    const size_t componentBytes = componentByteSize(accessor.componentType);
    const size_t elementBytes = components * componentBytes;
    if (components == 0 || componentBytes == 0 || accessor.type == TINYGLTF_TYPE_MAT2 ||
        accessor.type == TINYGLTF_TYPE_MAT3 || accessor.type == TINYGLTF_TYPE_MAT4)
        throw Error("accessor " + std::to_string(accessorIndex) + " has a type that cannot be read as vertex data");

    std::vector<double> values(accessor.count * components, 0.0);
    if (accessor.bufferView >= 0) {
        const size_t viewStride = model.bufferViews.at(size_t(accessor.bufferView)).byteStride;
        const size_t stride = viewStride ? viewStride : elementBytes;
        const uint8_t* source =
            viewBytes(model, accessor.bufferView, accessor.byteOffset, stride, accessor.count, elementBytes);
        for (size_t element = 0; element < accessor.count; ++element)
            for (size_t c = 0; c < components; ++c)
                values[element * components + c] = readComponent(source + element * stride + c * componentBytes,
                                                                 accessor.componentType, accessor.normalized);
    }
    if (accessor.sparse.isSparse) {
        const size_t sparseCount = size_t(std::max(accessor.sparse.count, 0));
        const int indexType = accessor.sparse.indices.componentType;
        const size_t indexBytes = componentByteSize(indexType);
        if (indexBytes == 0 || indexType == TINYGLTF_COMPONENT_TYPE_FLOAT)
            throw Error("sparse indices have component type " + componentTypeName(indexType));
        const uint8_t* indices =
            viewBytes(model, accessor.sparse.indices.bufferView,
                      size_t(std::max(accessor.sparse.indices.byteOffset, 0)), indexBytes, sparseCount, indexBytes);
        const uint8_t* substitutes =
            viewBytes(model, accessor.sparse.values.bufferView, size_t(std::max(accessor.sparse.values.byteOffset, 0)),
                      elementBytes, sparseCount, elementBytes);
        for (size_t s = 0; s < sparseCount; ++s) {
            const size_t element = size_t(readComponent(indices + s * indexBytes, indexType, false));
            if (element >= accessor.count)
                throw Error("sparse index " + std::to_string(element) + " is past the count");
            for (size_t c = 0; c < components; ++c)
                values[element * components + c] = readComponent(substitutes + s * elementBytes + c * componentBytes,
                                                                 accessor.componentType, accessor.normalized);
        }
    }
    return values;
}

std::vector<float> readAccessorFloats(const tinygltf::Model& model, int accessorIndex) {
    const std::vector<double> values = readAccessor(model, accessorIndex);
    return std::vector<float>(values.begin(), values.end());
}

std::vector<uint32_t> readAccessorIndices(const tinygltf::Model& model, int accessorIndex) {
    const std::vector<double> values = readAccessor(model, accessorIndex);
    std::vector<uint32_t> indices(values.size());
    for (size_t i = 0; i < values.size(); ++i) indices[i] = uint32_t(values[i]);
    return indices;
}

}  // namespace vct
