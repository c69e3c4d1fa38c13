// GPU tests share one Vulkan context with the validation layer on; every validation message
// (error or warning) fails the test that caused it.
#pragma once

#include <gtest/gtest.h>

#include "gpu/context.h"

namespace vct::test {

GpuContext& gpu();

class GpuTest : public ::testing::Test {
protected:
    void SetUp() override { gpu().clearValidationMessages(); }
    void TearDown() override {
        for (const std::string& message : gpu().validationMessages()) ADD_FAILURE() << message;
    }
};

}  // namespace vct::test
