// What a step of a pass does with a buffer or an image (an Access), and what the queue last did
// with it (a SyncState, kept in the resource). The barriers between passes follow from the two
// (pass_uses.h): passes say what they read and write, not which barrier the last pass needs.
#pragma once

#include <vulkan/vulkan.h>

namespace vct {

// The stages that touch the resource, how, and (images) the layout they need it in.
struct Access {
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // images only

    bool writes() const;
};

// One step's two uses of a buffer (a work list read by the shader and as indirect arguments).
constexpr Access operator|(const Access& a, const Access& b) {
    return {a.stages | b.stages, a.access | b.access, a.layout};
}

// The uses the passes make. Shader reads are SHADER_READ (sampled and storage alike) so that one
// barrier makes a write visible to every kind of read of the stage it names.
namespace access {
inline constexpr VkPipelineStageFlags2 kShaders =
    VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

// Storage images and buffers written (read, written, added to atomically) by compute shaders.
inline constexpr Access computeWrite{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                                     VK_ACCESS_2_SHADER_READ_BIT | VK_ACCESS_2_SHADER_WRITE_BIT,
                                     VK_IMAGE_LAYOUT_GENERAL};
// Read by compute or fragment shaders where storage writes leave them (the voxel volumes).
inline constexpr Access computeRead{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT,
                                    VK_IMAGE_LAYOUT_GENERAL};
inline constexpr Access fragmentRead{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT,
                                     VK_IMAGE_LAYOUT_GENERAL};
// Sampled read-only (render targets, finished 2D images, uploads).
inline constexpr Access computeSampled{VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT,
                                       VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
inline constexpr Access fragmentSampled{VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, VK_ACCESS_2_SHADER_READ_BIT,
                                        VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
inline constexpr Access shadersSampled{kShaders, VK_ACCESS_2_SHADER_READ_BIT, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
inline constexpr Access colorAttachment{VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                                        VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
                                        VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
inline constexpr Access depthAttachment{
    VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
    VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
    VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL};
// Filled, updated, cleared or copied into.
inline constexpr Access transferWrite{VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL};
// Copied from (a read-back); the next shader use moves an image back to its own layout.
inline constexpr Access copySource{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
                                   VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL};
inline constexpr Access indirectArguments{VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT};
inline constexpr Access hostRead{VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT};
}  // namespace access

// What the queue last did with a resource, as recorded so far: the layout, the last write not yet
// known to be finished before every later use, and the reads since it. Commands are recorded in
// submission order, so the state carries over from one command buffer to the next.
struct SyncState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 writeStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 writeAccess = VK_ACCESS_2_NONE;
    // The stages that read since the last write (a new write waits for them), and the accesses the
    // last write was made visible to in those stages.
    VkPipelineStageFlags2 readStages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 visibleAccess = VK_ACCESS_2_NONE;
};

// What a use must wait for after what `state` records (src: the stages and accesses to wait for;
// dst: the use's; all none when nothing), and `state` moved on past the use. `layoutChanges`: the
// use needs the image in another layout, which rewrites its memory like a write.
VkMemoryBarrier2 waitBeforeUse(SyncState& state, const Access& access, bool layoutChanges);

}  // namespace vct
