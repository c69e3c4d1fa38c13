// Descriptor writes are checked against the bindings the pipeline's shaders declare: a write to a
// slot the shaders do not have, or of another type or array size, is an error that names the
// shaders and the binding before anything is recorded.
#include <string>

#include "error.h"
#include "gpu/pipelines.h"
#include "gpu/resources.h"
#include "gpu_test.h"

namespace vct::test {
namespace {

class DescriptorPushTest : public GpuTest {};

// The message of the Error that pushing `writes` for `pipeline` throws ("" if none).
std::string pushError(DescriptorPush& writes, const Pipeline& pipeline) {
    try {
        // A mismatch throws before the command buffer is touched.
        writes.push(gpu(), VK_NULL_HANDLE, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST_F(DescriptorPushTest, AWriteOfTheWrongTypeNamesTheShaderAndTheBinding) {
    // mips.comp.glsl: binding 0 and 1 are storage images.
    const Pipeline mips = createComputePipeline(gpu(), "mips.comp");
    const Buffer buffer(gpu(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    DescriptorPush writes;
    writes.buffer(1, buffer.buffer);
    const std::string message = pushError(writes, mips);
    EXPECT_NE(message.find("mips.comp"), std::string::npos) << message;
    EXPECT_NE(message.find("binding 1 is a storage image"), std::string::npos) << message;
    EXPECT_NE(message.find("written as a storage buffer"), std::string::npos) << message;
}

TEST_F(DescriptorPushTest, AWriteToASlotTheShaderDoesNotDeclareIsAnError) {
    const Pipeline mips = createComputePipeline(gpu(), "mips.comp");
    const Buffer buffer(gpu(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    DescriptorPush writes;
    writes.buffer(7, buffer.buffer);
    const std::string message = pushError(writes, mips);
    EXPECT_NE(message.find("mips.comp: binding 7"), std::string::npos) << message;
    EXPECT_NE(message.find("declare no such binding"), std::string::npos) << message;
}

TEST_F(DescriptorPushTest, MoreArrayElementsThanTheShaderDeclaresIsAnError) {
    // diffuse_trace_list.comp.glsl: binding 2 is one storage buffer (the listed samples).
    const Pipeline trace = createComputePipeline(gpu(), "diffuse_trace_list.comp");
    const Buffer buffer(gpu(), 256, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, false);
    DescriptorPush writes;
    writes.buffers(2, {buffer.buffer, buffer.buffer});
    const std::string message = pushError(writes, trace);
    EXPECT_NE(message.find("binding 2 holds 1 descriptor(s), written with 2"), std::string::npos) << message;
}

}  // namespace
}  // namespace vct::test
