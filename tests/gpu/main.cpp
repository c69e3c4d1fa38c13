#include <memory>

#include "gpu_test.h"

namespace vct::test {

static std::unique_ptr<GpuContext> sharedContext;

GpuContext& gpu() {
    if (!sharedContext) {
        ContextOptions options;
        options.validation = true;
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
