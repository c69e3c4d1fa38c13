// The barriers a pass's declared uses need (gpu/access.h): the rules PassUses records.
#include <gtest/gtest.h>

#include "gpu/access.h"

namespace vct {
namespace {

bool waits(const VkMemoryBarrier2& wait) { return wait.srcStageMask != VK_PIPELINE_STAGE_2_NONE; }

TEST(Access, AFirstUseWaitsForNothing) {
    SyncState state;
    EXPECT_FALSE(waits(waitBeforeUse(state, access::computeRead, false)));
    SyncState other;
    EXPECT_FALSE(waits(waitBeforeUse(other, access::computeWrite, false)));
}

TEST(Access, AReadAfterAWriteWaitsForItAndSeesItsWrites) {
    SyncState state;
    waitBeforeUse(state, access::computeWrite, false);
    const VkMemoryBarrier2 wait = waitBeforeUse(state, access::fragmentRead, false);
    EXPECT_EQ(wait.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(wait.srcAccessMask, VK_ACCESS_2_SHADER_WRITE_BIT);
    EXPECT_EQ(wait.dstStageMask, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(wait.dstAccessMask, VK_ACCESS_2_SHADER_READ_BIT);
}

TEST(Access, AWriteSeenByAStageIsNotWaitedForAgainThereButIsElsewhere) {
    SyncState state;
    waitBeforeUse(state, access::computeWrite, false);
    EXPECT_TRUE(waits(waitBeforeUse(state, access::computeRead, false)));
    EXPECT_FALSE(waits(waitBeforeUse(state, access::computeRead, false)));
    const VkMemoryBarrier2 copy = waitBeforeUse(state, access::indirectArguments, false);
    EXPECT_EQ(copy.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(copy.dstAccessMask, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
}

TEST(Access, AWriteWaitsForTheReadsSinceTheLastWriteAndForIt) {
    SyncState state;
    waitBeforeUse(state, access::transferWrite, false);
    waitBeforeUse(state, access::computeRead, false);
    waitBeforeUse(state, access::fragmentRead, false);
    const VkMemoryBarrier2 wait = waitBeforeUse(state, access::computeWrite, false);
    EXPECT_EQ(wait.srcStageMask, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT | VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT |
                                     VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
    EXPECT_EQ(wait.srcAccessMask, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    // And the reads after it wait for it alone.
    const VkMemoryBarrier2 read = waitBeforeUse(state, access::fragmentRead, false);
    EXPECT_EQ(read.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
}

TEST(Access, ALayoutChangeForAReadIsALastWriteTheOtherStagesWaitFor) {
    SyncState state;
    waitBeforeUse(state, access::colorAttachment, true);
    const VkMemoryBarrier2 sampled = waitBeforeUse(state, access::computeSampled, true);
    EXPECT_EQ(sampled.srcStageMask, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(sampled.srcAccessMask, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_FALSE(waits(waitBeforeUse(state, access::computeSampled, false)));
    const VkMemoryBarrier2 fragment = waitBeforeUse(state, access::fragmentSampled, false);
    EXPECT_EQ(fragment.srcStageMask, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
    EXPECT_EQ(fragment.dstStageMask, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);
}

}  // namespace
}  // namespace vct
