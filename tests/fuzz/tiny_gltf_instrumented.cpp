// tinygltf's implementation, compiled with the fuzzer's instrumentation (see CMakeLists.txt).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
