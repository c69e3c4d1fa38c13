// Descriptor writes are checked against the bindings the pipeline's shaders declare: a write to a
// slot the shaders do not have, or of another type or array size, is an error that names the
// shaders and the binding before anything is recorded. (Every pass's writes, which match, are
// pushed by the other GPU tests.)
#include <string>
#include <vector>

#include "bindings.h"
#include "error.h"
#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "gpu_test.h"

namespace vct::test {
namespace {

class DescriptorPushTest : public GpuTest {};

// The message of the Error that pushing `count` storage-buffer descriptors to `binding` of the
// pipeline of `shader` throws ("" if none). A mismatch throws before the command buffer is touched.
std::string storageBufferWriteError(const char* shader, uint32_t binding, size_t count) {
    const Pipeline pipeline = createComputePipeline(gpu(), shader);
    const Buffer buffer(gpu(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    DescriptorPush writes;
    writes.buffers(binding, std::vector<VkBuffer>(count, buffer.buffer));
    try {
        writes.push(gpu(), VK_NULL_HANDLE, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST_F(DescriptorPushTest, AWriteOfTheWrongTypeNamesTheShaderAndTheBinding) {
    // mips.comp.glsl: the finer and the coarser level are storage images.
    const std::string message = storageBufferWriteError("mips.comp", glsl::COARSER_LEVEL_BINDING, 1);
    EXPECT_NE(message.find("mips.comp"), std::string::npos) << message;
    const std::string binding = "binding " + std::to_string(glsl::COARSER_LEVEL_BINDING);
    EXPECT_NE(message.find(binding + " is a storage image"), std::string::npos) << message;
    EXPECT_NE(message.find("written as a storage buffer"), std::string::npos) << message;
}

TEST_F(DescriptorPushTest, AWriteToASlotTheShaderDoesNotDeclareIsAnError) {
    const std::string message = storageBufferWriteError("mips.comp", 7, 1);
    EXPECT_NE(message.find("mips.comp: binding 7"), std::string::npos) << message;
    EXPECT_NE(message.find("declare no such binding"), std::string::npos) << message;
}

TEST_F(DescriptorPushTest, MoreArrayElementsThanTheShaderDeclaresIsAnError) {
    // diffuse_trace_list.comp.glsl: the listed samples are one storage buffer.
    const std::string message = storageBufferWriteError("diffuse_trace_list.comp", glsl::LISTED_SAMPLES_BINDING, 2);
    const std::string binding = "binding " + std::to_string(glsl::LISTED_SAMPLES_BINDING);
    EXPECT_NE(message.find(binding + " holds 1 descriptor(s), written with 2"), std::string::npos) << message;
}

}  // namespace
}  // namespace vct::test
