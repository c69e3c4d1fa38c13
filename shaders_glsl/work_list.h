// A work list: items a pass appends with atomics, and the indirect dispatch that covers them, so
// the pass after runs one invocation per item instead of one per texel, its lanes all busy.
// Shared by C++ and GLSL. The occupied voxels (voxel_grid.h) and the samples whose reduced diffuse
// light cannot be upsampled (reduced_diffuse.glsl) are such lists.
#ifndef VCT_WORK_LIST_H
#define VCT_WORK_LIST_H

#include "cpp_glsl.h"

VCT_SHARED_BEGIN

const uint WORK_LIST_GROUP_SIZE = 64u;  // invocations per workgroup of a pass over a list

struct WorkListHeader {
    uint groupsX, groupsY, groupsZ;  // VkDispatchIndirectCommand: ⌈count / 64⌉ capped at a limit, 1, 1
    uint count;                      // items listed
};

// Whether the item appended at `slot` adds a workgroup to the dispatch: the first of each
// workgroup's share does, up to `groupLimit` (the device's maxComputeWorkGroupCount[0]); a pass
// over the list strides over what a capped dispatch leaves.
SHARED_FN bool startsWorkgroup(uint slot, uint groupLimit) {
    return slot % WORK_LIST_GROUP_SIZE == 0u && slot / WORK_LIST_GROUP_SIZE < groupLimit;
}

VCT_SHARED_END

#endif
