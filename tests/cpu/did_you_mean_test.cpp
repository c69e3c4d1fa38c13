#include <gtest/gtest.h>

#include "app/did_you_mean.h"

namespace vct {
namespace {

TEST(DidYouMean, CountsEdits) {
    EXPECT_EQ(editDistance("render", "render"), 0u);
    EXPECT_EQ(editDistance("rendr", "render"), 1u);
    EXPECT_EQ(editDistance("redner", "render"), 2u);
    EXPECT_EQ(editDistance("", "view"), 4u);
}

TEST(DidYouMean, NamesTheClosestKnownNameOrNone) {
    EXPECT_EQ(didYouMean("rendr", {"render", "view", "bench"}), " (did you mean 'render'?)");
    EXPECT_EQ(didYouMean("veiw", {"render", "view", "bench"}), " (did you mean 'view'?)");
    EXPECT_EQ(didYouMean("shadowmap", {"shadow-map", "local-shadow-map"}, "--"), " (did you mean '--shadow-map'?)");
    EXPECT_EQ(didYouMean("frobnicate", {"render", "view", "bench"}), "");
}

}  // namespace
}  // namespace vct
