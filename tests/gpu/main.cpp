#include <memory>

#include "gpu_test.h"

namespace vct::test {

static std::unique_ptr<GpuContext> sharedContext;

GpuContext& gpu() {
    if (!sharedContext) {
        ContextOptions options;
        // Every message fails the test that caused it (gpu_test.h), hazards included. None is
        // filtered: with this layer (1.3.239) and these passes synchronization validation reports
        // nothing. Its known false positives to expect if that changes: it files vkCmdFillBuffer
        // under the COPY stage rather than CLEAR, and GPU-assisted validation (not enabled here)
        // misreads push descriptors.
        options.validation = true;
        options.synchronizationValidation = true;
        sharedContext = std::make_unique<GpuContext>(options);
    }
    return *sharedContext;
}

}  // namespace vct::test

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    const int result = RUN_ALL_TESTS();
    vct::test::sharedContext.reset();
    return result;
}
