// A step of a pass declares the buffers and images it uses and how; recording the declaration
// emits the barriers those uses need after everything recorded before them (one
// vkCmdPipelineBarrier2, or none), and moves each resource's SyncState on. So a pass never names
// the pass before it, and a pass skipped by the frame plan leaves nothing to wait for.
//
//     PassUses()
//         .use(volumes.albedoOpacity, access::computeRead)
//         .use(volumes.radiance, access::computeWrite)
//         .record(commands);
//     vkCmdDispatch(...);
#pragma once

#include <vulkan/vulkan.h>

#include <vector>

#include "gpu/access.h"
#include "gpu/resources.h"

namespace vct {

// What the step does with an image's earlier contents: Keep them, or Discard them (every texel is
// rewritten), which lets a layout change skip them.
enum class Contents { Keep, Discard };

// A step declares each resource with everything it does with it (two kinds of use of a buffer: their
// union, access::operator|); the same use declared twice (one image bound as two inputs) is harmless.
class PassUses {
public:
    PassUses& use(const Buffer& buffer, const Access& access);
    PassUses& use(const GpuImage& image, const Access& access, Contents contents = Contents::Keep);
    // The barriers the declared uses need, recorded into `commands`.
    void record(VkCommandBuffer commands);

private:
    void addMemoryWait(const VkMemoryBarrier2& wait);

    VkMemoryBarrier2 memory_{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
    std::vector<VkImageMemoryBarrier2> images_;
};

// For work recorded with its own barriers (uploads that build mip chains level by level): the
// image is now in `access`'s layout, written before it and visible to it.
void settle(const GpuImage& image, const Access& access);

}  // namespace vct
