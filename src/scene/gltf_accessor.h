// Reading glTF accessors into plain arrays: byte strides, normalised integers and sparse
// substitution handled here, once, for the validator and the loader alike.
//
// The validator (gltf_validate.h) checks every range before anything is read; the readers
// still check each range they touch and throw vct::Error instead of reading out of bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vct {

// Number of components in an accessor type (SCALAR = 1 ... MAT4 = 16), 0 if unknown.
int accessorComponentCount(int type);
// Size in bytes of one component type (BYTE = 1 ... FLOAT = 4), 0 if unknown.
size_t componentByteSize(int componentType);
// Size of one element, including the column padding of MAT2/MAT3 with 1- and 2-byte components
// (glTF 2.0 §3.6.2.4, data alignment).
size_t accessorElementBytes(int type, int componentType);
// "FLOAT", "UNSIGNED_SHORT", ... for messages.
std::string componentTypeName(int componentType);
std::string accessorTypeName(int type);

// Reads an accessor as floats, `components` per element. Normalised integers map to [0, 1] or
// [−1, 1] as glTF §3.11 defines; other integers convert to their value.
std::vector<float> readAccessorFloats(const tinygltf::Model& model, int accessorIndex);

// Reads a SCALAR accessor of unsigned integers (indices).
std::vector<uint32_t> readAccessorIndices(const tinygltf::Model& model, int accessorIndex);

}  // namespace vct
